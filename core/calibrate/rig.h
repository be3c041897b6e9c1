#pragma once
// What calibrate's benchmarks run on: the buffers, the texture, the descriptor set and layout
// they share; each benchmark's pipeline and render targets; recording one dispatch or draw.
#include <vector>

#include "core/calibrate/benches.h"
#include "core/gpu/descriptors.h"
#include "core/gpu/resources.h"

namespace tp {
class GpuContext;
}

namespace tp::calibrate {

struct Rig {
    GpuContext& ctx;
    Buffer src, dst;
    Image texture;
    Image depthMsaa4; // D32 at 4x: image_read_msaa4's reads
    VkSampler sampler = VK_NULL_HANDLE, nearest = VK_NULL_HANDLE;
    PassSet set;
    VkDescriptorSetLayout emptySet = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;

    Rig(GpuContext& c, uint64_t bufferBytes);
    ~Rig();
    Rig(const Rig&) = delete;
    Rig& operator=(const Rig&) = delete;
};

// A graphics benchmark's attachments (none for compute), and an indexed grid's indices.
struct Targets {
    std::vector<Image> colors; // the draw's colour attachments, in order
    Image depth;
    Buffer indices;
    Buffer indirect; // indirectDraws' commands
};
Targets createTargets(GpuContext& ctx, const Bench& b);

VkPipeline createBenchPipeline(Rig& rig, const Bench& b);
// One dispatch, or one draw into `targets` (whose previous contents do not matter).
void recordBench(VkCommandBuffer cmd, Rig& rig, const Bench& b, VkPipeline pipeline, const Targets& targets);

} // namespace tp::calibrate
