#pragma once
// An NVIDIA GPU's energy from NVML's total-energy counter (millijoules since the driver loaded),
// with NVML loaded at run time: a build needs no NVIDIA package, a machine without the driver
// gets a reason. The GPU is the one whose NVML UUID ("GPU-xxxxxxxx-xxxx-...") is the Vulkan
// device's deviceUUID, so the meter reads the card that runs the frames. The count is the whole
// board's, idle power included.
#include <array>
#include <cstdint>
#include <string>

#include "core/energy/energy_meter.h"

namespace tp {

constexpr const char* kNvmlLibrary = "libnvidia-ml.so.1";

// A meter of the GPU with this UUID, or why there is none (the library absent, no GPU of that
// UUID, the counter not supported).
EnergySource openNvmlMeter(const std::array<uint8_t, 16>& uuid, const std::string& library = kNvmlLibrary);

// NVML's text of a UUID: "GPU-" and the 16 bytes as 8-4-4-4-12 lower-case hex digits.
std::string nvmlUuidText(const std::array<uint8_t, 16>& uuid);

} // namespace tp
