#include "core/runner/device_energy.h"

#include "core/gpu/context.h"

namespace tp {

std::shared_ptr<EnergySource> openDeviceEnergy(const GpuContext& ctx, const EnergyPaths& paths) {
    EnergyTarget target;
    target.name = ctx.info.name;
    target.cpu = ctx.isCpuDevice();
    target.vendorId = ctx.info.vendorId;
    target.uuid = ctx.info.uuid;
    return std::make_shared<EnergySource>(openEnergySource(target, paths));
}

} // namespace tp
