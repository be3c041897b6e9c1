#include "compare/cache/reference_cache.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include "compare/cache/build_identity.h"
#include "compare/cache/scene_hash.h"
#include "core/cli/shadow_option.h"
#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/image_io.h"
#include "core/reference/reference_renderer.h"
#include "core/reference/reference_settings.h"

namespace tp::cli {
namespace {

namespace fs = std::filesystem;
constexpr const char* kSchema = "triptych.reference-cache/1";

// An image's size and pixels (RGBA or depth), as meta.json records them.
template <class T> std::string pixelHash(uint32_t width, uint32_t height, const std::vector<T>& v) {
    Fnv1a64 h;
    h.u64(width);
    h.u64(height);
    h.array(v);
    return h.hex();
}
std::string imageHash(const ImageRGBA& image) {
    return pixelHash(image.width, image.height, image.rgba);
}
std::string depthHash(const ImageR32& depth) { return pixelHash(depth.width, depth.height, depth.r); }

// Depth travels in an RGBA EXR's red channel (the EXR writer's one layout).
ImageRGBA depthAsRgba(const ImageR32& depth) {
    ImageRGBA out(depth.width, depth.height);
    for (size_t i = 0; i < depth.r.size(); ++i) {
        out.rgba[i * 4] = depth.r[i];
        out.rgba[i * 4 + 3] = 1.0f;
    }
    return out;
}

ImageR32 depthFromRgba(const ImageRGBA& image) {
    ImageR32 out{image.width, image.height, std::vector<float>(image.pixelCount())};
    for (size_t i = 0; i < out.r.size(); ++i)
        out.r[i] = image.rgba[i * 4];
    return out;
}

nlohmann::json runToJson(const RunResult& run) {
    nlohmann::json j;
    j["renderer"] = run.renderer;
    j["msaa"] = run.msaa;
    for (const auto& [knob, value] : run.knobs)
        j["knobs"][knob.name] = value;
    for (const TimingStats& t : run.timings)
        j["timings"].push_back({t.name, t.medianMs, t.minMs, t.maxMs, t.frames});
    for (const LedgerEntry& e : run.memory)
        j["memory"].push_back({e.tag.owner, e.tag.pass, e.tag.name, e.tag.purpose, e.isImage,
                               int(e.format), e.width, e.height, e.mipLevels, e.samples,
                               e.requestedBytes, e.bytes});
    for (const auto& [name, value] : run.stats.counters)
        j["counters"].push_back({name, value});
    for (const LeftOut& l : run.stats.leftOut)
        j["left_out"].push_back({l.what, l.why});
    j["passes"] = run.passes;
    j["culled_passes"] = run.culledPasses;
    return j;
}

// The run as runToJson wrote it; throws nlohmann's exceptions on a malformed file.
RunResult runFromJson(const nlohmann::json& j) {
    RunResult run;
    run.renderer = j.at("renderer").get<std::string>();
    run.msaa = j.at("msaa").get<uint32_t>();
    const RendererEntry& entry = **findRenderer(kReferenceRenderer);
    for (const Knob& k : entry.knobs)
        if (j.contains("knobs") && j["knobs"].contains(k.name))
            run.knobs.push_back({k, j["knobs"][k.name].get<std::string>()});
    for (const auto& t : j.value("timings", nlohmann::json::array()))
        run.timings.push_back({t[0], t[1], t[2], t[3], t[4]});
    for (const auto& e : j.value("memory", nlohmann::json::array())) {
        LedgerEntry l;
        l.tag = {e[0], e[1], e[2], e[3]};
        l.isImage = e[4];
        l.format = VkFormat(e[5].get<int>());
        l.width = e[6];
        l.height = e[7];
        l.mipLevels = e[8];
        l.samples = e[9];
        l.requestedBytes = e[10];
        l.bytes = e[11];
        run.memory.push_back(l);
    }
    for (const auto& c : j.value("counters", nlohmann::json::array()))
        run.stats.counters.push_back({c[0], c[1]});
    for (const auto& l : j.value("left_out", nlohmann::json::array()))
        run.stats.leftOut.push_back({l[0], l[1]});
    run.passes = j.value("passes", std::vector<std::string>{});
    run.culledPasses = j.value("culled_passes", std::vector<std::string>{});
    return run;
}

} // namespace

std::string defaultReferenceCacheDir() { return userCacheDir("references"); }

std::string referenceCacheDir(const std::string& option, bool off) {
    return off ? "" : option.empty() ? defaultReferenceCacheDir() : option;
}

void addReferenceCacheOptions(CLI::App& cmd, std::string& dir, bool& off) {
    cmd.add_option("--reference-cache", dir,
                   "Folder of the reference cache: a reference already rendered for the same "
                   "scene content, lights, camera, resolution, MSAA, reference settings, device "
                   "and triptych build is read from there instead of rendered again (a corrupt "
                   "or mismatched entry is rendered again), and a new one is stored. Default: "
                   "$XDG_CACHE_HOME/triptych/references or ~/.cache/triptych/references");
    cmd.add_flag("--no-reference-cache", off,
                 "Render the reference even where the cache holds it, and store nothing");
}

ReferenceKey referenceKey(const GpuContext& ctx, const SceneGpu& scene,
                          const SceneFeatures& features, const RenderSettings& settings) {
    Fnv1a64 lights;
    lights.array(scene.lightsGpu());
    std::string t = std::string(kSchema) + "\n";
    t += "build " + buildHash() + "\n";
    t += "device " + ctx.info.name + " | " + ctx.info.driver + " | " + ctx.info.type + "\n";
    t += "scene " + hashSceneContent(scene.scene()) + "\n";
    t += "lights " + std::to_string(scene.lightsGpu().size()) + " " + lights.hex() + "\n";
    t += "size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
         " msaa " + std::to_string(settings.msaa) + "\n";
    t += "features";
    for (bool f : {features.blended, features.masked, features.normalMaps, features.emissive,
                   features.textures, features.vertexColors, features.pointLights,
                   features.spotLights, features.directionalLights})
        t += f ? " 1" : " 0";
    t += " samples " + std::to_string(features.msaaSamples) + "\n";
    // --shadows: which lights cast shadows and their maps' sizes (the budget) change the image.
    if (settings.shadows.enabled())
        t += "shadows " + shadowCountText(settings.shadows) + " budget " +
             std::to_string(settings.shadows.budgetMb) + "\n";
    // What it follows of the pipelines' settings (--reference-shadows maps: their rasterizer).
    t += ref::followedSettingsText(settings);
    // The reference's own knobs, defaults filled in: the rest of what it reads.
    for (const Knob& k : (*findRenderer(kReferenceRenderer))->knobs)
        t += "knob " + k.name + "=" + k.valueIn(settings.knobs) + "\n";
    Fnv1a64 h;
    h.text(t);
    return {t, h.hex()};
}

std::optional<RunResult> loadReference(const std::string& dir, const ReferenceKey& key,
                                       std::string& note, std::string& renderedAt) {
    const fs::path entry = fs::path(dir) / key.hash;
    std::ifstream in(entry / "meta.json");
    if (!in) return std::nullopt; // a plain miss
    try {
        const nlohmann::json meta = nlohmann::json::parse(in);
        if (meta.value("schema", "") != kSchema || meta.value("key", "") != key.text) {
            note = "entry " + entry.string() + " holds another key: rendered again";
            return std::nullopt;
        }
        Result<ImageRGBA> hdr = readExr((entry / "hdr.exr").string());
        Result<ImageRGBA> depth = readExr((entry / "depth.exr").string());
        if (!hdr || !depth || imageHash(*hdr) != meta.value("hdr_hash", "") ||
            depthHash(depthFromRgba(*depth)) != meta.value("depth_hash", "")) {
            note = "entry " + entry.string() + " is corrupt (its images do not match their " +
                   "hashes): rendered again";
            return std::nullopt;
        }
        RunResult run = runFromJson(meta.at("run"));
        run.hdr = std::move(*hdr);
        run.depth = depthFromRgba(*depth);
        renderedAt = meta.value("rendered_at", "");
        return run;
    } catch (const std::exception& e) {
        note = "entry " + entry.string() + " is unreadable (" + e.what() + "): rendered again";
        return std::nullopt;
    }
}

Status storeReference(const std::string& dir, const ReferenceKey& key, const RunResult& run) {
    const fs::path final = fs::path(dir) / key.hash;
    const fs::path tmp = fs::path(dir) / (".tmp-" + key.hash + "-" + std::to_string(getpid()));
    std::error_code ec;
    fs::create_directories(tmp, ec);
    if (ec) return Error{"reference cache: cannot create " + tmp.string() + ": " + ec.message()};
    Status s = writeExr((tmp / "hdr.exr").string(), run.hdr, ExrPixelType::Float);
    if (s) s = writeExr((tmp / "depth.exr").string(), depthAsRgba(run.depth), ExrPixelType::Float);
    if (s) {
        nlohmann::json meta = {{"schema", kSchema},         {"key", key.text},
                               {"hdr_hash", imageHash(run.hdr)},
                               {"depth_hash", depthHash(run.depth)},
                               {"rendered_at", utcNow()}, {"run", runToJson(run)}};
        std::ofstream out(tmp / "meta.json");
        out << meta.dump(1) << "\n";
        if (!out) s = Error{"reference cache: cannot write " + (tmp / "meta.json").string()};
    }
    if (s) {
        fs::remove_all(final, ec); // a corrupt or mismatched entry it replaces
        fs::rename(tmp, final, ec);
        // Another process may have stored the same key in between: its entry stands.
        if (ec && !fs::exists(final / "meta.json"))
            s = Error{"reference cache: cannot move " + tmp.string() + " to " + final.string() +
                      ": " + ec.message()};
    }
    if (!s) fs::remove_all(tmp, ec);
    return s;
}

Result<RunResult> runReferenceCached(GpuContext& ctx, SceneGpu& scene,
                                     const SceneFeatures& features, const RenderSettings& settings,
                                     const RunOptions& options, const std::string& cacheDir,
                                     ReferenceCacheUse& use) {
    use = {};
    const RendererEntry& entry = **findRenderer(kReferenceRenderer);
    if (cacheDir.empty() || settings.debug)
        return tryRunRenderer(ctx, scene, entry, features, settings, options);
    // The knobs with their defaults, as the run will have them (so an explicit default and an
    // absent knob are one key).
    RenderSettings resolved = settings;
    if (Status s = resolveKnobs(entry.knobs, resolved); !s) return Error{s.error()};
    const ReferenceKey key = referenceKey(ctx, scene, features, resolved);
    use.dir = cacheDir;
    use.key = key.hash;
    use.entry = (fs::path(cacheDir) / key.hash).string();
    if (std::optional<RunResult> cached = loadReference(cacheDir, key, use.note, use.renderedAt)) {
        use.reused = true;
        // Its timings are the stored run's; what was measured beside them is not stored.
        cached->energy.reason = "reused from the reference cache: energy is measured only when the frames run";
        cached->statisticsWhy = "reused from the reference cache: its entry holds no pipeline statistics";
        return std::move(*cached);
    }
    Result<RunResult> run = tryRunRenderer(ctx, scene, entry, features, settings, options);
    if (run) {
        if (Status s = storeReference(cacheDir, key, *run); s)
            use.stored = true;
        else
            use.note += (use.note.empty() ? "" : "; ") + s.error();
    }
    if (!use.note.empty())
        std::fprintf(stderr, "triptych: warning: reference cache: %s\n", use.note.c_str());
    return run;
}

nlohmann::json referenceCacheJson(const ReferenceCacheUse& c) {
    if (c.dir.empty()) return {{"used", false}};
    nlohmann::json j = {{"used", true},        {"dir", c.dir},      {"entry", c.entry},
                        {"key_fnv1a64", c.key}, {"reused", c.reused}, {"stored", c.stored}};
    if (c.reused) j["rendered_at"] = c.renderedAt;
    if (!c.note.empty()) j["note"] = c.note;
    return j;
}

} // namespace tp::cli
