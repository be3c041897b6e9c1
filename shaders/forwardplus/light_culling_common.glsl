// What both ways of culling a Forward+ tile share (light_culling.comp: one invocation per
// tile; light_culling_subgroup.comp: one subgroup per tile): the bindings, the tile's set-up
// (its depth bounds are computed by the caller, serially or across the subgroup), the tests,
// the list slots and the tile record. Only the order in which candidates are visited and how
// survivors find their positions differ, and both give every survivor the position it has in
// ascending candidate order: the same lists, masks and records byte for byte.
#include "include/shared.h"
#include "forwardplus/forwardplus_shared.h"
#include "include/scene_bindings.glsl"

// One of TP_FP_CULL_COMPACT, TP_FP_CULL_FIXED, TP_FP_CULL_LINKED is defined (1) per variant.
#if !defined(TP_FP_CULL_FIXED) && !defined(TP_FP_CULL_LINKED) && !defined(TP_FP_CULL_COMPACT)
#define TP_FP_CULL_COMPACT 1
#endif

layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_SPEC_SAMPLES) const int kSamples = 1;
layout(constant_id = TP_FP_SPEC_TWO_LISTS) const bool kTwoLists = false;
// Binned (--light-cull binned): the tile tests only its candidates; otherwise every local
// light. Same test, same order: the same lists either way.
layout(constant_id = TP_FP_SPEC_BINNED) const bool kBinned = false;
// Clustered (TP_FP_CLUSTERED, compact layout only): one list per tile over its depth span
// (its opaque range, widened to its blended depth bounds when the scene has blended
// surfaces: kBlendedSpan), and per depth slice (include/light_assign.glsl: laSliceOf) a bitmask over that
// list: bit i of slice s is set when light i of the list can reach the slice.
layout(constant_id = TP_FP_SPEC_SLICES) const uint kSlices = 16u;
layout(constant_id = TP_FP_SPEC_BLENDED_SPAN) const bool kBlendedSpan = false;

// Read back by the later dispatches of the pass (their lists continue these).
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_TILES) buffer TileBlock {
    FpTileLists tiles[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_INDICES) writeonly buffer IndexBlock {
    uint indices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_PARAMS) readonly buffer ParamBlock {
    FpParams params;
    uint data[];
};
// Every light's lightSphereView, from the light_spheres pass (light_spheres.comp), when
// kSpheres (--light-spheres, forwardplus/register.cpp); otherwise a 16-byte stand-in and each
// candidate's sphere is computed here. The same function on the same inputs either way.
layout(constant_id = TP_FP_SPEC_SPHERES) const bool kSpheres = true;
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_SPHERES) readonly buffer SphereBlock {
    vec4 spheres[];
};
#ifdef TP_FP_DEPTH_MS
layout(set = TP_SET_PASS, binding = TP_FP_BINDING_DEPTH) uniform sampler2DMS depthImage;
#define TP_LA_DEPTH_FETCH(p, s) texelFetch(depthImage, p, int(s)).r
#else
layout(set = TP_SET_PASS, binding = TP_FP_BINDING_DEPTH) uniform sampler2D depthImage;
#define TP_LA_DEPTH_FETCH(p, s) texelFetch(depthImage, p, 0).r
#endif
#include "include/light_assign.glsl"
// Blended depth bounds (light_assign.h: TP_LA_BLEND_*), read only with blended surfaces
// (kTwoLists or kBlendedSpan); a 16-byte stand-in otherwise.
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_BLEND_BOUNDS) readonly buffer BlendBoundsBlock {
    uint blendBounds[];
};
// At --msaa-shading pixel under MSAA the opaque shading runs once per pixel and primitive at
// the pixel centre, extrapolated along the triangle's plane where the centre lies off it (or
// interpolated over samples it does not keep): a point that can lie nearer or farther than
// every depth the tile's samples store (a silhouette seen at a slant). The centre bounds pass
// (core/passes/blended_bounds.h, `opaque`) records those fragments' view distances per tile, in
// the blended bounds' format; the opaque range is widened to them (kCentreBounds), otherwise a
// 16-byte stand-in is bound.
layout(constant_id = TP_FP_SPEC_CENTRE_BOUNDS) const bool kCentreBounds = false;
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_CENTRE_BOUNDS) readonly buffer CentreBoundsBlock {
    uint centreBounds[];
};
#ifdef TP_FP_CULL_LINKED
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_COUNTER) buffer CounterBlock {
    uint nodeCounter;
};
#endif
#ifdef TP_FP_CLUSTERED
// Each tile's rows belong to the invocation or subgroup that culls it, which writes every
// word the shading reads (words [0, ceil(count / 32)) of every slice row): no clear pass. A
// later dispatch reads back the word an earlier one left partial.
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_CLUSTER_MASKS) buffer MaskBlock {
    uint masks[];
};
#endif

