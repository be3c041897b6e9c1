#pragma once
// What a pass binds where its shader declares a resource the configuration does not use:
// every declared binding must hold something, and passes that only texelFetch still need a
// sampler in their combined image descriptors.
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "core/gpu/resources.h"

namespace tp {

// A 16-byte device-local storage buffer holding `words` (what a stray read would see; zeros by
// default), in the ledger under `tag` (purpose "stand-in: ..." by convention).
Buffer createStandInBuffer(GpuContext& ctx, const LedgerTag& tag,
                           const std::array<uint32_t, 4>& words = {});

// Nearest filtering, clamped to the edge, no mip levels: for passes that only texelFetch, where
// the filtering is never used. The caller destroys it (vkDestroySampler).
VkSampler createNearestClampSampler(GpuContext& ctx);

} // namespace tp
