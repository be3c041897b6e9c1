// Forward+ on the default device (lavapipe in CI), validation on, small resolutions.
//
// Tolerance against the reference (derived, see docs/forwardplus.md): the BRDF, the light
// model and the materials are the same code, culling at the window's range is exact, so
// what remains is
//   - storage: hdr (and hdr_msaa) are RGBA16F. Vulkan leaves the rounding of fp32 -> fp16
//     conversions to the implementation (to nearest or toward zero), so each rounding is
//     below one ulp: <= 2^-10 relative in the normal range, <= 2^-24 absolute for
//     subnormals. One rounding at 1x, two with MSAA (per-sample store, resolve), one more
//     per blended layer;
//   - summation: the reference sums in fp64 in light order, Forward+ in fp32 (directional
//     lights first, then the tile's list in light order). Every term is >= 0, so the fp32
//     sum is within n * 2^-24 of the exact sum, relative (n = terms);
//   - per-term evaluation: the same code compiled into other shaders, a few ulps.
// So |fp - ref| <= ((roundings + layers) * 2^-10 + (n + 8) * 2^-24 + 1e-5) * |ref| + 1e-6.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "core/calibrate/pass_work.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/image/difference.h"
#include "core/lightassign/knobs.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/blended_bounds.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "forwardplus/forwardplus_debug.h"
#include "forwardplus/forwardplus_shared.h"
#include "forwardplus/light_culling.h"
#include "gpu_test_util.h"
#include "include/light_model.h"

