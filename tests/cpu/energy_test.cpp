// The energy sources (core/energy, docs/efficiency.md "Energy per frame") without a device: a
// fake powercap tree in a temp folder (package domains summed, subdomains not, a wrapped counter
// unwrapped), a fake NVML library (the GPU picked by the Vulkan UUID), every absent source with
// its one-line reason, and the window around the timed frames with a fake meter.
#include <dlfcn.h>

#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/energy/energy_json.h"
#include "core/energy/energy_text.h"
#include "core/energy/energy_window.h"
#include "core/energy/nvml_meter.h"
#include "core/energy/open_energy.h"
#include "core/energy/rapl_meter.h"
#include "temp_path.h"

using namespace tp;
namespace fs = std::filesystem;

namespace {

constexpr uint64_t kRange = 262143328850; // a common max_energy_range_uj

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text << "\n";
}

void writeDomain(const fs::path& root, const std::string& dir, const std::string& name, uint64_t uj) {
    writeFile(root / dir / "name", name);
    writeFile(root / dir / "energy_uj", std::to_string(uj));
    writeFile(root / dir / "max_energy_range_uj", std::to_string(kRange));
}

bool oneLine(const std::string& s) {
    return !s.empty() && s.find('\n') == std::string::npos;
}

} // namespace

TEST(Energy, RaplDeltaUnwrapsOnce) {
    EXPECT_EQ(raplDelta(100, 350, 1000), 250u);
    EXPECT_EQ(raplDelta(900, 50, 1000), 150u); // wrapped at the range
    EXPECT_EQ(raplDelta(7, 7, 1000), 0u);
}

TEST(Energy, AbsentPowercapGivesAReason) {
    const std::string root = freshDir("energy_none");
    EnergySource s = openRaplMeter(root); // the folder does not even exist
    EXPECT_EQ(s.meter, nullptr);
    EXPECT_TRUE(oneLine(s.why)) << s.why;
    EXPECT_NE(s.why.find("no " + root + "/intel-rapl:*/energy_uj"), std::string::npos) << s.why;
    fs::create_directories(fs::path(root) / "intel-rapl:0"); // a domain without a counter
    s = openRaplMeter(root);
    EXPECT_EQ(s.meter, nullptr);
    EXPECT_NE(s.why.find("no readable"), std::string::npos) << s.why;
    EXPECT_TRUE(oneLine(s.why)) << s.why;
    fs::remove_all(root);
}

TEST(Energy, RaplSumsPackagesAndUnwrapsTheCounter) {
    const fs::path root = freshDir("energy_rapl");
    writeDomain(root, "intel-rapl:0", "package-0", 1000000);
    writeDomain(root, "intel-rapl:0:0", "core", 5); // inside package-0: not added again
    writeDomain(root, "intel-rapl:1", "package-1", kRange - 500000);
    EnergySource s = openRaplMeter(root.string());
    ASSERT_NE(s.meter, nullptr) << s.why;
    EXPECT_STREQ(s.meter->source(), "rapl");
    EXPECT_NE(s.meter->device().find("package-0 + package-1"), std::string::npos) << s.meter->device();
    Result<double> start = s.meter->joules();
    ASSERT_TRUE(start) << start.error();
    writeFile(root / "intel-rapl:0" / "energy_uj", "3000000");   // +2 J
    writeFile(root / "intel-rapl:0:0" / "energy_uj", "9000000"); // ignored
    writeFile(root / "intel-rapl:1" / "energy_uj", "1500000");   // wrapped: +0.5 J +1.5 J
    Result<double> end = s.meter->joules();
    ASSERT_TRUE(end) << end.error();
    EXPECT_NEAR(*end - *start, 4.0, 1e-9);
    fs::remove(root / "intel-rapl:1" / "energy_uj"); // gone mid-run: an error, one line
    Result<double> gone = s.meter->joules();
    EXPECT_FALSE(gone);
    EXPECT_TRUE(oneLine(gone.error())) << gone.error();
    fs::remove_all(root);
}

TEST(Energy, NvmlUuidTextIsNvmlsForm) {
    std::array<uint8_t, 16> uuid{};
    for (size_t i = 0; i < uuid.size(); ++i)
        uuid[i] = uint8_t(i + 1);
    uuid[2] = 0xa3;
    uuid[3] = 0xb4;
    EXPECT_EQ(nvmlUuidText(uuid), "GPU-0102a3b4-0506-0708-090a-0b0c0d0e0f10");
}

TEST(Energy, AbsentNvmlGivesAReason) {
    EnergySource s = openNvmlMeter({}, "libtriptych-no-such-nvml.so.1");
    EXPECT_EQ(s.meter, nullptr);
    EXPECT_NE(s.why.find("not loadable"), std::string::npos) << s.why;
    EXPECT_TRUE(oneLine(s.why)) << s.why;
}

