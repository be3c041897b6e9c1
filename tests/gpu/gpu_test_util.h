#pragma once
// Shared helpers of the GPU tests: a validated context on the default device and small
// hand-built scenes whose shading can be recomputed on the CPU.
#include <memory>

#include <gtest/gtest.h>

#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/shadow_raster_knob.h"
#include "core/renderer/error_model.h"
#include "core/runner/frame_runner.h"
#include "core/scene/scene.h"

namespace tp::test {

// Validation (with synchronization validation) on; fails the test if creation fails.
std::unique_ptr<GpuContext> makeValidatedContext();

// gltf_test_scenes.h's masked scene loaded (written to a temporary folder, removed after) with
// `lights` seeded lights.
Result<Scene> loadMaskedScene(uint32_t lights, uint32_t seed);

// Asserts that the validation layers reported nothing so far.
void expectNoValidationMessages(const GpuContext& ctx);

// Appends the quad origin, origin + u, origin + u + v, origin + v to m, facing cross(u, v).
void addQuad(Mesh& m, glm::vec3 origin, glm::vec3 u, glm::vec3 v);

// A 10 x 10 floor at y = 0 (white dielectric, roughness 1) with a box on it, camera above
// looking down at an angle; lights as given.
Scene makeFloorScene(const std::vector<Light>& lights);

RunResult runOrFail(GpuContext& ctx, SceneGpu& scene, const std::string& pipeline,
                    const RenderSettings& settings, uint32_t frames = 1);
// Whether the run recorded pass `pass`.
bool ranPass(const RunResult& run, const std::string& pass);

// One frame of `pipeline` through its own graph: the exported buffers `names` read back (empty
// where a name is not exported), for what runOrFail does not read back.
std::vector<std::vector<uint8_t>> exportedBuffers(GpuContext& ctx, SceneGpu& scene,
                                                  const std::string& pipeline,
                                                  const RenderSettings& settings,
                                                  const std::vector<std::string>& names);

// `s` with the visibility buffer's rasterizer held at hardware (when `pipeline` reads
// --vis-raster): on a GPU at 1x --vis-raster auto is hybrid, but hardware under
// --cull-geometry full (vis_settings.h), so comparing culling modes must fix it.
void holdRasterFixed(RenderSettings& s, const std::string& pipeline);

// Every registered renderer that reads --cull-geometry.
std::vector<std::string> cullingPipelines();
// `pipeline` on a validated context: unculled (one frame), then with --cull-geometry `mode` for
// each count of frames in `frames` (the last frame's result each); empty when no context.
std::vector<RunResult> renderCullModes(const std::string& pipeline, const Scene& scene, uint32_t w,
                                       uint32_t h, uint32_t msaa, const std::string& mode,
                                       const std::vector<uint32_t>& frames);

// Per pixel, an upper bound on the blended layers covering any of its samples: the blended
// triangles whose screen bounding box touches it (all of them when one crosses the near
// plane). CPU only; the scenes of these tests have few blended triangles.
std::vector<uint32_t> blendedLayers(const Scene& scene, const gpu::FrameUniforms& f);

// Pixels whose RGBA bytes differ (0: identical images); `first`, when given, the first of them.
size_t differingPixels(const ImageRGBA& a, const ImageRGBA& b, size_t* first = nullptr);

// The run's debug image of that name (settings.debug), or null.
const ImageRGBA* debugImageOf(const RunResult& run, const std::string& name);

// The summation bound: a and b agree per channel within 2 (N - 1) u max(|a|, |b|),
// N = samples * (lights + 1), u = 2^-24 (gpu_test_util.cpp says why).
void expectAgreeWithinSummationBound(const ImageRGBA& a, const ImageRGBA& b, uint32_t lights,
                                     uint32_t samples, const std::string& what);

// Records the compiled graph once and submits it `frames` times, waiting for each.
void recordAndSubmit(GpuContext& ctx, FrameGraph& graph, uint32_t frames = 1);

// The shadow atlas of the scene's plan rendered in a 96x54 frame (--shadow-cache off) by
// ShadowMaps with `cull` and `raster` (listCapacity: its setRasterListCapacity), exported and
// read back, with its counters after the frame.
struct ShadowAtlasRun {
    ImageR32 depth;
    std::vector<std::pair<std::string, double>> counters;
};
ShadowAtlasRun renderShadowAtlas(GpuContext& ctx, SceneGpu& scene, CullGeometry cull,
                                 ShadowRaster raster = ShadowRaster::Hardware,
                                 uint32_t listCapacity = 0);

// The built-in courtyard-small with `count` generated lights of `seed`.
Scene courtyardSmallWithLights(uint32_t count, uint64_t seed);

// Worst (|p - r| less the pixel's allowance) / (relative |r| + absolute) over every pixel
// (those `only` marks 1, when given) and colour channel (the allowance: the bound's per-pixel
// one where its model has one).
struct WorstRatio {
    double ratio = 0, got = 0, ref = 0;
    uint32_t x = 0, y = 0, pixelsOver = 0;
};
WorstRatio worstRatio(const ImageRGBA& got, const ImageRGBA& ref, const ErrorBound& b,
                      const std::vector<uint8_t>* only = nullptr);

// A pipeline's registered model of its image `run` (4x, --msaa-shading pixel) against the
// centre reference `centre`: without its shading-rate term (its input at --msaa-shading
// sample), which is what the centre reference removes (docs/shading.md); with the reference's
// depth, for the models with a per-pixel position allowance.
ErrorBound centreModelBound(const GpuContext& ctx, const Scene& scene, const std::string& pipeline,
                            const RenderSettings& run, const RunResult& centre);

// The visibility buffer's run `run` within the bound its error model derives against `ref` for
// `modelSettings` (the settings whose method the reference repeats), with the reference's depth
// (visbuffer_test.cpp, visbuffer_raster_test.cpp).
void expectVisbufferWithinBound(GpuContext& ctx, const Scene& scene, const RunResult& run,
                                const RunResult& ref, const RenderSettings& modelSettings,
                                const std::string& what);
} // namespace tp::test