namespace tp::test {
namespace {

double statOf(const RunResult& r, const std::string& name) {
    for (const auto& [n, v] : r.stats.counters)
        if (n == name) return v;
    ADD_FAILURE() << "no counter " << name;
    return -1.0;
}

bool hasLeftOut(const RunResult& r, const std::string& prefix) {
    for (const LeftOut& l : r.stats.leftOut)
        if (l.what.rfind(prefix, 0) == 0) return true;
    return false;
}

std::vector<Light> makeLights(const Aabb& bounds, uint32_t count, uint64_t seed) {
    LightGenOptions g;
    g.count = count;
    g.seed = seed;
    g.pointWeight = 3.0f;
    g.spotWeight = 1.0f;
    return generateLights(bounds, g);
}

Scene floorScene(uint32_t lightCount) {
    Scene s = makeFloorScene({});
    Aabb b = s.bounds;
    b.max.y = 3.0f; // lights above the floor as well
    s.lights = makeLights(b, lightCount, 11);
    return s;
}

Scene courtyardScene(uint32_t lightCount) {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    EXPECT_TRUE(s.ok()) << s.error();
    if (!s.ok()) return {};
    Scene scene = std::move(*s);
    std::vector<Light> lights = makeLights(scene.bounds, lightCount, 5);
    scene.lights = lights;
    return scene;
}

// Point lights only: the culling and shading variants without spot code (kHasSpot = 0),
// which the default light mix of the CLI (and the lavapipe benchmark) uses.
Scene courtyardPointScene(uint32_t lightCount) {
    Scene scene = courtyardScene(0);
    LightGenOptions g;
    g.count = lightCount;
    g.seed = 7;
    g.pointWeight = 1.0f;
    g.spotWeight = 0.0f;
    scene.lights = generateLights(scene.bounds, g);
    return scene;
}

struct Comparison {
    double worstRatio = 0.0; // max |d| / tolerance
    uint32_t worstX = 0, worstY = 0;
    double worstGot = 0.0, worstRef = 0.0;
    uint64_t nonFinite = 0;
};

Comparison compare(const ImageRGBA& got, const ImageRGBA& ref, uint32_t lightCount, uint32_t msaa,
                   uint32_t blendLayers) {
    Comparison c;
    const double roundings = (msaa > 1 ? 2.0 : 1.0) + blendLayers;
    const double relTol =
        roundings * std::ldexp(1.0, -10) + (lightCount + 8.0) * std::ldexp(1.0, -24) + 1e-5;
    for (uint32_t y = 0; y < ref.height; ++y)
        for (uint32_t x = 0; x < ref.width; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                double g = got.at(x, y)[ch], r = ref.at(x, y)[ch];
                if (!std::isfinite(g)) {
                    ++c.nonFinite;
                    continue;
                }
                double ratio = std::abs(g - r) / (relTol * std::abs(r) + 1e-6);
                if (ratio > c.worstRatio) {
                    c.worstRatio = ratio;
                    c.worstX = x;
                    c.worstY = y;
                    c.worstGot = g;
                    c.worstRef = r;
                }
            }
    return c;
}

void expectMatchesReference(const Scene& scene, RenderSettings settings, uint32_t blendLayers = 0) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    RunResult ref = runOrFail(*ctx, gpuScene, "reference", settings);
    RunResult fp = runOrFail(*ctx, gpuScene, "forwardplus", settings);
    ASSERT_EQ(fp.hdr.width, ref.hdr.width);
    ASSERT_EQ(fp.hdr.height, ref.hdr.height);
    Comparison c =
        compare(fp.hdr, ref.hdr, uint32_t(scene.lights.size()), settings.msaa, blendLayers);
    EXPECT_EQ(c.nonFinite, 0u);
    EXPECT_LE(c.worstRatio, 1.0) << "worst pixel " << c.worstX << "," << c.worstY << ": got "
                                 << c.worstGot << ", reference " << c.worstRef;
    EXPECT_EQ(statOf(fp, "lights_dropped"), 0.0);
    EXPECT_EQ(fp.depth.r, ref.depth.r) << "prepass depth differs from the reference's depth";
    double sum = 0.0;
    for (size_t i = 0; i < ref.hdr.pixelCount(); ++i)
        sum += ref.hdr.rgba[i * 4];
    EXPECT_GT(sum, 0.0);
    std::printf("[ forwardplus ] %zu lights, %ux%u, %ux: worst |d|/tol = %.3g, lights/tile mean "
                "%.2f max %.0f\n",
                scene.lights.size(), settings.width, settings.height, settings.msaa, c.worstRatio,
                statOf(fp, "lights_per_tile_mean"), statOf(fp, "lights_per_tile_max"));
    expectNoValidationMessages(*ctx);
}

// Under MSAA these tests shade every sample (--msaa-shading sample), as the supersampled
// reference does; the pixel rate has its own tests (ForwardPlusPixelRate).
RenderSettings small(uint32_t w, uint32_t h, uint32_t msaa) {
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.msaa = msaa;
    if (msaa > 1) s.set("msaa-shading", "sample");
    return s;
}

// ---- against the reference ----

TEST(ForwardPlusReference, FloorNoLights) {
    expectMatchesReference(floorScene(0), small(96, 64, 1));
}
TEST(ForwardPlusReference, FloorOneLight) {
    expectMatchesReference(floorScene(1), small(96, 64, 1));
}
TEST(ForwardPlusReference, Floor256Lights) {
    expectMatchesReference(floorScene(256), small(96, 64, 1));
}
TEST(ForwardPlusReference, Floor256LightsMsaa4) {
    expectMatchesReference(floorScene(256), small(96, 64, 4));
}
TEST(ForwardPlusReference, Floor4096LightsTiny) {
    expectMatchesReference(floorScene(4096), small(40, 24, 1));
}
TEST(ForwardPlusReference, Floor4096LightsTinyMsaa4) {
    expectMatchesReference(floorScene(4096), small(40, 24, 4));
}

TEST(ForwardPlusReference, FloorTileSizes8And32) {
    for (uint32_t tile : {8u, 32u}) {
        SCOPED_TRACE(tile);
        RenderSettings s = small(80, 56, 1);
        s.set("tile", tile);
        expectMatchesReference(floorScene(256), s);
    }
}

TEST(ForwardPlusReference, CourtyardNoLights) {
    expectMatchesReference(courtyardScene(0), small(96, 54, 1), 4);
}
TEST(ForwardPlusReference, CourtyardOneLight) {
    expectMatchesReference(courtyardScene(1), small(96, 54, 1), 4);
}
TEST(ForwardPlusReference, Courtyard256Lights) {
    expectMatchesReference(courtyardScene(256), small(96, 54, 1), 4);
}
TEST(ForwardPlusReference, Courtyard256LightsMsaa4) {
    expectMatchesReference(courtyardScene(256), small(96, 54, 4), 4);
}
TEST(ForwardPlusReference, Courtyard256PointLightsOnly) {
    expectMatchesReference(courtyardPointScene(256), small(96, 54, 1), 4);
}
TEST(ForwardPlusReference, Courtyard4096LightsTiny) {
    expectMatchesReference(courtyardScene(4096), small(48, 27, 1), 4);
}
TEST(ForwardPlusReference, Courtyard4096LightsTinyMsaa4) {
    expectMatchesReference(courtyardScene(4096), small(48, 27, 4), 4);
}

// --cull-geometry frustum (core/passes/meshlet_cull.h): the prepass and forward_opaque draw
// the meshlets the cull pass kept; the same bound against the reference, depth bit for bit
// (expectMatchesReference), so culling dropped nothing visible.
TEST(ForwardPlusReference, CourtyardCullGeometryFrustum) {
    RenderSettings s = small(96, 54, 1);
    s.set("cull-geometry", "frustum");
    expectMatchesReference(courtyardScene(256), s, 4);
}
TEST(ForwardPlusReference, CourtyardCullGeometryFrustumMsaa4) {
    RenderSettings s = small(96, 54, 4);
    s.set("cull-geometry", "frustum");
    expectMatchesReference(courtyardScene(256), s, 4);
}

// 4x, --msaa-shading pixel (the default): one invocation per pixel and primitive with its
// inputs at the pixel centre, its value stored to the samples that primitive covers and that
// pass the EQUAL test against the per-sample prepass. The reference with --reference-msaa
// center shades every sample with the inputs at the pixel centre of the surface that sample
// sees. So on a pixel whose samples all see one surface both store the same value at the
// same point: the 1x bound holds (two fp16 roundings, as under MSAA). On an edge pixel each
// sample still holds the value of the surface it sees, evaluated at the pixel centre in both
// (extrapolated from the triangle's plane where the centre lies outside it: both use the
// centre, not the centroid), and the resolve averages the same samples: the same bound
// holds, and the test checks edge pixels against it too (docs/forwardplus.md). Edge pixels
// are found with deferred's edge mask (samples whose G-buffer differs), a fact about the scene.
void expectPixelRateMatchesCentreReference(const Scene& scene, RenderSettings settings,
                                           uint32_t blendLayers) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    settings.set("msaa-shading", "pixel");
    settings.set("reference-msaa", "center");
    settings.debug = true;
    RunResult ref = runOrFail(*ctx, gpuScene, "reference", settings);
    RunResult fp = runOrFail(*ctx, gpuScene, "forwardplus", settings);
    RunResult deferred = runOrFail(*ctx, gpuScene, "deferred", settings);
    settings.set("msaa-shading", "sample");
    RunResult fpSample = runOrFail(*ctx, gpuScene, "forwardplus", settings);
    const ImageRGBA* edges = debugImageOf(deferred, "edge_mask");
    ASSERT_NE(edges, nullptr);
    ImageRGBA interior = ref.hdr, edge = ref.hdr, fpInterior = fp.hdr, fpEdge = fp.hdr;
    size_t edgeCount = 0;
    for (size_t i = 0; i < ref.hdr.pixelCount(); ++i) {
        const bool isEdge = edges->rgba[i * 4] > 0.5f;
        edgeCount += isEdge;
        for (int c = 0; c < 4; ++c) {
            (isEdge ? interior : edge).rgba[i * 4 + c] = 0.0f; // the other class: 0 in both
            (isEdge ? fpInterior : fpEdge).rgba[i * 4 + c] = 0.0f;
        }
    }
    const uint32_t lights = uint32_t(scene.lights.size());
    Comparison in = compare(fpInterior, interior, lights, settings.msaa, blendLayers);
    Comparison ed = compare(fpEdge, edge, lights, settings.msaa, blendLayers);
    EXPECT_EQ(in.nonFinite + ed.nonFinite, 0u);
    EXPECT_GT(edgeCount, 0u);
    EXPECT_LE(in.worstRatio, 1.0) << "interior: worst pixel " << in.worstX << "," << in.worstY
                                  << ": got " << in.worstGot << ", centre reference "
                                  << in.worstRef;
    EXPECT_LE(ed.worstRatio, 1.0) << "edge: worst pixel " << ed.worstX << "," << ed.worstY
                                  << ": got " << ed.worstGot << ", centre reference "
                                  << ed.worstRef;
    // The counter (a pipeline-statistics query per pass). Lavapipe counts one invocation per
    // pixel fragment at both rates (it loops over the samples inside one invocation), so only
    // its presence and order are checked here (docs/shading.md), on the shading passes: the
    // frame's total also holds, at pixel rate only, the centre_bounds pass's fragments.
    auto shadingInvocations = [](const RunResult& r) {
        double n = 0;
        for (const PassWork& w : r.work)
            if (w.pass.starts_with("forward_")) n += double(w.counts.fragmentInvocations);
        return n;
    };
    EXPECT_GT(statOf(fp, "fragment_shader_invocations"), 0.0);
    const double pixel = shadingInvocations(fp);
    const double sample = shadingInvocations(fpSample);
    EXPECT_GT(pixel, 0.0);
    EXPECT_GE(sample, pixel);
    std::printf("[ forwardplus ] 4x pixel rate, %u lights: interior worst |d|/tol %.3g, %zu edge "
                "pixels worst %.3g; "
                "fragment invocations pixel %.0f, sample %.0f\n",
                lights, in.worstRatio, edgeCount, ed.worstRatio, pixel, sample);
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusPixelRate, Floor256LightsMsaa4MatchesCentreReference) {
    expectPixelRateMatchesCentreReference(floorScene(256), small(96, 64, 4), 0);
}
// The courtyard with its alpha-masked grille and leaves: at pixel rate a masked surface keeps
// its per-sample coverage (the prepass alpha-tests each sample), and so does the centre
// reference (issue 29), so along an alpha-test boundary both cover the same samples.
TEST(ForwardPlusPixelRate, Courtyard256LightsMsaa4MatchesCentreReference) {
    expectPixelRateMatchesCentreReference(courtyardScene(256), small(96, 54, 4), 4);
}

TEST(ForwardPlusReference, DirectionalLightsAreShadedUnculled) {
    Scene s = floorScene(32);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.intensity = 2.0f;
    s.lights.insert(s.lights.begin() + 7, sun);
    expectMatchesReference(s, small(64, 48, 1));
}

// ---- the lists themselves ----

