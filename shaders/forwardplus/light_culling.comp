#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+ light culling: one workgroup per tile (tile size 8, 16 or 32: a specialization
// constant), 64 invocations.
//  1. Depth bounds: min/max over every sample of every pixel that has geometry (depth > 0);
//     a tile with no geometry (sky) gets an empty opaque list. The transparent list (only
//     when the scene has blended materials) spans the near plane to the tile's farthest
//     depth, unbounded where any sample sees the sky.
//  2. Point/spot lights (every one, or only the tile's binned candidates) are tested in chunks of TP_FP_CHUNK_LIGHTS against the tile
//     sub-frustum's bounding box and the sub-frustum itself (include/tile_culling.glsl via light_assign.glsl);
//     survivors set a bit in shared memory.
//  3. Each chunk's bitmask is compacted in light-index order (a prefix of popcounts, then
//     laStoreWord of include/light_assign.glsl for the compact and fixed layouts), so
//     every layout stores the same lights in the same order and gives the same image.
// Directional lights are never culled: the shading pass loops over them separately.
// Layout (one shader variant each):
//  compact: the tile's slots [offset[t], offset[t+1]) come from a conservative CPU bound
//           (sphere vs the depth-unbounded tile frustum), so nothing can be dropped; a
//           count that exceeded it anyway would be reported in `dropped`, never silent.
//  fixed:   tileCapacity slots per tile; lights beyond it are counted in `dropped`.
//  linked:  nodes {light, next} from a pool with one atomic allocation per chunk; chunks
//           are processed last to first and prepended, so a walk of `count` nodes from the
//           head visits lights in index order.
#include "include/shared.h"
#include "forwardplus/forwardplus_shared.h"
#include "include/scene_bindings.glsl"

// One of TP_FP_CULL_COMPACT, TP_FP_CULL_FIXED, TP_FP_CULL_LINKED is defined (1) per variant.
#if !defined(TP_FP_CULL_FIXED) && !defined(TP_FP_CULL_LINKED) && !defined(TP_FP_CULL_COMPACT)
#define TP_FP_CULL_COMPACT 1
#endif

// 64 invocations whatever the tile size: enough for the compaction (2 lists x 32 words),
// and few enough that a barrier is cheap on lavapipe (it runs a workgroup as 8-lane
// coroutines that switch at every barrier). Each invocation reads (tile / 8)^2 pixels.
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = TP_FP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_FP_SPEC_SAMPLES) const int kSamples = 1;
layout(constant_id = TP_FP_SPEC_TWO_LISTS) const bool kTwoLists = false;
// Binned (--light-cull binned): the tile tests only its candidates, the lights whose
// conservative tile rectangle covers it (core/lightassign/tile_candidates.h, ascending);
// otherwise every local light. Same test, same order: the same lists either way.
layout(constant_id = TP_FP_SPEC_BINNED) const bool kBinned = false;
// Clustered (TP_FP_CLUSTERED, compact layout only): one list per tile over its depth span
// (the near plane or its nearest depth, to its farthest), and per depth slice a bitmask
// over that list: bit i of slice s is set when light i of the list can reach the slice.
layout(constant_id = TP_FP_SPEC_SLICES) const uint kSlices = 16u;
layout(constant_id = TP_FP_SPEC_SPAN_FROM_NEAR) const bool kSpanFromNear = false;

layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_TILES) writeonly buffer TileBlock {
    FpTileLists tiles[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_INDICES) writeonly buffer IndexBlock {
    uint indices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_PARAMS) readonly buffer ParamBlock {
    FpParams params;
    uint data[];
};
#ifdef TP_FP_DEPTH_MS
layout(set = TP_SET_PASS, binding = TP_FP_BINDING_DEPTH) uniform sampler2DMS depthImage;
#else
layout(set = TP_SET_PASS, binding = TP_FP_BINDING_DEPTH) uniform sampler2D depthImage;
#endif
#ifdef TP_FP_DEPTH_MS
#define TP_LA_DEPTH_FETCH(p, s) texelFetch(depthImage, p, int(s)).r
#else
#define TP_LA_DEPTH_FETCH(p, s) texelFetch(depthImage, p, 0).r
#endif
// Candidate k of this tile is data[gCandidateBase + k]: the k-th local light (after the
// directional ones, never culled), or the k-th of the tile's binned candidates.
uint gCandidateBase;
#define TP_LA_LIST_STORE(slot, k) indices[slot] = data[gCandidateBase + (k)]
#include "include/light_assign.glsl"
#ifdef TP_FP_CLUSTERED
// Cleared to 0 before this pass (cluster_mask_clear); bits are set with atomicOr, whose
// result does not depend on the order of the invocations.
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_CLUSTER_MASKS) buffer MaskBlock {
    uint masks[];
};

