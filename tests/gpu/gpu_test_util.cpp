#include "gpu_test_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include <unistd.h>

#include "core/gpu/vk_check.h"
#include "core/passes/shadow_maps.h"
#include "core/renderer/error_model.h"
#include "core/image/tonemap.h"
#include "core/image/metrics.h"
#include "core/renderer/knobs.h"
#include "core/renderer/renderer.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "core/scene/stress_scenes.h"
#include "gltf_test_scenes.h"

namespace tp::test {

std::unique_ptr<GpuContext> makeValidatedContext() {
    ContextOptions options;
    options.validate = true;
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(options);
    EXPECT_TRUE(ctx.ok()) << ctx.error();
    return ctx.ok() ? std::move(*ctx) : nullptr;
}

void expectNoValidationMessages(const GpuContext& ctx) {
    std::vector<std::string> messages = ctx.validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation messages, first: "
                                  << (messages.empty() ? "" : messages.front());
}

void addQuad(Mesh& m, glm::vec3 origin, glm::vec3 u, glm::vec3 v) {
    uint32_t base = uint32_t(m.positions.size());
    glm::vec3 n = glm::normalize(glm::cross(u, v));
    glm::vec3 corners[4] = {origin, origin + u, origin + u + v, origin + v};
    glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        m.positions.push_back(corners[i]);
        m.normals.push_back(n);
        m.tangents.push_back(glm::vec4(glm::normalize(u), 1.0f));
        m.uvs.push_back(uvs[i]);
        m.colors.push_back(glm::vec4(1.0f));
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        m.indices.push_back(base + i);
}

Scene makeFloorScene(const std::vector<Light>& lights) {
    Scene s;
    s.source = "test:floor";
    Material white;
    white.name = "white";
    white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    white.metallicFactor = 0.0f;
    white.roughnessFactor = 1.0f;
    Material red = white;
    red.name = "red";
    red.baseColorFactor = glm::vec4(0.8f, 0.2f, 0.1f, 1.0f);
    red.roughnessFactor = 0.3f;
    s.materials = {white, red};
    Mesh floor;
    floor.name = "floor";
    addQuad(floor, {-5, 0, 5}, {10, 0, 0}, {0, 0, -10}); // CCW seen from +y
    Mesh box;
    box.name = "box";
    box.material = 1;
    const float h = 1.0f;
    addQuad(box, {-1, 0, 1}, {2, 0, 0}, {0, h, 0});  // front (+z)
    addQuad(box, {1, 0, -1}, {-2, 0, 0}, {0, h, 0}); // back (-z)
    addQuad(box, {1, 0, 1}, {0, 0, -2}, {0, h, 0});  // right (+x)
    addQuad(box, {-1, 0, -1}, {0, 0, 2}, {0, h, 0}); // left (-x)
    addQuad(box, {-1, h, 1}, {2, 0, 0}, {0, 0, -2}); // top
    s.meshes = {floor, box};
    s.lights = lights;
    s.camera.position = {0, 6, 8};
    s.camera.target = {0, 0, 0};
    s.camera.yfov = 0.9f;
    s.camera.znear = 0.1f;
    s.ambient = glm::vec3(0.01f);
    s.computeBounds();
    return s;
}

namespace {
// TP_TIME_RUNS=1: one line per run on stderr with the process's CPU seconds over it (every
// thread: lavapipe's rasterizer threads and pipeline compiles included), to see which runs
// make a test slow (docs/build.md, "Test time").
void printRunCpu(const std::string& pipeline, const SceneGpu& scene, const RenderSettings& s,
                 clock_t cpu) {
    std::string knobs;
    for (const auto& [name, value] : s.knobs)
        knobs += " " + name + "=" + value;
    std::fprintf(stderr, "[ run-cpu ] %6.2f s %s %ux%u %ux lights=%zu debug=%d%s\n",
                 double(cpu) / CLOCKS_PER_SEC, pipeline.c_str(), s.width, s.height, s.msaa,
                 scene.scene().lights.size(), int(s.debug), knobs.c_str());
}
} // namespace

bool ranPass(const RunResult& run, const std::string& pass) {
    return std::find(run.passes.begin(), run.passes.end(), pass) != run.passes.end();
}

RunResult runOrFail(GpuContext& ctx, SceneGpu& scene, const std::string& pipeline,
                    const RenderSettings& settings, uint32_t frames) {
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    EXPECT_TRUE(entry.ok()) << entry.error();
    RunOptions options;
    options.warmupFrames = 0;
    options.timedFrames = frames;
    SceneFeatures features = analyzeScene(scene.scene(), settings.msaa);
    const clock_t c0 = std::clock();
    Result<RunResult> run = runRenderer(ctx, scene, **entry, features, settings, options);
    if (std::getenv("TP_TIME_RUNS")) printRunCpu(pipeline, scene, settings, std::clock() - c0);
    EXPECT_TRUE(run.ok()) << run.error();
    return run.ok() ? std::move(*run) : RunResult{};
}

std::vector<uint32_t> blendedLayers(const Scene& scene, const gpu::FrameUniforms& f) {
    const uint32_t w = f.viewport.x, h = f.viewport.y;
    std::vector<uint32_t> layers(size_t(w) * h, 0);
    for (const Mesh& m : scene.meshes) {
        if (scene.materials[m.material].alphaMode != AlphaMode::Blend) continue;
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            glm::vec2 lo(0.0f), hi{float(w), float(h)};
            bool inFront = true;
            glm::vec2 pmin(1e30f), pmax(-1e30f);
            for (int k = 0; k < 3; ++k) {
                glm::vec4 clip = f.viewProj * glm::vec4(m.positions[m.indices[t + k]], 1.0f);
                if (clip.w <= f.projParams.x) inFront = false;
                glm::vec2 px((clip.x / clip.w * 0.5f + 0.5f) * float(w),
                             (0.5f - clip.y / clip.w * 0.5f) * float(h));
                pmin = glm::min(pmin, px);
                pmax = glm::max(pmax, px);
            }
            if (inFront) {
                lo = glm::max(lo, glm::floor(pmin) - 1.0f);
                hi = glm::min(hi, glm::ceil(pmax) + 1.0f);
            }
            for (int y = int(lo.y); y < int(hi.y); ++y)
                for (int x = int(lo.x); x < int(hi.x); ++x)
                    ++layers[size_t(y) * w + size_t(x)];
        }
    }
    return layers;
}

