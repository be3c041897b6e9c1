// The knob schema and the registry built from the pipelines' own declarations: one check
// per knob, defaults filled in, shared knobs declared once, every pipeline found without a
// list (each registers itself from its folder).
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "core/render/renderer.h"

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

TEST(Registry, EveryPipelineRegistersItselfInOrder) {
    std::vector<std::string> names;
    for (const RendererEntry& e : registeredRenderers())
        names.push_back(e.name);
    // The reference first, then each pipeline in the order it declared.
    EXPECT_EQ(names, (std::vector<std::string>{"reference", "forwardplus", "deferred",
                                               "visbuffer", "multipass_forward"}));
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
    bool tileShared = false;
    for (const KnobReaders& k : allKnobs())
        if (k.knob.name == "tile")
            tileShared =
                k.readers == std::vector<std::string>{"forwardplus", "deferred", "visbuffer"};
    EXPECT_TRUE(tileShared);

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
