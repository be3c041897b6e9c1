#include "core/energy/rapl_meter.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace tp {
namespace {

namespace fs = std::filesystem;

// RAPL's energy status registers count in steps of about 1 ms (Intel SDM: 976 us).
constexpr double kRaplPeriodMs = 1.0;

struct Domain {
    std::string path; // its energy_uj
    std::string name; // "package-0"
    uint64_t range = 0, last = 0, total = 0;
};

// A sysfs counter's value; error: the file and why it could not be read.
Result<uint64_t> readCounter(const std::string& path) {
    errno = 0;
    std::ifstream in(path);
    uint64_t v = 0;
    if (in >> v) return v;
    const int e = errno;
    return Error{path + ": " + (e ? std::strerror(e) : "not a number")};
}

std::string readName(const fs::path& dir) {
    std::ifstream in(dir / "name");
    std::string name;
    return std::getline(in, name) && !name.empty() ? name : dir.filename().string();
}

// intel-rapl:N, not intel-rapl:N:M (a subdomain, counted inside its package).
bool isPackage(const std::string& name) {
    const std::string prefix = "intel-rapl:";
    return name.rfind(prefix, 0) == 0 && name.size() > prefix.size() &&
           name.find(':', prefix.size()) == std::string::npos;
}

class RaplMeter final : public EnergyMeter {
  public:
    explicit RaplMeter(std::vector<Domain> domains) : domains_(std::move(domains)) {
        for (const Domain& d : domains_)
            device_ += (device_.empty() ? "" : " + ") + d.name;
        device_ = "CPU " + device_ + " (RAPL, every process on the packages)";
    }
    const char* source() const override { return "rapl"; }
    const std::string& device() const override { return device_; }
    double updatePeriodMs() const override { return kRaplPeriodMs; }
    Result<double> joules() override {
        uint64_t uj = 0;
        for (Domain& d : domains_) {
            Result<uint64_t> v = readCounter(d.path);
            if (!v) return Error{v.error()};
            d.total += raplDelta(d.last, *v, d.range);
            d.last = *v;
            uj += d.total;
        }
        return double(uj) * 1e-6;
    }

  private:
    std::vector<Domain> domains_;
    std::string device_;
};

} // namespace

uint64_t raplDelta(uint64_t before, uint64_t after, uint64_t range) {
    if (after >= before) return after - before;
    return range > before ? range - before + after : after; // a range below the value: no wrap known
}

EnergySource openRaplMeter(const std::string& root) {
    const std::string pattern = root + "/intel-rapl:*/energy_uj";
    std::error_code ec;
    std::vector<fs::path> dirs;
    for (const fs::directory_entry& e : fs::directory_iterator(root, ec))
        if (isPackage(e.path().filename().string())) dirs.push_back(e.path());
    if (dirs.empty()) return {nullptr, "no " + pattern + " (no RAPL powercap here: a VM, a container or not an x86 CPU)"};
    std::sort(dirs.begin(), dirs.end());
    std::vector<Domain> domains;
    for (const fs::path& dir : dirs) {
        Domain d{(dir / "energy_uj").string(), readName(dir)};
        Result<uint64_t> now = readCounter(d.path);
        if (!now) return {nullptr, "no readable " + pattern + " (" + now.error() + ")"};
        Result<uint64_t> range = readCounter((dir / "max_energy_range_uj").string());
        if (!range) return {nullptr, "no readable " + pattern + " range (" + range.error() + ")"};
        d.last = *now;
        d.range = *range;
        domains.push_back(std::move(d));
    }
    return {std::make_unique<RaplMeter>(std::move(domains)), ""};
}

} // namespace tp
