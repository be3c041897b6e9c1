#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred lighting (Andersson 2009, Uncharted; Lauritzen 2010): one workgroup per
// tile. (1) the tile's depth bounds from the G-buffer depth (every sample), (2) the lights
// of this dispatch's batch (push constant: [first, end), at most the shared capacity) that
// reach the tile's sub-frustum are culled into a shared list, in ascending candidate order
// (compactList: the same list, and so the same opaque lighting, on every run), (3) every pixel of the tile
// is shaded from that list: the first batch writes hdr (with ambient and emissive), later
// batches add to it. Under MSAA a pixel whose samples differ (an edge) is shaded per
// sample, every other pixel once. Blended scenes also get each tile's transparent light
// list (every light, first batch only), culled against the tile's blended depth bounds
// (include/light_assign.glsl: LaBlendedBounds; empty where no blended fragment is shaded),
// in ascending candidate order too (a bitmask over the candidates, or cullTransparentIndices),
// stored in the compact layout of
// include/light_assign.h: per-tile runs sized on the CPU by a conservative bound, so the
// buffer grows with the lights the lists can hold, never with tiles x lights.
//   TP_EMISSIVE (0/1): the G-buffer has an emissive target.
//   TP_MSAA: the G-buffer is per-sample.  TP_HDR_MSAA: hdr is per-sample (the blended
//   forward pass draws into it and resolves).  TP_TRANSPARENT: write transparent lists.
//   TP_DEBUG: write the edge mask and decoded G-buffer channels.  TP_HDR16: hdr is RGBA16F.
//   TP_LISTS_ONLY: only the transparent lists and tile statistics (volumes lighting
//   shades the opaque surfaces; the hybrid forward pass still needs the lists).
//   TP_VIS_BLEND (with TP_VISBUFFER and TP_TRANSPARENT): blended fragments composited here
//   from per-pixel lists (visbuffer/vis_blend.glsl), lit from the transparent lists.
//   TP_SHADOW_MAPS (the _shadow twins, --shadows): every light's term (and the composited
//   blended fragments') times its visibility in the shadow atlas (include/shadow_light.glsl).
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "include/light_model.h"
// evalLightShadowed: evalLight itself, or (TP_SHADOW_MAPS, the _shadow twins) times the
// light's visibility in the shadow atlas (set TP_SET_SHADOW).
#include "include/shadow_light.glsl"
#ifdef TP_LISTS_ONLY
#define TP_GBUFFER_DEPTH_ONLY
#endif
// The surface source's reader (core/passes/tiled_lighting.h: SurfaceSource): readSurfaceAt,
// ambientEmissive, fetchDepth, meanDepth, isEdge, sampleOffset, debugRoughMetal.
#ifdef TP_VISBUFFER
#include "visbuffer/vis_read.glsl"
#else
#include "deferred/gbuffer_read.glsl"
#endif
#define TP_LA_DEPTH_FETCH(p, s) fetchDepth(p, s)
#include "include/light_assign.glsl"

// A fixed 8 x 8 group covers a tile of 8, 16 or 32 pixels, each invocation taking
// (tileSize / 8)^2 pixels: a spec-constant workgroup size (LocalSizeId) would need
// maintenance4, which the context does not enable.
#define TP_GROUP 8u
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;

