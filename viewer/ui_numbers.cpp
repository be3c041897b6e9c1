// The live numbers (per-pass GPU times over the last frames, memory ledger, counters, error
// against the reference), the pixel inspector and export.
#include <algorithm>
#include <cmath>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/energy/energy_text.h"
#include "core/reference/reference_renderer.h"
#include "viewer/live_numbers.h"
#include "viewer/ui_colour.h"
#include "viewer/ui_panels.h"
#include "viewer/viewer_app.h"

namespace tp::view {
namespace {

struct Spread {
    double median = 0, min = 0, max = 0;
};

Spread spreadOf(const std::deque<double>& values) {
    std::vector<double> v(values.begin(), values.end());
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    return {v[v.size() / 2], v.front(), v.back()};
}

// The last render's binding ceiling of `pass` and how close it came ("frame": the passes at
// their ceilings against the frame); empty without a calibration.
std::string ceilingText(const RunResult& run, const std::string& pass) {
    if (!run.efficiency) return {};
    char text[96];
    if (pass == "frame") {
        std::snprintf(text, sizeof text, "passes at ceilings: %.0f%%", run.efficiency->percent);
        return text;
    }
    const PassEfficiency* p = run.efficiency->placed(pass);
    if (!p) return {};
    std::snprintf(text, sizeof text, "%.0f%% of %s", p->percent, p->bound.ceiling.c_str());
    return text;
}

void timingGraph(const std::string& pipeline, const TimingHistory& h, const std::string& device,
                 const RunResult& run) {
    pipelineSwatch(pipeline);
    ImGui::Text("%s: GPU ms over the last %zu renders on %s", pipeline.c_str(),
                h.passes.count("frame") ? h.passes.at("frame").size() : size_t(0), device.c_str());
    if (ImGui::BeginTable(("timing" + pipeline).c_str(), 5,
                          ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
        for (const char* c : {"pass", "median", "min", "max", "binding ceiling (last)"})
            ImGui::TableSetupColumn(c);
        ImGui::TableHeadersRow();
        for (const std::string& name : h.order) {
            Spread s = spreadOf(h.passes.at(name));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            for (double v : {s.median, s.min, s.max}) {
                ImGui::TableNextColumn();
                ImGui::Text("%.3f", v);
            }
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(ceilingText(run, name).c_str());
        }
        ImGui::EndTable();
    }
    // The last render's energy per frame: its timed frames only (--frames), so a counter that
    // moves every 100 ms needs a second of them (docs/efficiency.md).
    ImGui::TextWrapped("%s", energyLine(run.energy).c_str());
    if (!run.statisticsCollected) ImGui::TextWrapped("pipeline statistics off: %s", run.statisticsWhy.c_str());
    if (h.passes.count("frame")) {
        std::vector<float> values(h.passes.at("frame").begin(), h.passes.at("frame").end());
        ImGui::PushStyleColor(ImGuiCol_PlotLines, pipelineImColour(pipeline));
        ImGui::PlotLines(("frame ms##" + pipeline).c_str(), values.data(), int(values.size()), 0,
                         nullptr, 0.0f, FLT_MAX, ImVec2(0, 48));
        ImGui::PopStyleColor();
    }
}

void ledgerTable(const char* id, const std::vector<LedgerEntry>& entries) {
    uint64_t total = 0;
    for (const LedgerEntry& e : entries)
        total += e.bytes;
    ImGui::Text("%s: %.2f MiB", id, double(total) / (1 << 20));
    if (!ImGui::BeginTable(id, 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp))
        return;
    for (const char* c : {"pass", "resource", "KiB"})
        ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (const LedgerEntry& e : entries) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(e.tag.pass.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(e.tag.name.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.tag.purpose.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%.1f", double(e.bytes) / 1024.0);
    }
    ImGui::EndTable();
}

void errorLine(const char* what, const std::optional<ErrorReport>& e) {
    if (e) ImGui::Text("%s: RMSE %.4g, PSNR %.2f dB, max %.3g", what, e->rmse, e->psnr, e->maxAbs);
}

// The last error against a reference stays on screen while the view moves on, marked stale and
// naming its view, so a user flying or playing a path still sees where the error stood.
void errorAgainstReference(const ViewerApp& app) {
    if (app.errorVsReference()) return; // fresh: shown by the caller
    const std::optional<KeptError>& kept = app.keptError();
    if (!kept) {
        ImGui::TextDisabled(app.referenceStale() ? "A vs reference: no reference of this view yet"
                                                 : "A vs reference: waiting for A of this view");
        return;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
    ImGui::TextWrapped("STALE: of %s (the reference of this view is not done)", kept->view.c_str());
    errorLine("A vs reference, linear", kept->hdr);
    errorLine("A vs reference, tonemapped", kept->display);
    ImGui::PopStyleColor();
}

// Frames per second and GPU memory, live: what the user of an interactive tool watches.
void liveLine(const ViewerApp& app, const Shown& s) {
    const LiveMemory m = liveMemory(app, s);
    pipelineSwatch(s.pipeline);
    if (const TimingHistory* h = app.history(s.pipeline)) {
        const LiveRate r = liveRate(*h);
        ImGui::Text("%s: %.1f views/s shown (render %.1f ms), GPU %.1f frames/s (%.2f ms)",
                    s.pipeline.c_str(), r.shownFps(), r.wallMs, r.gpuFps(), r.gpuMs);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("medians over the last %zu renders: a render's wall time (its "
                              "update, frames and readback) and its GPU frame",
                              r.renders);
    }
    ImGui::Text("  GPU memory %.2f MiB (its own %.2f + the shared scene %.2f)",
                double(m.total()) / (1 << 20), double(m.pipeline) / (1 << 20),
                double(m.scene) / (1 << 20));
}

} // namespace

void Panels::numbers(ViewerApp& app) {
    if (!ImGui::CollapsingHeader("Numbers")) return;
    const Shown* a = app.shownA();
    if (app.errorVsReference_) {
        errorLine("A vs reference, linear", app.errorVsReference_);
        errorLine("A vs reference, tonemapped", app.errorVsReferenceDisplay_);
    } else {
        errorAgainstReference(app);
    }
    if (const auto& cal = app.options_.calibration; cal && !app.deviceName_.empty() && cal->device != app.deviceName_)
        ImGui::TextDisabled("--calibration %s is of %s, not %s: passes not placed", cal->path.c_str(),
                            cal->device.c_str(), app.deviceName_.c_str());
    else if (cal && a && a->run && !a->run->efficiency)
        ImGui::TextDisabled("--calibration %s: of another driver (%s): passes not placed", cal->path.c_str(),
                            cal->driver.c_str());
    for (const Shown* s : {a, app.shownB()}) {
        if (!s || !s->run) continue;
        liveLine(app, *s);
        if (app.history_.count(s->pipeline))
            timingGraph(s->pipeline, app.history_.at(s->pipeline), app.deviceName_, *s->run);
        for (const auto& [name, value] : s->run->stats.counters)
            ImGui::Text("  %s: %.6g", name.c_str(), value);
        ledgerTable(("memory of " + s->pipeline).c_str(), s->run->memory);
        if (s == app.shownB()) break;
    }
    ledgerTable("memory of the scene (shared)", app.sceneMemory_);
}

void Panels::inspector(ViewerApp& app) {
    if (!ImGui::CollapsingHeader("Pixel under the cursor", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Inspection& i = app.inspection_;
    if (!i.valid) {
        ImGui::TextDisabled("(move the cursor over the image)");
        return;
    }
    ImGui::Text("pixel %u, %u", i.x, i.y);
    ImGui::Text("A %.5g %.5g %.5g", i.a[0], i.a[1], i.a[2]);
    ImGui::Text("B %.5g %.5g %.5g", i.b[0], i.b[1], i.b[2]);
    ImGui::Text("A-B %.5g %.5g %.5g", i.a[0] - i.b[0], i.a[1] - i.b[1], i.a[2] - i.b[2]);
    if (!i.surface) {
        ImGui::TextDisabled("(no surface: the sky)");
        return;
    }
    // The lights every pipeline must shade here; a tile's list may hold more (its conservatism).
    std::string list;
    for (size_t k = 0; k < i.lights.size() && k < 12; ++k)
        list += (k ? ", " : "") + std::to_string(i.lights[k]);
    if (i.lights.size() > 12) list += ", ...";
    ImGui::TextWrapped("lights reaching this surface: %zu%s%s", i.lights.size(),
                       list.empty() ? "" : ": ", list.c_str());
}

void Panels::exporting(ViewerApp& app) {
    if (!ImGui::CollapsingHeader("Export")) return;
    ImGui::InputText("folder", &app.exportDir_);
    ImGui::BeginDisabled(app.exporter_.busy());
    if (ImGui::Button("render A and compare A, B")) app.startExport(app.exportDir_);
    ImGui::EndDisabled();
    std::string status = app.exporter_.status();
    if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
}

} // namespace tp::view