// Whether renderer `e` declares the knob `name`.
bool readsKnob(const RendererEntry& e, const std::string& name) {
    return std::any_of(e.knobs.begin(), e.knobs.end(), [&](const Knob& k) { return k.name == name; });
}

std::vector<std::string> cullingPipelines() {
    std::vector<std::string> out;
    for (const RendererEntry& e : registeredRenderers())
        if (readsKnob(e, "cull-geometry")) out.push_back(e.name);
    return out;
}

std::vector<std::vector<uint8_t>> exportedBuffers(GpuContext& ctx, SceneGpu& scene,
                                                  const std::string& pipeline,
                                                  const RenderSettings& settings,
                                                  const std::vector<std::string>& names) {
    scene.setView(settings.width, settings.height, settings.msaa);
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    EXPECT_TRUE(entry.ok());
    if (!entry.ok()) return std::vector<std::vector<uint8_t>>(names.size());
    RenderSettings resolved = settings;
    EXPECT_TRUE(resolveKnobs((*entry)->knobs, resolved).ok());
    RendererCreateInfo info{ctx, scene, analyzeScene(scene.scene(), settings.msaa), resolved};
    std::unique_ptr<Renderer> renderer = createRenderer(**entry, info);
    FrameGraph graph(ctx, pipeline, settings.width, settings.height);
    renderer->plan(graph);
    graph.compile();
    renderer->prepare(graph);
    recordAndSubmit(ctx, graph);
    std::vector<std::vector<uint8_t>> out;
    for (const std::string& name : names) {
        ResourceHandle h = graph.exported(name);
        out.push_back(h.valid() ? readbackBuffer(ctx, graph.buffer(h)) : std::vector<uint8_t>{});
    }
    return out;
}

