// The tiled lighting pass, part 4 of 4 (passes/tiled_lighting_inputs.glsl lists the parts):
// the culling, the ordered lists, the clustered slice rows and main.

void cull(uvec2 tile, bool hasGeometry) {
    uint groupSize = TP_GROUP * TP_GROUP;
    vec2 size = vec2(frame.viewport.xy);
    float nearDepth = laTileNearDepth(), farDepth = laTileFarDepth();
    TileFrustum f = laOpaqueFrustum(tile, kTileSize, size, frame.invProj, nearDepth, farDepth);
    // The box of each range as well as its planes, as Forward+ culls: without it a light near
    // a corner of the tile's frustum stayed in the lists (12.6 transparent lights per tile
    // against Forward+'s 9.2 on the courtyard at 480x270, 1,024 lights; docs/deferred.md).
    const TileBox box = makeTileBox(tile, kTileSize, size, frame.invProj, f);
    uint tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
    uint candidates = candidateCount(tileIndex);
#ifdef TP_TRANSPARENT
    const TransparentRun t = transparentRun(tile);
    const TileBox tBox = makeTileBox(tile, kTileSize, size, frame.invProj, t.frustum);
#endif
#ifndef TP_LISTS_ONLY
    // A survivor sets its bit in sBits (bit i: this batch's candidate i); compactList turns
    // the bits into the list.
    const uint first = draw.TP_TL_LIGHT_FIRST, end = min(draw.TP_TL_LIGHT_END, candidates);
    for (uint i = first + gl_LocalInvocationIndex; hasGeometry && i < end; i += groupSize) {
        uint light = candidateLight(tileIndex, i);
        if (lightInTileAndBox(sceneLight(light), f, box, frame.view)) atomicOr(sBits[(i - first) >> 5u], 1u << ((i - first) & 31u));
    }
#endif
#ifdef TP_TRANSPARENT
    // kTransparentMasks: every candidate, once (first batch), sets its bit in the tile's mask
    // (atomicOr: the same mask whatever the order); a loop of candidates / 64 iterations per
    // invocation, none where no blended fragment is shaded. Index lists: cullTransparentIndices.
    for (uint i = gl_LocalInvocationIndex; kTransparentMasks && firstBatch() && t.blended.any && i < candidates; i += groupSize) {
        if (lightInTileAndBox(sceneLight(candidateLight(tileIndex, i)), t.frustum, tBox, frame.view)) {
            atomicAdd(sTransparentCount, 1u);
            if ((i >> 5u) < t.capacity) atomicOr(tLists[t.start + (i >> 5u)], 1u << (i & 31u)); // cleared in main
            else atomicAdd(sMaskDropped, 1u); // counted, never silent
        }
    }
#endif
}

// The culling's survivors into ordered lists: compactList (the opaque list in sLights) and
// cullTransparentIndices (the transparent index lists).
#include "passes/ordered_lists.glsl"

#if defined(TP_TRANSPARENT) && !defined(TP_LISTS_ONLY)
// Clustered: the slice rows of tile `tileIndex`'s transparent list, for the blended pass
// (passes/blended_forward.frag): front slices from the nearest blended fragment to the nearest opaque
// depth (light_assign.glsl: laFrontNear), range
// slices over the opaque range (light_assign.glsl: laFrontSlices). A light's bit is set in
// every slice its padded depth interval reaches (laLightSlices: conservative). Each
// invocation owns whole 32-light words and writes each word of every row once: no clear,
// no atomics. After memoryBarrierBuffer + barrier (the list is complete).
uint gWordBits[64]; // kSlices <= 64 (core/lightassign/knobs.cpp)
void writeTransparentSlices(uint tileIndex) {
    const uint tileCount = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    const uint offset = tOffsets[tileIndex];
    const uint kept = min(sTransparentCount, tOffsets[tileIndex + 1u] - offset);
    const uint start = laListStart(tileCount, offset);
    const uint words = (kept + 31u) / 32u;
    const bool geometry = laTileHasGeometry();
    const float sliceNear = geometry ? max(-viewZFromDepth(laTileNearDepth(), frame.invProj), 1e-30) : 1e30;
    const float sliceFar = geometry ? -viewZFromDepth(laTileFarDepth(), frame.invProj) : 1e30;
    const uint front = laFrontSlices(kSlices, true);
    const LaSlicing s = laSlicing(laFrontNear(tileBlendedBounds(tileIndex), sliceNear), sliceNear,
                                  laSliceScale(sliceNear, sliceFar, kSlices, front), kSlices, front);
    const uint base = tlClusterRowsBase(tileCount, offset, tileIndex, kSlices);
    for (uint w = gl_LocalInvocationIndex; w < words; w += TP_GROUP * TP_GROUP) {
        for (uint sl = 0u; sl < kSlices; ++sl) gWordBits[sl] = 0u;
        for (uint b = 0u; b < 32u && w * 32u + b < kept; ++b) {
            LightGpu light = sceneLight(tLists[start + w * 32u + b]);
            vec4 sphere = lightSphereView(light, frame.view);
            uvec2 range = light.type == TP_LIGHT_DIRECTIONAL ? uvec2(0u, kSlices - 1u)
                                                             : laLightSlices(sphere.xyz, sphere.w, s);
            for (uint sl = range.x; sl <= range.y; ++sl) gWordBits[sl] |= 1u << b;
        }
        for (uint sl = 0u; sl < kSlices; ++sl) tMasks[base + sl * words + w] = gWordBits[sl];
    }
    if (gl_LocalInvocationIndex == 0u) {
        tMasks[2u * tileIndex] = floatBitsToUint(s.sliceNear);
        tMasks[2u * tileIndex + 1u] = floatBitsToUint(s.sliceScale);
    }
}
#endif

