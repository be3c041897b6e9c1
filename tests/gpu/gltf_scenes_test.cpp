// Scenes the loader decodes or repairs (Draco, meshopt, repaired attributes, texture
// transform; written by gltf_test_scenes.h) rendered by every pipeline and the reference:
// no NaN or Inf, and each pipeline within its derived error bound of the reference, beyond
// each pixel's allowance where its model gives one (core/renderer/error_model.h, as
// `triptych stress` checks it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "core/renderer/error_model.h"
#include "core/renderer/knobs.h"
#include "core/renderer/renderer.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/lights.h"
#include "core/scene/stress_scenes.h"
#include "gltf_test_scenes.h"
#include "gpu_test_util.h"
#include "transformed_scenes.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

struct ReferenceRun {
    RunResult run;
    float ev = 0;
    ImageRGBA display;
};

// One pipeline's image against the reference: no NaN or Inf, and within its derived bound
// beyond each pixel's allowance.
// `blendedLayers`: the most blended layers over one pixel (each model counts its blends' roundings).
void expectWithinBound(GpuContext& ctx, SceneGpu& gpuScene, const Scene& scene,
                       const RendererEntry& entry, const RenderSettings& settings,
                       const ReferenceRun& ref, uint32_t blendedLayers, const std::string& label) {
    SCOPED_TRACE(label);
    stress::StressCase c;
    c.name = "gltf";
    c.freeNormals = true; // a sphere: normals in every direction
    c.blendedLayers = blendedLayers;
    const RunResult run = runOrFail(ctx, gpuScene, entry.name, settings);
    EXPECT_EQ(countNonFinitePixels(run.hdr), 0u);
    RenderSettings resolved = settings;
    ASSERT_TRUE(resolveKnobs(entry.knobs, resolved).ok());
    // Deferred lights each pixel at the position it reconstructs from the depth buffer, the
    // reference at the interpolated one; a rasterizer that snaps vertices to its sub-pixel
    // grid (the H100 does) moves the two apart next to a light by more than deferred's
    // scalar terms cover (docs/deferred.md, "Position reconstruction and the reference").
    // Its model bounds that per pixel from the reference's depth and the device's sub-pixel
    // bits, as `triptych stress` checks it; the scalar bound then holds what is left beyond
    // each pixel's allowance. Models without a per-pixel allowance get none: checked == raw.
    const ErrorModelInput in{
        c,           scene, resolved, &ref.run.depth, ctx.properties.limits.subPixelPrecisionBits,
        &ref.run.hdr};
    const ErrorBound bound = expectedBound(entry.errorModel, in);
    ASSERT_TRUE(bound.bounded) << bound.why;
    const double raw = computeError(tonemapToDisplay(run.hdr, ref.ev), ref.display).maxAbs;
    const AllowanceCheck checked = errorBeyondAllowance(bound, run.hdr, ref.run.hdr, ref.ev);
    // raw: max |T(p) - T(r)|; checked: what is left beyond each pixel's allowance (== raw
    // where the model gives none).
    std::printf("[ bound    ] %-40s tonemapped max |p - r| raw %.3g, checked %.3g <= %.3g; %s\n",
                label.c_str(), raw, checked.worstBeyond, bound.tonemapped(ref.ev),
                bound.perPixel.name.empty() ? "no per-pixel allowance"
                                            : (std::to_string(checked.widenedPixels) +
                                               " pixels widened by " + bound.perPixel.name)
                                                  .c_str());
    // A +Inf allowance (a light within the position error of a shaded point) checks nothing
    // there: none may hide in these scenes.
    EXPECT_EQ(checked.unboundedPixels, 0u) << "pixels the per-pixel allowance leaves unchecked";
    EXPECT_LE(checked.worstBeyond, bound.tonemapped(ref.ev))
        << "tonemapped max |p - r| beyond the per-pixel allowance";
}

// Light assignment's conservative tests beside the defaults: clusters, GPU binning, no binning.
const std::vector<std::pair<std::string, std::string>> kAssignmentVariants = {
    {"light-assign", "clustered"}, {"light-bin", "gpu"}, {"light-cull", "all"}};

