#pragma once
// The energy counter of the device a context runs on (core/energy/open_energy.h), opened once
// per command and handed to every run (RunOptions::energy).
#include <memory>

#include "core/energy/energy_meter.h"
#include "core/energy/open_energy.h"

namespace tp {

class GpuContext;

// Never null: a meter, or the one-line reason there is none.
std::shared_ptr<EnergySource> openDeviceEnergy(const GpuContext& ctx, const EnergyPaths& paths = {});

} // namespace tp
