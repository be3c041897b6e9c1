// The control panels: pipelines and display mode, knobs (from the schema), view, lights,
// scene, camera. A change edits ViewerApp::state_; the next frame submits what it needs.
#include "viewer/ui_panels.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "core/cli/scene_input.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/renderer.h"
#include "core/renderer/view_settings.h"
#include "viewer/ui_colour.h"
#include "viewer/viewer_app.h"

namespace tp::view {
namespace {

bool pipelineCombo(const char* label, std::string& value) {
    bool changed = false;
    pipelineSwatch(value);
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const RendererEntry& e : registeredRenderers()) {
            pipelineSwatch(e.name);
            if (ImGui::Selectable(e.name.c_str(), e.name == value)) {
                value = e.name;
                changed = true;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.description.c_str());
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool valueCombo(const char* label, std::string& value, const std::vector<std::string>& values) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& v : values)
            if (ImGui::Selectable(v.c_str(), v == value)) {
                value = v;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// One knob's control, from its declaration: a list of values is a combo, a range an integer field.
void knobControl(const Knob& k, std::string& value) {
    if (!k.values.empty()) {
        valueCombo(k.name.c_str(), value, k.values);
    } else {
        // Applied on Enter or a step button: a half-typed number would rebuild the renderer.
        int v = std::atoi(value.c_str());
        if (ImGui::InputInt(k.name.c_str(), &v, 1, 16, ImGuiInputTextFlags_EnterReturnsTrue))
            value = std::to_string(std::clamp<int64_t>(v, k.min, k.max));
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s\nallowed: %s; default %s", k.help.c_str(), k.allowedText().c_str(),
                          k.defaultValue.c_str());
}

// Play, pause and scrub the path (--camera-path / --light-motion, path_player.h).
void pathControls(ViewerApp& app) {
    const PathPlayer& p = app.path();
    if (!p.loaded()) {
        ImGui::TextDisabled("no path playing (--camera-path FILE, --light-motion, or load one)");
        return;
    }
    if (ImGui::Button(p.playing ? "pause (space)" : "play (space)")) app.togglePlay();
    ImGui::SameLine();
    bool loop = p.loop;
    if (ImGui::Checkbox("loop", &loop)) app.setPathLoop(loop);
    int view = int(p.frame);
    if (ImGui::SliderInt("view", &view, 0, int(p.frames) - 1)) app.seekPath(uint32_t(view));
    const std::string& motion = app.const_state().lightMotion;
    ImGui::TextDisabled(
        "%s%s%s", p.views.empty() ? "the camera is yours" : p.source.c_str(),
        motion == "none" ? "" : "; lights: ", motion == "none" ? "" : motion.c_str());
}

} // namespace

void Panels::pipelines(ViewerApp& app) {
    ViewState& s = app.state_;
    if (!ImGui::CollapsingHeader("Pipelines and display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    pipelineCombo("A (left)", s.pipelineA);
    pipelineCombo("B (right)", s.pipelineB);
    int mode = int(s.mode);
    ImGui::RadioButton("split", &mode, int(DisplayMode::Split));
    ImGui::SameLine();
    ImGui::RadioButton("|A - B|", &mode, int(DisplayMode::Difference));
    ImGui::SameLine();
    ImGui::RadioButton("overlay of A", &mode, int(DisplayMode::Overlay));
    if (mode != int(s.mode)) {
        s.mode = DisplayMode(mode);
        app.sceneInputsChanged_ = true;
    }
    float split = s.split;
    if (ImGui::SliderFloat("split", &split, 0.0f, 1.0f, "%.3f")) app.setSplit(split);
    bool flip = s.flip;
    if (ImGui::Checkbox("flip A/B (key F)", &flip)) app.toggleFlip();
    if (s.mode == DisplayMode::Overlay) {
        std::vector<std::string> names;
        if (const Shown* a = app.shownA(); a && a->run)
            for (const DebugImage& d : a->run->debugImages)
                names.push_back(d.name);
        if (names.empty())
            ImGui::TextDisabled("(debug images of A: rendering...)");
        else
            valueCombo("overlay", s.overlay, names);
        if (s.overlay.empty() && !names.empty()) s.overlay = names.front();
    }
}

void Panels::knobs(ViewerApp& app) {
    ViewState& s = app.state_;
    if (!ImGui::CollapsingHeader("Knobs of A and B", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (const KnobReaders& k : allKnobs()) {
        bool read = std::find(k.readers.begin(), k.readers.end(), s.pipelineA) != k.readers.end() ||
                    std::find(k.readers.begin(), k.readers.end(), s.pipelineB) != k.readers.end();
        if (!read) continue;
        // A knob that changes nothing at 1x is greyed there, with the reason.
        const bool disabled = k.knob.msaaOnly && s.msaa == 1;
        ImGui::BeginDisabled(disabled);
        std::string& value = s.knobs[k.knob.name];
        if (value.empty()) value = k.knob.defaultValue;
        knobControl(k.knob, value);
        ImGui::EndDisabled();
        if (disabled)
            ImGui::TextDisabled("  %s changes nothing at 1x: only under MSAA", k.knob.name.c_str());
    }
}

void Panels::view(ViewerApp& app) {
    ViewState& s = app.state_;
    if (!ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) return;
    // MSAA: every count is listed; the device's unsupported ones are greyed with the reason.
    if (ImGui::BeginCombo("MSAA", (std::to_string(s.msaa) + "x").c_str())) {
        for (uint32_t n : kMsaaCounts) {
            const bool supported = (app.sampleCounts_ & n) != 0;
            std::string label = std::to_string(n) + "x" +
                                (supported ? "" : "  (not supported by " + app.deviceName_ + ")");
            ImGuiSelectableFlags flags = supported ? 0 : ImGuiSelectableFlags_Disabled;
            if (ImGui::Selectable(label.c_str(), n == s.msaa, flags)) s.msaa = n;
        }
        ImGui::EndCombo();
    }
    int size[2] = {int(app.draft_.width), int(app.draft_.height)};
    ImGui::InputInt2("resolution", size);
    uint32_t maxDim = std::min<uint32_t>(app.ui_.caps.maxImageDimension2D, kViewMaxSide);
    app.draft_.width = uint32_t(std::clamp(size[0], int(kViewMinSide), int(maxDim)));
    app.draft_.height = uint32_t(std::clamp(size[1], int(kViewMinSide), int(maxDim)));
    ImGui::SameLine();
    if (ImGui::Button("apply##res")) {
        s.width = app.draft_.width;
        s.height = app.draft_.height;
    }
    ImGui::Checkbox("auto exposure", &s.autoExposure);
    ImGui::BeginDisabled(s.autoExposure);
    ImGui::SliderFloat("exposure EV", &s.exposureEv, -16.0f, 16.0f, "%.2f");
    ImGui::EndDisabled();
    ImGui::Checkbox("render the reference in the background", &s.reference);
    if (!s.reference && ImGui::Button("render the reference now")) app.requestReference();
}

void Panels::lights(ViewerApp& app) {
    if (!ImGui::CollapsingHeader("Lights")) return;
    cli::SceneOptions& d = app.draft_.scene;
    ImGui::InputInt("count", &d.lightCount);
    d.lightCount = std::clamp(d.lightCount, 0, 1 << 20);
    int seed = int(d.seed);
    ImGui::InputInt("seed", &seed);
    d.seed = uint64_t(std::max(seed, 0));
    ImGui::InputText("types", &d.lightTypes);
    ImGui::InputText("range MIN,MAX", &d.lightRadius);
    ImGui::InputText("intensity MIN,MAX", &d.lightIntensity);
    if (ImGui::Button("apply##lights")) {
        // Checked here, so a bad value is a message and not a failed render.
        try {
            (void)cli::generatorOptions(d);
            cli::SceneOptions& s = app.state_.scene;
            s.lightCount = d.lightCount, s.seed = d.seed, s.lightTypes = d.lightTypes;
            s.lightRadius = d.lightRadius, s.lightIntensity = d.lightIntensity;
            app.error_.clear();
        } catch (const std::exception& e) {
            app.error_ = e.what();
        }
    }
}

void Panels::scene(ViewerApp& app) {
    if (!ImGui::CollapsingHeader("Scene")) return;
    ImGui::InputText("file or builtin:NAME", &app.draft_.scene.scene);
    if (ImGui::Button("load")) {
        app.state_.scene.scene = app.draft_.scene.scene;
        app.state_.cameraFromScene = true;
    }
    ImGui::Text("%zu triangles, %zu lights", app.triangleCount_, app.lightCount_);
}

void Panels::camera(ViewerApp& app) {
    if (app.path().loaded()) ImGui::SetNextItemOpen(true, ImGuiCond_Once); // its play controls
    if (!ImGui::CollapsingHeader("Camera")) return;
    const Camera& c = app.state_.camera;
    ImGui::Text("eye %.3g %.3g %.3g", c.position.x, c.position.y, c.position.z);
    ImGui::Text("target %.3g %.3g %.3g", c.target.x, c.target.y, c.target.z);
    ImGui::TextDisabled("left drag: orbit; right drag: look; wheel: dolly; WASD/QE: fly");
    if (ImGui::Button("scene camera")) app.resetCamera();
    ImGui::InputText("bookmark", &app.bookmarkPath_);
    if (ImGui::Button("save bookmark")) app.saveBookmark(app.bookmarkPath_);
    ImGui::SameLine();
    if (ImGui::Button("load bookmark")) app.loadBookmark(app.bookmarkPath_);
    // A path by flying: a key per stop, saved for --camera-path (docs/camera_paths.md).
    if (ImGui::Button("add path key")) app.addPathKey();
    ImGui::SameLine();
    ImGui::Text("%zu keys", app.pathKeys());
    ImGui::InputText("path", &app.pathFile_);
    if (ImGui::Button("save path")) app.savePath(app.pathFile_);
    ImGui::SameLine();
    if (ImGui::Button("load and play")) {
        app.loadPath(app.pathFile_);
        if (app.error_.empty()) app.setPlaying(true);
    }
    pathControls(app);
}

void Panels::status(ViewerApp& app) {
    ImGui::Text("%s, UI %.0f frames/s", app.deviceName_.c_str(), ImGui::GetIO().Framerate);
    if (!app.error_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", app.error_.c_str());
        ImGui::PopStyleColor();
    }
    // A camera move ("view") replans nothing: the kept renderers follow it (render_worker.h).
    ImGui::Text("last: %s, %.1f ms, %.1f views/s (scene/lights %.0f ms)",
                app.lastRebuilt_.c_str(), app.lastRenderMs_,
                app.lastRenderMs_ > 0 ? 1000.0 / app.lastRenderMs_ : 0.0, app.lastSceneMs_);
    for (const Shown* s : {app.shownA(), app.shownB()})
        if (s) {
            const double gpu = frameGpuMs(s);
            ImGui::Text("%s: %.1f ms, %s; GPU frame %.2f ms, viewer overhead %.1f ms "
                        "(view update %.2f ms)%s",
                        s->pipeline.c_str(), s->buildMs, s->planned ? "planned" : "followed",
                        gpu, std::max(0.0, s->buildMs - gpu), s->updateMs,
                        s->pipeline == kReferenceRenderer && app.referenceStale()
                            ? " (STALE: another view)"
                            : "");
        }
    if (const PathPlayer& p = app.path(); p.loaded())
        ImGui::Text("path: view %u of %u, %s", p.frame, p.frames, p.playing ? "playing" : "paused");
    if (!app.worker_->idle()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "rendering...");
    if (!app.referenceWorker_->idle())
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "reference rendering in the background...");
    if (!app.composite_.note.empty()) ImGui::TextDisabled("%s", app.composite_.note.c_str());
}

void ViewerApp::drawPanels() {
    ImGuiIO& io = ImGui::GetIO();
    const float width = float(options_.panelWidth);
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - width, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("triptych view", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-150.0f); // room for the knobs' names
    Panels::status(*this);
    Panels::pipelines(*this);
    Panels::knobs(*this);
    Panels::view(*this);
    Panels::inspector(*this);
    Panels::numbers(*this);
    Panels::lights(*this);
    Panels::scene(*this);
    Panels::camera(*this);
    Panels::exporting(*this);
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace tp::view
