#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+ light culling: one invocation per tile (tile size 8, 16 or 32: a specialization
// constant), 8 x 8 tiles per workgroup, no shared memory and no barrier.
//  1. Depth bounds: min/max over every sample of every pixel of the tile that has geometry
//     (depth > 0); a tile with no geometry (sky) gets an empty opaque list. The transparent
//     list (only when the scene has blended materials) spans the tile's blended depth bounds
//     (include/light_assign.glsl: LaBlendedBounds; the blended_bounds pass records them),
//     and is empty where no blended fragment is shaded.
//  2. The tile's candidates - every local light, or with binned culling only those whose
//     conservative tile rectangle covers it (core/lightassign/tile_candidates.h), both in
//     ascending light order - are tested against the sub-frustum's bounding box and the
//     sub-frustum itself (include/tile_culling.glsl); survivors are appended in that order,
//     so every layout and both culling modes store the same lights in the same order.
//     Each candidate's view-space sphere comes from the light_spheres pass (computed once
//     per light, not once per tile; --light-spheres pass) or is computed here (inline);
//     the light itself is read only when the scene has spot lights (their cone test). Code
//     a lane does not need is still run, under a mask, on lavapipe, so whatever the scene
//     lacks is left out by specialization (kHasSpot).
// Directional lights are never culled: the shading pass loops over them separately.
// Layout (one shader variant each):
//  compact: the tile's slots [offset[t], offset[t+1]) come from a conservative CPU bound
//           (sphere vs the depth-unbounded tile frustum), so nothing can be dropped; a
//           count that exceeded it anyway would be reported in `dropped`, never silent.
//  fixed:   tileCapacity slots per tile; lights beyond it are counted in `dropped`.
//  linked:  nodes {light, next} from a pool: the survivors are counted first, then one
//           atomic allocation per list gives consecutive nodes, chained in light order.
// Why one invocation per tile: lavapipe runs a workgroup as 8-lane coroutines that switch at
// every barrier; with a workgroup per tile the barriers and the per-tile setup cost more
// than the tests themselves (docs/clustered.md has the measurements).
#include "include/shared.h"
#include "forwardplus/forwardplus_shared.h"
#include "include/scene_bindings.glsl"

// One of TP_FP_CULL_COMPACT, TP_FP_CULL_FIXED, TP_FP_CULL_LINKED is defined (1) per variant.
#if !defined(TP_FP_CULL_FIXED) && !defined(TP_FP_CULL_LINKED) && !defined(TP_FP_CULL_COMPACT)
#define TP_FP_CULL_COMPACT 1
#endif

layout(local_size_x = 8, local_size_y = 8) in; // 8 x 8 tiles
layout(constant_id = TP_FP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_FP_SPEC_SAMPLES) const int kSamples = 1;
layout(constant_id = TP_FP_SPEC_TWO_LISTS) const bool kTwoLists = false;
// Binned (--light-cull binned): the tile tests only its candidates; otherwise every local
// light. Same test, same order: the same lists either way.
layout(constant_id = TP_FP_SPEC_BINNED) const bool kBinned = false;
// Clustered (TP_FP_CLUSTERED, compact layout only): one list per tile over its depth span
// (its opaque range, widened to its blended depth bounds when the scene has blended
// surfaces: kSpanFromNear, named for when the span started at the near plane), and per depth slice (include/light_assign.glsl: laSliceOf) a bitmask over that
// list: bit i of slice s is set when light i of the list can reach the slice.
layout(constant_id = TP_FP_SPEC_SLICES) const uint kSlices = 16u;
layout(constant_id = TP_FP_SPEC_SPAN_FROM_NEAR) const bool kSpanFromNear = false;

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
// (kTwoLists or kSpanFromNear); a 16-byte stand-in otherwise.
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_BLEND_BOUNDS) readonly buffer BlendBoundsBlock {
    uint blendBounds[];
};
#ifdef TP_FP_CULL_LINKED
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_COUNTER) buffer CounterBlock {
    uint nodeCounter;
};
#endif
#ifdef TP_FP_CLUSTERED
// Each tile's rows belong to its invocation, which writes every word the shading reads
// (words [0, ceil(count / 32)) of every slice row): no clear pass. A later dispatch reads
// back the word an earlier one left partial.
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_CLUSTER_MASKS) buffer MaskBlock {
    uint masks[];
};
// The bits of the current 32-slot word for every slice, written out once per word: a
// survivor reaches several slices, and one store per slice and word is far cheaper on
// lavapipe than a read-modify-write of the buffer per slice and light.
uint gWordBits[64]; // kSlices <= 64 (core/lightassign/assign_knob.cpp)
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

