#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_vote : require
// Forward+ light culling, one subgroup per tile (--cull-by subgroup, the default on a GPU):
// the same set-up, tests and results as light_culling.comp (light_culling_common.glsl has
// them), with the work of a tile spread over the lanes of one subgroup.
//  1. Depth bounds: each lane takes every lanes-th pixel of the tile; subgroupMin/Max/Any
//     join them (min and max are exact: the same bounds as the serial loop).
//  2. The candidates are taken a subgroup at a time, lane i testing candidate first + i.
//     A ballot of the survivors gives each its position: the survivors before it in this
//     step (subgroupBallotExclusiveBitCount) after all earlier steps' - its position in
//     ascending candidate order, as the serial loop gives it. Linked counts a batch's
//     survivors the same way first; one lane allocates the nodes.
//  3. Clustered: a survivor at position p sets bit p % 32 of word p / 32 in each slice that
//     takes it, in a shared window of the three words a step can reach (atomicOr); the
//     words a step completes are written out once, each slice row by one lane.
// Why: one invocation per tile runs only as many threads as there are tiles (8,160 at
// 1920x1080, tile 16), and each walks its whole run of candidates alone; a GPU then waits
// for the longest run. On lavapipe (8-lane subgroups run as one thread) the serial loop is
// cheaper: --cull-by auto picks it there (forwardplus/register.cpp).
#include "forwardplus/light_culling_common.glsl"

// One workgroup per tile, exactly one full subgroup: the pipeline is created with full
// subgroups of the device's subgroup size, and that size is this specialization constant
// (forwardplus/light_culling.cpp).
layout(local_size_x_id = TP_FP_SPEC_CULL_LANES) in;

LaTileDepth tileDepth(uvec2 tile) {
    float lo = 2.0, hi = 0.0;
    bool sky = false;
    const uvec2 p0 = tile * kTileSize, size = min(p0 + uvec2(kTileSize), frame.viewport.xy) - p0;
    for (uint i = gl_SubgroupInvocationID; i < size.x * size.y; i += gl_SubgroupSize) {
        const ivec2 p = ivec2(p0 + uvec2(i % size.x, i / size.x));
        for (uint s = 0u; s < uint(kSamples); ++s) {
            float d = TP_LA_DEPTH_FETCH(p, s);
            if (d > 0.0) {
                lo = min(lo, d);
                hi = max(hi, d);
            } else {
                sky = true;
            }
        }
    }
    return laTileDepthOf(subgroupMin(lo), subgroupMax(hi), subgroupAny(sky));
}

// One step's candidate for this lane (valid: within the batch).
struct Candidate {
    bool valid;
    uint lightIndex;
    vec4 sphere;
};

Candidate candidateAt(CullTile c, uint k) {
    Candidate x;
    x.valid = k < c.batchEnd;
    x.lightIndex = 0u;
    x.sphere = vec4(0.0);
    if (x.valid) {
        x.lightIndex = data[c.candidateBase + k];
        x.sphere = candidateSphere(x.lightIndex);
    }
    return x;
}

#ifdef TP_FP_CLUSTERED
// Slice sl's word w0 + j of the current window is sWords[sl * 3 + j], where w0 is the word
// of the first unstored position: a step of at most 64 survivors reaches words w0 .. w0 + 2
// (the device's subgroup size is at most 64: light_culling.cpp).
shared uint sWords[64 * 3]; // kSlices <= 64 (core/lightassign/knobs.cpp)

// Loads the window at a batch's start: a word left partial by the previous batch is
// continued, not restarted. Each lane keeps the slices sl = lane (mod lanes).
void loadWindow(CullTile c, uint stored) {
    for (uint sl = gl_SubgroupInvocationID; sl < kSlices; sl += gl_SubgroupSize) {
        sWords[sl * 3u] = (stored & 31u) != 0u ? masks[c.maskBase + sl * c.maskStride + (stored >> 5u)] : 0u;
        sWords[sl * 3u + 1u] = 0u;
        sWords[sl * 3u + 2u] = 0u;
    }
    memoryBarrierShared();
    barrier();
}

// Sets the survivor's bit at position `pos` (stored >> 5 is the window's first word).
void markSlices(Candidate x, uint pos, uint stored, LaSlicing slicing, bool inOpaque, bool openEnd) {
    const uint slot = (pos >> 5u) - (stored >> 5u);
    const uvec2 range = laLightSlices(x.sphere.xyz, x.sphere.w, slicing);
    for (uint sl = range.x; sl <= range.y; ++sl)
        if (sliceTakes(sl, slicing, inOpaque, openEnd)) atomicOr(sWords[sl * 3u + slot], 1u << (pos & 31u));
}