#ifndef TP_LISTS_ONLY
// Read back by the later batches, which add their lights to what the earlier ones wrote.
// TP_HDR16 (--hdr fp16): hdr is RGBA16F, so each batch's store rounds the running sum.
#ifdef TP_HDR16
#define TP_HDR_FORMAT rgba16f
#else
#define TP_HDR_FORMAT rgba32f
#endif
#ifdef TP_HDR_MSAA
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_HDR, TP_HDR_FORMAT) uniform image2DMS hdrOut;
#else
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_HDR, TP_HDR_FORMAT) uniform image2D hdrOut;
#endif
#endif
#ifdef TP_TRANSPARENT
// coherent: clustered, the invocations of a tile read each other's list entries (after
// memoryBarrierBuffer and barrier) to build the slice rows.
// Binned (kBinned), the runs are bitmasks over the tile's candidates (bit p: candidate p,
// deferred/candidates.glsl), ceil(candidates / 32) words: a transparent list is a subset of
// the candidates, so this takes a bit where an index took 32; every light, index runs.
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_TRANSPARENT_LISTS) coherent buffer TransparentLists {
    uint tLists[]; // LaListHeader per tile, then the tiles' runs (light indices, or candidate bitmasks)
};
// Clustered: per-slice bitmask rows over the transparent lists (deferred_shared.h:
// defClusterRowsBase); a 16-byte dummy otherwise.
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_TRANSPARENT_MASKS) writeonly buffer TransparentMasks {
    uint tMasks[];
};
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_LIST_OFFSETS) readonly buffer ListOffsets {
    uint tOffsets[]; // tileCount + 1: tile t's run is [tOffsets[t], tOffsets[t + 1])
};
// Blended depth bounds (the blended_bounds pass, after the G-buffer).
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_BLEND_BOUNDS) readonly buffer BlendBounds {
    uint blendBounds[]; // light_assign.h: TP_LA_BLEND_*
};
LaBlendedBounds tileBlendedBounds(uint tileIndex) {
    return laBlendedBounds(blendBounds[tileIndex], blendBounds[gl_NumWorkGroups.x * gl_NumWorkGroups.y + tileIndex]);
}
// A tile's transparent list: the blended range it is culled against and its run in tLists.
struct TransparentRun {
    LaBlendedBounds blended;
    TileFrustum frustum;
    uint start, capacity; // the run's first word and its length (index slots or mask words)
};
TransparentRun transparentRun(uvec2 tile) {
    const uint tileCount = gl_NumWorkGroups.x * gl_NumWorkGroups.y, tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
    TransparentRun r;
    r.blended = tileBlendedBounds(tileIndex);
    r.frustum = laBlendedFrustum(tile, kTileSize, vec2(frame.viewport.xy), frame.invProj, r.blended);
    const uint offset = tOffsets[tileIndex];
    r.capacity = tOffsets[tileIndex + 1u] - offset;
    r.start = laListStart(tileCount, offset);
    return r;
}
#endif
#ifdef TP_DEBUG
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_DEBUG, rgba32f) uniform writeonly image2D debugOut;
#endif
// Binned culling (--light-cull binned): a tile tests only its candidates (the directional
// lights, then the point/spot lights whose conservative tile rectangle covers it);
// otherwise every light of the scene.
layout(constant_id = TP_DEF_SPEC_BINNED) const bool kBinned = false;
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_CANDIDATES) readonly buffer Candidates {
    uint cand[]; // deferred_shared.h: TP_DEF_CAND_*
};

#include "deferred/candidates.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_TILE_STATS) buffer TileStats {
    uvec4 tileStats[]; // per tile: opaque lights, transparent lights, edge pixels, overflow
};

shared uint sCount;
shared uint sTransparentCount;
shared uint sMaskDropped; // binned: survivors past the tile's mask words (none while the runs match the bound)
shared uint sEdges;
shared uint sLights[TP_DEF_TILE_LIGHT_CAPACITY];
// The culling's survivors of this batch as bits over its candidates (a batch holds at most
// the shared capacity: core/passes/tiled_lighting.cpp), made into sLights by compactList.
shared uint sBits[TP_DEF_TILE_LIGHT_CAPACITY / 32u];
// Clustered (kSlices > 0): bit i of slice s's row is set when sLights[i] can reach the
// slice (include/light_assign.glsl: laSliceOf over the tile's opaque depth range, no front
// slice: only opaque surfaces are lit here). Rows are ceil(count / 32) words.
layout(constant_id = TP_DEF_SPEC_SLICES) const uint kSlices = 0u;
// TP_DEF_CLUSTER_MASK_WORDS when clustered, 1 when tiled: shared memory is declared per
// pipeline, and a tiled group would otherwise reserve 8 KiB it never touches.
layout(constant_id = TP_DEF_SPEC_MASK_WORDS) const uint kMaskWords = 1u;
shared uint sMask[kMaskWords];
shared float sSliceNear, sSliceScale;
// The tile's slices: the opaque range only (no front slices: blended surfaces are not lit here).
LaSlicing rangeSlicing() { return laSlicing(1.0, sSliceNear, sSliceScale, kSlices, 0u); }

// The first batch writes hdr, the tile statistics and the transparent lists; later
// batches add to them.
bool firstBatch() { return draw.TP_DEF_LIGHT_FIRST == 0u; }