// The pixels of this invocation: (k % perAxis, k / perAxis) steps of TP_GROUP.
ivec2 pixelOf(uvec2 tile, uint k) {
    uint perAxis = kTileSize / TP_GROUP;
    uvec2 local = gl_LocalInvocationID.xy + uvec2(k % perAxis, k / perAxis) * TP_GROUP;
    return ivec2(tile * kTileSize + local);
}

bool insideViewport(ivec2 p) { return all(lessThan(uvec2(p), frame.viewport.xy)); }

// The pixel of a listed edge (sEdgePixels: its index in the tile).
ivec2 listedPixel(uvec2 tile, uint local) {
    return ivec2(tile * kTileSize + uvec2(local % kTileSize, local / kTileSize));
}

// The tile's shared state cleared, its depth bounds read and (clustered) its slices set.
void beginTile(uvec2 tile) {
    if (gl_LocalInvocationIndex == 0u) {
        laDepthBoundsLoad(tileDepth[tile.y * gl_NumWorkGroups.x + tile.x]);
        sCount = 0u;
        sTransparentCount = 0u;
        sMaskDropped = 0u;
        sEdges = 0u;
        sFlatEdges = 0u;
        sCompositeEdges = 0u;
    }
    if (kSlices > 0u) // every word a row may use: the host keeps slices * rows within the array
        for (uint i = gl_LocalInvocationIndex; i < kMaskWords; i += TP_GROUP * TP_GROUP) sMask[i] = 0u;
    for (uint i = gl_LocalInvocationIndex; i < TP_TL_TILE_LIGHT_CAPACITY / 32u; i += TP_GROUP * TP_GROUP) sBits[i] = 0u;
    barrier();
    if (kSlices > 0u && gl_LocalInvocationIndex == 0u) {
        // Slices over the tile's opaque range (laSliceOf; nothing to slice without geometry).
        bool geometry = laTileHasGeometry();
        sSliceNear = geometry ? max(-viewZFromDepth(laTileNearDepth(), frame.invProj), 1e-30) : 1e30;
        float far = geometry ? -viewZFromDepth(laTileFarDepth(), frame.invProj) : 1e30;
        sSliceScale = laSliceScale(sSliceNear, far, kSlices, 0u);
    }
#ifdef TP_TRANSPARENT
    if (kTransparentMasks && firstBatch()) {
        // The tile's candidate bitmask starts empty (cull sets its bits with atomicOr).
        uint t = tile.y * gl_NumWorkGroups.x + tile.x;
        uint start = laListStart(gl_NumWorkGroups.x * gl_NumWorkGroups.y, tOffsets[t]);
        for (uint w = gl_LocalInvocationIndex; w < tOffsets[t + 1u] - tOffsets[t]; w += TP_GROUP * TP_GROUP)
            tLists[start + w] = 0u;
        memoryBarrierBuffer();
        barrier();
    }
#endif
}

