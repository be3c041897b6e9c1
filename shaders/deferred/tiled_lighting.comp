#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred lighting (Andersson 2009, Uncharted; Lauritzen 2010): one workgroup per
// tile. (1) the tile's depth bounds from the G-buffer depth (every sample), (2) the lights
// of this dispatch's batch (push constant: [first, end), at most the shared capacity) that
// reach the tile's sub-frustum are culled into shared memory, (3) every pixel of the tile
// is shaded from that list: the first batch writes hdr (with ambient and emissive), later
// batches add to it. Under MSAA a pixel whose samples differ (an edge) is shaded per
// sample, every other pixel once. Blended scenes also get each tile's transparent light
// list (every light, first batch only), culled against [near plane, farthest opaque depth].
//   TP_EMISSIVE (0/1): the G-buffer has an emissive target.
//   TP_MSAA: the G-buffer is per-sample.  TP_HDR_MSAA: hdr is per-sample (the blended
//   forward pass draws into it and resolves).  TP_TRANSPARENT: write transparent lists.
//   TP_DEBUG: write the edge mask and decoded G-buffer channels.
//   TP_LISTS_ONLY: only the transparent lists and tile statistics (volumes lighting
//   shades the opaque surfaces; the hybrid forward pass still needs the lists).
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/light_model.h"
#include "include/tile_culling.glsl"
#ifdef TP_LISTS_ONLY
#define TP_GBUFFER_DEPTH_ONLY
#endif
#include "deferred/gbuffer_read.glsl"

// A fixed 8 x 8 group covers a tile of 8, 16 or 32 pixels, each invocation taking
// (tileSize / 8)^2 pixels: a spec-constant workgroup size (LocalSizeId) would need
// maintenance4, which the context does not enable.
#define TP_GROUP 8u
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = TP_DEF_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_DEF_SPEC_LIST_STRIDE) const uint kListStride = 1u;

#ifndef TP_LISTS_ONLY
// Read back by the later batches, which add their lights to what the earlier ones wrote.
#ifdef TP_HDR_MSAA
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_HDR, rgba32f) uniform image2DMS hdrOut;
#else
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_HDR, rgba32f) uniform image2D hdrOut;
#endif
#endif
#ifdef TP_TRANSPARENT
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_TRANSPARENT_LISTS) buffer TransparentLists {
    uint tLists[]; // per tile: count, then kListStride - 1 light indices
};
#endif
#ifdef TP_DEBUG
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_DEBUG, rgba32f) uniform writeonly image2D debugOut;
#endif
layout(std430, set = TP_SET_PASS, binding = TP_DEF_BINDING_TILE_STATS) buffer TileStats {
    uvec4 tileStats[]; // per tile: opaque lights, transparent lights, edge pixels, overflow
};

shared uint sMaxDepthBits; // nearest (reverse-Z: largest) depth
shared uint sMinDepthBits; // farthest geometry
shared uint sCount;
shared uint sTransparentCount;
shared uint sEdges;
shared uint sLights[TP_DEF_TILE_LIGHT_CAPACITY];

// The first batch writes hdr, the tile statistics and the transparent lists; later
// batches add to them.
bool firstBatch() { return draw.TP_DEF_LIGHT_FIRST == 0u; }

#ifndef TP_LISTS_ONLY
// One G-buffer sample, lit by the tile's lights of this batch (the host keeps a batch
// within the shared capacity: sCount never exceeds it).
vec3 shade(ivec2 p, uint s, vec2 offset, float depth) {
    SurfaceSample ss = readSurface(p, s, reconstructPosition(p, offset, depth));
    vec3 sum = firstBatch() ? ambientEmissive(p, s) : vec3(0.0);
    uint n = min(sCount, TP_DEF_TILE_LIGHT_CAPACITY);
    for (uint i = 0u; i < n; ++i) sum += evalLight(lights[sLights[i]], ss, kHasSpot);
    return sum;
}