#ifndef TP_LISTS_ONLY
// One G-buffer sample, lit by the tile's lights of this batch (the host keeps a batch
// within the shared capacity: sCount never exceeds it).
vec3 shade(ivec2 p, uint s, vec2 offset, float depth) {
    SurfaceSample ss = readSurfaceAt(p, s, offset, depth);
    vec3 sum = firstBatch() ? ambientEmissive(p, s) : vec3(0.0);
    uint n = min(sCount, TP_DEF_TILE_LIGHT_CAPACITY);
    if (kSlices > 0u) {
        // The lights of this sample's cluster: its slice's bits over the tile list.
        float dist = -(frame.view * vec4(ss.position, 1.0)).z;
        uint words = (n + 31u) / 32u;
        uint row = laSliceOf(dist, rangeSlicing()) * words;
        for (uint w = 0u; w < words; ++w) {
            uint bits = sMask[row + w];
            for (uint b = 0u; b < 32u && bits != 0u; ++b) {
                int lsb = findLSB(bits);
                bits &= bits - 1u;
                sum += evalLightShadowed(lights[sLights[w * 32u + uint(lsb)]], ss);
            }
        }
        return sum;
    }
    for (uint i = 0u; i < n; ++i) sum += evalLightShadowed(lights[sLights[i]], ss);
    return sum;
}

// Clustered: the slices each light of the shared list reaches (after the culling's barrier;
// a barrier must follow before shading).
void markSlices() {
    uint n = min(sCount, TP_DEF_TILE_LIGHT_CAPACITY);
    uint words = (n + 31u) / 32u;
    for (uint i = gl_LocalInvocationIndex; i < n; i += TP_GROUP * TP_GROUP) {
        LightGpu light = lights[sLights[i]];
        vec4 sphere = lightSphereView(light, frame.view);
        // The shared list holds the directional lights too: they reach every slice.
        uvec2 range = light.type == TP_LIGHT_DIRECTIONAL
                          ? uvec2(0u, kSlices - 1u)
                          : laLightSlices(sphere.xyz, sphere.w, rangeSlicing());
        for (uint sl = range.x; sl <= range.y; ++sl) atomicOr(sMask[sl * words + (i >> 5u)], 1u << (i & 31u));
    }
}

// --hdr fp16: sums beyond the largest half saturate there, as Forward+'s do, not +Inf.
vec3 storable(vec3 c) {
#ifdef TP_HDR16
    return min(c, vec3(65504.0));
#else
    return c;
#endif
}

void writeHdr(ivec2 p, uint s, vec3 c) {
#ifdef TP_HDR_MSAA
    if (!firstBatch()) c += imageLoad(hdrOut, p, int(s)).rgb;
    imageStore(hdrOut, p, int(s), vec4(storable(c), 1.0));
#else
    if (!firstBatch()) c += imageLoad(hdrOut, p).rgb;
    imageStore(hdrOut, p, vec4(storable(c), 1.0));
#endif
}

#ifdef TP_VISBUFFER
#include "visbuffer/vis_shade_pixel.glsl"
#else
// Shades pixel p (all samples, once or per sample) and writes hdr; returns whether it was an edge.
bool shadePixel(ivec2 p) {
    bool edge = kSamples > 1u && isEdge(p);
    if (!edge) {
        // One surface: shade once at the pixel centre with the mean sample depth.
        float d = meanDepth(p);
        vec3 c = d > 0.0 ? shade(p, 0u, vec2(0.5), d) : vec3(0.0);
#ifdef TP_HDR_MSAA
        for (uint s = 0u; s < kSamples; ++s) writeHdr(p, s, c);
#else
        writeHdr(p, 0u, c);
#endif
        return false;
    }
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < kSamples; ++s) {
        float d = fetchDepth(p, s);
        vec3 c = d > 0.0 ? shade(p, s, sampleOffset(s), d) : vec3(0.0);
#ifdef TP_HDR_MSAA
        writeHdr(p, s, c);
#endif
        sum += c;
    }
#ifndef TP_HDR_MSAA
    writeHdr(p, 0u, sum / float(kSamples));
#endif
    return true;
}
#endif
#endif