// The tile's lists: the culling, the opaque list in sLights, the transparent list and
// (clustered) the slice masks and rows. Ends after a barrier: the lists are complete.
void buildLists(uvec2 tile) {
    cull(tile, laTileHasGeometry());
#ifndef TP_LISTS_ONLY
    barrier(); // every survivor's bit
    compactList(tile.y * gl_NumWorkGroups.x + tile.x);
#endif
#ifdef TP_TRANSPARENT
    if (!kTransparentMasks && firstBatch()) { // uniform over the group
        barrier(); // compactList has read sBits
        cullTransparentIndices(tile);
    }
#endif
#ifndef TP_LISTS_ONLY
#ifdef TP_TL_COMPOSITES_BLENDED
    memoryBarrierBuffer(); // the transparent list, which the blended fragments are lit from
#elif defined(TP_TRANSPARENT)
    if (kSlices > 0u) memoryBarrierBuffer(); // the transparent list, for writeTransparentSlices
#endif
    barrier();
    if (kSlices > 0u) {
        markSlices();
#if defined(TP_TRANSPARENT) && !defined(TP_TL_COMPOSITES_BLENDED) // no blended pass to read slice rows
        if (firstBatch()) writeTransparentSlices(tile.y * gl_NumWorkGroups.x + tile.x);
#endif
        barrier();
    }
#endif
}

#ifndef TP_LISTS_ONLY
// Under MSAA, after the rest: the tile's edge pixels, kSamples slots a pixel, one slot an
// invocation. Slot k of a pixel lights its k-th surface (edgeItemSample: a sample, or at the
// visibility buffer's pixel rate a distinct triangle; a slot past the pixel's surfaces idles),
// then one invocation a pixel gathers each sample's radiance (edgeSampleItem) and finishes it
// (finishEdge). Lit an invocation a pixel instead, a pixel of four surfaces held its
// subgroup for four shades while most lanes had one or none (Lauritzen 2010 compacts edges
// for the same reason; the H200's visibility buffer at 4x: docs/visbuffer.md). The same shade
// of the same surface either way: the same image. A group (64 or 256) is a multiple of
// kSamples (at most 8), so a pixel's slots are in one round.
void shadeEdges(uvec2 tile) {
    const uint groupSize = TP_GROUP * TP_GROUP, lane = gl_LocalInvocationIndex;
    const uint slots = sFlatEdges * kSamples; // uniform: after the barrier that ends the listing
    for (uint first = 0u; first < slots; first += groupSize) {
        const uint i = first + lane, e = i / kSamples, k = i % kSamples;
        const bool listed = e < sFlatEdges;
        ivec2 p = ivec2(0);
        vec3 c = vec3(0.0);
        if (listed) {
            const uint local = sEdgePixels[e];
            p = listedPixel(tile, local);
            const uint s = edgeItemSample(p, k);
            if (s < kSamples) c = shadeEdgeSample(p, s);
        }
        sSlot[3u * lane] = c.x;
        sSlot[3u * lane + 1u] = c.y;
        sSlot[3u * lane + 2u] = c.z;
        barrier();
        // The round's pixels finished by its first invocations, one a pixel: adjacent lanes, so
        // that the finish fills whole subgroups.
        const uint f = first / kSamples + lane;
        if (lane < groupSize / kSamples && f < sFlatEdges) {
            const uint local = sEdgePixels[f];
            const ivec2 q = listedPixel(tile, local);
            vec3 samples[8];
            for (uint s = 0u; s < kSamples; ++s) {
                const uint at = 3u * (lane * kSamples + edgeSampleItem(q, s));
                samples[s] = vec3(sSlot[at], sSlot[at + 1u], sSlot[at + 2u]);
            }
            finishEdge(q, samples);
        }
        barrier(); // the slots are read before the next round writes them
    }
}