const uint kNoNode = 0xffffffffu;

// The culling volumes of one list: sub-frustum and its view-space box.
struct ListVolume {
    TileFrustum frustum;
    TileBox box;
    bool tests; // false: the list stays empty (opaque list of a sky tile)
};

ListVolume volumeOf(uvec2 tile, TileFrustum f, bool tests) {
    ListVolume v;
    v.frustum = f;
    v.box = makeTileBox(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, f);
    v.tests = tests;
    return v;
}

// The opaque range's sub-frustum between two depths, widened to the tile's opaque fragment
// centres (kCentreBounds: `centres`, padded like the blended bounds).
TileFrustum opaqueFrustum(uvec2 tile, float nearDepth, float farDepth, LaBlendedBounds centres) {
    TileFrustum f = makeTileFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, nearDepth, farDepth);
    if (centres.any) {
        f.nearViewZ = max(f.nearViewZ, -centres.nearDist);
        f.farViewZ = min(f.farViewZ, -centres.farDist);
    }
    return f;
}

vec4 candidateSphere(uint lightIndex) {
    return kSpheres ? spheres[lightIndex] : lightSphereView(lights[lightIndex], frame.view);
}

// `sphere`: candidateSphere(lightIndex), once per candidate for both lists. Without spot
// lights (kHasSpot false) neither the light nor the cone test is needed: lavapipe runs both
// sides of a branch under a lane mask, so they would cost every candidate.
bool passes(uint lightIndex, vec4 sphere, ListVolume v) {
    return v.tests && sphereInTileBox(sphere, v.box) &&
           (kHasSpot ? lightSphereInTile(lights[lightIndex], sphere, v.frustum, frame.view)
                     : tileSphereTest(sphere.xyz, sphere.w, v.frustum));
}

#ifdef TP_FP_CLUSTERED
// Whether slice `sl`, one of those a survivor's sphere reaches (laLightSlices), takes it. The
// slices inside the opaque range take the light only when it meets the tile's opaque volume
// (`inOpaque`, the test a tiled opaque list makes), so an opaque fragment's cluster never
// holds more than the tiled opaque list; the front slices (blended surfaces nearer than the
// opaque range) and, where the tile sees the sky, the last one take it from the span test alone.
bool sliceTakes(uint sl, LaSlicing slicing, bool inOpaque, bool openEnd) {
    return sl < slicing.front || inOpaque || (openEnd && sl == kSlices - 1u);
}
#endif

// Stores light `lightIndex` at position `pos` of a list (compact/fixed: slot start + pos
// when within capacity; linked: node start + pos, chained to the next - the last kept one
// to `tail` - when within this batch's kept nodes).
void store(uint lightIndex, uint pos, uint start, uint capacity, uint tail) {
#ifdef TP_FP_CULL_LINKED
    if (pos < capacity) {
        indices[2u * (start + pos)] = lightIndex;
        indices[2u * (start + pos) + 1u] = pos + 1u < capacity ? start + pos + 1u : tail;
    }
#else
    if (pos < capacity) indices[start + pos] = lightIndex;
#endif
}

LaListHeader emptyHeader() {
    LaListHeader h;
    h.count = 0u;
    h.start = kNoNode; // linked: no head yet
    h.dropped = 0u;
    h.found = 0u;
    return h;
}

// compact/fixed: `found` survivors so far, the first `capacity` stored from `start`.
LaListHeader header(uint found, uint start, uint capacity) {
    LaListHeader h;
    h.count = min(found, capacity);
    h.start = start;
    h.dropped = found - h.count;
    h.found = found;
    return h;
}