ListVolume makeVolume(uvec2 tile, float nearDepth, float farDepth, bool tests) {
    return volumeOf(tile, makeTileFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, nearDepth, farDepth),
                    tests);
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
// Sets list slot `pos`'s bit in every slice its light's sphere (lightSphereView) reaches.
// The slices inside the opaque range take the light only when it meets the tile's opaque
// volume (`inOpaque`, the test a tiled opaque list makes), so an opaque fragment's cluster
// never holds more than the tiled opaque list; the front slices (blended surfaces nearer
// than the opaque range) and, where the tile sees the sky, the last one take it from the
// span test alone.
void markSlices(vec4 sphere, uint pos, LaSlicing slicing, bool inOpaque, bool openEnd) {
    uvec2 range = laLightSlices(sphere.xyz, sphere.w, slicing);
    for (uint sl = range.x; sl <= range.y; ++sl) {
        bool front = sl < slicing.front;
        if (front || inOpaque || (openEnd && sl == kSlices - 1u)) gWordBits[sl] |= 1u << (pos & 31u);
    }
}

// Writes word `word` of every slice row and clears the bits for the next word.
void flushWord(uint word, uint maskBase, uint maskStride) {
    for (uint sl = 0u; sl < kSlices; ++sl) {
        masks[maskBase + sl * maskStride + word] = gWordBits[sl];
        gWordBits[sl] = 0u;
    }
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

void main() {
    const uvec2 tile = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(tile, params.tiles.xy))) return;
    const uint tileIndex = tile.y * params.tiles.x + tile.x;

    // 1. Depth bounds over every sample (include/light_assign.glsl).
    const LaTileDepth depth = laTileDepthSerial(tile, kTileSize, frame.viewport.xy, uint(kSamples));
    const float transparentFar = laTransparentFarDepth(depth.hasGeometry, depth.seesSky, depth.farDepth);
    // The blended fragments' [nearest, farthest] view distance, padded (none without blended surfaces).
    LaBlendedBounds blended = laBlendedBounds(TP_LA_BLEND_EMPTY, 0u);
    if (kTwoLists || kSpanFromNear)
        blended = laBlendedBounds(blendBounds[tileIndex], blendBounds[params.tiles.z + tileIndex]);
    const TileFrustum blendedFrustum = laBlendedFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, blended);
#ifdef TP_FP_CLUSTERED
    // The span: the opaque range, widened to the blended bounds where the tile has blended
    // fragments (only those can be nearer than the opaque range, or farther where the tile
    // sees the sky). Slices follow the opaque range and, with blended surfaces, the front
    // region from the nearest blended fragment (include/light_assign.glsl: laSliceOf, laFrontNear).
    TileFrustum span = makeTileFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, depth.nearDepth,
                                       depth.farDepth);
    if (blended.any && depth.hasGeometry) {
        span.nearViewZ = max(span.nearViewZ, blendedFrustum.nearViewZ);
        span.farViewZ = min(span.farViewZ, blendedFrustum.farViewZ);
    } else if (blended.any) {
        span = blendedFrustum;
    }
    const bool spanTests = blended.any || depth.hasGeometry;
    const bool openEnd = blended.any && transparentFar == 0.0;
    const float sliceNear = depth.hasGeometry ? max(-viewZFromDepth(depth.nearDepth, frame.invProj), 1e-30) : 1e30;
    const float sliceFar = depth.hasGeometry ? -viewZFromDepth(depth.farDepth, frame.invProj) : 1e30;
    const uint front = laFrontSlices(kSlices, kSpanFromNear);
    const float sliceScale = laSliceScale(sliceNear, sliceFar, kSlices, front);
    const LaSlicing slicing = laSlicing(laFrontNear(blended, sliceNear), sliceNear, sliceScale, kSlices, front);
    const uint maskBase = data[params.lists.w + tileIndex];
    const uint maskStride = (data[params.lists.w + tileIndex + 1u] - maskBase) / kSlices;
    const ListVolume volume0 = volumeOf(tile, span, spanTests);
#else
    const ListVolume volume0 = makeVolume(tile, depth.nearDepth, depth.farDepth, depth.hasGeometry);
#endif
    // Two plain variables, not an array: lavapipe's compiler keeps a dynamically indexed
    // array of structs in memory. Tiled: the transparent list's; clustered with blended
    // surfaces: the opaque range (markSlices).
#ifdef TP_FP_CLUSTERED
    const ListVolume volume1 = makeVolume(tile, depth.nearDepth, depth.farDepth, kSpanFromNear && depth.hasGeometry);
#else
    const ListVolume volume1 = volumeOf(tile, blendedFrustum, kTwoLists && blended.any);
#endif

    // 2. The candidates: every local light (after the directional ones in data[]), or the
    //    tile's binned run.
    uint candidateBase = params.lights.x;
    uint candidateCount = params.lights.y;
    if (kBinned) {
        const uint first = data[params.lights.z + tileIndex];
        candidateCount = data[params.lights.z + tileIndex + 1u] - first;
        candidateBase = params.lists.z + first;
    }

    // This dispatch's candidates [first, end) (forwardplus/light_culling.cpp: LightCulling::record) and
    // what the earlier dispatches of the pass left in the tile's record.
    const uint batchFirst = draw.TP_FP_CULL_FIRST;
    const uint batchEnd = min(draw.TP_FP_CULL_END, candidateCount);
    LaListHeader prev0 = emptyHeader(), prev1 = emptyHeader();
    if (draw.TP_FP_CULL_INITIAL == 0u) {
        prev0 = tiles[tileIndex].list[0];
        prev1 = tiles[tileIndex].list[1];
    }

