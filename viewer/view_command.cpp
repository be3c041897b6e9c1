// triptych view: the interactive viewer (a window), or offscreen with a script (--headless).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include <imgui.h>
#include <CLI/CLI.hpp>

#include "viewer/view_command.h"

#include "core/calibrate/calibration_file.h"
#include "core/camera/camera_path.h"
#include "core/cli/options.h"
#include "core/cli/scene_input.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/view_settings.h"
#include "core/scene/light_motion.h"
#include "viewer/view_loop.h"

namespace tp::view {

void createImGuiContext() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename =
        nullptr; // the layout is the program's, not a file left in the working directory
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
}

void surfaceSize(const ViewerApp& app, uint32_t& width, uint32_t& height) {
    uint32_t sceneW = std::max(app.scene().width, app.const_state().width);
    uint32_t sceneH = std::max(app.scene().height, app.const_state().height + kLegendHeight);
    width = sceneW + app.panelWidth();
    height = std::max(sceneH, 600u);
}

int finish(ViewerApp& app, const GpuContext& ui, const std::string& scriptError) {
    std::vector<std::string> messages = app.stop();
    std::vector<std::string> own = ui.validationMessages();
    messages.insert(messages.end(), own.begin(), own.end());
    if (!scriptError.empty()) {
        std::fprintf(stderr, "triptych: %s\n", scriptError.c_str());
        return 2;
    }
    return cli::validationExit(messages);
}

} // namespace tp::view

namespace tp::cli {
namespace {

struct ViewCommandOptions {
    SceneOptions scene;
    DeviceOptions device;
    ViewOptions view;
    std::map<std::string, std::string> knobs;
    std::string pipelineA, pipelineB = kReferenceRenderer;
    bool headless = false;
    std::string script;
    std::string out = "view_out";
    int frames = 1;
    double waitLimit = 600;
    int quitAfter = 0;
    bool noReference = false;
    std::string calibration; // empty: the passes are not placed
    bool passStatistics = true;
    std::string shareDevice = "auto";
    // As render's and compare's (their reader and parser); the viewer plays them.
    std::string cameraPath;
    uint32_t pathFrames = kDefaultGltfPathFrames;
    std::string lightMotion = "none";
};

std::string firstPipeline() {
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != kReferenceRenderer) return e.name;
    return kReferenceRenderer;
}

// --camera-path / --light-motion, read and checked before any window opens (a bad file is one
// line and exit 2): the path plays from its first view.
void loadPath(const ViewCommandOptions& o, view::LoopSetup& setup) {
    Result<LightMotion> motion = parseLightMotion(o.lightMotion);
    if (!motion) throw UsageError(motion.error());
    setup.viewer.initial.lightMotion = lightMotionToString(*motion);
    setup.viewer.pathFrames = o.pathFrames;
    view::PathPlayer& p = setup.viewer.path;
    if (!o.cameraPath.empty()) {
        Result<std::vector<Camera>> views = readCameraPath(o.cameraPath, o.pathFrames);
        if (!views) throw UsageError(views.error());
        p.views = std::move(*views);
        p.frames = uint32_t(p.views.size());
        p.source = o.cameraPath;
    } else if (motion->mode != LightMotion::Mode::None) {
        p.frames = o.pathFrames; // the lights move at the user's camera
        p.source = "--light-motion";
    }
    p.playing = p.loaded();
}

int runView(ViewCommandOptions& o, const std::string& exe) {
    checkKnobs(o.knobs);
    for (const std::string& p : {o.pipelineA, o.pipelineB})
        if (Result<const RendererEntry*> e = findRenderer(p); !e)
            throw UsageError("--a/--b: " + e.error());
    if (o.headless && o.script.empty())
        throw UsageError("view --headless needs --script FILE (docs/viewer.md)");
    if (o.frames < 1 || o.frames > 1000) throw UsageError("--frames must be between 1 and 1000");
    view::LoopSetup setup;
    if (!o.script.empty()) {
        Result<std::vector<view::ScriptLine>> lines = view::readScript(o.script);
        if (!lines) throw UsageError(lines.error());
        setup.script = std::move(*lines);
        setup.scriptPath = o.script;
        ensureDirectory(o.out);
    }
    (void)generatorOptions(o.scene); // a bad light option is a usage error before any window opens
    loadPath(o, setup);
    view::ViewState& s = setup.viewer.initial;
    s.scene = o.scene;
    if (!view::parseViewResolution(o.view.resolution, s.width, s.height))
        throw UsageError("--res '" + o.view.resolution + "': expected WIDTHxHEIGHT, each side " +
                         std::to_string(view::kViewMinSide) + " to " +
                         std::to_string(view::kViewMaxSide));
    if (Status ok = checkSetting(kMsaaSetting, std::to_string(o.view.msaa)); !ok)
        throw UsageError(ok.error());
    s.msaa = uint32_t(o.view.msaa);
    s.knobs = o.knobs;
    s.pipelineA = o.pipelineA;
    s.pipelineB = o.pipelineB;
    s.reference = !o.noReference;
    setup.viewer.context.device = o.device.device;
    setup.viewer.context.validate = o.device.validate;
    setup.viewer.timedFrames = uint32_t(o.frames);
    setup.viewer.exe = exe;
    setup.viewer.passStatistics = o.passStatistics;
    setup.viewer.shareDevice = o.shareDevice;
    if (!o.calibration.empty()) {
        Result<CeilingFile> cal = readCeilingFile(o.calibration);
        if (!cal) throw UsageError("--calibration: " + cal.error());
        setup.viewer.calibration = std::make_shared<const CeilingFile>(std::move(*cal));
    }
    setup.out = o.out;
    setup.waitLimitSeconds = o.waitLimit;
    setup.quitAfterFrames = o.quitAfter;
    return o.headless ? view::runHeadless(setup) : view::runWindow(setup);
}

// This program's path, for export (it runs `render` and `compare` on the current view).
std::string selfPath(const std::string& argv0) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? argv0 : p.string();
}

} // namespace