// linked: this batch's `found` survivors, `kept` of them in nodes from `base`, in front of
// what the earlier batches (`prev`) left.
LaListHeader prepend(LaListHeader prev, uint found, uint base, uint kept) {
    LaListHeader h;
    h.count = prev.count + kept;
    h.start = kept > 0u ? base : prev.start;
    h.dropped = prev.dropped + found - kept;
    h.found = prev.found + found;
    return h;
}

// ---- the tile's set-up, the same for both ways of culling it ----

// Everything about one tile that does not depend on its candidates' tests.
struct CullTile {
    uint index;
    LaTileDepth depth;
    ListVolume volume0; // tiled: the opaque list's; clustered: the span's
    ListVolume volume1; // tiled: the transparent list's; clustered with blended surfaces: the opaque range
    uint candidateBase, candidateCount; // the candidates: data[candidateBase + k]
    uint batchFirst, batchEnd;          // this dispatch's candidates [first, end)
    LaListHeader prev0, prev1;          // what the earlier dispatches of the pass left
#ifdef TP_FP_CLUSTERED
    LaSlicing slicing;
    bool openEnd;
    uint maskBase, maskStride;
#endif
};

CullTile cullTile(uvec2 tile, LaTileDepth depth) {
    CullTile c;
    c.index = tile.y * params.tiles.x + tile.x;
    c.depth = depth;
    const float transparentFar = laTransparentFarDepth(depth.hasGeometry, depth.seesSky, depth.farDepth);
    // The blended fragments' [nearest, farthest] view distance, padded (none without blended surfaces).
    LaBlendedBounds blended = laBlendedBounds(TP_LA_BLEND_EMPTY, 0u);
    if (kTwoLists || kBlendedSpan)
        blended = laBlendedBounds(blendBounds[c.index], blendBounds[params.tiles.z + c.index]);
    const TileFrustum blendedFrustum = laBlendedFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, blended);
    LaBlendedBounds centres = laBlendedBounds(TP_LA_BLEND_EMPTY, 0u);
    if (kCentreBounds) centres = laBlendedBounds(centreBounds[c.index], centreBounds[params.tiles.z + c.index]);
    const TileFrustum opaque = opaqueFrustum(tile, depth.nearDepth, depth.farDepth, centres);
#ifdef TP_FP_CLUSTERED
    // The span: the opaque range, widened to the blended bounds where the tile has blended
    // fragments (only those can be nearer than the opaque range, or farther where the tile
    // sees the sky). Slices follow the opaque range and, with blended surfaces, the front
    // region from the nearest blended fragment (include/light_assign.glsl: laSliceOf, laFrontNear).
    TileFrustum span = opaque;
    if (blended.any && depth.hasGeometry) {
        span.nearViewZ = max(span.nearViewZ, blendedFrustum.nearViewZ);
        span.farViewZ = min(span.farViewZ, blendedFrustum.farViewZ);
    } else if (blended.any) {
        span = blendedFrustum;
    }
    const bool spanTests = blended.any || depth.hasGeometry;
    c.openEnd = blended.any && transparentFar == 0.0;
    const float sliceNear = depth.hasGeometry ? max(-viewZFromDepth(depth.nearDepth, frame.invProj), 1e-30) : 1e30;
    const float sliceFar = depth.hasGeometry ? -viewZFromDepth(depth.farDepth, frame.invProj) : 1e30;
    const uint front = laFrontSlices(kSlices, kBlendedSpan);
    const float sliceScale = laSliceScale(sliceNear, sliceFar, kSlices, front);
    c.slicing = laSlicing(laFrontNear(blended, sliceNear), sliceNear, sliceScale, kSlices, front);
    c.maskBase = data[params.lists.w + c.index];
    c.maskStride = (data[params.lists.w + c.index + 1u] - c.maskBase) / kSlices;
    c.volume0 = volumeOf(tile, span, spanTests);
    c.volume1 = volumeOf(tile, opaque, kBlendedSpan && depth.hasGeometry);
#else
    c.volume0 = volumeOf(tile, opaque, depth.hasGeometry);
    c.volume1 = volumeOf(tile, blendedFrustum, kTwoLists && blended.any);
