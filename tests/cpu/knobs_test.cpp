// The knob schema and the registry built from the pipelines' own declarations: one check
// per knob, defaults filled in, shared knobs declared once, every pipeline found without a
// list (each registers itself from its folder).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>

#include "core/renderer/renderer.h"

namespace tp {
namespace {

Knob tileLike() {
    return Knob::integerOf("tile", {"8", "16", "32"}, "16", "tile edge");
}

TEST(Knobs, ChecksChoiceListAndRange) {
    const Knob choice = Knob::choice("accum", {"fp16", "fp32"}, "precision");
    EXPECT_EQ(choice.defaultValue, "fp16");
    EXPECT_TRUE(choice.check("fp16").ok());
    EXPECT_EQ(choice.check("fp8").error(), "--accum 'fp8': allowed values are fp16, fp32");
    EXPECT_FALSE(choice.check("").ok());

    const Knob tile = tileLike();
    EXPECT_TRUE(tile.check("32").ok());
    EXPECT_EQ(tile.check("12").error(), "--tile '12': allowed values are 8, 16, 32");
    EXPECT_FALSE(tile.check("016").ok()); // listed values are matched as written

    const Knob range = Knob::integer("tile-capacity", 1, 65536, 256, "slots");
    EXPECT_TRUE(range.check("1").ok());
    EXPECT_TRUE(range.check("65536").ok());
    EXPECT_EQ(range.check("0").error(), "--tile-capacity '0': allowed values are 1 to 65536");
    for (const char* bad : {"65537", "-1", " 5", "5x", "1e3", "99999999999", ""})
        EXPECT_FALSE(range.check(bad).ok()) << bad;
    EXPECT_EQ(range.key(), "tile_capacity");
}

TEST(Knobs, ResolveFillsDefaultsAndRefusesBadValues) {
    RenderSettings s;
    ASSERT_TRUE(resolveKnobs({tileLike()}, s).ok());
    EXPECT_EQ(s.integer("tile"), 16u);
    s.set("tile", 32u);
    ASSERT_TRUE(resolveKnobs({tileLike()}, s).ok());
    EXPECT_EQ(s.integer("tile"), 32u);
    s.set("tile", "64");
    EXPECT_EQ(resolveKnobs({tileLike()}, s).error(), "--tile '64': allowed values are 8, 16, 32");
    EXPECT_THROW(s.text("never-declared"), RendererError);
}

// The reference first, then each pipeline in the order it declared (ties by name), each once;
// and every pipeline folder (a top-level folder with a register.cpp, named as its pipeline:
// tests/cli/no_pipeline_names.sh) is registered, so none was left out of the link.
TEST(Registry, EveryPipelineRegistersItselfInOrder) {
    const std::vector<RendererEntry>& all = registeredRenderers();
    ASSERT_FALSE(all.empty());
    EXPECT_EQ(all.front().name, "reference");
    std::set<std::string> names;
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_TRUE(names.insert(all[i].name).second) << all[i].name << " registered twice";
        if (i == 0) continue;
        EXPECT_TRUE(all[i - 1].order < all[i].order ||
                    (all[i - 1].order == all[i].order && all[i - 1].name < all[i].name))
            << all[i - 1].name << " before " << all[i].name;
    }
    size_t folders = 0;
    for (const auto& dir : std::filesystem::directory_iterator(TP_SOURCE_DIR))
        if (std::filesystem::exists(dir.path() / "register.cpp")) {
            ++folders;
            EXPECT_TRUE(names.count(dir.path().filename().string()))
                << dir.path() << " has a register.cpp but no renderer of its name is registered";
        }
    EXPECT_EQ(folders + 1, all.size()) << "a renderer registered from no pipeline folder";
}

TEST(Registry, EveryDeclaredKnobIsComplete) {
    for (const RendererEntry& e : registeredRenderers()) {
        std::set<std::string> seen;
        for (const Knob& k : e.knobs) {
            SCOPED_TRACE(e.name + " --" + k.name);
            EXPECT_TRUE(seen.insert(k.name).second) << "declared twice";
            EXPECT_FALSE(k.help.empty());
            EXPECT_TRUE(k.check(k.defaultValue).ok()) << "the default is not an allowed value";
            EXPECT_EQ(k.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-"),
                      std::string::npos);
        }
    }
}

TEST(Registry, SharedKnobsAreOneDeclaration) {
    // "tile": one entry, read by every registered renderer that declares it (the tiled ones).
    std::vector<std::string> declaring;
    for (const RendererEntry& e : registeredRenderers())
        for (const Knob& k : e.knobs)
            if (k.name == "tile") declaring.push_back(e.name);
    EXPECT_GE(declaring.size(), 2u) << "--tile is no longer shared";
    size_t tileEntries = 0;
    for (const KnobReaders& k : allKnobs())
        if (k.knob.name == "tile") {
            ++tileEntries;
            EXPECT_EQ(k.readers, declaring);
        }
    EXPECT_EQ(tileEntries, 1u);

    // A renderer that declares "tile" with other values is refused before it is added.
    Knob other = tileLike();
    other.values = {"8", "64"};
    const size_t before = registeredRenderers().size();
    EXPECT_THROW(registerRenderer({"knobs_test_conflict", "test", nullptr, 50, {other}, {}, {}}),
                 std::logic_error);
    EXPECT_EQ(registeredRenderers().size(), before);
    EXPECT_FALSE(findRenderer("knobs_test_conflict").ok());
}

} // namespace
} // namespace tp
