#pragma once
// The one Renderer interface every pipeline (and the reference) implements, and the
// name -> factory registry the CLI loops over.
//
// Contract:
//   1. The factory gets the scene (already on the GPU), its SceneFeatures and the settings.
//   2. plan(graph) declares every pass and resource (format, size, usage) in the frame graph
//      and exports the standard outputs "hdr" (linear RGBA float, single-sample) and "depth"
//      (D32, reverse-Z, single-sample). It records nothing yet.
//   3. After the graph is compiled (resources exist), prepare(graph) creates pipelines and
//      descriptor sets that point at the graph's resources.
//   4. The pass callbacks given to the graph record the work; the graph adds barriers and
//      timestamps. The same recording is submitted for every frame.
//   5. After the timed frames, collectStats(graph) may read back counters; stats() reports
//      them, and leftOut() what the renderer did not build for this scene and why.
//   6. Plan once, render many views (RendererSession, core/runner/render_session.h): between
//      frames the camera and the lights' positions may change (SceneGpu holds the new ones; the
//      light count and the scene do not change). updateView(graph) then recomputes whatever the
//      renderer derived from them into what plan() sized, and the pass callbacks are recorded
//      again. It returns false when the new view does not fit (a list outgrew the capacity
//      plan() gave it: counted, never silent) or the renderer cannot update; the session then
//      plans it again and counts the replan. The default is false: a renderer that bakes the
//      view is planned again for every view, as before.
//   7. A capacity sized from what views were seen to need (not from a bound that cannot be
//      exceeded) is checked after each view's frames: overflowed(graph) reads the renderer's
//      own counters and says whether this view dropped anything. The session then plans the
//      renderer again with RenderSettings::capacities holding capacityHints() (the needs it
//      measured), renders the view again and counts the replan: an image with a dropped
//      element is never kept. The default: nothing is sized that way.
// Nothing downstream asks which renderer ran.
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image/image.h"
#include "core/renderer/error_model.h"
#include "core/renderer/knobs.h"
#include "core/renderer/settings.h"
#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

class GpuContext;
class SceneGpu;
class FrameGraph;

// Thrown by a renderer's constructor, plan() or prepare() when this configuration cannot
// be built (e.g. a buffer beyond maxStorageBufferRange); runRenderer turns it into an Error
// (one line for the user) instead of a crash.
class RendererError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct LeftOut {
    std::string what;
    std::string why;
};

// A debug output (lights-per-tile heat map, G-buffer channel, edge mask, ...), produced only
// when settings.debug is set. display = true: already display-space [0,1] for a PNG.
struct DebugImage {
    std::string name;
    ImageRGBA image;
    bool display = true;
};

// The light evaluations one pass makes (docs/efficiency.md, "Placing a pass: what is counted"):
// `perItem` lights per item of `base`, its fragment-shader invocations (counted by the device) or
// the pixels that hold geometry (from the depth image). Counted from the renderer's own counters.
// Base::Items: `items` given by the renderer itself (e.g. the MSAA edge samples a compute pass
// shades beside its pixels). Several entries of one pass add up.
struct PassLightWork {
    enum class Base { Fragments, CoveredPixels, Items };
    std::string pass;
    Base base = Base::Fragments;
    double perItem = 0;
    bool exact = false; // false: an estimate (a mean over tiles or clusters, each weighted alike)
    std::string how;    // one line: where perItem comes from
    double items = 0;   // Base::Items only
};

