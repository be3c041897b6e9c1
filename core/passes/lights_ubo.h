#pragma once
// The scene's lights again as a uniform buffer (shaders/include/lights_ubo.h says why), for a
// pass's shading loop on a CPU device: Forward+'s shading passes, the tiled lighting of
// deferred and the visibility buffer. Read (active()) on a CPU device when the prefix and every
// light fit TP_LIGHTS_UBO_CAPACITY and the device's uniform range holds them; otherwise a
// one-light stand-in is bound and the shaders read the scene's storage buffer. The shaders
// take slot prefix.size() + k for the scene's light k, and slot i < prefix.size() for light
// prefix[i] (Forward+ puts its directional lights first, so its loop reads no index for them).
// The light count and types are fixed for a plan; positions follow the view (update()).
#include <cstdint>
#include <string>
#include <vector>

#include "core/gpu/resources.h"
#include "include/shared.h"

namespace tp {

class GpuContext;
class SceneGpu;

class LightsUbo {
  public:
    // owner, name: the ledger's line.
    LightsUbo(GpuContext& ctx, const SceneGpu& scene, const std::string& owner,
              const std::string& name, std::vector<uint32_t> prefix = {});
    bool active() const { return active_; }
    VkBuffer buffer() const { return buffer_.buffer; }
    // A new view (Renderer::updateView, between frames): the copy again, when it is read.
    void update();

  private:
    std::vector<gpu::LightGpu> copy() const;
    GpuContext& ctx_;
    const SceneGpu& scene_;
    std::vector<uint32_t> prefix_;
    bool active_ = false;
    Buffer buffer_;
};

} // namespace tp