void writeHdr(ivec2 p, uint s, vec3 c) {
#ifdef TP_HDR_MSAA
    if (!firstBatch()) c += imageLoad(hdrOut, p, int(s)).rgb;
    imageStore(hdrOut, p, int(s), vec4(c, 1.0));
#else
    if (!firstBatch()) c += imageLoad(hdrOut, p).rgb;
    imageStore(hdrOut, p, vec4(c, 1.0));
#endif
}

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

void cull(uvec2 tile, bool hasGeometry) {
    uint groupSize = TP_GROUP * TP_GROUP;
    vec2 size = vec2(frame.viewport.xy);
    float nearDepth = uintBitsToFloat(sMaxDepthBits), farDepth = uintBitsToFloat(sMinDepthBits);
    TileFrustum f = makeTileFrustum(tile, kTileSize, size, frame.invProj, nearDepth, farDepth);
#ifdef TP_TRANSPARENT
    // Transparent surfaces lie anywhere in front of the opaque ones: [near plane, farthest
    // opaque]; a tile with no opaque geometry reaches to infinity (depth 0).
    TileFrustum ft = makeTileFrustum(tile, kTileSize, size, frame.invProj, 1.0,
                                     hasGeometry ? farDepth : 0.0);
    uint listBase = (tile.y * gl_NumWorkGroups.x + tile.x) * kListStride;
#endif
#ifndef TP_LISTS_ONLY
    uint end = min(draw.TP_DEF_LIGHT_END, frame.viewport.z);
    for (uint i = draw.TP_DEF_LIGHT_FIRST + gl_LocalInvocationIndex; hasGeometry && i < end; i += groupSize) {
        if (lightInTile(lights[i], f, frame.view)) {
            uint slot = atomicAdd(sCount, 1u);
            if (slot < TP_DEF_TILE_LIGHT_CAPACITY) sLights[slot] = i;
        }
    }
#endif
#ifdef TP_TRANSPARENT
    // Every light, once (first batch): a loop of lights / 64 iterations per invocation.
    for (uint i = gl_LocalInvocationIndex; firstBatch() && i < frame.viewport.z; i += groupSize) {
        if (lightInTile(lights[i], ft, frame.view)) {
            uint slot = atomicAdd(sTransparentCount, 1u);
            if (slot + 1u < kListStride) tLists[listBase + 1u + slot] = i;
        }
    }
#endif
}

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
    if (gl_LocalInvocationIndex == 0u) {
        sMaxDepthBits = 0u;
        sMinDepthBits = floatBitsToUint(1.0);
        sCount = 0u;
        sTransparentCount = 0u;
        sEdges = 0u;
    }
    barrier();
    for (uint k = 0u; k < pixelsPerInvocation; ++k) {
        ivec2 p = pixelOf(tile, k);
        if (!insideViewport(p)) continue;
        for (uint s = 0u; s < kSamples; ++s) {
            float d = fetchDepth(p, s);
            if (d <= 0.0) continue; // no geometry: does not bound the tile
            atomicMax(sMaxDepthBits, floatBitsToUint(d)); // positive floats order as uints
            atomicMin(sMinDepthBits, floatBitsToUint(d));
        }
    }
    barrier();
    cull(tile, sMaxDepthBits != 0u);
#ifndef TP_LISTS_ONLY
    barrier();
    // A later batch with no light in this tile adds nothing (sCount is uniform here).
    uint shadedPixels = firstBatch() || sCount > 0u ? pixelsPerInvocation : 0u;
    for (uint k = 0u; k < shadedPixels; ++k) {
        ivec2 p = pixelOf(tile, k);
        if (!insideViewport(p)) continue;
        bool edge = shadePixel(p);
        if (edge) atomicAdd(sEdges, 1u);
#ifdef TP_DEBUG
        vec2 rm = FETCH(gRoughMetal, p, 0u).rg;
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
            tLists[tileIndex * kListStride] = min(sTransparentCount, kListStride - 1u);
#endif
        } else {
            tileStats[tileIndex].x += sCount;
        }
        // Overflow: the tile met more lights than one shared list holds (its lights came
        // from several batches; none is dropped).
        if (tileStats[tileIndex].x > TP_DEF_TILE_LIGHT_CAPACITY) tileStats[tileIndex].w = 1u;
    }
}