// One frame of Forward+ run by hand (plan, compile, prepare, record, submit) so that the
// tile lists can be read back.
struct ListRun {
    ImageR32 depth;
    std::vector<gpu::FpTileLists> tiles;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> masks;                // clustered: the per-slice bitmasks
    std::vector<la::TileBlendedBounds> blended; // blended scenes: each tile's blended depth bounds
    la::TileGrid grid;
    RendererStats stats;
    std::vector<DebugImage> debug;
};

ListRun runLists(GpuContext& ctx, SceneGpu& scene, const RenderSettings& settings) {
    ListRun out;
    scene.setView(settings.width, settings.height, settings.msaa);
    Result<const RendererEntry*> entry = findRenderer("forwardplus");
    EXPECT_TRUE(entry.ok());
    RenderSettings resolved = settings; // the knobs' defaults filled in, as the renderer sees them
    EXPECT_TRUE(resolveKnobs((*entry)->knobs, resolved).ok());
    RendererCreateInfo info{ctx, scene, analyzeScene(scene.scene(), settings.msaa), resolved};
    std::unique_ptr<Renderer> renderer = createRenderer(**entry, info);
    FrameGraph graph(ctx, "forwardplus", settings.width, settings.height);
    renderer->plan(graph);
    graph.compile();
    renderer->prepare(graph);
    recordAndSubmit(ctx, graph);
    out.depth = readbackDepth(ctx, graph.image(graph.exported("depth")));
    std::vector<uint8_t> t = readbackBuffer(ctx, graph.buffer(graph.exported("fp_tile_lists")));
    out.tiles.resize(t.size() / sizeof(gpu::FpTileLists));
    std::memcpy(out.tiles.data(), t.data(), out.tiles.size() * sizeof(gpu::FpTileLists));
    std::vector<uint8_t> i = readbackBuffer(ctx, graph.buffer(graph.exported("fp_light_indices")));
    out.indices.resize(i.size() / 4);
    std::memcpy(out.indices.data(), i.data(), out.indices.size() * 4);
    if (ResourceHandle m = graph.exported("fp_cluster_masks"); m.valid()) {
        std::vector<uint8_t> b = readbackBuffer(ctx, graph.buffer(m));
        out.masks.resize(b.size() / 4);
        std::memcpy(out.masks.data(), b.data(), out.masks.size() * 4);
    }
    out.grid = la::makeTileGrid(settings.width, settings.height, resolved.integer("tile"));
    if (ResourceHandle b = graph.exported("blended_bounds"); b.valid())
        out.blended =
            la::unpackBlendedBounds(readbackBuffer(ctx, graph.buffer(b)), out.grid.count());
    renderer->collectStats(graph);
    out.stats = renderer->stats();
    out.debug = renderer->debugImages(graph);
    return out;
}

// The lights of one list, walked with its explicit count.
std::vector<uint32_t> listOf(const ListRun& r, uint32_t tile, uint32_t list,
                             const std::string& layout) {
    const gpu::FpTileLists& t = r.tiles[tile];
    std::vector<uint32_t> out;
    if (layout == "linked") {
        uint32_t node = t.list[list].start;
        for (uint32_t i = 0; i < t.list[list].count; ++i) {
            if (2 * size_t(node) + 1 >= r.indices.size()) {
                ADD_FAILURE() << "node " << node << " outside the pool";
                break;
            }
            out.push_back(r.indices[2 * node]);
            node = r.indices[2 * node + 1];
        }
    } else {
        for (uint32_t i = 0; i < t.list[list].count; ++i)
            out.push_back(r.indices.at(t.list[list].start + i));
    }
    return out;
}

glm::vec3 unproject(const gpu::FrameUniforms& f, uint32_t x, uint32_t y, float depth) {
    float w = float(f.viewport.x), h = float(f.viewport.y);
    glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, 1.0f - (y + 0.5f) / h * 2.0f, depth, 1.0f);
    glm::vec4 p = f.invViewProj * ndc;
    return glm::vec3(p) / p.w;
}

// A light reaches p (before N.L): inside its range and, for a spot, inside its outer cone.
bool reaches(const gpu::LightGpu& l, const glm::vec3& p) {
    if (l.type == TP_LIGHT_DIRECTIONAL) return true;
    glm::vec3 d = l.position - p;
    float dist = glm::length(d);
    if (dist >= l.range) return false;
    if (l.type == TP_LIGHT_SPOT && dist > 0.0f)
        return gpu::spotAttenuation(d / dist, l.direction, l.spotScale, l.spotOffset) > 0.0f;
    return true;
}

// The points of blended surfaces that pixel centres see in front of the opaque depth: what
// the blended pass shades at 1x, found on the CPU by casting each pixel centre's ray at the
// blended triangles (back faces of single-sided materials skipped, as the draws cull them).
// Points near a triangle's edge (the fill rule decides those) or near the opaque surface
// (the depth test's rounding decides those) are left out.
struct BlendedPoint {
    uint32_t x, y;
    glm::vec3 p;
};

std::vector<BlendedPoint> blendedPoints(const Scene& scene, const gpu::FrameUniforms& f,
                                        const ImageR32& depth) {
    std::vector<BlendedPoint> out;
    const uint32_t w = depth.width, h = depth.height;
    const glm::vec3 eye(f.eyeWorld);
    for (const Mesh& m : scene.meshes) {
        const Material& mat = scene.materials[m.material];
        if (mat.alphaMode != AlphaMode::Blend) continue;
        for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            const glm::vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]],
                            c = m.positions[m.indices[i + 2]];
            const glm::vec3 e1 = b - a, e2 = c - a;
            if (!mat.doubleSided && glm::dot(glm::cross(e1, e2), eye - a) <= 0.0f) continue;
            // The triangle's pixel rectangle (the whole screen if a vertex is behind the eye).
            float x0 = 0, x1 = float(w), y0 = 0, y1 = float(h);
            bool behind = false;
            glm::vec2 lo(1e30f), hi(-1e30f);
            for (const glm::vec3& v : {a, b, c}) {
                glm::vec4 cl = f.viewProj * glm::vec4(v, 1.0f);
                if (cl.w <= 0.0f) behind = true;
                glm::vec2 s((cl.x / cl.w * 0.5f + 0.5f) * float(w),
                            (0.5f - cl.y / cl.w * 0.5f) * float(h));
                lo = glm::min(lo, s);
                hi = glm::max(hi, s);
            }
            if (!behind) {
                x0 = std::max(0.0f, std::floor(lo.x)),
                x1 = std::min(float(w), std::ceil(hi.x) + 1.0f);
                y0 = std::max(0.0f, std::floor(lo.y)),
                y1 = std::min(float(h), std::ceil(hi.y) + 1.0f);
            }
            for (uint32_t y = uint32_t(y0); float(y) < y1; ++y)
                for (uint32_t x = uint32_t(x0); float(x) < x1; ++x) {
                    const glm::vec3 o = unproject(f, x, y, 1.0f),
                                    dir = unproject(f, x, y, 0.5f) - o;
                    const glm::vec3 pv = glm::cross(dir, e2);
                    const float det = glm::dot(e1, pv);
                    if (std::fabs(det) < 1e-20f) continue;
                    const glm::vec3 tv = o - a, qv = glm::cross(tv, e1);
                    const float u = glm::dot(tv, pv) / det, v = glm::dot(dir, qv) / det,
                                t = glm::dot(e2, qv) / det;
                    if (u < 1e-3f || v < 1e-3f || u + v > 1.0f - 1e-3f || t <= 0.0f) continue;
                    const glm::vec3 p = o + t * dir;
                    const glm::vec4 cl = f.viewProj * glm::vec4(p, 1.0f);
                    const float pd = cl.z / cl.w, d = depth.r[y * w + x];
                    if (pd >= 1.0f || pd <= d * (1.0f + 1e-4f) + 1e-7f) continue;
                    out.push_back({x, y, p});
                }
        }
    }
    return out;
}

