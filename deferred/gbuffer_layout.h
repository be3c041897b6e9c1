#pragma once
// The G-buffer layout, planned from SceneFeatures and --gbuffer before anything is
// allocated, so the ledger can be checked against it (bytes per pixel per sample).
//   compact: base colour + occlusion RGBA8_SRGB (occlusion in alpha, stored linearly),
//            octahedral normal RG16_SNORM (see shaders/include/gbuffer_encoding.h for why
//            SNORM), roughness/metallic RG8_UNORM, emissive in a packed HDR format only when
//            something emits (B10G11R11_UFLOAT if the device renders to it, else RGBA16F),
//            D32 depth; position is reconstructed from depth.
//   wide:    the same channels in float32 (normal as xyz), so G-buffer quantization can be
//            told apart from every other error.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/scene/scene.h"
#include "deferred/def_settings.h"

namespace tp {

class GpuContext;

struct GBufferTarget {
    std::string name; // graph/ledger name
    VkFormat format;
    std::string purpose;
};

struct GBufferLayout {
    bool wide = false;
    bool emissive = false;
    uint32_t samples = 1;
    std::vector<GBufferTarget> colors; // base, normal, rough_metal, [emissive] = locations 0..3
    VkFormat depth = VK_FORMAT_D32_SFLOAT;
    // Bytes one sample of the G-buffer takes: every colour target plus depth.
    uint32_t bytesPerSample() const;
};

GBufferLayout planGBufferLayout(GpuContext& ctx, const SceneFeatures& features,
                                def::GBuffer gbuffer, uint32_t samples);

} // namespace tp
