#pragma once
// The scene's materials again as a uniform buffer (shaders/include/materials_ubo.h says why),
// for a fragment pass on a CPU device: Forward+'s shading passes and deferred's G-buffer. Read
// (active()) on a CPU device when every material fits TP_MATERIALS_UBO_CAPACITY and the
// device's uniform range holds them; otherwise a one-material stand-in is bound and the shaders
// read the scene's storage buffer. Slot k holds material k; materials do not change in a plan.
#include <string>

#include "core/gpu/resources.h"

namespace tp {

class GpuContext;
class SceneGpu;

class MaterialsUbo {
  public:
    // owner, name: the ledger's line.
    MaterialsUbo(GpuContext& ctx, const SceneGpu& scene, const std::string& owner,
                 const std::string& name);
    bool active() const { return active_; }
    VkBuffer buffer() const { return buffer_.buffer; }

  private:
    bool active_ = false;
    Buffer buffer_;
};

} // namespace tp