TEST(ForwardPlusCulling, ConservativeOnEveryTileWithFalsePositiveRate) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings = small(128, 72, 1);
    ListRun r = runLists(*ctx, gpuScene, settings);
    const gpu::FrameUniforms& f = gpuScene.frame();
    const auto& lights = gpuScene.lightsGpu();
    uint64_t listed = 0, needed = 0, missing = 0, skyTiles = 0;
    for (uint32_t ty = 0; ty < r.grid.tilesY; ++ty)
        for (uint32_t tx = 0; tx < r.grid.tilesX; ++tx) {
            uint32_t tile = ty * r.grid.tilesX + tx;
            std::vector<uint32_t> list = listOf(r, tile, 0, "compact");
            std::set<uint32_t> inList(list.begin(), list.end());
            EXPECT_EQ(inList.size(), list.size()) << "duplicates in tile " << tile;
            EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
            std::set<uint32_t> contributing;
            bool anyGeometry = false;
            for (uint32_t y = ty * 16; y < std::min(settings.height, ty * 16 + 16); ++y)
                for (uint32_t x = tx * 16; x < std::min(settings.width, tx * 16 + 16); ++x) {
                    float d = r.depth.r[y * r.depth.width + x];
                    if (d <= 0.0f) continue;
                    anyGeometry = true;
                    glm::vec3 p = unproject(f, x, y, d);
                    for (uint32_t li = 0; li < lights.size(); ++li)
                        if (reaches(lights[li], p)) contributing.insert(li);
                }
            if (!anyGeometry) {
                ++skyTiles;
                EXPECT_EQ(r.tiles[tile].list[0].count, 0u) << "sky tile " << tile << " has lights";
                EXPECT_EQ(r.tiles[tile].nearDepth, 0.0f);
            }
            for (uint32_t li : contributing)
                if (!inList.count(li)) {
                    ++missing;
                    ADD_FAILURE() << "tile " << tx << "," << ty << ": light " << li
                                  << " reaches a pixel but is not listed";
                }
            listed += list.size();
            needed += contributing.size();
        }
    EXPECT_EQ(missing, 0u);
    // The transparent list holds every light that reaches a blended fragment's own point
    // (the blended depth bounds are conservative).
    std::vector<BlendedPoint> points = blendedPoints(scene, f, r.depth);
    EXPECT_GT(points.size(), 100u);
    uint64_t blendedMissing = 0;
    for (const BlendedPoint& bp : points) {
        const uint32_t tile = (bp.y / 16) * r.grid.tilesX + bp.x / 16;
        std::vector<uint32_t> tlist = listOf(r, tile, 1, "compact");
        std::set<uint32_t> inT(tlist.begin(), tlist.end());
        for (uint32_t li = 0; li < lights.size(); ++li)
            if (lights[li].type != TP_LIGHT_DIRECTIONAL && reaches(lights[li], bp.p) &&
                !inT.count(li) && ++blendedMissing < 10)
                ADD_FAILURE() << "blended point at pixel " << bp.x << "," << bp.y << ": light "
                              << li << " reaches it but is not in the transparent list";
    }
    EXPECT_EQ(blendedMissing, 0u);
    double fpRate = listed ? double(listed - needed) / double(listed) : 0.0;
    std::printf("[ forwardplus ] culling: %llu listed, %llu reach a pixel, false-positive rate "
                "%.1f%%, %llu sky tiles\n",
                (unsigned long long)listed, (unsigned long long)needed, 100.0 * fpRate,
                (unsigned long long)skyTiles);
    RecordProperty("false_positive_rate", std::to_string(fpRate));
    EXPECT_LT(fpRate, 0.9); // useful: most listed lights do reach the tile
    expectNoValidationMessages(*ctx);
}

// The transparent list covers the tile's blended depth bounds (core/lightassign/
// blended_bounds.h): empty in every tile where no blended fragment is shaded, and in the
// others much shorter than the lights that can reach the tile at any depth (the list used
// to run from the near plane). Every tile where a pixel centre sees a blended surface in
// front of the opaque one has bounds. An opaque-only scene has no bounds pass.
TEST(ForwardPlusCulling, TransparentListsFollowTheBlendedDepthBounds) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    ListRun r = runLists(*ctx, gpuScene, small(128, 72, 1));
    ASSERT_EQ(r.blended.size(), size_t(r.grid.count()));
    const gpu::FrameUniforms& f = gpuScene.frame();
    const auto& lights = gpuScene.lightsGpu();
    la::LightClasses classes = la::classifyLights(lights);
    std::vector<uint32_t> bound =
        la::conservativeTileBound(r.grid, f.view, f.proj, lights, classes.local);
    uint64_t emptyTiles = 0, blendedTiles = 0, listed = 0, reachable = 0;
    for (uint32_t t = 0; t < r.grid.count(); ++t) {
        if (!r.blended[t].any) {
            ++emptyTiles;
            EXPECT_EQ(r.tiles[t].list[1].count, 0u) << "tile " << t << " has no blended fragment";
            continue;
        }
        EXPECT_LE(r.blended[t].nearDist, r.blended[t].farDist) << "tile " << t;
        ++blendedTiles;
        listed += r.tiles[t].list[1].count;
        reachable += bound[t];
    }
    for (const BlendedPoint& bp : blendedPoints(scene, f, r.depth))
        EXPECT_TRUE(r.blended[(bp.y / 16) * r.grid.tilesX + bp.x / 16].any) << bp.x << "," << bp.y;
    EXPECT_GT(emptyTiles, 0u);
    EXPECT_GT(blendedTiles, 0u);
    EXPECT_LT(2 * listed, reachable);
    double mean = -1.0;
    for (const auto& [n, v] : r.stats.counters)
        if (n == "transparent_lights_per_tile_mean") mean = v;
    EXPECT_DOUBLE_EQ(mean, double(listed) / double(r.grid.count()));
    std::printf("[ forwardplus ] transparent lists: %llu tiles without blended fragments (empty "
                "lists), %llu with: "
                "%.1f lights per list against %.1f that reach the tile at any depth\n",
                (unsigned long long)emptyTiles, (unsigned long long)blendedTiles,
                double(listed) / double(blendedTiles), double(reachable) / double(blendedTiles));

    Scene floor = floorScene(16);
    SceneGpu floorGpu(*ctx, floor);
    ListRun opaque = runLists(*ctx, floorGpu, small(64, 48, 1));
    EXPECT_TRUE(opaque.blended.empty());
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusCulling, LayoutsHoldTheSameListsAndHeatMapCountsMatch) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings = small(96, 54, 4);
    std::vector<ListRun> runs;
    for (const char* layout : {"compact", "fixed", "linked"}) {
        RenderSettings s = settings;
        s.set("light-lists", layout);
        s.debug = true;
        runs.push_back(runLists(*ctx, gpuScene, s));
    }
    const la::TileGrid& g = runs[0].grid;
    for (uint32_t tile = 0; tile < g.count(); ++tile)
        for (uint32_t list = 0; list < 2; ++list) {
            std::vector<uint32_t> a = listOf(runs[0], tile, list, "compact");
            EXPECT_EQ(a, listOf(runs[1], tile, list, "fixed")) << "tile " << tile;
            EXPECT_EQ(a, listOf(runs[2], tile, list, "linked")) << "tile " << tile;
            for (uint32_t li : a)
                EXPECT_LT(li, scene.lights.size());
        }
    // The heat map shows each tile's list length: rebuild it from the walked lists.
    for (size_t k = 0; k < runs.size(); ++k) {
        const ListRun& r = runs[k];
        std::vector<gpu::FpTileLists> walked = r.tiles;
        for (uint32_t tile = 0; tile < g.count(); ++tile)
            walked[tile].list[0].count =
                uint32_t(listOf(r, tile, 0, k == 2 ? "linked" : "compact").size());
        ImageRGBA expect = fp::lightsPerTileHeatMap(g, walked, 0);
        ASSERT_FALSE(r.debug.empty());
        EXPECT_EQ(r.debug[0].name, "lights_per_tile");
        EXPECT_EQ(r.debug[0].image.rgba, expect.rgba);
    }
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusCulling, CompactBoundIsAnUpperBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(512);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings = small(96, 64, 1);
    ListRun r = runLists(*ctx, gpuScene, settings);
    const gpu::FrameUniforms& f = gpuScene.frame();
    la::LightClasses classes = la::classifyLights(gpuScene.lightsGpu());
    std::vector<uint32_t> bound =
        la::conservativeTileBound(r.grid, f.view, f.proj, gpuScene.lightsGpu(), classes.local);
    for (uint32_t tile = 0; tile < r.grid.count(); ++tile) {
        EXPECT_LE(r.tiles[tile].list[0].count, bound[tile]);
        EXPECT_EQ(r.tiles[tile].list[0].dropped, 0u);
    }
    expectNoValidationMessages(*ctx);
}

