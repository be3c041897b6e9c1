#pragma once
// The frame graph's planning half: no device, no command buffer, only declarations in and a
// plan out, so it is tested on the CPU (tests/cpu/frame_graph_test.cpp). FrameGraph
// (frame_graph.h) allocates and records from the plan.
//
// From the resources, the passes (in declaration order, each with its list of uses) and
// the exported resources, plan() gives
//   - which passes are live: a pass lives when it writes a resource that an export or a
//     later live pass needs; the others are culled,
//   - per resource the usage flags of its live uses (a resource no live pass touches is not
//     allocated) and the first live pass that writes it (for the memory ledger),
//   - per live pass the barriers to record before it, and the barriers after the last pass
//     that leave every export readable by transfer.
// Declaration mistakes are GraphError exceptions naming the pass and the resource.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

enum class Use {
    ColorAttachment, // written (and read by blending)
    ColorResolve,    // MSAA colour resolve target
    DepthAttachment, // depth test and write
    DepthResolve,    // MSAA depth resolve target
    DepthTest,       // depth test without writes; may be sampled in the same pass
    Sampled,         // sampled or texelFetch'd in fragment/compute shaders
    StorageRead,
    StorageWrite, // write-only or read-write storage access
    TransferSrc,
    TransferDst,
    IndirectRead, // indirect draw commands or their count (vkCmdDrawIndexedIndirectCount)
};

const char* useName(Use use);

struct ResourceHandle {
    uint32_t index = ~0u;
    bool valid() const { return index != ~0u; }
};

constexpr uint32_t kNoBinding = ~0u;

// One use of a resource by a pass. A use with a binding is also bound through the pass's
// descriptor set (set TP_SET_PASS) at that binding: the set's layout, descriptor types and
// writes follow from these uses (FrameGraph::createPassSet), so a resource is declared once.
struct PassUse {
    ResourceHandle resource;
    Use use;
    uint32_t binding = kNoBinding;
};

// A mistake in what passes declare; the message names the pass and the resource.
struct GraphError : std::logic_error {
    using std::logic_error::logic_error;
};

// How a use touches memory: what a barrier waits for and makes visible.
struct UseInfo {
    VkPipelineStageFlags2 stages;
    VkAccessFlags2 access;
    VkImageLayout layout;
    bool writes;
    bool reads;
};
UseInfo useInfo(Use use);
bool imageOnly(Use use); // attachments and sampling: meaningless on a buffer

// The descriptor type a bound use needs: sampled (and depth-tested-and-sampled) images are
// combined image samplers, storage uses are storage images or storage buffers.
VkDescriptorType descriptorType(Use use, bool isImage);

struct PlanBarrier {
    uint32_t resource;
    bool image;
    VkImageLayout oldLayout, newLayout; // images only
    VkPipelineStageFlags2 srcStages, dstStages;
    VkAccessFlags2 srcAccess, dstAccess;
};

struct PlannedPass {
    uint32_t pass;                     // index in declaration order
    std::vector<PlanBarrier> barriers; // recorded before the pass, in this order
};

struct PlannedResource {
    bool allocated = false;
    VkImageUsageFlags imageUsage = 0;
    VkBufferUsageFlags bufferUsage = 0;
    std::string firstWriter; // the first live pass that writes it
};

struct GraphPlan {
    std::vector<bool> live;                 // per declared pass
    std::vector<PlannedPass> passes;        // the live passes, in declaration order
    std::vector<PlannedResource> resources; // per declared resource
    std::vector<PlanBarrier> exportBarriers;
};

class GraphDecl {
  public:
    ResourceHandle addResource(const std::string& name, bool isImage);
    void addPass(const std::string& name, std::vector<PassUse> uses);
    void exportResource(const std::string& publicName, ResourceHandle h);
    GraphPlan plan() const;
    // Throws unless pass `pass` declared `use` of `h`: for what a pass names again while
    // recording (its attachments), so a use left out of the declaration is an error.
    void expectUse(uint32_t pass, ResourceHandle h, Use use) const;

    struct Resource {
        std::string name;
        bool isImage;
        bool exported = false;
    };
    struct Pass {
        std::string name;
        std::vector<PassUse> uses;
    };
    const std::vector<Resource>& resources() const { return resources_; }
    const std::vector<Pass>& passes() const { return passes_; }
    const std::vector<std::pair<std::string, ResourceHandle>>& exports() const { return exports_; }
    const Pass& pass(const std::string& name) const;

  private:
    std::vector<bool> cull() const;
    void checkReads(const std::vector<bool>& live) const;

    std::vector<Resource> resources_;
    std::vector<Pass> passes_;
    std::vector<std::pair<std::string, ResourceHandle>> exports_;
};

} // namespace tp