void holdRasterFixed(RenderSettings& s, const std::string& pipeline) {
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    if (entry.ok() && readsKnob(**entry, "vis-raster")) s.set("vis-raster", "hardware");
}

std::vector<RunResult> renderCullModes(const std::string& pipeline, const Scene& scene, uint32_t w,
                                       uint32_t h, uint32_t msaa, const std::string& mode,
                                       const std::vector<uint32_t>& frames) {
    auto ctx = makeValidatedContext();
    EXPECT_TRUE(ctx);
    if (!ctx) return {};
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.msaa = msaa;
    holdRasterFixed(s, pipeline);
    std::vector<RunResult> out{runOrFail(*ctx, gpuScene, pipeline, s)};
    s.set("cull-geometry", mode);
    for (uint32_t n : frames)
        out.push_back(runOrFail(*ctx, gpuScene, pipeline, s, n));
    expectNoValidationMessages(*ctx);
    return out;
}

size_t differingPixels(const ImageRGBA& a, const ImageRGBA& b, size_t* first) {
    size_t n = 0;
    if (first) *first = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        if (std::memcmp(&a.rgba[i * 4], &b.rgba[i * 4], 4 * sizeof(float)) != 0 && n++ == 0 &&
            first)
            *first = i;
    return n;
}

const ImageRGBA* debugImageOf(const RunResult& run, const std::string& name) {
    for (const DebugImage& d : run.debugImages)
        if (d.name == name) return &d.image;
    return nullptr;
}

// Two images whose pixels sum the same fp32 terms in different orders (e.g. deferred
// tiled against volumes: the same code on the same G-buffer, culled-list order in a
// register against one blend per light), with an RGBA32F target. Every term is >= 0, so two
// summation orders of N terms differ by at most 2 (N - 1) u * sum, u = 2^-24 (Higham,
// recursive summation), with N = samples * (lights + 1) per pixel. Checked per channel against
// that bound (+1e-30 for zeros).
void expectAgreeWithinSummationBound(const ImageRGBA& a, const ImageRGBA& b, uint32_t lights,
                                     uint32_t samples, const std::string& what) {
    const double u = std::ldexp(1.0, -24);
    const double n = double(samples) * (lights + 1);
    double worstRatio = 0.0;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            double x = a.rgba[i * 4 + c], y = b.rgba[i * 4 + c];
            double bound = 2.0 * (n - 1.0) * u * std::max(std::abs(x), std::abs(y)) + 1e-30;
            worstRatio = std::max(worstRatio, std::abs(x - y) / bound);
        }
    EXPECT_LE(worstRatio, 1.0) << what << ": worst |a - b| / bound = " << worstRatio;
    std::printf("[ summation order ] %s: worst difference = %.3g of the bound\n", what.c_str(),
                worstRatio);
}

void recordAndSubmit(GpuContext& ctx, FrameGraph& graph, uint32_t frames) {
    VkCommandBuffer cmd = ctx.allocateCommandBuffer();
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    graph.record(cmd, nullptr);
    VK_CHECK(vkEndCommandBuffer(cmd));
    for (uint32_t i = 0; i < frames; ++i)
        ctx.submitAndWait(cmd);
    ctx.freeCommandBuffer(cmd);
}

Scene courtyardSmallWithLights(uint32_t count, uint64_t seed) {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    EXPECT_TRUE(s.ok());
    if (!s.ok()) return {};
    LightGenOptions o;
    o.count = count;
    o.seed = seed;
    s->lights = generateLights(s->bounds, o);
    return std::move(*s);
}