void cull(uvec2 tile, bool hasGeometry) {
    uint groupSize = TP_GROUP * TP_GROUP;
    vec2 size = vec2(frame.viewport.xy);
    float nearDepth = laTileNearDepth(), farDepth = laTileFarDepth();
    TileFrustum f = laOpaqueFrustum(tile, kTileSize, size, frame.invProj, nearDepth, farDepth);
    uint tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
    uint candidates = candidateCount(tileIndex);
#ifdef TP_TRANSPARENT
    const TransparentRun t = transparentRun(tile);
#endif
#ifndef TP_LISTS_ONLY
    // A survivor sets its bit in sBits (bit i: this batch's candidate i); compactList turns
    // the bits into the list.
    const uint first = draw.TP_DEF_LIGHT_FIRST, end = min(draw.TP_DEF_LIGHT_END, candidates);
    for (uint i = first + gl_LocalInvocationIndex; hasGeometry && i < end; i += groupSize) {
        uint light = candidateLight(tileIndex, i);
        if (lightInTile(lights[light], f, frame.view)) atomicOr(sBits[(i - first) >> 5u], 1u << ((i - first) & 31u));
    }
#endif
#ifdef TP_TRANSPARENT
    // Binned: every candidate, once (first batch), sets its bit in the tile's mask (atomicOr:
    // the same mask whatever the order); a loop of candidates / 64 iterations per invocation,
    // none where no blended fragment is shaded. Index lists: cullTransparentIndices.
    for (uint i = gl_LocalInvocationIndex; kBinned && firstBatch() && t.blended.any && i < candidates; i += groupSize) {
        if (lightInTile(lights[candidateLight(tileIndex, i)], t.frustum, frame.view)) {
            atomicAdd(sTransparentCount, 1u);
            if ((i >> 5u) < t.capacity) atomicOr(tLists[t.start + (i >> 5u)], 1u << (i & 31u)); // cleared in main
            else atomicAdd(sMaskDropped, 1u); // counted, never silent
        }
    }
#endif
}

// The culling's survivors into ordered lists: compactList (the opaque list in sLights) and
// cullTransparentIndices (the transparent index lists).
#include "deferred/ordered_lists.glsl"

