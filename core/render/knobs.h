#pragma once
// A renderer's knobs, declared once by the renderer and read by everything else: the CLI
// builds its options, help and checks from them, sweep its axes and CSV columns, the reports
// their settings, the viewer its controls. A knob declared by several renderers (the tile
// size of the tiled pipelines) must be declared identically; the registry checks that.
#include <cstdint>
#include <string>
#include <vector>

#include "core/render/settings.h"
#include "core/util/result.h"

namespace tp {

struct Knob {
    enum class Kind { Choice, Integer };
    std::string name;                // option --NAME; report.json and sweep.csv key NAME with '-' -> '_'
    Kind kind = Kind::Choice;
    std::vector<std::string> values; // allowed values (Choice; Integer: empty = any in [min, max])
    uint32_t min = 0, max = 0;       // Integer: inclusive range
    std::string defaultValue;
    std::string help;                // one line: what it does (the CLI adds values and default)
    bool msaaOnly = false;           // changes nothing at 1x (sweep runs one value there)
    bool sweepable = true;           // sweep may take a list of values

    std::string key() const;         // report.json / sweep.csv name
    std::string allowedText() const; // "8, 16, 32" or "1 to 65536"
    // One line naming the knob and its allowed values when `value` is not allowed.
    Status check(const std::string& value) const;
    bool operator==(const Knob&) const = default;
};

using KnobSchema = std::vector<Knob>;

// Checks every knob of `schema` present in `s`, fills in the missing ones with their
// defaults. Error: the first bad value, one line.
Status resolveKnobs(const KnobSchema& schema, RenderSettings& s);

} // namespace tp