// The fake library's second GPU has the UUID below; its first one cannot read its energy.
TEST(Energy, NvmlPicksTheVulkanDevicesGpuByUuid) {
    void* fake = dlopen(TP_FAKE_NVML, RTLD_NOW | RTLD_LOCAL); // the meter's dlopen shares it
    ASSERT_NE(fake, nullptr) << dlerror();
    auto setEnergy = reinterpret_cast<void (*)(unsigned, unsigned long long)>(dlsym(fake, "fake_nvml_set_energy"));
    auto initialised = reinterpret_cast<int (*)()>(dlsym(fake, "fake_nvml_initialised"));
    ASSERT_TRUE(setEnergy && initialised);
    std::array<uint8_t, 16> uuid = {0x01, 0x02, 0xA3, 0xB4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    setEnergy(1, 5000);
    {
        EnergySource s = openNvmlMeter(uuid, TP_FAKE_NVML);
        ASSERT_NE(s.meter, nullptr) << s.why;
        EXPECT_STREQ(s.meter->source(), "nvml");
        EXPECT_NE(s.meter->device().find("Fake GPU 1"), std::string::npos) << s.meter->device();
        setEnergy(1, 7250); // millijoules
        Result<double> j = s.meter->joules();
        ASSERT_TRUE(j) << j.error();
        EXPECT_NEAR(*j, 7.25, 1e-12);
        EXPECT_EQ(initialised(), 1);
    }
    EXPECT_EQ(initialised(), 0); // the meter shut NVML down
    EnergySource other = openNvmlMeter({}, TP_FAKE_NVML); // GPU-0000...: no energy counter
    EXPECT_EQ(other.meter, nullptr);
    EXPECT_NE(other.why.find("Not Supported"), std::string::npos) << other.why;
    uuid[15] = 0xff;
    EnergySource none = openNvmlMeter(uuid, TP_FAKE_NVML);
    EXPECT_EQ(none.meter, nullptr);
    EXPECT_NE(none.why.find("no GPU with the Vulkan device's UUID GPU-0102a3b4-0506-0708-090a-0b0c0d0e0fff"),
              std::string::npos)
        << none.why;
    EXPECT_EQ(initialised(), 0);
    dlclose(fake);
}

TEST(Energy, SourceFollowsTheDevice) {
    EnergyPaths paths;
    paths.powercapRoot = freshDir("energy_source");
    paths.nvmlLibrary = "libtriptych-no-such-nvml.so.1";
    EnergyTarget cpu{"llvmpipe", true, 0x10005, {}};
    EXPECT_NE(openEnergySource(cpu, paths).why.find("intel-rapl"), std::string::npos);
    EnergyTarget nvidia{"NVIDIA H200", false, 0x10de, {}};
    EXPECT_NE(openEnergySource(nvidia, paths).why.find("NVML"), std::string::npos);
    EnergyTarget other{"Some GPU", false, 0x1002, {}};
    const std::string why = openEnergySource(other, paths).why;
    EXPECT_NE(why.find("0x1002"), std::string::npos) << why;
    EXPECT_TRUE(oneLine(why));
}

namespace {

// A meter whose counter the test sets, moving every `period` ms.
class FakeMeter final : public EnergyMeter {
  public:
    double value = 0, period = 1;
    const char* source() const override { return "rapl"; }
    const std::string& device() const override { return name_; }
    double updatePeriodMs() const override { return period; }
    Result<double> joules() override { return value; }

  private:
    std::string name_ = "fake";
};

} // namespace

TEST(Energy, WindowIsExtendedUntilTheCounterCanMeasureIt) {
    FakeMeter m;
    m.period = 0.5; // a 5 ms window
    EnergyWindow w(&m, "");
    m.value = 10;
    w.begin();
    uint32_t extended = 0;
    while (w.wantsMore(extended)) { // a frame of 1 ms each time: the window grows to 5 ms
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++extended;
    }
    EXPECT_LT(extended, 10u);
    m.value = 13;
    FrameEnergy e = w.end(3 + extended, extended);
    ASSERT_TRUE(e.joulesPerFrame) << e.reason;
    EXPECT_GE(e.windowMs, 5.0);
    EXPECT_NEAR(*e.joulesPerFrame, 3.0 / double(3 + extended), 1e-12);
    EXPECT_EQ(e.frames, 3 + extended);
    const nlohmann::json j = energyJson(e);
    EXPECT_EQ(j["source"], "rapl");
    EXPECT_EQ(j["extended_frames"], extended);
    EXPECT_NE(energyLine(e).find("J/frame"), std::string::npos);
}

TEST(Energy, ShortWindowAndStillCounterAreReasonsNotZeros) {
    FakeMeter m;
    m.period = 1000; // a 10 s window: never reached here
    EnergyWindow shortWindow(&m, "");
    shortWindow.begin();
    m.value = 1;
    FrameEnergy e = shortWindow.end(1, 0);
    EXPECT_FALSE(e.joulesPerFrame);
    EXPECT_NE(e.reason.find("shorter than the 10000 ms"), std::string::npos) << e.reason;
    EXPECT_TRUE(energyJson(e)["joules_per_frame"].is_null());

    m.period = 0.0; // any window will do, but the counter does not move
    EnergyWindow still(&m, "");
    still.begin();
    e = still.end(2, 0);
    EXPECT_FALSE(e.joulesPerFrame);
    EXPECT_NE(e.reason.find("did not move"), std::string::npos) << e.reason;

    EnergyWindow none(nullptr, "no readable counter");
    none.begin();
    EXPECT_FALSE(none.wantsMore(0));
    e = none.end(3, 0);
    EXPECT_EQ(e.reason, "no readable counter");
    const nlohmann::json j = energyJson(e);
    EXPECT_TRUE(j["joules_per_frame"].is_null());
    EXPECT_EQ(j["reason"], "no readable counter");
    EXPECT_FALSE(j.contains("source"));
}
