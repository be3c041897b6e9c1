#include "core/energy/nvml_meter.h"

#include <dlfcn.h>
#include <strings.h>

#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>

#include "core/energy/nvml_api.h"

namespace tp {
namespace {

// NVML's counter moves about every 20-100 ms (it is the driver's sampled power, integrated):
// the worst case, so a window is long enough on every board.
constexpr double kNvmlPeriodMs = 100.0;

// The library and its entry points; unloads (and shuts NVML down, once initialised) when destroyed.
struct NvmlLibrary {
    void* handle = nullptr;
    bool initialised = false;
    nvml::InitFn init = nullptr;
    nvml::ShutdownFn shutdown = nullptr;
    nvml::ErrorStringFn errorString = nullptr;
    nvml::DeviceGetCountFn count = nullptr;
    nvml::DeviceGetHandleByIndexFn handleByIndex = nullptr;
    nvml::DeviceGetUuidFn uuid = nullptr;
    nvml::DeviceGetNameFn name = nullptr;
    nvml::DeviceGetTotalEnergyConsumptionFn energy = nullptr;

    ~NvmlLibrary() {
        if (initialised) shutdown();
        if (handle) dlclose(handle);
    }
    std::string text(nvml::Return r) const {
        const char* s = errorString ? errorString(r) : nullptr;
        return s ? s : "NVML error " + std::to_string(r);
    }
};

// Every entry point by name; the first one missing, or empty when all are there.
std::string bind(NvmlLibrary& l) {
    auto one = [&](auto& fn, const char* name) {
        fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(l.handle, name));
        return fn ? std::string() : std::string(name);
    };
    for (std::string missing :
         {one(l.init, "nvmlInit_v2"), one(l.shutdown, "nvmlShutdown"), one(l.errorString, "nvmlErrorString"),
          one(l.count, "nvmlDeviceGetCount_v2"), one(l.handleByIndex, "nvmlDeviceGetHandleByIndex_v2"),
          one(l.uuid, "nvmlDeviceGetUUID"), one(l.name, "nvmlDeviceGetName"),
          one(l.energy, "nvmlDeviceGetTotalEnergyConsumption")})
        if (!missing.empty()) return missing;
    return {};
}

class NvmlMeter final : public EnergyMeter {
  public:
    NvmlMeter(std::unique_ptr<NvmlLibrary> lib, nvml::Device device, const std::string& name)
        : lib_(std::move(lib)), device_(device), name_(name + " (NVML, the whole board)") {}
    const char* source() const override { return "nvml"; }
    const std::string& device() const override { return name_; }
    double updatePeriodMs() const override { return kNvmlPeriodMs; }
    Result<double> joules() override {
        unsigned long long mj = 0;
        if (nvml::Return r = lib_->energy(device_, &mj); r != nvml::kSuccess)
            return Error{"nvmlDeviceGetTotalEnergyConsumption: " + lib_->text(r)};
        return double(mj) * 1e-3; // 64 bits of millijoules: no wrap in practice
    }

  private:
    std::unique_ptr<NvmlLibrary> lib_;
    nvml::Device device_;
    std::string name_;
};

// The device whose UUID is `want` (compared without case), or null.
nvml::Device findDevice(const NvmlLibrary& l, const std::string& want, unsigned& count) {
    count = 0;
    if (l.count(&count) != nvml::kSuccess) return nullptr;
    for (unsigned i = 0; i < count; ++i) {
        nvml::Device d = nullptr;
        char uuid[nvml::kUuidChars] = {};
        if (l.handleByIndex(i, &d) == nvml::kSuccess && l.uuid(d, uuid, sizeof uuid) == nvml::kSuccess &&
            strcasecmp(uuid, want.c_str()) == 0)
            return d;
    }
    return nullptr;
}

} // namespace

std::string nvmlUuidText(const std::array<uint8_t, 16>& uuid) {
    std::string s = "GPU-";
    char hex[3];
    for (size_t i = 0; i < uuid.size(); ++i) {
        if (i == 4 || i == 6 || i == 8 || i == 10) s += '-';
        std::snprintf(hex, sizeof hex, "%02x", uuid[i]);
        s += hex;
    }
    return s;
}

EnergySource openNvmlMeter(const std::array<uint8_t, 16>& uuid, const std::string& library) {
    auto lib = std::make_unique<NvmlLibrary>();
    lib->handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib->handle) {
        const char* e = dlerror();
        return {nullptr, "no NVML: " + library + " not loadable (" + (e ? e : "?") + ")"};
    }
    if (std::string missing = bind(*lib); !missing.empty())
        return {nullptr, "no NVML: " + library + " has no " + missing};
    if (nvml::Return r = lib->init(); r != nvml::kSuccess)
        return {nullptr, "NVML: nvmlInit_v2 failed (" + lib->text(r) + ")"};
    lib->initialised = true;
    const std::string want = nvmlUuidText(uuid);
    unsigned count = 0;
    nvml::Device device = findDevice(*lib, want, count);
    if (!device)
        return {nullptr, "NVML has no GPU with the Vulkan device's UUID " + want + " (of " + std::to_string(count) +
                             " GPUs)"};
    char name[nvml::kNameChars] = {};
    if (lib->name(device, name, sizeof name) != nvml::kSuccess) std::snprintf(name, sizeof name, "%s", want.c_str());
    unsigned long long mj = 0;
    if (nvml::Return r = lib->energy(device, &mj); r != nvml::kSuccess) // older than Volta: not supported
        return {nullptr, std::string("NVML cannot read the energy of ") + name + " (" + lib->text(r) + ")"};
    return {std::make_unique<NvmlMeter>(std::move(lib), device, name), ""};
}

} // namespace tp