// Like laStoreWord, and also sets the survivors' bits in the slices their sphere reaches.
uint clusterStoreWord(uint bits, uint firstCandidate, uint listStart, uint pos, uint capacity, uint maskBase,
                      uint maskStride, float sliceNear, float sliceScale) {
    for (uint b = 0u; b < 32u && bits != 0u; ++b) {
        int lsb = findLSB(bits);
        bits &= bits - 1u;
        if (pos < capacity) {
            uint lightIndex = data[gCandidateBase + firstCandidate + uint(lsb)];
            indices[listStart + pos] = lightIndex;
            LightGpu light = lights[lightIndex];
            vec3 c = (frame.view * vec4(light.position, 1.0)).xyz;
            float r = light.range + TP_TILE_CULL_PAD * (light.range + length(c)); // lightInTile's padding
            uvec2 range = laLightSlices(c, r, sliceNear, sliceScale, kSlices);
            for (uint sl = range.x; sl <= range.y; ++sl)
                atomicOr(masks[maskBase + sl * maskStride + (pos >> 5u)], 1u << (pos & 31u));
        }
        ++pos;
    }
    return pos;
}
#endif
#ifdef TP_FP_CULL_LINKED
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_COUNTER) buffer CounterBlock {
    uint nodeCounter;
};
#endif

shared TileFrustum sFrustum[2]; // opaque, transparent
shared TileBox sBox[2];         // their view-space bounding boxes
// Survivor bitmasks, triple-buffered by chunk so that the compact/fixed layouts need a
// single barrier per chunk (buffer (c+1)%3 is cleared while chunk c is tested; its last
// readers, chunk c-2's compaction, finished before chunk c-1's barrier).
shared uint sBits[3][2][TP_FP_CHUNK_WORDS];
shared uint sCount[2];   // survivors so far (kept + dropped)
shared uint sDropped[2];
shared uint sNodeBase[2]; // linked: first node of this chunk
shared uint sKept[2];     // linked: nodes of this chunk that fit in the pool
shared uint sHead[2];     // linked: current head

const uint kNoNode = 0xffffffffu;

