#include "forwardplus/fp_settings.h"

namespace tp::fp {
namespace {

const ChoiceKnob<ListLayout>& listsKnob() {
    static const ChoiceKnob<ListLayout> k{
        "light-lists",
        {{ListLayout::Compact, "compact"},
         {ListLayout::Fixed, "fixed"},
         {ListLayout::Linked, "linked"}},
        "Forward+ light-list layout: compact (count, prefix sum, fill; never drops), fixed (fixed "
        "capacity per tile; drops are counted), linked (per-tile linked lists)"};
    return k;
}

const IntegerKnob& capacityKnob() {
    static const IntegerKnob k =
        IntegerKnob{Knob::integer("tile-capacity", 1, 65536, 256,
                                  "Light slots per tile of the 'fixed' light-list layout")}
            .fixed();
    return k;
}

// Same lists either way: only where the time and the 16 bytes per light go.
const ChoiceKnob<Spheres>& spheresKnob() {
    static const ChoiceKnob<Spheres> k{
        "light-spheres",
        {{Spheres::Auto, "auto"}, {Spheres::Pass, "pass"}, {Spheres::Inline, "inline"}},
        "Each light's view-space sphere for the culling: pass (once per light in the "
        "light_spheres pass, 16 bytes per light), inline (per candidate in the culling) or auto "
        "(pass on a CPU device such as lavapipe, inline on a GPU)"};
    return k;
}

// Same bytes either way: only who does the work.
const ChoiceKnob<CullBy>& cullByKnob() {
    static const ChoiceKnob<CullBy> k{
        "cull-by",
        {{CullBy::Auto, "auto"},
         {CullBy::Invocation, "invocation"},
         {CullBy::Subgroup, "subgroup"}},
        "Who culls a tile in light_culling: invocation (one thread walks the tile's candidates; "
        "cheapest on a CPU device such as lavapipe), subgroup (one subgroup per tile, a candidate "
        "per lane, survivors placed in order by a ballot: a GPU runs tiles x lanes threads) or "
        "auto "
        "(invocation on a CPU device, subgroup on a GPU that supports it); the same lists either "
        "way"};
    return k;
}

} // namespace

KnobSchema knobs() {
    return {la::tileSizeKnob().knob(),    la::lightCullKnob().knob(), la::lightBinKnob().knob(),
            la::lightAssignKnob().knob(), la::slicesKnob().knob(),    la::lightLoopKnob().knob(),
            msaaShadingKnob().knob(),     listsKnob().knob(),         capacityKnob().knob(),
            spheresKnob().knob(),         cullByKnob().knob(),        hdrKnob(),
            cullGeometryKnob().knob(),    shadowRasterKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    Settings f;
    f.width = s.width;
    f.height = s.height;
    f.sampling = readSampling(s);
    f.assign = la::readAssignSettings(s);
    f.loop = la::lightLoopKnob().in(s);
    f.lists = listsKnob().in(s);
    f.tileCapacity = capacityKnob().in(s);
    f.spheres = spheresKnob().in(s);
    f.cullBy = cullByKnob().in(s);
    // --hdr auto: RGBA16F, Forward+'s storage before the knob existed (half the bytes).
    f.hdr = readHdr(s, HdrStorage::Fp16);
    f.cullGeometry = cullGeometryKnob().in(s);
    f.shadowRaster = shadowRasterKnob().in(s);
    return f;
}

const std::string& listsText(ListLayout l) {
    return listsKnob().text(l);
}
const std::string& spheresText(Spheres s) {
    return spheresKnob().text(s);
}

} // namespace tp::fp