Result<Scene> loadMaskedScene(uint32_t lights, uint32_t seed) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("triptych_masked_" + std::to_string(::getpid()) + "_" + std::to_string(seed));
    std::filesystem::remove_all(dir);
    Result<Scene> loaded = loadGltf(writeMaskedScene(dir / "masked").string(), {});
    std::filesystem::remove_all(dir);
    if (!loaded) return loaded;
    LightGenOptions g;
    g.count = lights;
    g.seed = seed;
    loaded->lights = generateLights(loaded->bounds, g);
    return loaded;
}

WorstRatio worstRatio(const ImageRGBA& got, const ImageRGBA& ref, const ErrorBound& b,
                      const std::vector<uint8_t>* only) {
    WorstRatio w;
    const bool perPixel = b.perPixel.radiance.r.size() == ref.pixelCount();
    for (uint32_t y = 0; y < ref.height; ++y)
        for (uint32_t x = 0; x < ref.width; ++x) {
            const size_t i = size_t(y) * ref.width + x;
            if (only && !(*only)[i]) continue;
            const double allowance = perPixel ? double(b.perPixel.radiance.r[i]) : 0.0;
            bool over = false;
            for (int c = 0; c < 3; ++c) {
                const double g = got.at(x, y)[c], r = ref.at(x, y)[c];
                const double ratio = std::isfinite(g) && std::isfinite(allowance)
                                         ? std::max(std::abs(g - r) - allowance, 0.0) /
                                               (b.relative() * std::abs(r) + b.absolute())
                                         : INFINITY;
                over = over || ratio > 1.0;
                if (ratio > w.ratio) w = {ratio, g, r, x, y, w.pixelsOver};
            }
            w.pixelsOver += over;
        }
    return w;
}

ErrorBound centreModelBound(const GpuContext& ctx, const Scene& scene, const std::string& pipeline,
                            const RenderSettings& run, const RunResult& centre) {
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    EXPECT_TRUE(entry.ok()) << entry.error();
    if (!entry) {
        ErrorBound none;
        none.bounded = false;
        none.why = entry.error();
        return none;
    }
    RenderSettings model = run;
    model.set("msaa-shading", "sample"); // the model without its shading-rate term
    EXPECT_TRUE(resolveKnobs((*entry)->knobs, model).ok());
    stress::StressCase c;
    c.name = "centre";
    return expectedBound(
        (*entry)->errorModel,
        {c, scene, model, &centre.depth, ctx.properties.limits.subPixelPrecisionBits, &centre.hdr});
}