// Which pipelines, at which sample count and rate (default: every pipeline at 1x).
struct Renders {
    std::vector<std::string> only; // empty: every registered pipeline
    uint32_t msaa = 1;
    std::string shading = "pixel";
    fs::path lightsFile; // lights added from this lights file too (none: empty)
    std::vector<std::pair<std::string, std::string>> knobs; // set for every run
};

// `grazing`: that many more lights that barely touch a surface near a triangle's corner or edge
// (transformed_scenes.h), and each pipeline also under every light-assignment variant it reads.
void renderEveryPipeline(const fs::path& path, uint32_t grazing = 0, const Renders& renders = {}) {
    SCOPED_TRACE(path.string());
    std::vector<std::string> warnings;
    GltfLoadOptions options;
    options.warnings = &warnings;
    Result<Scene> loaded = loadGltf(path.string(), options);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    Scene scene = std::move(*loaded);
    LightGenOptions g;
    g.count = 24;
    g.seed = 5;
    std::vector<Light> lights = generateLights(scene.bounds, g);
    const std::vector<Light> grazingLights = lightsGrazingSurfaces(scene, grazing, 7);
    lights.insert(lights.end(), grazingLights.begin(), grazingLights.end());
    if (!renders.lightsFile.empty()) {
        Result<std::vector<Light>> fromFile = readLightsFile(renders.lightsFile.string());
        ASSERT_TRUE(fromFile.ok()) << fromFile.error();
        lights.insert(lights.end(), fromFile->begin(), fromFile->end());
    }
    scene.lights.insert(scene.lights.end(), lights.begin(), lights.end());

    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.msaa = renders.msaa;
    settings.set("msaa-shading", renders.shading);
    // The textured surfaces' base colour is not in the compact G-buffer's model (which
    // bounds 8-bit storage by the material factors): the wide one stores it in fp32.
    settings.set("gbuffer", "wide");
    for (const auto& [knob, value] : renders.knobs)
        settings.set(knob, value);
    ReferenceRun ref;
    ref.run = runOrFail(*ctx, gpuScene, "reference", settings);
    ASSERT_EQ(countNonFinitePixels(ref.run.hdr), 0u);
    ref.ev = autoExposureEv(ref.run.hdr);
    ref.display = tonemapToDisplay(ref.run.hdr, ref.ev);
    double lit = 0;
    for (size_t i = 0; i < ref.run.hdr.pixelCount(); ++i)
        lit += ref.run.hdr.rgba[i * 4 + 1];
    EXPECT_GT(lit, 0.0) << "the reference is black";
    // The blended layers over a pixel: every blended triangle whose screen rectangle (one pixel
    // wider each side) holds the pixel, counted (an upper bound on the layers there).
    const std::vector<uint32_t> layers = blendedLayers(scene, gpuScene.frame());
    const uint32_t mostLayers = layers.empty() ? 0u : *std::max_element(layers.begin(), layers.end());

    const std::string name = path.filename().string() == "scene.gltf"
                                 ? path.parent_path().filename().string()
                                 : path.filename().string();
    for (const RendererEntry& entry : registeredRenderers()) {
        if (entry.name == "reference") continue;
        if (!renders.only.empty() &&
            std::find(renders.only.begin(), renders.only.end(), entry.name) == renders.only.end())
            continue;
        expectWithinBound(*ctx, gpuScene, scene, entry, settings, ref, mostLayers,
                          name + " " + entry.name);
        for (const auto& [knob, value] : kAssignmentVariants) {
            auto reads = [&, &knob = knob](const Knob& k) { return k.name == knob; };
            if (grazing == 0 || std::none_of(entry.knobs.begin(), entry.knobs.end(), reads))
                continue;
            RenderSettings variant = settings;
            variant.set(knob, value);
            expectWithinBound(*ctx, gpuScene, scene, entry, variant, ref, mostLayers,
                              name + " " + entry.name + " --" + knob + " " + value);
        }
    }
    expectNoValidationMessages(*ctx);
}

class GltfScenesRender : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("triptych_gltf_gpu_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(GltfScenesRender, Draco) {
    renderEveryPipeline(writeDracoScene(dir_ / "draco"));
}

