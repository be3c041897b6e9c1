#include "core/lightassign/loop_knob.h"

#include <vulkan/vulkan.h>

#include "core/gpu/context.h"

namespace tp::la {

Knob lightLoopKnob() {
    return Knob::choice("light-loop", {"lane", "subgroup"},
                        "Clustered shading loop: lane (each fragment walks its own cluster's bits) or subgroup "
                        "(lanes of one tile walk the OR of their bits together, light loads uniform; the same "
                        "image); changes nothing under --light-assign tiled");
}

std::string subgroupLoopUnsupported(const DeviceCaps& caps) {
    if (!(caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT))
        return "the device has no subgroup operations in fragment shaders";
    const uint32_t need =
        VK_SUBGROUP_FEATURE_VOTE_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
    if ((caps.subgroupOps & need) != need)
        return "the device lacks subgroup vote, arithmetic or ballot operations";
    return {};
}

} // namespace tp::la
