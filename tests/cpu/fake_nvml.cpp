// A stand-in for the driver's libnvidia-ml.so.1, built as its own shared library for the energy
// tests (energy_test.cpp): two GPUs with fixed UUIDs, the second one's energy counter set by the
// test through fake_nvml_set_energy. Only the entry points core/energy/nvml_meter.cpp binds.
#include <cstdio>
#include <cstring>

namespace {

struct FakeDevice {
    const char* uuid;
    const char* name;
    unsigned long long mj;
    int energyReturn; // 0 success, 3 NVML_ERROR_NOT_SUPPORTED
};

FakeDevice devices[2] = {{"GPU-00000000-0000-0000-0000-000000000000", "Fake GPU 0", 0, 3},
                         {"GPU-0102a3b4-0506-0708-090a-0b0c0d0e0f10", "Fake GPU 1", 0, 0}};
int initialised = 0;

} // namespace

extern "C" {

void fake_nvml_set_energy(unsigned index, unsigned long long mj) { devices[index].mj = mj; }
int fake_nvml_initialised() { return initialised; }

int nvmlInit_v2() { ++initialised; return 0; }
int nvmlShutdown() { --initialised; return 0; }
const char* nvmlErrorString(int r) { return r == 3 ? "Not Supported" : "Unknown Error"; }
int nvmlDeviceGetCount_v2(unsigned* count) { *count = 2; return 0; }
int nvmlDeviceGetHandleByIndex_v2(unsigned index, void** device) {
    if (index >= 2) return 2; // NVML_ERROR_INVALID_ARGUMENT
    *device = &devices[index];
    return 0;
}
int nvmlDeviceGetUUID(void* device, char* uuid, unsigned length) {
    std::snprintf(uuid, length, "%s", static_cast<FakeDevice*>(device)->uuid);
    return 0;
}
int nvmlDeviceGetName(void* device, char* name, unsigned length) {
    std::snprintf(name, length, "%s", static_cast<FakeDevice*>(device)->name);
    return 0;
}
int nvmlDeviceGetTotalEnergyConsumption(void* device, unsigned long long* mj) {
    const FakeDevice* d = static_cast<FakeDevice*>(device);
    *mj = d->mj;
    return d->energyReturn;
}

} // extern "C"