TEST_F(GltfScenesRender, Meshopt) {
    renderEveryPipeline(writeMeshoptScene(dir_ / "meshopt"));
}

TEST_F(GltfScenesRender, Repaired) {
    RepairCounts counts;
    renderEveryPipeline(writeRepairScene(dir_ / "repair", counts));
}

TEST_F(GltfScenesRender, TextureTransform) {
    renderEveryPipeline(writeTextureTransformScene(dir_ / "transform"));
}

// Meshes placed by mirrored, non-uniformly scaled, rotated and translated nodes, lit by 48
// more lights that barely touch them where a box and its triangles part most: every
// conservative box or sphere test on the way (multipass's draw selection and scissors, tile and
// cluster culling, CPU and GPU binning) must keep each light where it lights a pixel. Every
// third mesh blended: the blended bounds and transparent lists take the same transforms, and
// each model counts the roundings of its blended layers (core/renderer/error_model.h:
// addBlendedLayersTerm) with the most layers over a pixel counted on the CPU. The visibility
// buffer's blended layers through its forward pass (--vis-blended forward: interpolated
// positions, as the reference's): its compute path shades them at the exact ray hit, and its
// model's position allowance next to lights is taken at the opaque surface only (the
// reference's depth), not at the blended layers' points, so next to these grazing lights it
// has no bound there (measured 4.4e-4 tonemapped against a limit of 9.1e-6; issue 40, left open).
TEST_F(GltfScenesRender, TransformedNodes) {
    Renders renders;
    renders.knobs = {{"vis-blended", "forward"}};
    renderEveryPipeline(writeTransformedNodesScene(dir_ / "transformed", 3, 13, true), 48, renders);
}

// The visibility buffer on the shared scenes that exercise what its resolve rebuilds by itself:
// alpha modes (masked ids, blended layers), textures with mipmaps (the analytic level of
// detail), vertex colours, mirrored tangents (facing and the tangent frame), at 1x and with
// every 4x sample shaded, each within its derived bound of the reference.
TEST(GltfSharedScenesRender, VisbufferOnTheSharedScenes) {
    const fs::path root = TP_SHARED_SCENES;
    if (!fs::exists(root)) GTEST_SKIP() << root << " not found";
    std::string missing;
    for (const char* rel : {"AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf",
                            "DamagedHelmet/glTF-Binary/DamagedHelmet.glb",
                            "NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf",
                            "VertexColorTest/glTF/VertexColorTest.gltf",
                            "TextureTransformTest/glTF/TextureTransformTest.gltf"}) {
        if (!fs::exists(root / rel)) {
            missing += std::string(missing.empty() ? "" : ", ") + rel;
            continue;
        }
        renderEveryPipeline(root / rel, 0, {{"visbuffer"}, 1, "pixel"});
        renderEveryPipeline(root / rel, 0, {{"visbuffer"}, 4, "sample"});
    }
    // The scenes found were checked; a missing one makes the test a skip, never a pass.
    if (!missing.empty()) GTEST_SKIP() << "not found under " << root << ": " << missing;
}

// A real scene whose nodes are all mirrored and whose glass panes include two instances of one
// mesh at one transform: coincident surfaces, which multipass forward lit once per surface
// (RMSE 2.1e-2 against the reference; docs/multipass_forward.md) with the light that shows it.
TEST(GltfSharedScenesRender, SubpassGlassCoincidentPanes) {
    const fs::path dir = fs::path(TP_SHARED_SCENES) / "SubpassGlass";
    const fs::path path = dir / "subpass_scene_transparent.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found; skipping";
    renderEveryPipeline(path, 0, {{}, 1, "pixel", dir / "missed_light.json"});
    renderEveryPipeline(path, 0, {{}, 4, "sample", dir / "missed_light.json"});
}

TEST(GltfSharedScenesRender, DuckDraco) {
    const fs::path path = fs::path(TP_SHARED_SCENES) / "Duck-Draco/glTF-Draco/Duck.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found; skipping";
    renderEveryPipeline(path);
}

} // namespace
} // namespace tp::test
