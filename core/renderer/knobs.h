#pragma once
// A renderer's knobs, declared once by the renderer and read by everything else: the CLI
// builds its options, help and checks from them, sweep its axes and CSV columns, the reports
// their settings, the viewer its controls. A knob declared by several renderers (the tile
// size of the tiled pipelines) must be declared identically; the registry checks that.
//
// Passes and renderers never read a knob as text: a knob is declared as a ChoiceKnob<Enum>
// or an IntegerKnob (below), whose knob() goes into the schema and whose in(settings) gives
// the typed value; each pipeline turns RenderSettings into its own typed settings struct once,
// in its factory (docs/architecture.md: "Typed settings").
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/renderer/settings.h"
#include "core/util/result.h"

namespace tp {

struct Knob {
    enum class Kind { Choice, Integer };
    std::string name; // option --NAME; report.json and sweep.csv key NAME with '-' -> '_'
    Kind kind = Kind::Choice;
    std::vector<std::string> values; // allowed values (Choice; Integer: empty = any in [min, max])
    uint32_t min = 0, max = 0;       // Integer: inclusive range
    std::string defaultValue;
    std::string help;      // one line: what it does (the CLI adds values and default)
    bool msaaOnly = false; // changes nothing at 1x (sweep runs one value there)
    bool sweepable = true; // sweep may take a list of values

    // Declarations read as one line each in a pipeline's register.cpp:
    //   Knob::choice("accum", {"fp32", "fp16"}, "...")          default: the first value
    //   Knob::integer("tile-capacity", 1, 65536, 256, "...").fixed()
    static Knob choice(std::string name, std::vector<std::string> values, std::string help);
    static Knob integer(std::string name, uint32_t min, uint32_t max, uint32_t defaultValue,
                        std::string help);
    // An integer from a list (e.g. tile sizes 8, 16, 32); default: `defaultValue`.
    static Knob integerOf(std::string name, std::vector<std::string> values,
                          std::string defaultValue, std::string help);
    Knob& onlyUnderMsaa() {
        msaaOnly = true;
        return *this;
    }
    Knob& fixed() {
        sweepable = false;
        return *this;
    } // one value per sweep

    std::string key() const; // report.json / sweep.csv name
    // Its value in `values` (knob name -> value), or its default when absent.
    const std::string& valueIn(const std::map<std::string, std::string>& values) const;
    std::string allowedText() const; // "8, 16, 32" or "1 to 65536"
    // One line naming the knob and its allowed values when `value` is not allowed.
    Status check(const std::string& value) const;
    bool operator==(const Knob&) const = default;
};

using KnobSchema = std::vector<Knob>;

// Thrown by ChoiceKnob::in for text that is none of its values: unreachable after
// resolveKnobs, so a programming error (RendererError, one line).
[[noreturn]] void throwNotAValue(const Knob& knob, const std::string& value);

// A choice knob bound to an enum: the values' text and their enum values are listed once,
// side by side, so a misspelt value does not compile and nothing compares text.
//   const ChoiceKnob<Layout> lists{"light-lists", {{Layout::Compact, "compact"}, ...}, "help"};
//   schema: lists.knob()          read: lists.in(settings) == Layout::Compact
template <class E> class ChoiceKnob {
  public:
    ChoiceKnob(std::string name, std::vector<std::pair<E, std::string>> values, std::string help)
        : values_(std::move(values)) {
        std::vector<std::string> texts;
        for (const auto& v : values_)
            texts.push_back(v.second);
        knob_ = Knob::choice(std::move(name), std::move(texts), std::move(help));
    }
    ChoiceKnob&& onlyUnderMsaa() && {
        knob_.onlyUnderMsaa();
        return std::move(*this);
    }
    ChoiceKnob&& fixed() && {
        knob_.fixed();
        return std::move(*this);
    }
    const Knob& knob() const { return knob_; }
    // The value `s` holds (its default filled in by resolveKnobs).
    E in(const RenderSettings& s) const { return of(s.text(knob_.name)); }
    // The value of a knob other renderers declare, as `s` carries it (its default where it
    // does not): for a renderer that follows their setting without taking the knob as its own
    // (the reference's shadow maps follow the pipelines' --shadow-raster).
    E carriedIn(const RenderSettings& s) const { return of(knob_.valueIn(s.knobs)); }
    // The text of `e`, for a report line ("--light-bin auto resolved to cpu").
    const std::string& text(E e) const {
        for (const auto& v : values_)
            if (v.first == e) return v.second;
        throwNotAValue(knob_, "?");
    }

  private:
    E of(const std::string& text) const {
        for (const auto& v : values_)
            if (v.second == text) return v.first;
        throwNotAValue(knob_, text);
    }
    Knob knob_;
    std::vector<std::pair<E, std::string>> values_;
};

// An integer knob (a range or a list of allowed values), read as a number.
class IntegerKnob {
  public:
    explicit IntegerKnob(Knob knob) : knob_(std::move(knob)) {}
    IntegerKnob&& fixed() && {
        knob_.fixed();
        return std::move(*this);
    }
    const Knob& knob() const { return knob_; }
    uint32_t in(const RenderSettings& s) const { return s.integer(knob_.name); }

  private:
    Knob knob_;
};

// Checks every knob of `schema` present in `s`, fills in the missing ones with their
// defaults. Error: the first bad value, one line.
Status resolveKnobs(const KnobSchema& schema, RenderSettings& s);

} // namespace tp