// Binned culling (--light-cull binned) tests each tile's candidates only; its lists must be
// exactly brute-force culling's (--light-cull all): the same lights in the same order, for
// every tile and both lists, hence the same image, with far fewer tests.
void expectBinnedEqualsBruteForce(const Scene& scene, RenderSettings settings) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    settings.set("light-cull", "all");
    ListRun all = runLists(*ctx, gpuScene, settings);
    settings.set("light-cull", "binned");
    ListRun binned = runLists(*ctx, gpuScene, settings);
    ASSERT_EQ(all.tiles.size(), binned.tiles.size());
    uint64_t listed = 0;
    for (uint32_t tile = 0; tile < all.grid.count(); ++tile)
        for (uint32_t list = 0; list < 2; ++list) {
            std::vector<uint32_t> a = listOf(all, tile, list, "compact");
            EXPECT_EQ(a, listOf(binned, tile, list, "compact"))
                << "tile " << tile << " list " << list;
            EXPECT_EQ(all.tiles[tile].list[list].found, binned.tiles[tile].list[list].found);
            listed += a.size();
        }
    EXPECT_GT(listed, 0u);
    auto counter = [](const ListRun& r, const std::string& name) {
        for (const auto& [n, v] : r.stats.counters)
            if (n == name) return v;
        ADD_FAILURE() << "no counter " << name;
        return -1.0;
    };
    EXPECT_EQ(counter(binned, "lights_dropped"), 0.0);
    EXPECT_LT(counter(binned, "lights_tested"), counter(all, "lights_tested"));
    for (const ListRun* r : {&all, &binned}) { // light_culling's counted work: the tests
        double tests = -1;
        for (const PassOpWork& w : r->stats.opWork)
            if (w.pass == "light_culling" && w.kind == PassOpWork::Kind::TileTests) tests = w.items;
        EXPECT_EQ(tests, counter(*r, "lights_tested"));
    }
    std::printf(
        "[ forwardplus ] binned culling: %.0f tests against %.0f for every light, %llu listed\n",
        counter(binned, "lights_tested"), counter(all, "lights_tested"),
        (unsigned long long)listed);
    RunResult ra = runOrFail(*ctx, gpuScene, "forwardplus", settings);
    settings.set("light-cull", "all");
    RunResult rb = runOrFail(*ctx, gpuScene, "forwardplus", settings);
    EXPECT_EQ(ra.hdr.rgba, rb.hdr.rgba);
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusCulling, BinnedListsEqualBruteForceOnCourtyard) {
    expectBinnedEqualsBruteForce(courtyardScene(512), small(128, 72, 1));
}

TEST(ForwardPlusCulling, BinnedListsEqualBruteForcePointLightsOnly) {
    expectBinnedEqualsBruteForce(courtyardPointScene(512), small(128, 72, 1));
}

// --light-spheres pass reads each light's sphere from the light_spheres pass, inline computes
// it per candidate (the culling before the pass): the same function, so the same tile records
// and lists, byte for byte; with spot lights (cone test) and without, tiled (two lists) and
// clustered.
TEST(ForwardPlusCulling, SpherePassGivesTheInlineLists) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (bool spots : {true, false}) {
        Scene scene = spots ? courtyardScene(256) : courtyardPointScene(256);
        SceneGpu gpuScene(*ctx, scene);
        for (const char* assign : {"tiled", "clustered"}) {
            RenderSettings s = small(96, 54, 1);
            s.set("light-assign", assign);
            s.set("light-spheres", "inline");
            ListRun inlined = runLists(*ctx, gpuScene, s);
            s.set("light-spheres", "pass");
            ListRun pass = runLists(*ctx, gpuScene, s);
            ASSERT_EQ(inlined.tiles.size(), pass.tiles.size());
            EXPECT_EQ(std::memcmp(inlined.tiles.data(), pass.tiles.data(),
                                  inlined.tiles.size() * sizeof(gpu::FpTileLists)),
                      0)
                << assign << (spots ? ", spots" : "");
            uint64_t listed = 0;
            for (uint32_t t = 0; t < pass.grid.count(); ++t)
                for (uint32_t list = 0; list < 2; ++list) {
                    std::vector<uint32_t> a = listOf(inlined, t, list, "compact"),
                                          b = listOf(pass, t, list, "compact");
                    EXPECT_EQ(a, b) << assign << " tile " << t << " list " << list;
                    listed += b.size();
                }
            EXPECT_GT(listed, 0u);
        }
    }
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusCulling, BinnedListsEqualBruteForceMsaa4Tile8) {
    RenderSettings s = small(96, 54, 4);
    s.set("tile", 8);
    expectBinnedEqualsBruteForce(courtyardScene(256), s);
}

TEST(ForwardPlusCulling, BinnedListsEqualBruteForceOnFloorTile32) {
    RenderSettings s = small(160, 96, 1);
    s.set("tile", 32);
    expectBinnedEqualsBruteForce(floorScene(2048), s);
}

