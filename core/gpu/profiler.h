#pragma once
// Timestamp profiler: named GPU time per pass. The frame graph writes a timestamp at the
// start and end of every pass it records (passes never do it themselves). Ticks are masked
// by timestampValidBits and scaled by timestampPeriod; statistics are over the frames
// after warm-up.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

class GpuContext;

struct TimingStats {
    std::string name;
    double medianMs = 0, minMs = 0, maxMs = 0;
    uint32_t frames = 0;
};

class GpuProfiler {
  public:
    GpuProfiler(GpuContext& ctx, uint32_t maxScopes);
    ~GpuProfiler();
    GpuProfiler(const GpuProfiler&) = delete;
    GpuProfiler& operator=(const GpuProfiler&) = delete;

    void beginFrame(VkCommandBuffer cmd); // resets the queries; first scope is the whole frame
    uint32_t beginScope(VkCommandBuffer cmd, const std::string& name);
    void endScope(VkCommandBuffer cmd, uint32_t scope);
    void endFrame(VkCommandBuffer cmd);

    // After the frame's submission completed: reads the timestamps into the sample lists.
    void collect();
    void discardSamples(); // e.g. after warm-up
    // Per scope, in recording order; "frame" (the whole command buffer) comes first.
    std::vector<TimingStats> stats() const;

  private:
    GpuContext& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t capacity_;
    std::vector<std::string> names_;
    std::vector<std::vector<double>> samples_;
    uint32_t used_ = 0;
};

TimingStats summarize(const std::string& name, std::vector<double> samplesMs);

} // namespace tp
