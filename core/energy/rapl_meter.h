#pragma once
// The CPU packages' energy through Linux powercap (RAPL): ROOT/intel-rapl:N/energy_uj, one
// package domain per N (the intel-rapl:N:M subdomains, cores and uncore, are inside a package's
// count and not added again; AMD's RAPL appears under the same name). For a CPU device such as
// lavapipe, whose frames run on those packages. The count is the whole packages': every process
// on them, not only this one.
#include <cstdint>
#include <string>

#include "core/energy/energy_meter.h"

namespace tp {

constexpr const char* kPowercapRoot = "/sys/class/powercap";

// A meter over every package domain under `root`, or why there is none ("no readable
// ROOT/intel-rapl:*/energy_uj (...)"): absent in most VMs and containers, and readable only by
// root since Linux 5.10.
EnergySource openRaplMeter(const std::string& root = kPowercapRoot);

// Microjoules a counter moved from `before` to `after`; a counter below its previous value wrapped
// at `range` (max_energy_range_uj) once between the readings.
uint64_t raplDelta(uint64_t before, uint64_t after, uint64_t range);

} // namespace tp
