#include "core/passes/materials_ubo.h"

#include <algorithm>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "include/materials_ubo.h"

namespace tp {

// The same 80-byte records, padded with zeros to the block's length.
MaterialsUbo::MaterialsUbo(GpuContext& ctx, const SceneGpu& scene, const std::string& owner,
                           const std::string& name) {
    const std::vector<gpu::MaterialGpu>& materials = scene.materialsGpu();
    constexpr VkDeviceSize kBytes = TP_MATERIALS_UBO_CAPACITY * sizeof(gpu::MaterialGpu);
    active_ = ctx.isCpuDevice() && materials.size() <= TP_MATERIALS_UBO_CAPACITY &&
              ctx.properties.limits.maxUniformBufferRange >= kBytes;
    std::vector<gpu::MaterialGpu> copy(active_ ? TP_MATERIALS_UBO_CAPACITY : 1, gpu::MaterialGpu{});
    if (active_) std::copy(materials.begin(), materials.end(), copy.begin());
    buffer_ = createBufferWithData(
        ctx, copy.data(), copy.size() * sizeof(gpu::MaterialGpu), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
        {owner, "", name,
         active_ ? "the materials as a uniform buffer (read by the fragment passes: a CPU device)"
                 : "stand-in (the fragment passes read the scene's material buffer)"});
}

} // namespace tp
