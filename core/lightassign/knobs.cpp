#include "core/lightassign/knobs.h"

#include <algorithm>

#include "core/gpu/context.h"

namespace tp::la {

const IntegerKnob& tileSizeKnob() {
    // 8 to 32: one workgroup per tile within lavapipe's and every desktop GPU's limits.
    static const IntegerKnob k{Knob::integerOf(
        "tile", {"8", "16", "32"}, "16", "Tile edge in pixels of the tiled light assignment")};
    return k;
}

const ChoiceKnob<Assign>& lightAssignKnob() {
    static const ChoiceKnob<Assign> k{
        "light-assign",
        {{Assign::Tiled, "tiled"}, {Assign::Clustered, "clustered"}},
        "Light assignment: tiled (a list per screen tile and depth range) or clustered (tiles x "
        "depth slices: a list per tile over its depth span, a bitmask over it per slice)"};
    return k;
}

const IntegerKnob& slicesKnob() {
    // Up to 64: a slice's bitmask costs one bit per light of the tile list.
    static const IntegerKnob k{
        Knob::integerOf("slices", {"4", "8", "16", "32", "64"}, "16",
                        "Depth slices per tile of --light-assign clustered (exponential in "
                        "view distance)")};
    return k;
}

const ChoiceKnob<Cull>& lightCullKnob() {
    static const ChoiceKnob<Cull> k{
        "light-cull",
        {{Cull::Auto, "auto"}, {Cull::Binned, "binned"}, {Cull::All, "all"}},
        "Which lights a tile tests: binned (only those whose conservative tile rectangle covers "
        "it, built as --light-bin says; cost lights + candidates), all (every light: tiles x "
        "lights) or auto (all on a GPU up to 2,048 lights for forwardplus and visbuffer, where "
        "the binning passes cost more than the tests they save; binned on a CPU device, past "
        "that and for deferred; counter light_cull_all says which ran); binned and all keep "
        "exactly the same lists"};
    return k;
}

const ChoiceKnob<Bin>& lightBinKnob() {
    static const ChoiceKnob<Bin> k{
        "light-bin",
        {{Bin::Auto, "auto"}, {Bin::Cpu, "cpu"}, {Bin::Gpu, "gpu"}},
        "Where --light-cull binned builds each tile's candidates: cpu (once per configuration), "
        "gpu (every frame, timed passes light_binning: rectangles, counts, prefix sum; "
        "light_bin_fill; "
        "light_bin_sort: each run ascending; the same runs as cpu) or auto (cpu on a CPU device "
        "such as lavapipe, where the sort costs more than the CPU's scatter; else gpu)"};
    return k;
}

const ChoiceKnob<Loop>& lightLoopKnob() {
    static const ChoiceKnob<Loop> k{
        "light-loop",
        {{Loop::Lane, "lane"}, {Loop::Subgroup, "subgroup"}},
        "Clustered shading loop: lane (each fragment walks its own cluster's bits) or subgroup "
        "(lanes of one tile walk the OR of their bits together, light loads uniform; the same "
        "image); changes nothing under --light-assign tiled"};
    return k;
}

const ChoiceKnob<TileGroup>& tileGroupKnob() {
    static const ChoiceKnob<TileGroup> k{
        "tile-group",
        {{TileGroup::Auto, "auto"}, {TileGroup::Eight, "8"}, {TileGroup::Sixteen, "16"}},
        "Workgroup edge of the tiled lighting (invocations per tile edge, at most the tile): 8 "
        "(each invocation shades (tile/8)^2 pixels), 16 (a 16-pixel tile's pixels one an "
        "invocation: on a GPU it hides the surface reads' latency, 2.2x faster on an H200) or "
        "auto (16 on a GPU, 8 on a CPU device such as lavapipe); the same image whichever"};
    return k;
}

uint32_t tileGroupEdge(const GpuContext& ctx, TileGroup group, uint32_t tile) {
    uint32_t edge = group == TileGroup::Sixteen ? 16u
                    : group == TileGroup::Eight  ? 8u
                    : ctx.isCpuDevice()          ? 8u
                                                 : 16u;
    return std::min(edge, tile);
}

AssignSettings readAssignSettings(const RenderSettings& s) {
    AssignSettings a;
    a.tile = tileSizeKnob().in(s);
    a.assign = lightAssignKnob().in(s);
    a.slices = slicesKnob().in(s);
    a.cull = lightCullKnob().in(s);
    a.bin = lightBinKnob().in(s);
    return a;
}

Cull resolveCull(const GpuContext& ctx, Cull cull, size_t lights, bool allPays) {
    if (cull != Cull::Auto) return cull;
    return allPays && !ctx.isCpuDevice() && lights <= kAutoCullAllLights ? Cull::All : Cull::Binned;
}

bool binsOnGpu(const GpuContext& ctx, Bin bin) {
    return bin == Bin::Gpu || (bin == Bin::Auto && !ctx.isCpuDevice());
}

std::string subgroupLoopUnsupported(const DeviceCaps& caps) {
    if (!(caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT))
        return "the device has no subgroup operations in fragment shaders";
    const uint32_t need = VK_SUBGROUP_FEATURE_VOTE_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT |
                          VK_SUBGROUP_FEATURE_BALLOT_BIT;
    if ((caps.subgroupOps & need) != need)
        return "the device lacks subgroup vote, arithmetic or ballot operations";
    return {};
}

} // namespace tp::la
