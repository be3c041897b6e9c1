#include "core/energy/open_energy.h"

#include <cstdio>

#include "core/energy/nvml_meter.h"
#include "core/energy/rapl_meter.h"

namespace tp {

constexpr uint32_t kNvidiaVendor = 0x10de;

EnergyPaths::EnergyPaths() : powercapRoot(kPowercapRoot), nvmlLibrary(kNvmlLibrary) {}

EnergySource openEnergySource(const EnergyTarget& target, const EnergyPaths& paths) {
    if (target.cpu) return openRaplMeter(paths.powercapRoot);
    if (target.vendorId == kNvidiaVendor) return openNvmlMeter(target.uuid, paths.nvmlLibrary);
    char vendor[16];
    std::snprintf(vendor, sizeof vendor, "0x%04x", target.vendorId);
    return {nullptr, "no energy counter read for " + target.name + " (vendor " + vendor +
                         "): NVML reads NVIDIA GPUs, RAPL a CPU device's packages"};
}

} // namespace tp