CommandRunner addViewCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<ViewCommandOptions>();
    o->pipelineA = firstPipeline();
    CLI::App* cmd =
        app.add_subcommand("view", "Interactive viewer: pipelines side by side, live knobs, "
                                   "difference view, pixel inspector (Dear ImGui)");
    addSceneOptions(*cmd, o->scene);
    addViewOptions(*cmd, o->view);
    addDeviceOptions(*cmd, o->device);
    addKnobOptions(*cmd, o->knobs);
    cmd->add_option("--a", o->pipelineA, "Pipeline left of the divider (A)")->capture_default_str();
    cmd->add_option("--b", o->pipelineB, "Pipeline right of the divider (B)")
        ->capture_default_str();
    cmd->add_flag("--headless", o->headless,
                  "No window: run --script offscreen (screenshots hold the UI)");
    cmd->add_option("--calibration", o->calibration,
                    "A calibration FILE from 'triptych calibrate' of this device: the numbers panel places every "
                    "pass against its ceilings (docs/efficiency.md)");
    addPassStatisticsOption(*cmd, o->passStatistics);
    cmd->add_option("--share-device", o->shareDevice,
                    "Render on the window's own Vulkan device and compose the images where they are "
                    "(no readback to show a view; the hdr and depth are read back only for the "
                    "reference's error, the inspector and the overlays): on, off, or auto = on where "
                    "the device has a second queue for the renderers (a GPU; not lavapipe, whose one "
                    "queue would hold the UI's frames behind each render)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
    cmd->add_option("--camera-path", o->cameraPath,
                    "Play a camera path: a triptych.camera_path/1 JSON file or a glTF file with an "
                    "animated camera, as render and compare read it (docs/camera_paths.md). It "
                    "plays from its first view, one view per render of the pipelines; Space or "
                    "the Camera panel pauses, the slider scrubs")
        ->type_name("FILE");
    cmd->add_option("--path-frames", o->pathFrames,
                    "Views sampled from a glTF camera path, or played at the user's camera when "
                    "only --light-motion is given (a JSON path names its own count)")
        ->check(CLI::Range(1u, kMaxPathFrames))
        ->capture_default_str();
    cmd->add_option("--light-motion", o->lightMotion,
                    "Move the lights as the path plays, seeded by --seed: none, orbit or drift, "
                    "optionally :SPEED in scene units per view (as render and compare)")
        ->capture_default_str();
    cmd->add_option("--script", o->script, "Actions to run, one per line (docs/viewer.md)");
    cmd->add_option("--out", o->out, "Folder for the script's screenshots, stats and exports")
        ->capture_default_str();
    cmd->add_option("--frames", o->frames,
                    "Timed GPU frames per render (the timing graph's samples)")
        ->capture_default_str();
    cmd->add_option("--wait-limit", o->waitLimit, "Seconds a script line may wait before it fails")
        ->capture_default_str();
    cmd->add_option("--quit-after", o->quitAfter, "Window: close after this many frames (0: never)")
        ->capture_default_str();
    cmd->add_flag(
        "--no-reference", o->noReference,
        "Do not render the reference of each view in the background (render it on request: key R)");
    const std::string exe = selfPath(commandLine.empty() ? "triptych" : commandLine.front());
    return [o, cmd, exe]() { return cmd->parsed() ? runView(*o, exe) : -1; };
}

} // namespace tp::cli
