// light_binning_bench: the CPU's binning (la::binLights, what --light-bin cpu runs once per
// configuration) and the GPU binning's plan-time run (pipelines, upload, steps 1-5, one
// readback: what --light-bin gpu adds before the first frame), timed on the built-in
// courtyard. Not a test (timings on a shared machine make poor assertions); the frame's
// light_binning pass is timed by `triptych render --light-bin gpu` (docs/clustered.md).
//   light_binning_bench [LIGHTS [WIDTH HEIGHT [TILE [RADIUS_MIN RADIUS_MAX]]]]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/passes/light_binning.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"

using namespace tp;

namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
double cpuNow() {
    return double(std::clock()) / CLOCKS_PER_SEC;
}

template <class F> void timeIt(const char* what, int runs, F&& f) {
    std::vector<double> wall, cpu;
    for (int i = 0; i < runs; ++i) {
        double w0 = now(), c0 = cpuNow();
        f();
        wall.push_back(now() - w0);
        cpu.push_back(cpuNow() - c0);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    std::printf("%-28s median %9.3f ms (min %9.3f), CPU median %9.3f ms, %d runs\n", what,
                1e3 * wall[runs / 2], 1e3 * wall[0], 1e3 * cpu[runs / 2], runs);
}

} // namespace

int main(int argc, char** argv) {
    const uint32_t lights = argc > 1 ? uint32_t(std::atol(argv[1])) : 1024;
    const uint32_t w = argc > 3 ? uint32_t(std::atol(argv[2])) : 1280,
                   h = argc > 3 ? uint32_t(std::atol(argv[3])) : 720;
    const uint32_t tile = argc > 4 ? uint32_t(std::atol(argv[4])) : 16;
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(ContextOptions{});
    if (!ctx.ok()) {
        std::fprintf(stderr, "light_binning_bench: %s\n", ctx.error().c_str());
        return 1;
    }
    Result<Scene> scene = makeBuiltinScene("courtyard");
    if (!scene.ok()) {
        std::fprintf(stderr, "light_binning_bench: %s\n", scene.error().c_str());
        return 1;
    }
    LightGenOptions o;
    o.count = lights;
    if (argc > 6) {
        o.radiusMin = float(std::atof(argv[5]));
        o.radiusMax = float(std::atof(argv[6]));
    }
    scene->lights = generateLights(scene->bounds, o);
    SceneGpu gpuScene(**ctx, *scene);
    gpuScene.setView(w, h, 1);
    const la::TileGrid grid = la::makeTileGrid(w, h, tile);
    const std::vector<uint32_t> local = la::classifyLights(gpuScene.shadingLights()).local;
    const gpu::FrameUniforms& f = gpuScene.shadingFrame();
    std::printf("%u lights, %ux%u, tile %u (%u tiles), %s\n", lights, w, h, tile, grid.count(),
                (*ctx)->info.name.c_str());
    la::LightBins bins;
    timeIt("cpu binLights", 5, [&] {
        bins = la::binLights(grid, f.view, f.proj, gpuScene.shadingLights(), local, true);
    });
    std::printf("  candidates %llu, longest run %u\n", (unsigned long long)bins.slots,
                bins.maxBound);
    timeIt("gpu plan-time (incl. pipelines)", 3, [&] {
        la::GpuBinning b(**ctx, gpuScene, grid, local, "bench");
        b.sizes();
    });
    la::GpuBinning b(**ctx, gpuScene, grid, local, "bench");
    timeIt("gpu plan-time sizes()", 5, [&] { b.sizes(); });
    return 0;
}