// After a step that took the stored count from `before` to `after`: writes out the words it
// completed and slides the window to after's word.
void flushWindow(CullTile c, uint before, uint after) {
    memoryBarrierShared();
    barrier();
    const uint w0 = before >> 5u, done = (after >> 5u) - w0; // words w0 .. w0 + done - 1 are complete
    if (done == 0u) return;
    for (uint sl = gl_SubgroupInvocationID; sl < kSlices; sl += gl_SubgroupSize) {
        for (uint j = 0u; j < done; ++j) masks[c.maskBase + sl * c.maskStride + w0 + j] = sWords[sl * 3u + j];
        sWords[sl * 3u] = sWords[sl * 3u + done];
        sWords[sl * 3u + 1u] = 0u;
        sWords[sl * 3u + 2u] = 0u;
    }
    memoryBarrierShared();
    barrier();
}

// The last, partial word of every slice row.
void flushPartial(CullTile c, uint stored) {
    if ((stored & 31u) == 0u) return;
    for (uint sl = gl_SubgroupInvocationID; sl < kSlices; sl += gl_SubgroupSize)
        masks[c.maskBase + sl * c.maskStride + (stored >> 5u)] = sWords[sl * 3u];
}
#endif

void main() {
    const uvec2 tile = gl_WorkGroupID.xy; // the dispatch is exactly tiles.x x tiles.y workgroups
    // 1. Depth bounds, the lists' volumes, the candidates.
    const CullTile c = cullTile(tile, tileDepth(tile));

#if defined(TP_FP_CULL_LINKED)
    // 2. Linked: count this batch's survivors, then one lane allocates each list's nodes.
    uint found0 = 0u, found1 = 0u;
    for (uint k = c.batchFirst; k < c.batchEnd; k += gl_SubgroupSize) {
        const Candidate x = candidateAt(c, k + gl_SubgroupInvocationID);
        found0 += subgroupBallotBitCount(subgroupBallot(x.valid && passes(x.lightIndex, x.sphere, c.volume0)));
        if (kTwoLists)
            found1 += subgroupBallotBitCount(subgroupBallot(x.valid && passes(x.lightIndex, x.sphere, c.volume1)));
    }
    uint base0 = 0u, base1 = 0u;
    if (subgroupElect()) {
        if (found0 > 0u) base0 = atomicAdd(nodeCounter, found0);
        if (found1 > 0u) base1 = atomicAdd(nodeCounter, found1);
    }
    const ListSlots s0 = linkedSlots(found0, subgroupBroadcastFirst(base0), c.prev0);
    const ListSlots s1 = linkedSlots(found1, subgroupBroadcastFirst(base1), c.prev1);
#else
    const ListSlots s0 = arraySlots(c, 0u), s1 = arraySlots(c, 1u);
#endif
    uint count0 = s0.first, count1 = s1.first; // the same on every lane

    // 3. Test and append in candidate (ascending light) order, a subgroup of candidates a step.
#ifdef TP_FP_CLUSTERED
    loadWindow(c, min(count0, s0.capacity));
#endif
    for (uint k = c.batchFirst; k < c.batchEnd; k += gl_SubgroupSize) {
        const Candidate x = candidateAt(c, k + gl_SubgroupInvocationID);
        const bool pass0 = x.valid && passes(x.lightIndex, x.sphere, c.volume0);
        const uvec4 ballot0 = subgroupBallot(pass0);
        const uint pos0 = count0 + subgroupBallotExclusiveBitCount(ballot0);
        if (pass0) store(x.lightIndex, pos0, s0.start, s0.capacity, s0.tail);
        const uint found = subgroupBallotBitCount(ballot0);
#ifdef TP_FP_CLUSTERED
        if (found > 0u) {
            const uint before = min(count0, s0.capacity), after = min(count0 + found, s0.capacity);
            if (pass0 && pos0 < s0.capacity)
                markSlices(x, pos0, before, c.slicing,
                           !kBlendedSpan || passes(x.lightIndex, x.sphere, c.volume1), c.openEnd);
            flushWindow(c, before, after);
        }
#endif
        count0 += found;
        if (kTwoLists) {
            const bool pass1 = x.valid && passes(x.lightIndex, x.sphere, c.volume1);
            const uvec4 ballot1 = subgroupBallot(pass1);
            if (pass1) store(x.lightIndex, count1 + subgroupBallotExclusiveBitCount(ballot1), s1.start, s1.capacity,
                             s1.tail);
            count1 += subgroupBallotBitCount(ballot1);
        }
    }

#ifdef TP_FP_CLUSTERED
    flushPartial(c, min(count0, s0.capacity));
#endif
    if (subgroupElect()) writeTile(c, s0, s1, count0, count1);
}
