#include "core/passes/lights_ubo.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "include/lights_ubo.h"

namespace tp {

LightsUbo::LightsUbo(GpuContext& ctx, const SceneGpu& scene, const std::string& owner,
                     const std::string& name, std::vector<uint32_t> prefix)
    : ctx_(ctx), scene_(scene), prefix_(std::move(prefix)) {
    constexpr VkDeviceSize kBytes = TP_LIGHTS_UBO_CAPACITY * sizeof(gpu::LightGpu);
    const size_t lights = scene_.shadingLights().size();
    active_ = ctx_.isCpuDevice() && lights > 0 && prefix_.size() + lights <= TP_LIGHTS_UBO_CAPACITY &&
              ctx_.properties.limits.maxUniformBufferRange >= kBytes;
    const std::vector<gpu::LightGpu> data = copy();
    buffer_ = createBufferWithData(
        ctx_, data.data(), data.size() * sizeof(gpu::LightGpu), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
        {owner, "", name,
         active_ ? "the lights as a uniform buffer (read by the shading loops: a CPU device)"
                 : "stand-in (the shading loops read the scene's light buffer)"});
}

// The prefix's lights, then every light at its index plus the prefix's length; zeros past them.
// The one-light stand-in (zeros) when the shaders do not read it.
std::vector<gpu::LightGpu> LightsUbo::copy() const {
    if (!active_) return std::vector<gpu::LightGpu>(1, gpu::LightGpu{});
    std::vector<gpu::LightGpu> out(TP_LIGHTS_UBO_CAPACITY, gpu::LightGpu{});
    const std::vector<gpu::LightGpu>& lights = scene_.shadingLights();
    for (size_t k = 0; k < prefix_.size(); ++k)
        out[k] = lights[prefix_[k]];
    std::copy(lights.begin(), lights.end(), out.begin() + ptrdiff_t(prefix_.size()));
    return out;
}

void LightsUbo::update() {
    if (!active_) return;
    const std::vector<gpu::LightGpu> data = copy();
    uploadBufferData(ctx_, buffer_, data.data(), data.size() * sizeof(gpu::LightGpu));
}

} // namespace tp
