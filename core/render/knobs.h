#pragma once
// A renderer's knobs, declared once by the renderer and read by everything else: the CLI
// builds its options, help and checks from them, sweep its axes and CSV columns, the reports
// their settings (and the coming viewer will build its controls from them). A knob declared by several renderers (the tile
// size of the tiled pipelines) must be declared identically; the registry checks that.
#include <cstdint>
#include <map>
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

    // Declarations read as one line each in a pipeline's register.cpp:
    //   Knob::choice("accum", {"fp32", "fp16"}, "...")          default: the first value
    //   Knob::integer("tile-capacity", 1, 65536, 256, "...").fixed()
    static Knob choice(std::string name, std::vector<std::string> values, std::string help);
    static Knob integer(std::string name, uint32_t min, uint32_t max, uint32_t defaultValue, std::string help);
    // An integer from a list (e.g. tile sizes 8, 16, 32); default: `defaultValue`.
    static Knob integerOf(std::string name, std::vector<std::string> values, std::string defaultValue,
                          std::string help);
    Knob& onlyUnderMsaa() { msaaOnly = true; return *this; }
    Knob& fixed() { sweepable = false; return *this; } // one value per sweep

    std::string key() const;         // report.json / sweep.csv name
    // Its value in `values` (knob name -> value), or its default when absent.
    const std::string& valueIn(const std::map<std::string, std::string>& values) const;
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
