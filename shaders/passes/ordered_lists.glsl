// Ordered light lists of the tiled lighting pass (tiled_lighting_main.glsl, which includes this
// after its culling): the survivors of a cull are marked as bits over the candidates they were
// taken from (shared sBits) and compacted in ascending candidate order, never appended with an
// atomic counter. An atomic append orders a list as the GPU happens to schedule the
// invocations, and the shading sums a list in its order: the image then changes in its last
// bits from run to run (it did on an H100 with the opaque list; the transparent index lists of
// --light-cull all were the last such append).
// The includer declares: shared uint sBits[TP_TL_TILE_LIGHT_CAPACITY / 32], sLights[...],
// sCount, sTransparentCount; TP_GROUP; candidateLight/candidateCount (candidates.glsl); under
// TP_TRANSPARENT the buffer tLists, TransparentRun and transparentRun().
#ifndef TP_TL_ORDERED_LISTS_GLSL
#define TP_TL_ORDERED_LISTS_GLSL
#include "include/light_list_walk.glsl"

// Survivors of sBits' words [0, w).
uint survivorsBefore(uint w) {
    uint n = 0u;
    for (uint v = 0u; v < w; ++v) n += bitCount(sBits[v]);
    return n;
}

// The survivors marked in sBits[0, words) (bit i: candidate first + i) in ascending candidate
// order (after the culling's barrier; a barrier must follow): each invocation takes whole
// words and places their lights after the survivors of every earlier word, from list position
// `placed` on. toShared: into sLights (the batch's opaque list);
// otherwise into the transparent run at `start`, positions from `capacity` on left out (the
// caller counts them as dropped).
// Survivor `light` at position `pos` of the shared list or of the transparent run at `start`
// (positions from `capacity` on left out).
void storeSurvivor(bool toShared, uint pos, uint light, uint start, uint capacity) {
    if (toShared) sLights[pos] = light;
#ifdef TP_TRANSPARENT
    else if (pos < capacity) tLists[start + pos] = light;
#endif
}

void compactBits(uint tileIndex, uint first, uint words, uint placed, bool toShared, uint start, uint capacity) {
    for (uint w = gl_LocalInvocationIndex; w < words; w += TP_GROUP * TP_GROUP) {
        uint pos = placed + survivorsBefore(w);
        uint bits = sBits[w];
        TP_FOR_EACH_BIT(bits, lsb, storeSurvivor(toShared, pos++, candidateLight(tileIndex, first + w * 32u + uint(lsb)), start, capacity);)
    }
}

#ifndef TP_LISTS_ONLY
// The batch's survivors into sLights, in ascending candidate order (compactBits).
void compactList(uint tileIndex) {
    const uint first = draw.TP_TL_LIGHT_FIRST, end = min(draw.TP_TL_LIGHT_END, candidateCount(tileIndex));
    const uint words = end > first ? (end - first + 31u) / 32u : 0u;
    compactBits(tileIndex, first, words, 0u, true, 0u, 0u);
    if (gl_LocalInvocationIndex == 0u) sCount = survivorsBefore(words);
}
#endif

#ifdef TP_TRANSPARENT
// Index lists (--light-cull all, first batch): every light against the tile's blended range,
// one shared-capacity chunk of candidates at a time through sBits and compactBits, so the run
// holds its lights in ascending order as the opaque list does (the blended pass sums them in
// run order). Called by every invocation (barriers) once sBits is free (the opaque list
// compacted, then a barrier); ends with a barrier.
void cullTransparentIndices(uvec2 tile) {
    const uint tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
    const TransparentRun t = transparentRun(tile);
    const TileBox box = makeTileBox(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, t.frustum);
    const uint candidates = t.blended.any ? candidateCount(tileIndex) : 0u; // none where no blended fragment is
    uint placed = 0u; // the earlier chunks' survivors: the same in every invocation
    for (uint first = 0u; first < candidates; first += TP_TL_TILE_LIGHT_CAPACITY) {
        const uint n = min(candidates - first, TP_TL_TILE_LIGHT_CAPACITY), words = (n + 31u) / 32u;
        for (uint w = gl_LocalInvocationIndex; w < words; w += TP_GROUP * TP_GROUP) sBits[w] = 0u;
        barrier();
        for (uint i = gl_LocalInvocationIndex; i < n; i += TP_GROUP * TP_GROUP)
            if (lightInTileAndBox(sceneLight(candidateLight(tileIndex, first + i)), t.frustum, box, frame.view))
                atomicOr(sBits[i >> 5u], 1u << (i & 31u));
        barrier();
        compactBits(tileIndex, first, words, placed, false, t.start, t.capacity);
        placed += survivorsBefore(words);
        barrier(); // every invocation has read sBits before the next chunk clears it
    }
    if (gl_LocalInvocationIndex == 0u) sTransparentCount = placed;
}
#endif

#endif
