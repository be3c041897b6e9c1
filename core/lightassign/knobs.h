#pragma once
// The light-assignment knobs of the tiled pipelines, declared once here so that Forward+ and
// deferred share one option each with one set of values (the registry refuses two different
// declarations of a name), and the typed settings they become (docs/clustered.md).
#include <cstdint>
#include <string>

#include "core/renderer/knobs.h"

namespace tp {
class GpuContext;
struct DeviceCaps;
} // namespace tp

namespace tp::la {

// --light-assign tiled|clustered. tiled (default): a light list per screen tile (Forward+:
// two when something is blended). clustered: tiles x depth slices; one list per tile over
// its whole depth span plus, per slice, a bitmask over that list.
enum class Assign { Tiled, Clustered };
// --light-cull auto|binned|all. binned: each tile tests only the lights whose conservative
// tile rectangle covers it (tile_candidates.h); all: every tile tests every light (brute
// force, tiles x lights), the yardstick the binned lists must equal; auto (default, resolved
// by resolveCull before a renderer plans): all where the renderer gains by it, else binned.
enum class Cull { Auto, Binned, All };
// --light-cull auto takes `all` on a GPU up to this many lights, for the renderers whose lists
// do not depend on it (Forward+, the visibility buffer): there the binning's passes cost more
// than testing every light in every tile (H200, 1080p, 1,024 and 2,048 lights, 1x and 4x:
// docs/clustered.md, "--light-cull auto").
constexpr size_t kAutoCullAllLights = 2048;
// --light-bin auto|cpu|gpu: where binned culling's candidate runs are built. cpu:
// la::binLights, when planned and for every new view (light_bins.h); gpu: the light_binning
// compute pass every frame (core/passes/light_binning.h), after a sizing run per view; auto
// (default): cpu on a CPU device (lavapipe: the "GPU" is the same cores and the serial
// scatter is cheapest), gpu otherwise. Meaningful only under --light-cull binned.
enum class Bin { Auto, Cpu, Gpu };
// --light-loop lane|subgroup (docs/clustered.md). lane (default): every fragment walks its
// own cluster's bit row. subgroup: where every active lane of a subgroup shades the same
// tile, the lanes walk the OR of their rows together, each adding a light only where its
// own bit is set, so the light loads are uniform; other subgroups keep the lane loop. The
// same lights in the same order per fragment either way: identical images.
enum class Loop { Lane, Subgroup };
// --tile-group auto|8|16: the tiled lighting's workgroup edge (deferred's and the visibility
// buffer's, passes/tiled_lighting.h). auto: 16 on a GPU with 16- and 32-pixel tiles, 8 on a CPU
// device; never more than the tile. The same image whichever (docs/efficiency.md).
enum class TileGroup { Auto, Eight, Sixteen };

const IntegerKnob& tileSizeKnob(); // --tile 8|16|32
const ChoiceKnob<Assign>& lightAssignKnob();
const IntegerKnob& slicesKnob(); // --slices N: depth slices per tile (clustered only)
const ChoiceKnob<Cull>& lightCullKnob();
const ChoiceKnob<Bin>& lightBinKnob();
const ChoiceKnob<Loop>& lightLoopKnob();
const ChoiceKnob<TileGroup>& tileGroupKnob();
// --tile-group resolved on `ctx` for `tile`-pixel tiles: the workgroup's edge in invocations.
uint32_t tileGroupEdge(const GpuContext& ctx, TileGroup group, uint32_t tile);

// The assignment knobs every tiled pipeline declares (tile, cull, bin, assign, slices), typed.
struct AssignSettings {
    uint32_t tile = 16;
    Assign assign = Assign::Tiled;
    uint32_t slices = 16; // read only when clustered
    Cull cull = Cull::Binned;
    Bin bin = Bin::Auto;
    bool clustered() const { return assign == Assign::Clustered; }
    bool binned() const { return cull != Cull::All; } // auto: binned until resolved
    // Depth slices when clustered, 0 when tiled (the passes' "no slices").
    uint32_t slicesOrZero() const { return clustered() ? slices : 0; }
};
// The knobs of tileSizeKnob() .. lightBinKnob() in `s` (their values checked by the schema).
AssignSettings readAssignSettings(const RenderSettings& s);

// --light-cull resolved on `ctx` for a scene of `lights` lights: auto is `all` on a GPU up to
// kAutoCullAllLights where `allPays` (a renderer whose image is the same either way and that
// gains by it), else binned; binned and all stay.
Cull resolveCull(const GpuContext& ctx, Cull cull, size_t lights, bool allPays);
// A renderer's settings (anything with an AssignSettings `assign`) with --light-cull resolved.
template <class Settings>
Settings withResolvedCull(Settings s, const GpuContext& ctx, size_t lights, bool allPays) {
    s.assign.cull = resolveCull(ctx, s.assign.cull, lights, allPays);
    return s;
}

// --light-bin resolved on `ctx`: true for gpu. A run reports it (counter
// light_binning_on_gpu), so two runs of one command on one device report the same.
bool binsOnGpu(const GpuContext& ctx, Bin bin);

// Whether the device runs the subgroup loop: vote (subgroupAllEqual), arithmetic
// (subgroupOr) and ballot (subgroupBroadcastFirst) in the fragment stage. Empty when it
// does; otherwise the reason, for the report's note.
std::string subgroupLoopUnsupported(const DeviceCaps& caps);

} // namespace tp::la
