#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+ light culling, one invocation per tile (--cull-by invocation; tile size 8, 16 or 32:
// a specialization constant), 8 x 8 tiles per workgroup, no shared memory and no barrier.
// light_culling_subgroup.comp culls a tile with a subgroup instead (--cull-by subgroup), with
// the same set-up and the same results (light_culling_common.glsl).
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
// than the tests themselves (docs/clustered.md has the measurements). A GPU, though, runs only
// as many threads as tiles (8,160 at 1920x1080, tile 16) and waits for the longest tile.
#include "forwardplus/light_culling_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in; // 8 x 8 tiles

#ifdef TP_FP_CLUSTERED
// The bits of the current 32-slot word for every slice, written out once per word: a
// survivor reaches several slices, and one store per slice and word is far cheaper on
// lavapipe than a read-modify-write of the buffer per slice and light.
uint gWordBits[64]; // kSlices <= 64 (core/lightassign/knobs.cpp)

// Sets list slot `pos`'s bit in every slice that takes the light (sliceTakes).
void markSlices(vec4 sphere, uint pos, LaSlicing slicing, bool inOpaque, bool openEnd) {
    uvec2 range = laLightSlices(sphere.xyz, sphere.w, slicing);
    for (uint sl = range.x; sl <= range.y; ++sl)
        if (sliceTakes(sl, slicing, inOpaque, openEnd)) gWordBits[sl] |= 1u << (pos & 31u);
}

// Writes word `word` of every slice row and clears the bits for the next word.
void flushWord(uint word, uint maskBase, uint maskStride) {
    for (uint sl = 0u; sl < kSlices; ++sl) {
        masks[maskBase + sl * maskStride + word] = gWordBits[sl];
        gWordBits[sl] = 0u;
    }
}
#endif

// The tile's depth bounds (include/light_assign.glsl: laTileDepthSerial's). Single-sample
// depth is read with textureGather, a 2 x 2 block of texels per call: a quarter of the
// texture operations, which were most of this pass's fixed cost on lavapipe (3.0 of 3.3 ms at
// 1280x720 with one light). Gathered at the corner the texels (x, y) .. (x + 1, y + 1) share,
// it returns exactly those four (tiles start on even pixels); past an odd viewport's last
// column or row the clamp-to-edge sampler repeats the edge texel, a pixel of the same tile.
// The same texels as the serial fetch loop: the same bounds (light_culling_subgroup.comp
// fetches texel by texel, and ForwardPlusCulling.SubgroupCullingGivesTheInvocationBytes
// compares the two).
LaTileDepth tileDepth(uvec2 tile) {
#ifdef TP_FP_DEPTH_MS
    return laTileDepthSerial(tile, kTileSize, frame.viewport.xy, uint(kSamples));
#else
    float lo = 2.0, hi = 0.0;
    bool sky = false;
    const uvec2 p0 = tile * kTileSize, p1 = min(p0 + uvec2(kTileSize), frame.viewport.xy);
    const vec2 texel = 1.0 / vec2(frame.viewport.xy);
    for (uint y = p0.y; y < p1.y; y += 2u) {
        for (uint x = p0.x; x < p1.x; x += 2u) {
            const vec4 d = textureGather(depthImage, vec2(x + 1u, y + 1u) * texel);
            const vec4 geometry = mix(vec4(2.0), d, greaterThan(d, vec4(0.0)));
            lo = min(lo, min(min(geometry.x, geometry.y), min(geometry.z, geometry.w)));
            hi = max(hi, max(max(d.x, d.y), max(d.z, d.w)));
            sky = sky || any(equal(d, vec4(0.0)));
        }
    }
    return laTileDepthOf(lo, hi, sky);
#endif
}

void main() {
    const uvec2 tile = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(tile, params.tiles.xy))) return;
    // 1. Depth bounds over every sample (include/light_assign.glsl), the lists' volumes,
    //    the candidates (light_culling_common.glsl).
    const CullTile c = cullTile(tile, tileDepth(tile));

#if defined(TP_FP_CULL_LINKED)
    // 2. Linked: count this batch's survivors, then allocate consecutive nodes per list.
    uint found0 = 0u, found1 = 0u;
    for (uint k = c.batchFirst; k < c.batchEnd; ++k) {
        const uint lightIndex = data[c.candidateBase + k];
        const vec4 sphere = candidateSphere(lightIndex);
        if (passes(lightIndex, sphere, c.volume0)) ++found0;
        if (kTwoLists && passes(lightIndex, sphere, c.volume1)) ++found1;
    }
    const ListSlots s0 = linkedSlots(found0, found0 > 0u ? atomicAdd(nodeCounter, found0) : 0u, c.prev0);
    const ListSlots s1 = linkedSlots(found1, found1 > 0u ? atomicAdd(nodeCounter, found1) : 0u, c.prev1);
#else
    const ListSlots s0 = arraySlots(c, 0u), s1 = arraySlots(c, 1u);
#endif
    uint count0 = s0.first, count1 = s1.first;

    // 3. Test and append in candidate (ascending light) order.
#ifdef TP_FP_CLUSTERED
    // A word left partial by the previous batch is continued, not restarted.
    const uint storedBefore = min(count0, s0.capacity);
    for (uint sl = 0u; sl < kSlices; ++sl)
        gWordBits[sl] =
            (storedBefore & 31u) != 0u ? masks[c.maskBase + sl * c.maskStride + (storedBefore >> 5u)] : 0u;
    bool dirty = false; // gWordBits holds bits this batch has not written out yet
#endif
    for (uint k = c.batchFirst; k < c.batchEnd; ++k) {
        const uint lightIndex = data[c.candidateBase + k];
        const vec4 sphere = candidateSphere(lightIndex);
        if (passes(lightIndex, sphere, c.volume0)) {
            store(lightIndex, count0, s0.start, s0.capacity, s0.tail);
#ifdef TP_FP_CLUSTERED
            if (count0 < s0.capacity) {
                if (dirty && (count0 & 31u) == 0u) {
                    flushWord((count0 >> 5u) - 1u, c.maskBase, c.maskStride);
                    dirty = false;
                }
                markSlices(sphere, count0, c.slicing, !kBlendedSpan || passes(lightIndex, sphere, c.volume1),
                           c.openEnd);
                dirty = true;
            }
#endif
            ++count0;
        }
        if (kTwoLists && passes(lightIndex, sphere, c.volume1)) {
            store(lightIndex, count1, s1.start, s1.capacity, s1.tail);
            ++count1;
        }
    }

#ifdef TP_FP_CLUSTERED
    if (dirty) flushWord((min(count0, s0.capacity) - 1u) >> 5u, c.maskBase, c.maskStride); // the last, partial word
#endif
    writeTile(c, s0, s1, count0, count1);
}
