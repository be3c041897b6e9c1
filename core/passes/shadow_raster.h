#pragma once
// The shadow maps' compute rasterizer (--shadow-raster compute; docs/shadows.md, "Rasterizing
// the maps in compute"; the triangle is shaders/include/raster_triangle.glsl's, the visibility
// buffer's). It rasterizes what the face cull (shadow_cull.h) kept, not what the hardware would
// be given: every command slot of the cull's rows is a workgroup, every triangle of a kept
// meshlet an invocation.
//   shadow_raster_clear  zeroes the depth buffer (0: the hardware's clear value, reverse-Z's far)
//                        and the list's counters.
//   shadow_raster        a triangle within TP_RT_SMALL_PIXELS texels each way writes its depth's
//                        bits per covered texel with a 32-bit atomic max; a larger one (or one
//                        the near plane or the face's guard band cuts) is listed. A triangle the
//                        full list cannot take is counted (shadow_raster_triangles_overflow)
//                        and its meshlet listed instead: never dropped.
//   shadow_raster_big    a workgroup per listed triangle, dispatched indirectly; then per
//                        overflowed meshlet, its large triangles again (the atomic max is
//                        idempotent: those it had listed change nothing).
//   shadow_maps          one vkCmdCopyBufferToImage of the depth buffer into the D32 map: the
//                        sampling shaders read the very image they read from the hardware.
// In a frame (plan(): the graph's buffers and passes, barriers from the declared uses) or
// outside the frames for the kept atlas (allocate(), recordOwn(): its own buffers and
// hand-written barriers).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "shadow/shadow_raster.h"

namespace tp {

class GpuContext;
class SceneGpu;
class ShadowCull;

class ShadowComputeRaster {
  public:
    // Large triangles listed for shadow_raster_big at most: 16 bytes each (16 MiB); fewer when
    // the rows hold fewer triangles.
    static constexpr uint32_t kMaxListed = 1u << 20;

    // Throws RendererError (one line) where the device lacks shaderInt64.
    ShadowComputeRaster(GpuContext& ctx, SceneGpu& scene, const ShadowCull& cull);
    ~ShadowComputeRaster();
    ShadowComputeRaster(const ShadowComputeRaster&) = delete;
    ShadowComputeRaster& operator=(const ShadowComputeRaster&) = delete;

    // The map's size in texels and the triangles of the cull's rows (what its list may need at
    // most); `listCapacity` 0: min(those triangles, kMaxListed), else that (tests: overflow).
    // Throws RendererError when the depth buffer is over the device's maxStorageBufferRange.
    void size(uint32_t width, uint32_t height, double rowTriangles, uint32_t listCapacity = 0);
    // In a frame: its buffers and passes, the last ("shadow_maps") copying into `map`.
    // map invalid: no copy (the consumers read depth() through the shadow set).
    void plan(FrameGraph& graph, ResourceHandle map);
    ResourceHandle depth() const { return depth_; } // in a frame: the atlas's texels
    // Read through depth(), the atlas has no image: a 1x1 D32 map in the read-only layout for
    // the shadow set's image binding, which the shaders then do not read (made once).
    VkImageView standInMap(const std::string& owner);
    // Outside the frames: buffers of its own (ledger owner `owner`, pass "shadow_maps (once)").
    void allocate(const std::string& owner);
    // The sets and pipelines (after graph.compile() when planned in a frame).
    void prepare(FrameGraph* graph);
    // Outside the frames, after the cull's dispatch and a barrier from its writes to compute
    // reads: clear, raster, big, the copy into `image` (its contents discarded), left
    // READ_ONLY_OPTIMAL for the shading's fragment and compute shaders. Writes its set again
    // first: the cull's own buffers may have grown since the last render.
    void recordOwn(VkCommandBuffer cmd, VkImage image);

    // The counters of the last render read back (in a frame: after the frames).
    void collect(FrameGraph* graph);
    // shadow_raster_triangles (rasterized in compute: small + listed), _small, _listed,
    // _culled, _clipped, _overflow, shadow_raster_list_capacity, shadow_raster_depth_atomics.
    std::vector<std::pair<std::string, double>> counters() const;

  private:
    void recordClear(VkCommandBuffer cmd, VkBuffer depth, VkBuffer list, VkBuffer args) const;
    void recordRaster(VkCommandBuffer cmd) const;
    void recordBig(VkCommandBuffer cmd, VkBuffer args) const;
    void recordCopy(VkCommandBuffer cmd, VkBuffer depth, VkImage image) const;
    void writeOwnSets();
    void makePipelines();

    GpuContext& ctx_;
    SceneGpu& scene_;
    const ShadowCull& cull_;
    uint32_t width_ = 0, height_ = 0, capacity_ = 1;
    bool inFrame_ = false;
    void allocateOverflow();
    ResourceHandle depth_, list_, args_, overflow_;  // in a frame
    Buffer ownDepth_, ownList_, ownArgs_, ownOverflow_; // outside the frames
    Image standIn_;                                      // standInMap()
    uint32_t overflowCapacity_ = 0;
    std::string owner_;
    PassSet set_, bigSet_;
    bool ownSets_ = false;
    VkPipelineLayout layout_ = VK_NULL_HANDLE, bigLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE, big_ = VK_NULL_HANDLE;
    bool collected_ = false;
    uint32_t counts_[TP_SR_LIST_HEADER] = {};
};

} // namespace tp
