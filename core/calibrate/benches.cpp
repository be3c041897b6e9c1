#include "core/calibrate/benches.h"

#include <algorithm>

namespace tp::calibrate {
namespace {

constexpr double kVec4Bytes = 16.0;
constexpr double kFmaFlopsPerStep = 8 * 4 * 2; // calibrate_fma.glsl: 8 vec4 chains, 2 FLOPs an FMA
constexpr VkFormat kLoopTarget = VK_FORMAT_R8G8B8A8_UNORM;  // one write after a long loop
constexpr VkFormat kHdrTarget = VK_FORMAT_R16G16B16A16_SFLOAT; // what our passes shade into
constexpr uint32_t kSmallCell = 2, kLargeCell = 32; // grid cells' edge in pixels (2 triangles a cell)
// Deferred's compact G-buffer without emission (deferred/gbuffer_layout.cpp), after the first
// (base colour, RGBA8 sRGB): the least a pass that writes three targets writes (10 B a pixel).
const std::vector<VkFormat> kGBufferRest = {VK_FORMAT_R16G16_SNORM, VK_FORMAT_R8G8_UNORM};

Bench stream(const char* name, uint32_t kind, const char* what, uint64_t bytes, bool quick) {
    const uint32_t elements = uint32_t(bytes / 16), steps = quick ? 4u : 16u;
    Bench b{name, kind, "GB/s", what};
    b.invocations = elements / steps;
    b.push = {b.invocations, steps, elements - 1u, 0u};
    b.work = double(b.invocations) * steps * kVec4Bytes * (kind == TP_CAL_COPY ? 2 : 1);
    b.scalable = false; // sized by the buffer instead (calibration.cpp, streamBytes)
    return b;
}

// A compute loop of `steps` steps per invocation, `perStep` units of work each.
Bench loop(const char* name, uint32_t kind, const char* unit, const char* what, bool quick,
           uint32_t steps, double perStep, gpu::CalPush push = {}) {
    Bench b{name, kind, unit, what};
    b.invocations = quick ? 16384u : 262144u;
    b.push = push;
    b.push.iterations = steps;
    if (b.push.stride == 0) b.push.stride = b.invocations;
    b.work = double(b.invocations) * steps * perStep;
    return b;
}

// A fragment loop over one full-screen triangle: `steps` steps per pixel.
Bench fragmentLoop(const char* name, uint32_t kind, const char* unit, const char* what, bool quick,
                   uint32_t steps, double perStep) {
    Bench b{name, kind, unit, what, true};
    b.draw.color = kLoopTarget;
    b.draw.size = targetSize(quick);
    b.push = {0u, steps, 0u, 0u};
    b.work = double(b.draw.size) * b.draw.size * steps * perStep;
    return b;
}

// `layers` instances of the draw, each covering the target once: work in pixels, or in
// triangles for a grid of cells `cell` pixels wide.
Bench raster(const char* name, const char* unit, const char* what, bool quick, BenchDraw draw,
             uint32_t cell = 0) {
    const uint32_t kind = draw.moreColors.empty() ? TP_CAL_FRAGMENT_FLAT : TP_CAL_FRAGMENT_FLAT3;
    Bench b{name, kind, unit, what, true, draw};
    b.draw.layered = true;
    b.draw.size = targetSize(quick);
    b.push = {cell ? b.draw.size / cell : 0u, quick ? 2u : 8u, 0u, 0u};
    if (cell && b.draw.vertex == TP_CAL_VERTEX_LAYERS) b.draw.vertex = TP_CAL_VERTEX_GRID;
    const double perLayer = cell ? double(b.push.stride) * b.push.stride * 2 : double(b.draw.size) * b.draw.size;
    b.work = perLayer * b.push.iterations;
    return b;
}

// `draws` draw commands of one full-screen triangle each, culled: what a draw costs before any
// primitive is set up (the command processor and the draw's state), per draw.
Bench drawCalls(const char* name, const char* what, bool quick) {
    BenchDraw draw{.color = kHdrTarget, .cullAll = true};
    draw.indirectDraws = quick ? 1024u : 65536u;
    Bench b{name, TP_CAL_FRAGMENT_FLAT, "Gdraw/s", what, true, draw};
    b.draw.size = targetSize(quick);
    b.push = {0u, 1u, 0u, 0u};
    b.work = double(draw.indirectDraws);
    b.scalable = false; // sized by its draw count
    return b;
}

std::vector<Bench> memoryBenches(uint64_t bytes, bool quick) {
    const uint32_t elements = uint32_t(bytes / 16);
    const uint32_t cacheWindow = std::min<uint32_t>(65536u, elements); // vec4: 1 MiB
    return {
        stream("dram_read", TP_CAL_READ, "a buffer far larger than any cache, read in order (passing over it again if longer)", bytes, quick),
        stream("dram_write", TP_CAL_WRITE, "the same buffer written in order", bytes, quick),
        stream("dram_copy", TP_CAL_COPY, "the buffer copied to another (bytes read + written)", bytes, quick),
        // Each step 16 KiB further on in the window (wrapping): a new cache line every step,
        // never the same address twice in a row (a compiler could keep that in a register),
        // neighbouring invocations on neighbouring vec4.
        loop("cache_read", TP_CAL_CACHE_READ, "GB/s", "the same 1 MiB read over and over, a new cache line each step",
             quick, quick ? 16u : 64u, kVec4Bytes, {1024u, 0u, cacheWindow - 1u, 0u}),
    };
}

std::vector<Bench> computeBenches(bool quick) {
    return {
        loop("fp32_fma", TP_CAL_FMA, "GFLOP/s", "8 independent vec4 FMA chains (2 FLOPs per FMA)",
             quick, quick ? 64u : 1024u, kFmaFlopsPerStep),
        loop("shared_atomic", TP_CAL_SHARED_ATOMIC, "Gatomic/s",
             "atomicAdd to shared memory, 256 words per workgroup", quick, quick ? 32u : 256u, 1.0),
        loop("global_atomic", TP_CAL_GLOBAL_ATOMIC, "Gatomic/s",
             "atomicAdd to 4 MiB of device memory, spread", quick, quick ? 16u : 64u, 1.0,
             {0u, 0u, (1u << 20) - 1u, 0u}),
        loop("texture_fetch", TP_CAL_TEXTURE, "Gfetch/s",
             "bilinear fetches of a 1024x1024 RGBA8 texture, neighbouring texels", quick,
             quick ? 8u : 64u, 1.0),
        // An image read as passes read depth and G-buffers: 4 bytes a texel (RGBA8).
        loop("image_read", TP_CAL_IMAGE_READ, "GB/s",
             "texelFetch of the 1024x1024 RGBA8 texture, neighbouring texels", quick,
             quick ? 8u : 64u, 4.0),
        // The same over a multisampled depth (what a 4x pass reads): 4 samples of 4 bytes a step.
        loop("image_read_msaa4", TP_CAL_IMAGE_READ_MSAA4, "GB/s",
             "texelFetch of every sample of a 1024x1024 D32 4x MSAA depth, neighbouring texels",
             quick, quick ? 8u : 64u, 16.0),
        loop("light_point", TP_CAL_LIGHT_POINT, "Geval/s",
             "one point light through the shared light model and BRDF", quick, quick ? 4u : 64u,
             1.0),
        loop("light_spot", TP_CAL_LIGHT_SPOT, "Geval/s",
             "one spot light through the shared light model and BRDF", quick, quick ? 4u : 64u,
             1.0),
    };
}

std::vector<Bench> fragmentBenches(bool quick) {
    return {
        fragmentLoop("fragment_fma", TP_CAL_FRAGMENT_FMA, "GFLOP/s", "fp32_fma's loop per pixel of a full-screen triangle",
                     quick, quick ? 16u : 256u, kFmaFlopsPerStep),
        fragmentLoop("fragment_texture_fetch", TP_CAL_FRAGMENT_TEXTURE, "Gfetch/s", "texture_fetch's loop per pixel, with texture()",
                     quick, quick ? 4u : 32u, 1.0),
        fragmentLoop("fragment_light_point", TP_CAL_FRAGMENT_LIGHT_POINT, "Geval/s", "light_point's loop per pixel",
                     quick, quick ? 4u : 32u, 1.0),
        fragmentLoop("fragment_light_spot", TP_CAL_FRAGMENT_LIGHT_SPOT, "Geval/s", "light_spot's loop per pixel",
                     quick, quick ? 4u : 32u, 1.0),
    };
}

std::vector<Bench> rasterBenches(bool quick) {
    BenchDraw depthOnly{.fragment = false, .depth = true};
    BenchDraw colour{.color = kHdrTarget};
    BenchDraw blend{.color = kHdrTarget, .blend = BlendMode::Additive};
    BenchDraw msaa{.color = kHdrTarget, .depth = true, .samples = VK_SAMPLE_COUNT_4_BIT};
    BenchDraw colourMsaa{.color = kHdrTarget, .samples = VK_SAMPLE_COUNT_4_BIT};
    BenchDraw depthMsaa{.fragment = false, .depth = true, .samples = VK_SAMPLE_COUNT_4_BIT};
    // Indexed: a mesh's vertices are shared by its triangles; the non-indexed grid shaded three
    // vertices a triangle and measured less than an indexed pass's triangles can go.
    BenchDraw culled{.vertex = TP_CAL_VERTEX_GRID_INDEXED, .color = kHdrTarget, .cullAll = true};
    BenchDraw gbuffer{.color = VK_FORMAT_R8G8B8A8_SRGB, .moreColors = kGBufferRest};
    BenchDraw gbufferMsaa{.color = VK_FORMAT_R8G8B8A8_SRGB, .moreColors = kGBufferRest,
                          .samples = VK_SAMPLE_COUNT_4_BIT};
    return {
        raster("raster_depth", "Gpixel/s",
               "full-screen layers into D32, depth test and write, no fragment shader", quick,
               depthOnly),
        raster("rop_colour", "Gpixel/s", "full-screen layers of one colour into RGBA16F", quick,
               colour),
        raster("rop_blend", "Gpixel/s",
               "the same, blended additively (multipass forward's light passes)", quick, blend),
        raster("raster_msaa4", "Gpixel/s",
               "the same as rop_colour with D32, both 4x MSAA (pixels, 4 samples each)", quick,
               msaa),
        // What a pass at 4x does at the least: colour alone (a light pass tests depth, writes
        // none), or depth alone (a prepass). Passes are placed against these, not raster_msaa4.
        raster("rop_colour_msaa4", "Gpixel/s",
               "rop_colour at 4x MSAA, no depth (pixels, 4 samples each)", quick, colourMsaa),
        raster("raster_depth_msaa4", "Gpixel/s", "raster_depth at 4x MSAA (pixels, 4 samples each)",
               quick, depthMsaa),
        // What a pass writing several targets does at the least (deferred's G-buffer): passes
        // with three colour attachments or more are placed against these, not rop_colour.
        raster("rop_gbuffer", "Gpixel/s",
               "full-screen layers into three targets, RGBA8 sRGB, RG16 SNORM and RG8 (deferred's "
               "compact G-buffer)",
               quick, gbuffer),
        raster("rop_gbuffer_msaa4", "Gpixel/s", "rop_gbuffer at 4x MSAA (pixels, 4 samples each)",
               quick, gbufferMsaa),
        raster("tri_small", "Gtri/s", "a grid of 2x2-pixel cells, 2 triangles each, one colour",
               quick, colour, kSmallCell),
        raster("tri_large", "Gtri/s", "a grid of 32x32-pixel cells, 2 triangles each, one colour",
               quick, colour, kLargeCell),
        // The fastest a triangle can go: every primitive a pass submits is placed against it.
        raster("tri_culled", "Gtri/s",
               "tri_small's grid, indexed (shared vertices), every triangle culled: no pixel",
               quick, culled, kSmallCell),
        // The fastest a draw can go: every draw a pass issues is placed against it (multipass
        // forward's, a draw per light and mesh).
        drawCalls("draw_culled",
                  "indirect draws of one full-screen triangle each, culled, in one multi-draw call",
                  quick),
    };
}

} // namespace

uint32_t targetSize(bool quick) { return quick ? 128u : 1024u; }

std::vector<uint32_t> gridIndices(uint32_t cells) {
    std::vector<uint32_t> out;
    out.reserve(size_t(cells) * cells * 6);
    const uint32_t row = cells + 1;
    for (uint32_t y = 0; y < cells; ++y)
        for (uint32_t x = 0; x < cells; ++x) {
            const uint32_t v = y * row + x; // corners (0,0) (1,0) (0,1), then (1,0) (1,1) (0,1)
            out.insert(out.end(), {v, v + 1, v + row, v + 1, v + row + 1, v + row});
        }
    return out;
}

std::vector<Bench> benches(uint64_t bufferBytes, bool quick) {
    std::vector<Bench> all;
    for (auto part : {memoryBenches(bufferBytes, quick), computeBenches(quick), fragmentBenches(quick), rasterBenches(quick)})
        all.insert(all.end(), part.begin(), part.end());
    return all;
}

} // namespace tp::calibrate