// `run` within the visbuffer's bound of `ref`, the bound derived for `modelSettings` (the
// settings whose method the reference repeats).
void expectVisbufferWithinBound(GpuContext& ctx, const Scene& scene, const RunResult& run,
                       const RunResult& ref, const RenderSettings& modelSettings,
                       const std::string& what) {
    SCOPED_TRACE(what);
    const RendererEntry& entry = **findRenderer("visbuffer");
    RenderSettings resolved = modelSettings;
    ASSERT_TRUE(resolveKnobs(entry.knobs, resolved).ok());
    stress::StressCase c;
    c.name = "visbuffer-test";
    c.freeNormals = true;
    const ErrorModelInput in{
        c, scene, resolved, &ref.depth, ctx.properties.limits.subPixelPrecisionBits, &ref.hdr};
    const ErrorBound bound = expectedBound(entry.errorModel, in);
    ASSERT_TRUE(bound.bounded) << bound.why;
    EXPECT_EQ(computeError(run.hdr, ref.hdr).nanInfCount, 0u);
    const float ev = autoExposureEv(ref.hdr);
    const AllowanceCheck checked = errorBeyondAllowance(bound, run.hdr, ref.hdr, ev);
    // How wide the allowance is: its median over the pixels, relative to the reference there
    // (printed, so a model that grew to cover everything shows).
    std::vector<double> relative;
    const std::vector<float>& allowance = bound.perPixel.radiance.r;
    for (size_t i = 0; i < allowance.size() && i < ref.hdr.pixelCount(); ++i) {
        const double r =
            std::max({ref.hdr.rgba[i * 4], ref.hdr.rgba[i * 4 + 1], ref.hdr.rgba[i * 4 + 2]});
        if (allowance[i] > 0.0f && r > 0.0) relative.push_back(allowance[i] / r);
    }
    std::sort(relative.begin(), relative.end());
    std::printf("[ visbuffer ] %-30s beyond allowance %.3g <= %.3g (%llu pixels widened, median "
                "allowance %.3g of the reference)\n",
                what.c_str(), checked.worstBeyond, bound.tonemapped(ev),
                (unsigned long long)checked.widenedPixels,
                relative.empty() ? 0.0 : relative[relative.size() / 2]);
    EXPECT_EQ(checked.unboundedPixels, 0u);
    const size_t w = checked.worstPixel;
    EXPECT_LE(checked.worstBeyond, bound.tonemapped(ev))
        << "at pixel (" << w % ref.hdr.width << ", " << w / ref.hdr.width << "): visbuffer "
        << run.hdr.rgba[w * 4] << " " << run.hdr.rgba[w * 4 + 1] << " " << run.hdr.rgba[w * 4 + 2]
        << ", reference " << ref.hdr.rgba[w * 4] << " " << ref.hdr.rgba[w * 4 + 1] << " "
        << ref.hdr.rgba[w * 4 + 2] << ", allowance "
        << (bound.perPixel.radiance.r.size() > w ? bound.perPixel.radiance.r[w] : 0.0f)
        << ", depth " << ref.depth.r[w];
}

ShadowAtlasRun renderShadowAtlas(GpuContext& ctx, SceneGpu& scene, CullGeometry cull,
                                 ShadowRaster raster, uint32_t listCapacity) {
    FrameGraph graph(ctx, "shadow_atlas_test", 96, 54);
    ShadowMaps maps(ctx, scene, ShadowMaps::Residency::Atlas, cull, raster);
    maps.setRasterListCapacity(listCapacity);
    maps.plan(graph);
    const ResourceHandle atlas = maps.sampledAtlas(); // compute: the depth buffer
    // A pipeline's shading samples it (its set's descriptor needs the usage): a pass that
    // declares so and writes a word (exported, so that the graph keeps it). The atlas is
    // exported for the readback.
    const ResourceHandle word = graph.createBuffer("word", 4, "keeps sample_atlas live");
    std::vector<PassUse> uses = maps.sampledUses();
    uses.push_back({word, Use::TransferDst});
    graph.addPass("sample_atlas", uses, [word](PassContext& pc) {
        vkCmdFillBuffer(pc.cmd, pc.buffer(word).buffer, 0, 4, 0);
    });
    graph.exportResource("word", word);
    graph.exportResource("shadow_atlas", atlas);
    graph.compile();
    maps.prepare(graph);
    recordAndSubmit(ctx, graph);
    maps.collect(graph);
    if (raster == ShadowRaster::Hardware)
        return {readbackDepth(ctx, graph.image(atlas)), maps.counters()};
    // The compute rasterizer's texels: the float bits the shaders read, as the copy stored them.
    const std::vector<uint8_t> bytes = readbackBuffer(ctx, graph.buffer(atlas));
    const ShadowPlan& p = scene.shadowPlan();
    ImageR32 depth{p.atlasWidth, p.atlasHeight, std::vector<float>(size_t(p.atlasWidth) * p.atlasHeight)};
    std::memcpy(depth.r.data(), bytes.data(), std::min(bytes.size(), depth.r.size() * sizeof(float)));
    return {depth, maps.counters()};
}

} // namespace tp::test
