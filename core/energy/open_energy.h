#pragma once
// Which energy counter measures a device's frames: NVML for an NVIDIA GPU, the CPU packages'
// RAPL for a CPU device (lavapipe), none for other devices (each case's reason in one line).
#include <array>
#include <cstdint>
#include <string>

#include "core/energy/energy_meter.h"

namespace tp {

// The device that runs the frames, as the energy sources know it (no Vulkan here).
struct EnergyTarget {
    std::string name;
    bool cpu = false;      // a CPU device: its frames run on the CPU packages
    uint32_t vendorId = 0; // PCI vendor: 0x10de is NVIDIA
    std::array<uint8_t, 16> uuid{}; // VkPhysicalDeviceIDProperties::deviceUUID
};

// Where the sources are read: a test points them at a fake powercap tree or a fake NVML.
struct EnergyPaths {
    std::string powercapRoot;
    std::string nvmlLibrary;
    EnergyPaths();
};

EnergySource openEnergySource(const EnergyTarget& target, const EnergyPaths& paths = {});

} // namespace tp
