#pragma once
// Pipeline statistics per pass (VK_QUERY_TYPE_PIPELINE_STATISTICS, where the device has the
// feature; lavapipe and NVIDIA do): the work a pass gave the device, counted by the device.
// The frame graph brackets every pass it records with one query, beside its timestamps
// (docs/efficiency.md, "Placing a pass: what is counted"). Counts are of the last frame submitted: the same
// recording every frame, so every frame's counts are the same.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

class GpuContext;

struct PipelineCounts {
    uint64_t inputPrimitives = 0;     // primitives assembled from the draws' vertices
    uint64_t clippingInvocations = 0; // primitives that reached clipping (after the vertex stage)
    uint64_t clippingPrimitives = 0;  // primitives out of clipping: what the rasterizer sets up
    uint64_t fragmentInvocations = 0;
    // Not compute-shader invocations: with that statistic, lavapipe (Mesa 22.3) crashes
    // beginning a query after a compute pass (it re-emits stale compute state).
};

struct PassCounts {
    std::string pass;
    PipelineCounts counts;
};

class PassStatistics {
  public:
    PassStatistics(GpuContext& ctx, uint32_t maxPasses);
    ~PassStatistics();
    PassStatistics(const PassStatistics&) = delete;
    PassStatistics& operator=(const PassStatistics&) = delete;

    bool available() const { return pool_ != VK_NULL_HANDLE; }
    void beginFrame(VkCommandBuffer cmd); // resets the queries; no query may be active
    uint32_t begin(VkCommandBuffer cmd, const std::string& pass);
    void end(VkCommandBuffer cmd, uint32_t query);
    // After a submission completed: every pass's counts in recording order (empty without
    // the feature).
    std::vector<PassCounts> read() const;

  private:
    GpuContext& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t capacity_;
    std::vector<std::string> names_;
};

} // namespace tp