// More candidates in a tile than one culling dispatch takes (32,768: lavapipe ends an
// invocation after 65,535 loop iterations, and one invocation culls a tile): the lists
// continue over several dispatches, for every layout (linked prepends them last to first),
// and still equal binned culling's.
TEST(ForwardPlusCulling, ListsContinueOverSeveralDispatches) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(40000);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings = small(32, 24, 1);
    settings.set("light-cull", "binned");
    ListRun binned = runLists(*ctx, gpuScene, settings);
    settings.set("light-cull", "all");
    for (const char* layout : {"compact", "fixed", "linked"}) {
        RenderSettings s = settings;
        s.set("light-lists", layout);
        s.set("tile-capacity", 65536);
        ListRun all = runLists(*ctx, gpuScene, s);
        double dispatches = -1.0;
        for (const auto& [n, v] : all.stats.counters)
            if (n == "culling_dispatches") dispatches = v;
        EXPECT_GE(dispatches, 2.0) << layout;
        uint64_t listed = 0;
        for (uint32_t tile = 0; tile < all.grid.count(); ++tile) {
            std::vector<uint32_t> a = listOf(all, tile, 0, layout);
            EXPECT_EQ(a, listOf(binned, tile, 0, "compact")) << layout << " tile " << tile;
            EXPECT_EQ(all.tiles[tile].list[0].dropped, 0u) << layout;
            listed += a.size();
        }
        EXPECT_GT(listed, 1000u) << layout;
    }
    expectNoValidationMessages(*ctx);
}

// ---- clustered (--light-assign clustered) ----

RenderSettings clustered(RenderSettings s, uint32_t slices = 16) {
    s.set("light-assign", "clustered");
    s.set("slices", slices);
    return s;
}

// The same culling results from two runs: every tile record (linked: but for where its nodes
// start, which the pool's atomic allocation orders), every list, and every slice word the
// shading reads (words [0, ceil(count / 32)) of each of the tile's rows; the rest is never
// written). `bound`: the tiles' slot counts (conservativeTileBound), for the mask rows.
void expectSameCulling(const ListRun& a, const ListRun& b, const std::string& layout,
                       uint32_t slices, const std::vector<uint32_t>& bound,
                       const std::string& what) {
    ASSERT_EQ(a.tiles.size(), b.tiles.size()) << what;
    uint32_t maskBase = 0;
    uint64_t listed = 0, words = 0;
    for (uint32_t t = 0; t < a.grid.count(); ++t) {
        gpu::FpTileLists ra = a.tiles[t], rb = b.tiles[t];
        for (uint32_t list = 0; list < 2; ++list) {
            if (layout == "linked") ra.list[list].start = rb.list[list].start = 0;
            std::vector<uint32_t> la = listOf(a, t, list, layout);
            EXPECT_EQ(la, listOf(b, t, list, layout)) << what << ", tile " << t << " list " << list;
            listed += la.size();
        }
        EXPECT_EQ(std::memcmp(&ra, &rb, sizeof(ra)), 0) << what << ", tile " << t;
        if (a.masks.empty()) continue;
        const uint32_t stride = (bound[t] + 31) / 32, used = (a.tiles[t].list[0].count + 31) / 32;
        for (uint32_t sl = 0; sl < slices; ++sl)
            for (uint32_t w = 0; w < used; ++w, ++words) {
                const uint32_t i = maskBase + sl * stride + w;
                if (a.masks[i] != b.masks[i])
                    ADD_FAILURE() << what << ", tile " << t << " slice " << sl << " word " << w;
            }
        maskBase += slices * stride;
    }
    EXPECT_GT(listed, 0u) << what;
    if (!a.masks.empty()) {
        EXPECT_GT(words, 0u) << what;
    }
}

// --cull-by subgroup (one subgroup per tile, a candidate per lane, survivors placed by a
// ballot) gives --cull-by invocation's results byte for byte: every layout, tiled (two lists)
// and clustered, with spot lights and without, under MSAA, and over several dispatches
// (clustered, 64 slices: 9; linked, prepended), with drops (fixed, 4 slots), on an odd viewport.
// lavapipe's subgroups have 8 lanes, so a tile takes many steps and its survivors cross words of
// the slice rows mid-step. The two read the depth differently (gathered 2 x 2 blocks, texel by
// texel): the same bounds.
TEST(ForwardPlusCulling, SubgroupCullingGivesTheInvocationBytes) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    if (std::string why = fp::subgroupCullingUnsupported(ctx->caps); !why.empty())
        GTEST_SKIP() << "the default device cannot cull by subgroup: " << why;
    struct Case {
        Scene scene;
        RenderSettings settings;
        std::string layout;
        uint32_t slices; // 0: tiled
    };
    std::vector<Case> cases;
    for (const char* layout : {"compact", "fixed", "linked"}) {
        RenderSettings s = small(96, 54, 1);
        s.set("light-lists", layout);
        cases.push_back({courtyardScene(256), s, layout, 0});
    }
    cases.push_back({courtyardPointScene(256), small(96, 54, 1), "compact", 0});
    // An odd viewport: the per-invocation culling's gathered 2 x 2 blocks overhang the last
    // column and row (clamped to the edge texel).
    cases.push_back({courtyardScene(256), small(97, 55, 1), "compact", 0});
    cases.push_back({courtyardScene(256), clustered(small(96, 54, 1)), "compact", 16});
    cases.push_back({courtyardPointScene(256), clustered(small(96, 54, 1)), "compact", 16});
    RenderSettings ms = clustered(small(96, 54, 4));
    ms.set("tile", 8);
    cases.push_back({courtyardScene(256), ms, "compact", 16});
    RenderSettings msLinked = small(96, 54, 4);
    msLinked.set("light-lists", "linked");
    cases.push_back({courtyardScene(256), msLinked, "linked", 0});
    cases.push_back({floorScene(4096), clustered(small(40, 24, 1), 64), "compact", 64});
    // fixed with 4 slots a tile: most survivors are dropped (counted), past the capacity mid-step.
    RenderSettings dropping = small(96, 54, 1);
    dropping.set("light-lists", "fixed");
    dropping.set("tile-capacity", 4);
    cases.push_back({courtyardScene(256), dropping, "fixed", 0});
    // linked over several dispatches (every light tested: 40,000 candidates a tile, batches
    // prepended last to first).
    RenderSettings linkedBatches = small(32, 24, 1);
    linkedBatches.set("light-cull", "all");
    linkedBatches.set("light-lists", "linked");
    cases.push_back({floorScene(40000), linkedBatches, "linked", 0});
    auto counter = [](const RendererStats& stats, const std::string& name) {
        for (const auto& [n, v] : stats.counters)
            if (n == name) return v;
        return -1.0;
    };
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const std::string what = "case " + std::to_string(i) + " (" + c.layout + ", " +
                                 (c.slices ? std::to_string(c.slices) + " slices" : "tiled") +
                                 ", msaa " + std::to_string(c.settings.msaa) + ")";
        SceneGpu gpuScene(*ctx, c.scene);
        RenderSettings s = c.settings;
        s.set("cull-by", "invocation");
        ListRun invocation = runLists(*ctx, gpuScene, s);
        s.set("cull-by", "subgroup");
        ListRun subgroup = runLists(*ctx, gpuScene, s);
        EXPECT_EQ(counter(subgroup.stats, "culling_by_subgroup"), 1.0) << what;
        EXPECT_EQ(counter(invocation.stats, "culling_by_subgroup"), 0.0) << what;
        EXPECT_EQ(counter(subgroup.stats, "culling_dispatches"),
                  counter(invocation.stats, "culling_dispatches"))
            << what;
        EXPECT_EQ(counter(subgroup.stats, "lights_dropped"),
                  counter(invocation.stats, "lights_dropped"))
            << what;
        if (i == cases.size() - 2) {
            EXPECT_GT(counter(subgroup.stats, "lights_dropped"), 0.0) << what;
        }
        if (i == cases.size() - 1) {
            EXPECT_GE(counter(subgroup.stats, "culling_dispatches"), 2.0) << what;
        }
        const gpu::FrameUniforms& f = gpuScene.frame();
        const auto& lights = gpuScene.lightsGpu();
        std::vector<uint32_t> bound = la::conservativeTileBound(
            invocation.grid, f.view, f.proj, lights, la::classifyLights(lights).local);
        expectSameCulling(invocation, subgroup, c.layout, c.slices, bound, what);
    }
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusClustered, CourtyardMatchesReference) {
    expectMatchesReference(courtyardScene(256), clustered(small(96, 54, 1)), 4);
}
TEST(ForwardPlusClustered, CourtyardMatchesReferenceMsaa4Slices64) {
    expectMatchesReference(courtyardScene(256), clustered(small(96, 54, 4), 64), 4);
}
// 64 slices: a culling dispatch takes 32,768 / 66 = 496 candidates (lavapipe's loop limit),
// so a tile's list and its slice words continue over 9 dispatches.
TEST(ForwardPlusClustered, Floor4096LightsTinySlices64ManyDispatches) {
    expectMatchesReference(floorScene(4096), clustered(small(40, 24, 1), 64));
}

