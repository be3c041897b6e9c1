#pragma once
// The few NVML entry points the energy meter calls, declared here because NVML is loaded at run
// time (dlopen of the driver's libnvidia-ml.so.1) and Debian ships no NVML header: signatures as
// in NVIDIA's nvml.h (the _v2 names are the ones that header's macros select).
namespace tp::nvml {

using Return = int; // nvmlReturn_t
constexpr Return kSuccess = 0;
struct DeviceSt;
using Device = DeviceSt*; // nvmlDevice_t
// NVML_DEVICE_UUID_V2_BUFFER_SIZE and NVML_DEVICE_NAME_V2_BUFFER_SIZE.
constexpr unsigned kUuidChars = 96;
constexpr unsigned kNameChars = 96;

using InitFn = Return (*)();                                            // nvmlInit_v2
using ShutdownFn = Return (*)();                                        // nvmlShutdown
using ErrorStringFn = const char* (*)(Return);                          // nvmlErrorString
using DeviceGetCountFn = Return (*)(unsigned* count);                   // nvmlDeviceGetCount_v2
using DeviceGetHandleByIndexFn = Return (*)(unsigned index, Device*);   // nvmlDeviceGetHandleByIndex_v2
using DeviceGetUuidFn = Return (*)(Device, char* uuid, unsigned length); // nvmlDeviceGetUUID
using DeviceGetNameFn = Return (*)(Device, char* name, unsigned length); // nvmlDeviceGetName
// Millijoules since the driver was last loaded (Volta and later).
using DeviceGetTotalEnergyConsumptionFn = Return (*)(Device, unsigned long long* mj);

} // namespace tp::nvml