// A pass's other counted work (docs/efficiency.md, "Placing a pass: what is counted"), per item
// of `base` as PassLightWork: texture fetches of its materials, atomics, light-vs-tile tests.
// Counted as lower bounds: what the pass cannot avoid doing (exact = the count itself is exact).
struct PassOpWork {
    // Triangles: set up and rasterized in a compute pass (the visibility buffer's compute
    // rasterizer). BytesRead, BytesWritten: buffer bytes a pass moves outside the frame graph's
    // declared uses (the GPU binning's runs, in its consumer's buffer), added to its memory work.
    // Draws: draw commands a graphics pass issues (direct, or each of an indirect call's).
    enum class Kind { TextureFetches, GlobalAtomics, SharedAtomics, TileTests, Triangles, BytesRead,
                      BytesWritten, Draws };
    std::string pass;
    Kind kind = Kind::TextureFetches;
    PassLightWork::Base base = PassLightWork::Base::Fragments;
    double perItem = 0;
    bool exact = false;
    std::string how;
    double items = 0; // Base::Items only
};

struct RendererStats {
    std::vector<std::pair<std::string, double>> counters; // e.g. lights_dropped, draws
    std::vector<LeftOut> leftOut;
    std::vector<PassLightWork> lightWork;
    std::vector<PassOpWork> opWork;
    double counter(const std::string& name, double fallback = 0) const {
        for (const auto& [k, v] : counters)
            if (k == name) return v;
        return fallback;
    }
};

class Renderer {
  public:
    virtual ~Renderer() = default;
    virtual void plan(FrameGraph& graph) = 0;
    virtual void prepare(FrameGraph& graph) = 0;
    virtual bool updateView(FrameGraph&) { return false; }
    virtual void collectStats(FrameGraph&) {}
    virtual bool overflowed(FrameGraph&) { return false; }
    virtual std::map<std::string, uint64_t> capacityHints() const { return {}; }
    // Read back after the frames when settings.debug is set (see DebugImage).
    virtual std::vector<DebugImage> debugImages(FrameGraph&) { return {}; }
    virtual RendererStats stats() const = 0;
};

struct RendererCreateInfo {
    GpuContext& ctx;
    SceneGpu& scene;
    SceneFeatures features;
    RenderSettings settings;
};

using RendererFactory = std::function<std::unique_ptr<Renderer>(const RendererCreateInfo&)>;

// What a pipeline tells the rest of the program about itself, from its own folder
// (register.cpp): nothing outside that folder spells its name or knows its knobs.
struct RendererEntry {
    std::string name;
    std::string description;
    RendererFactory factory;
    int order = 100;  // position in default lists and reports (the reference is 0)
    KnobSchema knobs; // every setting it reads (core/renderer/knobs.h)
    // `triptych stress`: the pipeline's own precision terms and the counters a case must
    // drive up for it (core/renderer/error_model.h); empty: a generic model.
    ErrorModel errorModel;
    StressedCounters stressedCounters;
};

// Adds or replaces the entry of that name. A knob declared by several renderers must be
// declared identically: otherwise std::logic_error (a programming error, caught by the tests).
void registerRenderer(RendererEntry entry);
// A pipeline registers itself with one static object in its folder:
//   static const tp::RendererRegistration registration{{"name", "...", factory, ...}};
struct RendererRegistration {
    explicit RendererRegistration(RendererEntry entry) { registerRenderer(std::move(entry)); }
};
const std::vector<RendererEntry>& registeredRenderers(); // in `order`, then by name
Result<const RendererEntry*> findRenderer(const std::string& name);
// Every knob of every registered renderer, once each, in registration order, with the
// names of the renderers that read it.
struct KnobReaders {
    Knob knob;
    std::vector<std::string> readers;
};
std::vector<KnobReaders> allKnobs();
// One line ("--msaa N: not supported by DEVICE") when the device cannot render `samples` per
// pixel in colour and depth.
Status checkSampleCount(const GpuContext& ctx, uint32_t samples);
// Checks the sample count and the entry's knobs in `info.settings`, fills in its defaults and
// builds it; RendererError (one line naming the knob and its allowed values, or the sample
// count) on a bad value. Every entry point (CLI, viewer, stress, info, tests) creates
// renderers here, so none can reach image creation with a count the device lacks; the frame
// graph checks each image's own format and usage as well (FrameGraph::compile).
std::unique_ptr<Renderer> createRenderer(const RendererEntry& entry, RendererCreateInfo info);

} // namespace tp