TEST(ForwardPlusClustered, Floor4096LightsTinyTile8Slices4) {
    RenderSettings s = clustered(small(40, 24, 1), 4);
    s.set("tile", 8);
    expectMatchesReference(floorScene(4096), s);
}

// --light-loop subgroup walks the OR of a tile's lanes' bit rows, each lane adding only its
// own lights in the same ascending order: the image must be bit-identical to the lane loop
// (1x; 4x shading every sample; 4x once per pixel, the other shader variant), and the blended
// pass (courtyard-small has blended draws) too.
TEST(ForwardPlusClustered, SubgroupLoopGivesTheLaneLoopsImage) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const std::string missing = la::subgroupLoopUnsupported(ctx->caps);
    if (!missing.empty()) GTEST_SKIP() << missing;
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    const std::pair<uint32_t, const char*> runs[] = {{1u, "pixel"}, {4u, "sample"}, {4u, "pixel"}};
    for (const auto& [msaa, rate] : runs) {
        RenderSettings s = clustered(small(96, 54, msaa));
        s.set("msaa-shading", rate);
        RunResult lane = runOrFail(*ctx, gpuScene, "forwardplus", s);
        s.set("light-loop", "subgroup");
        RunResult subgroup = runOrFail(*ctx, gpuScene, "forwardplus", s);
        EXPECT_EQ(statOf(lane, "light_loop_subgroup"), 0.0);
        EXPECT_EQ(statOf(subgroup, "light_loop_subgroup"), 1.0);
        EXPECT_FALSE(hasLeftOut(subgroup, "the subgroup light loop"));
        EXPECT_EQ(lane.hdr.rgba, subgroup.hdr.rgba) << msaa << "x, " << rate;
        EXPECT_GT(statOf(lane, "lights_per_cluster_mean"),
                  1.0); // clusters with several lights to walk
    }
    expectNoValidationMessages(*ctx);
}

// laSliceOf (include/light_assign.glsl) on the CPU, with front slices (blended scenes).
struct CpuSlicing {
    uint32_t slices, front;
    uint32_t operator()(float dist, const gpu::FpTileLists& t) const {
        if (front > 0 && dist < t.sliceNear) {
            float scale = float(front) / std::log(std::max(t.sliceNear / t.frontNear, 1.001f));
            float f = std::log(std::max(dist / t.frontNear, 1.0f)) * scale;
            return uint32_t(std::clamp(f, 0.0f, float(front - 1)));
        }
        float r = std::log(std::max(dist / t.sliceNear, 1.0f)) * t.sliceScale;
        return front + uint32_t(std::clamp(r, 0.0f, float(slices - 1 - front)));
    }
};

// Every light that reaches a pixel's surface point has its bit set in the pixel's cluster
// (tile, slice of its view distance): the clusters are conservative. The same for points of
// the pixel's ray in front of its surface, where blended surfaces are (they take the front
// slices when nearer than the tile's nearest opaque depth). Prints how much smaller a
// cluster is than the tile's span list.
TEST(ForwardPlusClustered, ConservativeOnEveryPixel) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings = clustered(small(128, 72, 1));
    ListRun r = runLists(*ctx, gpuScene, settings);
    ASSERT_FALSE(r.masks.empty());
    ListRun tiled = runLists(*ctx, gpuScene, small(128, 72, 1));
    const gpu::FrameUniforms& f = gpuScene.frame();
    const auto& lights = gpuScene.lightsGpu();
    la::LightClasses classes = la::classifyLights(lights);
    std::vector<uint32_t> bound =
        la::conservativeTileBound(r.grid, f.view, f.proj, lights, classes.local);
    std::vector<uint32_t> maskBase(bound.size() + 1, 0);
    for (size_t t = 0; t < bound.size(); ++t)
        maskBase[t + 1] = maskBase[t] + 16 * ((bound[t] + 31) / 32);
    ASSERT_EQ(size_t(maskBase.back()), r.masks.size());
    // The courtyard has blended surfaces: 16 / TP_LA_FRONT_SLICE_SHARE front slices, from
    // each tile's frontNear (its nearest blended fragment).
    const CpuSlicing sliceOf{16, 16 / TP_LA_FRONT_SLICE_SHARE};
    uint64_t missing = 0, pixels = 0, inCluster = 0, inList = 0, inTiled = 0;
    uint64_t frontPoints = 0, inFrontCluster = 0, inFrontList = 0;
    auto check = [&](uint32_t x, uint32_t y, const glm::vec3& p, uint32_t tile,
                     const std::vector<uint32_t>& list) {
        const gpu::FpTileLists& t = r.tiles[tile];
        uint32_t slice = sliceOf(-(f.view * glm::vec4(p, 1.0f)).z, t);
        uint32_t stride = (maskBase[tile + 1] - maskBase[tile]) / 16;
        std::set<uint32_t> cluster;
        for (uint32_t i = 0; i < list.size(); ++i)
            if (r.masks[maskBase[tile] + slice * stride + i / 32] & (1u << (i % 32)))
                cluster.insert(list[i]);
        for (uint32_t li = 0; li < lights.size(); ++li)
            if (lights[li].type != TP_LIGHT_DIRECTIONAL && reaches(lights[li], p) &&
                !cluster.count(li)) {
                if (++missing < 10)
                    ADD_FAILURE() << "pixel " << x << "," << y << " slice " << slice << ": light "
                                  << li << " reaches it but is not in its cluster";
            }
        return std::make_pair(slice, cluster.size());
    };
    for (uint32_t y = 0; y < settings.height; ++y)
        for (uint32_t x = 0; x < settings.width; ++x) {
            float d = r.depth.r[y * r.depth.width + x];
            if (d <= 0.0f) continue;
            uint32_t tile = (y / 16) * r.grid.tilesX + x / 16;
            std::vector<uint32_t> list = listOf(r, tile, 0, "compact");
            ++pixels;
            inTiled += tiled.tiles[tile].list[0].count;
            inCluster += check(x, y, unproject(f, x, y, d), tile, list).second;
            inList += list.size();
        }
    // Blended fragments' own points (blendedPoints): those nearer than the tile's opaque
    // range take the front slices, from the tile's nearest blended fragment.
    for (const BlendedPoint& bp : blendedPoints(scene, f, r.depth)) {
        const uint32_t tile = (bp.y / 16) * r.grid.tilesX + bp.x / 16;
        std::vector<uint32_t> list = listOf(r, tile, 0, "compact");
        auto [slice, size] = check(bp.x, bp.y, bp.p, tile, list);
        if (slice >= sliceOf.front) continue;
        ++frontPoints;
        inFrontCluster += size;
        inFrontList += list.size();
    }
    EXPECT_EQ(missing, 0u);
    EXPECT_GT(pixels, 0u);
    EXPECT_GT(frontPoints, 0u);
    EXPECT_LT(inCluster, inList);           // the slices do cut the span list
    EXPECT_LT(inFrontCluster, inFrontList); // and so do the front slices
    std::printf(
        "[ forwardplus ] clustered: %.2f lights per pixel's cluster against %.2f in its tile's "
        "span list "
        "and %.2f in the tiled opaque list; in front of the opaque surfaces %.2f against %.2f\n",
        double(inCluster) / double(pixels), double(inList) / double(pixels),
        double(inTiled) / double(pixels), double(inFrontCluster) / double(frontPoints),
        double(inFrontList) / double(frontPoints));
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusClustered, RefusesLayoutsOtherThanCompact) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(4);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = clustered(small(32, 32, 1));
    s.set("light-lists", "linked");
    Result<const RendererEntry*> entry = findRenderer("forwardplus");
    ASSERT_TRUE(entry.ok());
    RunOptions o;
    o.warmupFrames = 0;
    o.timedFrames = 1;
    Result<RunResult> r = runRenderer(*ctx, gpuScene, **entry, analyzeScene(scene, 1), s, o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("--light-assign clustered needs --light-lists compact"),
              std::string::npos)
        << r.error();
}