// Round 0 shades the tile's pixels that are not edges and lists the edges, which are shaded
// after the rest: flattened (shadeEdges), or one pixel an invocation (shadeEdgePixel) where
// edgeComposites says so: the visibility buffer's --vis-blended compute, for the edges whose
// pixel has blended fragments to composite with --vis-edges split (auto on a GPU) and for every
// edge with pixel (auto on a CPU device; vis_shared.h: TP_VIS_SPEC_SPLIT_EDGES). Flattened, a
// composite (one invocation a pixel, after the slots) ran a round at a time and took the H200's 1080p 4x resolve from 1.66 to 2.00 ms,
// while an edge with nothing to composite is 8 of 9 there; on lavapipe flattening those 8 took
// the 4x resolve from 1,607 to 1,976 ms. At --msaa-shading sample every pixel with geometry is
// an edge: nothing to compact, shaded in place. The same shade of the same pixel whichever way:
// the same image. Each round is a loop of its own around its one call: lavapipe runs both sides
// of every branch, so round 0 carried the edges' shading (every sample lit, and the blended
// composite) in every pixel while it was one loop's other branch (docs/visbuffer.md, "Edges in
// a loop of their own", "Edges with nothing to composite, flattened").
void shadeTile(uvec2 tile) {
    uint pixelsPerInvocation = (kTileSize / TP_GROUP) * (kTileSize / TP_GROUP);
    // A later batch with no light in this tile adds nothing (sCount is uniform here), unless
    // blended fragments composited here may have lights in it.
#ifdef TP_TL_COMPOSITES_BLENDED
    uint shadedPixels = firstBatch() || sCount > 0u || transparentRun(tile).blended.any ? pixelsPerInvocation : 0u;
#else
    uint shadedPixels = firstBatch() || sCount > 0u ? pixelsPerInvocation : 0u;
#endif
    const uint groupSize = TP_GROUP * TP_GROUP;
    const bool listEdges = kSamples > 1u && !kEverySample;
    for (uint k = 0u; k < shadedPixels; ++k) {
        ivec2 p = pixelOf(tile, k);
        bool shaded = insideViewport(p);
        const bool edge = shaded && kSamples > 1u && isEdge(p);
#ifdef TP_DEBUG
        vec2 rm = debugRoughMetal(p);
        if (shaded && firstBatch()) imageStore(debugOut, p, vec4(edge ? 1.0 : 0.0, rm, 1.0));
#endif
        if (edge && listEdges) { // one atomic an edge: sEdges is their sum (below)
            uvec2 local = uvec2(p) - tile * kTileSize;
            const uint e = edgeComposites(p) ? kEdgeWords - 1u - atomicAdd(sCompositeEdges, 1u)
                                             : atomicAdd(sFlatEdges, 1u);
            sEdgePixels[e] = local.y * kTileSize + local.x;
            shaded = false; // after the rest
        } else if (edge) {
            atomicAdd(sEdges, 1u);
        }
        if (!shaded) continue;
        // A listed edge never reaches here: the edge call folds away with listEdges.
        if (!listEdges && edge) shadeEdgePixel(p);
        else shadePixel(p);
    }
    barrier(); // round 0's lists complete (their counts are uniform after it)
    // The statistics' edge count, read after the pass's last barrier (main: writeTileStats).
    if (listEdges && gl_LocalInvocationIndex == 0u) sEdges = sFlatEdges + sCompositeEdges;
    if (listEdges) {
        const uint rounds = (sCompositeEdges + groupSize - 1u) / groupSize;
        for (uint k = 0u; k < rounds; ++k) {
            const uint e = k * groupSize + gl_LocalInvocationIndex;
            if (e < sCompositeEdges) shadeEdgePixel(listedPixel(tile, sEdgePixels[kEdgeWords - 1u - e]));
        }
        shadeEdges(tile); // its slots are its own: no barrier needed after the rounds above
    }
}
#endif

// The tile's statistics (and, first batch, its transparent list's header), by one invocation.
void writeTileStats(uvec2 tile) {
    uint tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
    if (firstBatch()) {
        tileStats[tileIndex] = uvec4(sCount, sTransparentCount, sEdges, 0u);
#ifdef TP_TRANSPARENT
        uint capacity = tOffsets[tileIndex + 1u] - tOffsets[tileIndex];
        // Masks: every survivor has its bit (the mask covers every candidate).
        uint kept = kTransparentMasks ? sTransparentCount - sMaskDropped : min(sTransparentCount, capacity);
        tLists[laHeaderWord(tileIndex, TP_LA_COUNT)] = kept;
        tLists[laHeaderWord(tileIndex, TP_LA_START)] =
            laListStart(gl_NumWorkGroups.x * gl_NumWorkGroups.y, tOffsets[tileIndex]);
        tLists[laHeaderWord(tileIndex, TP_LA_DROPPED)] = sTransparentCount - kept;
        tLists[laHeaderWord(tileIndex, TP_LA_FOUND)] = sTransparentCount;
#endif
    } else {
        tileStats[tileIndex].x += sCount;
    }
    // Overflow: the tile met more lights than one shared list holds (its lights came
    // from several batches; none is dropped).
    if (tileStats[tileIndex].x > TP_TL_TILE_LIGHT_CAPACITY) tileStats[tileIndex].w = 1u;
}

void main() {
    uvec2 tile = gl_WorkGroupID.xy;
    beginTile(tile);
    buildLists(tile);
#ifndef TP_LISTS_ONLY
    shadeTile(tile);
#endif
    barrier();
    if (gl_LocalInvocationIndex == 0u) writeTileStats(tile);
}