#if defined(TP_TRANSPARENT) && !defined(TP_LISTS_ONLY)
// Clustered: the slice rows of tile `tileIndex`'s transparent list, for the blended pass
// (transparent.frag): front slices from the nearest blended fragment to the nearest opaque
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
    // Binned: rows over the candidates, as the list's mask (bit p: candidate p); a row bit
    // is set only where the mask's is.
    const uint words = kBinned ? tOffsets[tileIndex + 1u] - offset : (kept + 31u) / 32u;
    const bool geometry = laTileHasGeometry();
    const float sliceNear = geometry ? max(-viewZFromDepth(laTileNearDepth(), frame.invProj), 1e-30) : 1e30;
    const float sliceFar = geometry ? -viewZFromDepth(laTileFarDepth(), frame.invProj) : 1e30;
    const uint front = laFrontSlices(kSlices, true);
    const LaSlicing s = laSlicing(laFrontNear(tileBlendedBounds(tileIndex), sliceNear), sliceNear,
                                  laSliceScale(sliceNear, sliceFar, kSlices, front), kSlices, front);
    const uint base = kBinned ? defMaskRowsBase(tileCount, offset, kSlices)
                              : defClusterRowsBase(tileCount, offset, tileIndex, kSlices);
    for (uint w = gl_LocalInvocationIndex; w < words; w += TP_GROUP * TP_GROUP) {
        for (uint sl = 0u; sl < kSlices; ++sl) gWordBits[sl] = 0u;
        uint mask = kBinned ? tLists[start + w] : 0u;
        for (uint b = 0u; b < 32u && (kBinned ? mask >> b != 0u : w * 32u + b < kept); ++b) {
            if (kBinned && (mask & (1u << b)) == 0u) continue;
            LightGpu light = lights[kBinned ? candidateLight(tileIndex, w * 32u + b) : tLists[start + w * 32u + b]];
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

void main() {
    uvec2 tile = gl_WorkGroupID.xy;
    uint pixelsPerInvocation = (kTileSize / TP_GROUP) * (kTileSize / TP_GROUP);
    laDepthBoundsBegin();
    if (gl_LocalInvocationIndex == 0u) {
        sCount = 0u;
        sTransparentCount = 0u;
        sMaskDropped = 0u;
        sEdges = 0u;
    }
    if (kSlices > 0u) // every word a row may use: the host keeps slices * rows within the array
        for (uint i = gl_LocalInvocationIndex; i < kMaskWords; i += TP_GROUP * TP_GROUP) sMask[i] = 0u;
    for (uint i = gl_LocalInvocationIndex; i < TP_DEF_TILE_LIGHT_CAPACITY / 32u; i += TP_GROUP * TP_GROUP) sBits[i] = 0u;
    barrier();
    laDepthBoundsReduce(tile, kTileSize, frame.viewport.xy, kSamples);
    barrier();
    if (kSlices > 0u && gl_LocalInvocationIndex == 0u) {
        // Slices over the tile's opaque range (laSliceOf; nothing to slice without geometry).
        bool geometry = laTileHasGeometry();
        sSliceNear = geometry ? max(-viewZFromDepth(laTileNearDepth(), frame.invProj), 1e-30) : 1e30;
        float far = geometry ? -viewZFromDepth(laTileFarDepth(), frame.invProj) : 1e30;
        sSliceScale = laSliceScale(sSliceNear, far, kSlices, 0u);
    }
#ifdef TP_TRANSPARENT
    if (kBinned && firstBatch()) {
        // The tile's candidate bitmask starts empty (cull sets its bits with atomicOr).
        uint t = tile.y * gl_NumWorkGroups.x + tile.x;
        uint start = laListStart(gl_NumWorkGroups.x * gl_NumWorkGroups.y, tOffsets[t]);
        for (uint w = gl_LocalInvocationIndex; w < tOffsets[t + 1u] - tOffsets[t]; w += TP_GROUP * TP_GROUP)
            tLists[start + w] = 0u;
        memoryBarrierBuffer();
        barrier();
    }
#endif
    cull(tile, laTileHasGeometry());
#ifndef TP_LISTS_ONLY
    barrier(); // every survivor's bit
    compactList(tile.y * gl_NumWorkGroups.x + tile.x);
#endif
#ifdef TP_TRANSPARENT
    if (!kBinned && firstBatch()) { // uniform over the group
        barrier(); // compactList has read sBits
        cullTransparentIndices(tile);
    }
#endif
#ifndef TP_LISTS_ONLY
#ifdef TP_VIS_BLEND
    memoryBarrierBuffer(); // the transparent list, which the blended fragments are lit from
#elif defined(TP_TRANSPARENT)
    if (kSlices > 0u) memoryBarrierBuffer(); // the transparent list, for writeTransparentSlices
#endif
    barrier();
    if (kSlices > 0u) {
        markSlices();
#if defined(TP_TRANSPARENT) && !defined(TP_VIS_BLEND) // no blended pass to read slice rows
        if (firstBatch()) writeTransparentSlices(tile.y * gl_NumWorkGroups.x + tile.x);
#endif
        barrier();
    }
    // A later batch with no light in this tile adds nothing (sCount is uniform here), unless
    // blended fragments composited here may have lights in it.
#ifdef TP_VIS_BLEND
    uint shadedPixels = firstBatch() || sCount > 0u || transparentRun(tile).blended.any ? pixelsPerInvocation : 0u;
#else
    uint shadedPixels = firstBatch() || sCount > 0u ? pixelsPerInvocation : 0u;
#endif
    for (uint k = 0u; k < shadedPixels; ++k) {
        ivec2 p = pixelOf(tile, k);
        if (!insideViewport(p)) continue;
        bool edge = shadePixel(p);
        if (edge) atomicAdd(sEdges, 1u);
#ifdef TP_DEBUG
        vec2 rm = debugRoughMetal(p);
        if (firstBatch()) imageStore(debugOut, p, vec4(edge ? 1.0 : 0.0, rm, 1.0));
#endif
    }
#endif
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uint tileIndex = tile.y * gl_NumWorkGroups.x + tile.x;
        if (firstBatch()) {
            tileStats[tileIndex] = uvec4(sCount, sTransparentCount, sEdges, 0u);
#ifdef TP_TRANSPARENT
            uint capacity = tOffsets[tileIndex + 1u] - tOffsets[tileIndex];
            // Binned: every survivor has its bit (the mask covers every candidate).
            uint kept = kBinned ? sTransparentCount - sMaskDropped : min(sTransparentCount, capacity);
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
        if (tileStats[tileIndex].x > TP_DEF_TILE_LIGHT_CAPACITY) tileStats[tileIndex].w = 1u;
    }
}
