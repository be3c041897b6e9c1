#pragma once
// The visibility buffer's compute rasterizer (--vis-raster compute|hybrid; docs/visbuffer.md,
// "The compute rasterizer"; shaders/include/raster_triangle.glsl says what it does to a triangle,
// shaders/visbuffer/vis_raster.glsl what is the visibility buffer's).
//   vis_raster_clear  zeroes the samples (0: no geometry) and the list's counters.
//   vis_raster        (compute) one invocation per triangle of the opaque draws and, in compute
//                     mode, the masked ones (or of the meshlets meshlet_cull kept): a triangle
//                     within TP_VR_SMALL_PIXELS each way writes (depth bits << 32 | ~id) per
//                     sample it covers with a 64-bit atomic max; a larger one is listed.
//   vis_raster_big    (compute mode) a workgroup per listed triangle, dispatched indirectly.
// raster_merge_pass.h then puts the samples into the visibility pass's id and depth targets (at
// 1x as their first contents, before the hardware draws the masked draws and the listed
// triangles into them in hybrid mode; under MSAA merged after those): everything downstream
// reads the targets it always read.
#include <string>
#include <utility>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/renderer/renderer.h"
#include "visbuffer/draw_table.h"
#include "visbuffer/vis_raster.h"

namespace tp {
class GpuContext;
class SceneGpu;
namespace passes {
class MeshletCull;
}

namespace vis {

struct RasterTargets {
    ResourceHandle samples; // uint64_t per sample: (depth bits << 32) | ~id, 0: none
    ResourceHandle list;    // counters, then the listed triangles (vis_raster.h)
    ResourceHandle args;    // the listed triangles' indirect dispatch (compute) or draw (hybrid)
    ResourceHandle hwList;  // hybrid: the listed triangles in the draws' order (vis_raster_order)
    bool hybrid = false;
    bool valid() const { return samples.valid(); }
};

class RasterPass {
  public:
    // Throws RendererError (one line) where the device lacks shaderInt64 or
    // shaderBufferInt64Atomics.
    RasterPass(GpuContext& ctx, SceneGpu& scene, const DrawTable& table, bool hybrid);
    ~RasterPass();
    RasterPass(const RasterPass&) = delete;
    RasterPass& operator=(const RasterPass&) = delete;

    // cull: the meshlets to rasterize (made with firstTriangle), or null for the draws whole.
    RasterTargets plan(FrameGraph& graph, uint32_t samples, const passes::MeshletCull* cull);
    void prepare(FrameGraph& graph);
    // After a frame: the counters read back (counters() then has them).
    void collect(FrameGraph& graph);
    // raster_triangles (the triangles it was given), raster_triangles_small (rasterized by
    // their own invocation), raster_triangles_listed (to vis_raster_big or the hardware),
    // raster_triangles_culled, raster_triangles_clipped (near plane or guard band),
    // raster_sample_atomics (the 64-bit atomics both passes issued).
    std::vector<std::pair<std::string, double>> counters() const;
    // The work counts of vis_raster and vis_raster_big (after collect): triangles rasterized in
    // compute and the 64-bit atomics they issued, both counted on the GPU.
    void addWork(RendererStats& s) const;

  private:
    void makeChunks();
    void record(PassContext& pc);
    void recordBig(PassContext& pc);
    void recordOrder(PassContext& pc);
    void dispatchChunks(VkCommandBuffer cmd) const;
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DrawTable& table_;
    bool hybrid_ = false;
    uint32_t samples_ = 1;
    const passes::MeshletCull* cull_ = nullptr;
    std::vector<TableDraw> draws_; // what it rasterizes: the opaque (compute: and masked) draws
    uint32_t triangles_ = 0;
    RasterTargets t_;
    std::vector<gpu::RasterChunk> chunkData_; // from plan until prepare uploads it
    Buffer chunks_, rows_;
    uint32_t chunkCount_ = 0;
    PassSet set_, bigSet_, orderSet_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE, bigLayout_ = VK_NULL_HANDLE,
                     orderLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE, big_ = VK_NULL_HANDLE, order_ = VK_NULL_HANDLE;
    bool collected_ = false;
    uint32_t counts_[TP_VR_LIST_HEADER] = {};
};

} // namespace vis
} // namespace tp
