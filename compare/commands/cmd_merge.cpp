// triptych merge: the outputs of `sweep --shard K/N` for every K put back together into the
// sweep.csv, sweep.json and sweep.html one unsharded sweep writes: the same rows in the same
// order (by each run's number in the whole sweep, sweep.json's run_index), failed runs kept.
// Shards of different sweeps (another sweep_id_fnv1a64), a shard given twice or missing, and a
// shard whose files disagree are refused with one line before anything is written
// (docs/scale-out.md).
#include <algorithm>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include "compare/commands/commands.h"
#include "compare/commands/sweep.h"
#include "compare/report/report_json.h"
#include "compare/report/sweep_output.h"
#include "core/renderer/renderer.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

struct ShardFiles {
    std::string dir;
    nlohmann::json json;
    std::vector<std::string> csvRows; // sweep.csv's lines after its header, in sweep.json's order
    std::string csvHeader;
};

std::string readFile(const std::string& path) {
    Result<std::string> bytes = readWholeFile(path);
    if (!bytes) throw UsageError("merge: " + bytes.error() + " (a shard that did not finish?)");
    return std::move(*bytes);
}

// sweep.csv's lines. A quoted field holds no newline (the writer quotes only commas and
// quotes), so a line is a row.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream s(text);
    for (std::string line; std::getline(s, line);)
        out.push_back(line);
    return out;
}

ShardFiles readShard(const std::string& dir) {
    ShardFiles f;
    f.dir = dir;
    try {
        f.json = nlohmann::json::parse(readFile(dir + "/sweep.json"));
    } catch (const nlohmann::json::exception& e) {
        throw UsageError("merge: " + dir + "/sweep.json is not JSON: " + e.what());
    }
    std::vector<std::string> csv = lines(readFile(dir + "/sweep.csv"));
    if (csv.empty() || !f.json.contains("runs") || !f.json.contains("shard") ||
        !f.json.contains("sweep_id_fnv1a64"))
        throw UsageError("merge: " + dir + " is not the output of a triptych sweep");
    f.csvHeader = csv.front();
    f.csvRows.assign(csv.begin() + 1, csv.end());
    if (f.csvRows.size() != f.json["runs"].size())
        throw UsageError("merge: " + dir + "'s sweep.csv has " + std::to_string(f.csvRows.size()) +
                         " rows, its sweep.json " + std::to_string(f.json["runs"].size()));
    return f;
}

// One line for shards that are not the N shards of one sweep.
void checkShards(const std::vector<ShardFiles>& shards) {
    const nlohmann::json& first = shards.front().json;
    const std::string id = first["sweep_id_fnv1a64"];
    const uint32_t count = first["shard"]["count"];
    std::map<uint32_t, std::string> seen;
    for (const ShardFiles& s : shards) {
        if (s.json["sweep_id_fnv1a64"] != id)
            throw UsageError("merge: " + s.dir + " is a shard of another sweep (sweep id " +
                             s.json["sweep_id_fnv1a64"].get<std::string>() + ", " +
                             shards.front().dir + " has " + id + ")");
        const uint32_t k = s.json["shard"]["index"];
        if (!seen.emplace(k, s.dir).second)
            throw UsageError("merge: shard " + std::to_string(k) + "/" + std::to_string(count) +
                             " is given twice: " + seen[k] + " and " + s.dir);
    }
    for (uint32_t k = 0; k < count; ++k)
        if (!seen.count(k))
            throw UsageError("merge: shard " + std::to_string(k) + "/" + std::to_string(count) +
                             " is missing (" + std::to_string(shards.size()) + " of " +
                             std::to_string(count) + " given)");
}

// The command line without its --shard K/N: the command the whole sweep is.
nlohmann::json unsharded(const nlohmann::json& commandLine) {
    nlohmann::json out = nlohmann::json::array();
    for (size_t i = 0; i < commandLine.size(); ++i) {
        const std::string a = commandLine[i];
        if (a == "--shard") {
            ++i;
            continue;
        }
        if (a.rfind("--shard=", 0) == 0) continue;
        out.push_back(a);
    }
    return out;
}