#if defined(TP_FP_CULL_COMPACT)
    const uint offset = data[params.lights.z + tileIndex];
    const uint capacity0 = data[params.lights.z + tileIndex + 1u] - offset, capacity1 = capacity0;
    const uint start0 = offset, start1 = params.lists.x + offset;
    uint count0 = prev0.found, count1 = prev1.found; // positions continue the earlier batches'
    const uint tail0 = kNoNode, tail1 = kNoNode;
#elif defined(TP_FP_CULL_FIXED)
    const uint capacity0 = params.lights.w, capacity1 = capacity0;
    const uint start0 = tileIndex * capacity0, start1 = params.lists.x + tileIndex * capacity0;
    uint count0 = prev0.found, count1 = prev1.found;
    const uint tail0 = kNoNode, tail1 = kNoNode;
#else
    // Linked: count this batch's survivors, then allocate consecutive nodes per list (one
    // atomic add each); nodes past the pool are dropped and counted (the pool is sized so
    // that it cannot happen). The batches run last to first and each is prepended: its
    // last node continues with the earlier head (tail), so a walk visits lights in order.
    // `capacity` is this batch's kept nodes, positions count from 0.
    uint found0 = 0u, found1 = 0u;
    for (uint k = batchFirst; k < batchEnd; ++k) {
        const uint lightIndex = data[candidateBase + k];
        const vec4 sphere = candidateSphere(lightIndex);
        if (passes(lightIndex, sphere, volume0)) ++found0;
        if (kTwoLists && passes(lightIndex, sphere, volume1)) ++found1;
    }
    const uint pool = params.lists.y;
    const uint start0 = found0 > 0u ? atomicAdd(nodeCounter, found0) : 0u;
    const uint start1 = found1 > 0u ? atomicAdd(nodeCounter, found1) : 0u;
    const uint capacity0 = min(found0, start0 < pool ? pool - start0 : 0u);
    const uint capacity1 = min(found1, start1 < pool ? pool - start1 : 0u);
    uint count0 = 0u, count1 = 0u;
    const uint tail0 = prev0.start, tail1 = prev1.start;
#endif

    // 3. Test and append in candidate (ascending light) order.
#ifdef TP_FP_CLUSTERED
    // A word left partial by the previous batch is continued, not restarted.
    const uint storedBefore = min(count0, capacity0);
    for (uint sl = 0u; sl < kSlices; ++sl)
        gWordBits[sl] = (storedBefore & 31u) != 0u ? masks[maskBase + sl * maskStride + (storedBefore >> 5u)] : 0u;
    bool dirty = false; // gWordBits holds bits this batch has not written out yet
#endif
    for (uint k = batchFirst; k < batchEnd; ++k) {
        const uint lightIndex = data[candidateBase + k];
        const vec4 sphere = candidateSphere(lightIndex);
        if (passes(lightIndex, sphere, volume0)) {
            store(lightIndex, count0, start0, capacity0, tail0);
#ifdef TP_FP_CLUSTERED
            if (count0 < capacity0) {
                if (dirty && (count0 & 31u) == 0u) {
                    flushWord((count0 >> 5u) - 1u, maskBase, maskStride);
                    dirty = false;
                }
                markSlices(sphere, count0, slicing, !kSpanFromNear || passes(lightIndex, sphere, volume1),
                           openEnd);
                dirty = true;
            }
#endif
            ++count0;
        }
        if (kTwoLists && passes(lightIndex, sphere, volume1)) {
            store(lightIndex, count1, start1, capacity1, tail1);
            ++count1;
        }
    }

#ifdef TP_FP_CLUSTERED
    if (dirty) flushWord((min(count0, capacity0) - 1u) >> 5u, maskBase, maskStride); // the last, partial word
#endif
    FpTileLists t;
#ifdef TP_FP_CULL_LINKED
    t.list[0] = prepend(prev0, found0, start0, capacity0);
    t.list[1] = prepend(prev1, found1, start1, capacity1);
#else
    t.list[0] = header(count0, start0, capacity0);
    t.list[1] = header(count1, start1, capacity1);
#endif
    t.nearDepth = depth.hasGeometry ? depth.nearDepth : 0.0;
    t.farDepth = depth.farDepth;
#ifdef TP_FP_CLUSTERED
    t.sliceNear = sliceNear;
    t.sliceScale = sliceScale;
    t.frontNear = slicing.frontNear;
#else
    t.sliceNear = 0.0;
    t.sliceScale = 0.0;
    t.frontNear = 0.0;
#endif
    t.pad0 = 0.0;
    t.pad1 = 0.0;
    t.pad2 = 0.0;
    tiles[tileIndex] = t;
}
