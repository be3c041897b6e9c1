#pragma once
// Where binned culling's candidate runs are built, declared once here (like --light-cull) so
// that Forward+ and deferred share one option. Meaningful only under --light-cull binned.
#include <string>

#include "core/render/knobs.h"

namespace tp {
class GpuContext;
}

namespace tp::la {

// --light-bin auto|cpu|gpu. cpu: la::binLights, once per configuration (light_bins.h);
// gpu: the light_binning compute pass every frame (gpu_binning.h), after one plan-time run
// that sizes the buffers; auto (default): cpu on a CPU device (lavapipe: the "GPU" is the
// same cores and the serial scatter is cheapest), gpu otherwise.
Knob lightBinKnob();

// The knob's value resolved on `ctx`: "cpu" or "gpu". A run reports it (counter
// light_binning_on_gpu), so two runs of one command on one device report the same.
std::string resolveLightBin(const GpuContext& ctx, const std::string& value);

} // namespace tp::la