void main() {
    const uint groupSize = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    const uint tileSize = kTileSize;
    const uint lid = gl_LocalInvocationIndex;
    const uvec2 tile = gl_WorkGroupID.xy;
    const uint tileIndex = tile.y * params.tiles.x + tile.x;
    const uint numLists = kTwoLists ? 2u : 1u;

    laDepthBoundsBegin();
    if (lid == 0u) {
        for (uint l = 0u; l < 2u; ++l) {
            sCount[l] = 0u;
            sDropped[l] = 0u;
            sHead[l] = kNoNode;
        }
    }
    if (lid < TP_FP_CHUNK_WORDS) {
        sBits[0][0][lid] = 0u;
        sBits[0][1][lid] = 0u;
    }
    barrier();

    // 1. Depth bounds over every sample (include/light_assign.glsl).
    uvec2 viewport = frame.viewport.xy;
    laDepthBoundsReduce(tile, tileSize, viewport, uint(kSamples));
    barrier();

    const bool hasGeometry = laTileHasGeometry();
    const float nearDepth = laTileNearDepth();
    const float farDepth = laTileFarDepth();
    // The sub-frusta are the same for the whole tile: one invocation builds them.
    float transparentFar = laTransparentFarDepth(hasGeometry, laTileSeesSky(), farDepth);
#ifdef TP_FP_CLUSTERED
    // The span: the opaque range, or from the near plane (blended surfaces lie anywhere in
    // front of the opaque ones). Slices are exponential from its near end to the farthest
    // opaque depth (to 1,000 x the near end without geometry); the last one is unbounded.
    const bool listTests = kSpanFromNear || hasGeometry;
    const float spanNearDepth = kSpanFromNear ? 1.0 : nearDepth;
    const float spanFarDepth = kSpanFromNear ? transparentFar : farDepth;
    const float sliceNear = max(-viewZFromDepth(spanNearDepth, frame.invProj), 1e-30);
    const float sliceFar = hasGeometry ? -viewZFromDepth(farDepth, frame.invProj) : 1000.0 * sliceNear;
    const float sliceScale = laSliceScale(sliceNear, sliceFar, kSlices);
    const uint maskBase = data[params.lists.w + tileIndex];
    const uint maskStride = (data[params.lists.w + tileIndex + 1u] - maskBase) / kSlices;
#else
    const bool listTests = hasGeometry;
    const float spanNearDepth = nearDepth, spanFarDepth = farDepth;
#endif
    if (lid == 0u) {
        const vec2 viewportSize = vec2(viewport);
        sFrustum[0] = laOpaqueFrustum(tile, tileSize, viewportSize, frame.invProj, spanNearDepth, spanFarDepth);
        sBox[0] = makeTileBox(tile, tileSize, viewportSize, frame.invProj, sFrustum[0]);
        if (kTwoLists) {
            sFrustum[1] = laTransparentFrustum(tile, tileSize, viewportSize, frame.invProj, transparentFar);
            sBox[1] = makeTileBox(tile, tileSize, viewportSize, frame.invProj, sFrustum[1]);
        }
    }
    barrier();
    const TileFrustum opaqueFrustum = sFrustum[0];
    const TileFrustum transparentFrustum = sFrustum[kTwoLists ? 1 : 0];
    const TileBox opaqueBox = sBox[0];
    const TileBox transparentBox = sBox[kTwoLists ? 1 : 0];

    const uint directionalCount = params.lights.x;
    uint localCount = params.lights.y; // candidates of this tile
    gCandidateBase = directionalCount;
    if (kBinned) {
        const uint first = data[params.lights.z + tileIndex];
        localCount = data[params.lights.z + tileIndex + 1u] - first;
        gCandidateBase = params.lists.z + first;
    }
    uint capacity;
    uint start[2];
#if defined(TP_FP_CULL_COMPACT)
    uint offset = data[params.lights.z + tileIndex];
    capacity = data[params.lights.z + tileIndex + 1u] - offset;
    start[0] = offset;
    start[1] = params.lists.x + offset;
#elif defined(TP_FP_CULL_FIXED)
    capacity = params.lights.w;
    start[0] = tileIndex * capacity;
    start[1] = params.lists.x + tileIndex * capacity;
#else
    capacity = 0xffffffffu; // bounded by the pool instead
    start[0] = 0u;
    start[1] = 0u;
#endif

    const uint list = lid / TP_FP_CHUNK_WORDS; // compaction: invocation (list, word)
    const uint word = lid % TP_FP_CHUNK_WORDS;
    const bool compacts = list < numLists;
    uint running = 0u; // compact/fixed: survivors of this invocation's list so far
    const uint chunkCount = (localCount + TP_FP_CHUNK_LIGHTS - 1u) / TP_FP_CHUNK_LIGHTS;
    for (uint step = 0u; step < chunkCount; ++step) {
        const uint buf = step % 3u;
#ifdef TP_FP_CULL_LINKED
        const uint chunk = chunkCount - 1u - step; // prepend: last chunk first
#else
        const uint chunk = step;
#endif
        const uint base = chunk * TP_FP_CHUNK_LIGHTS;
        if (lid < TP_FP_CHUNK_WORDS) {
            sBits[(step + 1u) % 3u][0][lid] = 0u;
            sBits[(step + 1u) % 3u][1][lid] = 0u;
        }

        // 2. Test this chunk's lights, groupSize at a time.
        const uint inChunk = min(TP_FP_CHUNK_LIGHTS, localCount - base);
        for (uint i = lid; i < inChunk; i += groupSize) {
            LightGpu light = lights[data[gCandidateBase + base + i]];
            uint bit = 1u << (i & 31u);
            if (listTests && lightInTileBox(light, opaqueBox, frame.view) &&
                lightInTile(light, opaqueFrustum, frame.view))
                atomicOr(sBits[buf][0][i >> 5u], bit);
            if (kTwoLists && lightInTileBox(light, transparentBox, frame.view) &&
                lightInTile(light, transparentFrustum, frame.view))
                atomicOr(sBits[buf][1][i >> 5u], bit);
        }
        barrier();

        // 3. Compaction: invocation (list, word) writes the survivors of one 32-light word
        //    after those of the words before it.
        uint prefix = 0u, bits = 0u, chunkTotal = 0u;
        if (compacts) {
            for (uint j = 0u; j < TP_FP_CHUNK_WORDS; ++j) {
                uint n = bitCount(sBits[buf][list][j]);
                prefix += j < word ? n : 0u;
                chunkTotal += n;
            }
            bits = sBits[buf][list][word];
        }
#ifdef TP_FP_CULL_LINKED
        // One allocation per chunk and list; nodes past the pool are dropped and counted
        // (the pool is sized so that it cannot happen).
        if (compacts && word == TP_FP_CHUNK_WORDS - 1u) {
            uint nodeBase = chunkTotal > 0u ? atomicAdd(nodeCounter, chunkTotal) : 0u;
            uint pool = params.lists.y;
            uint room = nodeBase < pool ? pool - nodeBase : 0u;
            uint kept = min(chunkTotal, room);
            sNodeBase[list] = nodeBase;
            sKept[list] = kept;
            sDropped[list] += chunkTotal - kept;
        }
        barrier();
        if (compacts && bits != 0u) {
            uint nodeBase = sNodeBase[list];
            uint kept = sKept[list];
            uint oldHead = sHead[list];
            uint rank = prefix;
            for (uint b = 0u; b < 32u && bits != 0u; ++b) {
                int lsb = findLSB(bits);
                bits &= bits - 1u;
                if (rank < kept) {
                    uint node = nodeBase + rank;
                    indices[2u * node] = data[gCandidateBase + base + word * 32u + uint(lsb)];
                    indices[2u * node + 1u] = rank + 1u < kept ? node + 1u : oldHead;
                }
                ++rank;
            }
        }
        barrier();
        if (compacts && word == TP_FP_CHUNK_WORDS - 1u && sKept[list] > 0u) {
            sHead[list] = sNodeBase[list];
            sCount[list] += sKept[list];
        }
        barrier();
#else
#ifdef TP_FP_CLUSTERED
        if (compacts && bits != 0u)
            clusterStoreWord(bits, base + word * 32u, start[list], running + prefix, capacity, maskBase, maskStride,
                             sliceNear, sliceScale);
#else
        if (compacts && bits != 0u)
            laStoreWord(bits, base + word * 32u, start[list], running + prefix, capacity);
#endif
        running += chunkTotal;
#endif
    }
#ifndef TP_FP_CULL_LINKED
    if (compacts && word == 0u) sCount[list] = running;
#endif
    barrier();

    if (lid == 0u) {
        FpTileLists t;
        for (uint l = 0u; l < 2u; ++l) {
#ifdef TP_FP_CULL_LINKED
            t.list[l].count = sCount[l];
            t.list[l].start = sHead[l];
            t.list[l].dropped = sDropped[l];
#else
            t.list[l].count = min(sCount[l], capacity);
            t.list[l].start = start[l];
            t.list[l].dropped = sCount[l] - t.list[l].count;
#endif
            t.list[l].found = t.list[l].count + t.list[l].dropped;
        }
#ifdef TP_FP_CLUSTERED
        t.sliceNear = sliceNear;
        t.sliceScale = sliceScale;
#else
        t.sliceNear = 0.0;
        t.sliceScale = 0.0;
#endif
        t.nearDepth = hasGeometry ? nearDepth : 0.0;
        t.farDepth = hasGeometry ? farDepth : 0.0;
        tiles[tileIndex] = t;
    }
}
