#pragma once
// The values a user sets for a render, beside the scene: the sample count and every knob of
// the registered pipelines. Their allowed values are declared here (MSAA) and in the knob
// schemas (core/renderer/knobs.h); every entry point checks a value through checkSetting: the
// commands (compare, render, sweep, stress, info, view) and the viewer's script and panels.
#include <array>
#include <cstdint>
#include <string>

#include "core/util/result.h"

namespace tp {

// Samples per pixel a render may ask for; a device may support fewer (checkSampleCount).
inline constexpr std::array<uint32_t, 4> kMsaaCounts = {1, 2, 4, 8};

// The setting name of the sample count (`--msaa`, the script's `msaa`); every other name is a
// knob's.
inline constexpr const char* kMsaaSetting = "msaa";

// One user value for the setting `name` (kMsaaSetting or a registered knob). Error, one line:
//   "--msaa 3: must be 1, 2, 4 or 8"
//   "--tile '12': allowed values are 8, 16, 32"      (Knob::check)
//   "no pipeline has a knob 'NAME'"
Status checkSetting(const std::string& name, const std::string& value);

// WIDTHxHEIGHT, digits only (sscanf's %u would take "-8", " 8" and wrap 2^32+8 to 8); each
// side at most 9 digits. The bounds are the caller's (the device's limit, the viewer's).
bool parseResolution(const std::string& text, uint32_t& width, uint32_t& height);

} // namespace tp