// ---- layouts: same image when nothing overflows; drops counted and visible ----

TEST(ForwardPlusLayouts, AllLayoutsGiveTheSameImage) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardScene(256);
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        RenderSettings s = small(96, 54, msaa);
        RunResult compact = runOrFail(*ctx, gpuScene, "forwardplus", s);
        s.set("light-lists", "linked");
        RunResult linked = runOrFail(*ctx, gpuScene, "forwardplus", s);
        s.set("light-lists", "fixed");
        s.set("tile-capacity", 256);
        RunResult fixed = runOrFail(*ctx, gpuScene, "forwardplus", s);
        EXPECT_EQ(compact.hdr.rgba, linked.hdr.rgba) << msaa << "x";
        EXPECT_EQ(compact.hdr.rgba, fixed.hdr.rgba) << msaa << "x";
        EXPECT_EQ(statOf(linked, "lights_dropped"), 0.0);
        EXPECT_EQ(statOf(fixed, "lights_dropped"), 0.0);
        EXPECT_EQ(statOf(linked, "lights_kept"), statOf(compact, "lights_kept"));
        EXPECT_LE(statOf(linked, "linked_nodes_used"), statOf(linked, "linked_pool_nodes"));
    }
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusLayouts, FixedWithTinyCapacityCountsDropsAndShowsThem) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(256);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = small(96, 64, 1);
    s.debug = true;
    ListRun compact = runLists(*ctx, gpuScene, s);
    RunResult ref = runOrFail(*ctx, gpuScene, "reference", s);
    s.set("light-lists", "fixed");
    s.set("tile-capacity", 2);
    ListRun fixed = runLists(*ctx, gpuScene, s);
    RunResult fixedRun = runOrFail(*ctx, gpuScene, "forwardplus", s);
    uint64_t expectDropped = 0, overflowTiles = 0;
    for (uint32_t tile = 0; tile < compact.grid.count(); ++tile) {
        uint32_t all = compact.tiles[tile].list[0].count;
        EXPECT_EQ(fixed.tiles[tile].list[0].count, std::min(all, 2u));
        EXPECT_EQ(fixed.tiles[tile].list[0].dropped, all - std::min(all, 2u));
        expectDropped += all - std::min(all, 2u);
        overflowTiles += all > 2;
        // The kept ones are the first lights of the full list.
        std::vector<uint32_t> full = listOf(compact, tile, 0, "compact");
        std::vector<uint32_t> kept = listOf(fixed, tile, 0, "fixed");
        full.resize(kept.size());
        EXPECT_EQ(kept, full);
    }
    ASSERT_GT(expectDropped, 0u);
    EXPECT_EQ(statOf(fixedRun, "lights_dropped"), double(expectDropped));
    // Drops show as error against the reference...
    Comparison c = compare(fixedRun.hdr, ref.hdr, 256, 1, 0);
    EXPECT_GT(c.worstRatio, 10.0);
    // ...and as green outlines in the heat map, exactly on the overflowing tiles.
    const ImageRGBA& heat = fixed.debug.at(0).image;
    uint64_t outlined = 0;
    for (uint32_t ty = 0; ty < fixed.grid.tilesY; ++ty)
        for (uint32_t tx = 0; tx < fixed.grid.tilesX; ++tx) {
            const float* p = heat.at(tx * 16, ty * 16); // the tile's top-left corner
            bool green = p[0] == 0.0f && p[1] == 1.0f && p[2] == 0.0f;
            EXPECT_EQ(green, fixed.tiles[ty * fixed.grid.tilesX + tx].list[0].dropped > 0)
                << tx << "," << ty;
            outlined += green;
        }
    EXPECT_EQ(outlined, overflowTiles);
    expectNoValidationMessages(*ctx);
}

// ---- what is built, and refusals ----

TEST(ForwardPlusPlan, LeavesOutWhatTheSceneDoesNotNeed) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(8); // no blended, no masked materials
    SceneGpu gpuScene(*ctx, scene);
    RunResult r = runOrFail(*ctx, gpuScene, "forwardplus", small(64, 48, 1));
    EXPECT_TRUE(hasLeftOut(r, "transparent light list"));
    EXPECT_TRUE(hasLeftOut(r, "MSAA targets"));
    EXPECT_EQ(statOf(r, "light_lists"), 1.0);
    for (const std::string& p : r.passes)
        EXPECT_NE(p, "forward_transparent");
    for (const LedgerEntry& e : r.memory) {
        EXPECT_NE(e.tag.name, "hdr_msaa");
        EXPECT_NE(e.tag.name, "depth_msaa");
        EXPECT_NE(e.tag.name, "node_counter");
    }
    Scene court = courtyardScene(8); // blended cloth
    SceneGpu gpuCourt(*ctx, court);
    RunResult c = runOrFail(*ctx, gpuCourt, "forwardplus", small(64, 36, 4));
    EXPECT_FALSE(hasLeftOut(c, "transparent light list"));
    EXPECT_FALSE(hasLeftOut(c, "MSAA targets"));
    EXPECT_EQ(statOf(c, "light_lists"), 2.0);
    EXPECT_NE(std::find(c.passes.begin(), c.passes.end(), "forward_transparent"), c.passes.end());
    expectNoValidationMessages(*ctx);
}

TEST(ForwardPlusPlan, RefusesListsBeyondMaxStorageBufferRange) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = floorScene(4);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = small(4096, 4096, 1);
    s.set("tile", 8);
    s.set("light-lists", "fixed");
    s.set("tile-capacity", 65536);
    Result<const RendererEntry*> entry = findRenderer("forwardplus");
    ASSERT_TRUE(entry.ok());
    RunOptions o;
    o.warmupFrames = 0;
    o.timedFrames = 1;
    Result<RunResult> r = runRenderer(*ctx, gpuScene, **entry, analyzeScene(scene, 1), s, o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("maxStorageBufferRange"), std::string::npos) << r.error();
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