#endif
    // The candidates: every local light (after the directional ones in data[]), or the
    // tile's binned run.
    c.candidateBase = params.lights.x;
    c.candidateCount = params.lights.y;
    if (kBinned) {
        const uint first = data[params.lights.z + c.index];
        c.candidateCount = data[params.lights.z + c.index + 1u] - first;
        c.candidateBase = params.lists.z + first;
    }
    // This dispatch's candidates (forwardplus/light_culling.cpp: LightCulling::record) and
    // what the earlier dispatches of the pass left in the tile's record.
    c.batchFirst = draw.TP_FP_CULL_FIRST;
    c.batchEnd = min(draw.TP_FP_CULL_END, c.candidateCount);
    c.prev0 = emptyHeader();
    c.prev1 = emptyHeader();
    if (draw.TP_FP_CULL_INITIAL == 0u) {
        c.prev0 = tiles[c.index].list[0];
        c.prev1 = tiles[c.index].list[1];
    }
    return c;
}

// Where a list's survivors go: position `pos` is stored at slot start + pos while pos <
// capacity (linked: node start + pos, chained on to `tail` after the last).
struct ListSlots {
    uint start, capacity, tail;
    uint first; // the position this dispatch's first survivor takes (compact/fixed: the earlier dispatches' count)
};

#ifdef TP_FP_CULL_LINKED
// found: this dispatch's survivors; base: their nodes' first (allocated by the caller, one
// atomic add per list and batch: nodes past the pool are dropped and counted, and the pool
// is sized so that it cannot happen). The batches run last to first and each is prepended:
// its last node continues with the earlier head (tail), so a walk visits lights in order.
ListSlots linkedSlots(uint found, uint base, LaListHeader prev) {
    const uint pool = params.lists.y;
    ListSlots s;
    s.start = found > 0u ? base : 0u;
    s.capacity = min(found, s.start < pool ? pool - s.start : 0u);
    s.tail = prev.start;
    s.first = 0u;
    return s;
}
#else
// list: 0 (opaque or span) or 1 (transparent). compact: the tile's slots [offset[t],
// offset[t+1]) come from a conservative bound, so nothing can be dropped; fixed: tileCapacity
// slots per tile.
ListSlots arraySlots(CullTile c, uint list) {
    ListSlots s;
#if defined(TP_FP_CULL_COMPACT)
    const uint offset = data[params.lights.z + c.index];
    s.capacity = data[params.lights.z + c.index + 1u] - offset;
    s.start = (list == 0u ? 0u : params.lists.x) + offset;
#ifdef TP_FP_CLUSTERED
    // No more lights than the tile's slice rows hold bits: a view past the mask rows' room
    // (--light-bin gpu: bin_scan_words.comp clamps their offsets, and the view is planned
    // again) gets shorter rows, and then neither this pass nor the shading touches a word past
    // them. Otherwise the rows hold ceil(run / 32) words and this never binds.
    if (c.maskStride < (1u << 27u)) s.capacity = min(s.capacity, c.maskStride << 5u);
#endif
#else
    s.capacity = params.lights.w;
    s.start = (list == 0u ? 0u : params.lists.x) + c.index * s.capacity;
#endif
    s.tail = kNoNode;
    s.first = list == 0u ? c.prev0.found : c.prev1.found; // positions continue the earlier batches'
    return s;
}
#endif

// The tile's record after this dispatch: `count` survivors so far per list (compact/fixed:
// all batches'; linked: this batch's).
void writeTile(CullTile c, ListSlots s0, ListSlots s1, uint count0, uint count1) {
    FpTileLists t;
#ifdef TP_FP_CULL_LINKED
    t.list[0] = prepend(c.prev0, count0, s0.start, s0.capacity);
    t.list[1] = prepend(c.prev1, count1, s1.start, s1.capacity);
#else
    t.list[0] = header(count0, s0.start, s0.capacity);
    t.list[1] = header(count1, s1.start, s1.capacity);
#endif
    t.nearDepth = c.depth.hasGeometry ? c.depth.nearDepth : 0.0;
    t.farDepth = c.depth.farDepth;
#ifdef TP_FP_CLUSTERED
    t.sliceNear = c.slicing.sliceNear;
    t.sliceScale = c.slicing.sliceScale;
    t.frontNear = c.slicing.frontNear;
#else
    t.sliceNear = 0.0;
    t.sliceScale = 0.0;
    t.frontNear = 0.0;
#endif
    t.pad0 = 0.0;
    t.pad1 = 0.0;
    t.pad2 = 0.0;
    tiles[c.index] = t;
}