// What sweep.html draws of a run, from its sweep.json entry.
SweepRow plotRow(const nlohmann::json& j) {
    SweepRow r;
    r.pipeline = j["pipeline"];
    r.lights = j["lights"];
    r.status = j["status"];
    r.error = j.value("error", "");
    const nlohmann::json& s = j["settings"];
    r.s.width = s["width"];
    r.s.height = s["height"];
    r.s.msaa = s["msaa"];
    // The knobs by name, as text (settingsJson wrote integer knobs as numbers).
    for (const KnobReaders& k : allKnobs())
        if (s.contains(k.knob.key()))
            r.s.knobs[k.knob.name] = s[k.knob.key()].is_string()
                                         ? s[k.knob.key()].get<std::string>()
                                         : s[k.knob.key()].dump();
    if (r.status == "ok") {
        for (const auto& t : j["run"]["timings"])
            if (t["pass"] == "frame") r.frame.medianMs = t["median_ms"];
        r.bytes = j["run"]["memory"]["total_bytes"];
    }
    auto rmse = [](const nlohmann::json& m) {
        return m.contains("rmse") && m["rmse"].is_number() ? m["rmse"].get<double>() : 0.0;
    };
    if (const auto& e = j["error_vs_reference"]; e.is_object()) {
        r.measured = true;
        r.hdr.rmse = rmse(e["hdr"]);
        if (e["flip"].is_object()) {
            r.flip.measured = true;
            r.flip.hdr.mean = e["flip"]["hdr"]["mean"];
        }
    }
    if (j.contains("error_vs_center_reference") && j["error_vs_center_reference"].is_object()) {
        r.measuredCenter = true;
        r.hdrCenter.rmse = rmse(j["error_vs_center_reference"]["hdr"]);
    }
    return r;
}

} // namespace

int runMerge(const std::vector<std::string>& dirs, const std::string& out) {
    std::vector<ShardFiles> shards;
    for (const std::string& d : dirs)
        shards.push_back(readShard(d));
    checkShards(shards);
    struct Row {
        size_t index;
        nlohmann::json json;
        std::string csv;
    };
    std::vector<Row> rows;
    nlohmann::json validation = nlohmann::json::array();
    for (const ShardFiles& s : shards) {
        for (size_t i = 0; i < s.csvRows.size(); ++i)
            rows.push_back({s.json["runs"][i]["run_index"], s.json["runs"][i], s.csvRows[i]});
        for (const auto& v : s.json.value("validation_messages", nlohmann::json::array()))
            validation.push_back(v);
    }
    std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.index < b.index; });
    nlohmann::json header = shards.front().json;
    const size_t runs = header["shard"]["runs"];
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].index != i || rows.size() != runs)
            throw UsageError("merge: the shards hold " + std::to_string(rows.size()) + " runs, " +
                             "not runs 0 to " + std::to_string(runs - 1) + " once each");
    header.erase("runs");
    header["command_line"] = unsharded(header["command_line"]);
    header["command"] = shellJoin(header["command_line"].get<std::vector<std::string>>());
    header["shard"] = {{"index", 0}, {"count", 1}, {"runs", runs}};
    header["validation_messages"] = validation;
    header["sweep_id_fnv1a64"] = sweepId(header); // the whole sweep's, as one process writes it
    header["merged_from"] = dirs;
    nlohmann::json all = nlohmann::json::array();
    std::string csv = shards.front().csvHeader + "\n";
    std::vector<SweepRow> plotRows;
    for (const Row& r : rows) {
        all.push_back(r.json);
        csv += r.csv + "\n";
        plotRows.push_back(plotRow(r.json));
    }
    header["runs"] = all;
    ensureDirectory(out);
    const std::string device = header["device"].value("name", "");
    Status s = writeTextFile(out + "/sweep.html",
                             sweepHtml(plotRows, device, header["command"]));
    if (s) s = writeTextFile(out + "/sweep.json", header.dump(1) + "\n");
    if (s) s = writeTextFile(out + "/sweep.csv", csv); // last: marks the sweep complete
    if (!s) throw UsageError(s.error());
    std::printf("triptych merge: %zu shards, %zu runs; wrote %s/sweep.csv, sweep.json and "
                "sweep.html\n",
                shards.size(), rows.size(), out.c_str());
    return std::any_of(rows.begin(), rows.end(),
                       [](const Row& r) { return r.json["status"] != "ok"; })
               ? 5
               : 0;
}


CommandRunner addMergeCommand(CLI::App& app) {
    auto dirs = std::make_shared<std::vector<std::string>>();
    auto out = std::make_shared<std::string>("sweep");
    CLI::App* cmd = app.add_subcommand(
        "merge",
        "Combine the output folders of 'sweep --shard K/N' (every K of one sweep) into the "
        "sweep.csv, sweep.json and sweep.html of the whole sweep: the same rows in the same "
        "order. Refuses shards of different sweeps, a missing or repeated shard. Exit 0 ok, 2 "
        "bad input, 5 a run failed (kept in the files)");
    cmd->add_option("dirs", *dirs, "The shards' output folders (their --out)")->required();
    cmd->add_option("--out", *out, "Output folder of the merged sweep")->capture_default_str();
    return [dirs, out, cmd]() {
        if (!cmd->parsed()) return -1;
        return runMerge(*dirs, *out);
    };
}

} // namespace tp::cli
