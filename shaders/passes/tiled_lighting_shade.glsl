// The tiled lighting pass, part 2 of 4 (passes/tiled_lighting_inputs.glsl lists the parts):
// after the surface reader, the tile's light lists, shade() and writeHdr().
#define TP_LA_DEPTH_FETCH(p, s) fetchDepth(p, s)
#include "include/light_assign.glsl"
#include "include/light_list_walk.glsl"

// A fixed 8 x 8 group covers a tile of 8, 16 or 32 pixels, each invocation taking
// (tileSize / 8)^2 pixels: a spec-constant workgroup size (LocalSizeId) would need
// maintenance4, which the context does not enable.
// TP_GROUP x TP_GROUP invocations a tile, each shading (kTileSize / TP_GROUP)^2 of its pixels:
// 16 x 16 on a GPU (a 16-pixel tile's pixels one an invocation: the H200 hid the surface reads'
// latency poorly with 64 invocations of 4 pixels each beside a 16 KiB shared list), 8 x 8 on
// lavapipe (tiled_lighting.h: TP_TL_SPEC_GROUP_X). The image is the same either way: each
// pixel's shade, and its list, do not depend on which invocation computes it.
layout(local_size_x = 8, local_size_y = 8, local_size_x_id = TP_TL_SPEC_GROUP_X, local_size_y_id = TP_TL_SPEC_GROUP_Y) in;
#define TP_GROUP gl_WorkGroupSize.x
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
layout(set = TP_SET_PASS, binding = TP_TL_BINDING_HDR, TP_HDR_FORMAT) uniform image2DMS hdrOut;
#else
layout(set = TP_SET_PASS, binding = TP_TL_BINDING_HDR, TP_HDR_FORMAT) uniform image2D hdrOut;
#endif
#endif
#ifdef TP_TRANSPARENT
// coherent: clustered, the invocations of a tile read each other's list entries (after
// memoryBarrierBuffer and barrier) to build the slice rows.
// The runs hold light indices in candidate order (cullTransparentIndices), binned or not, so
// the blended pass reads them as Forward+ reads its lists. kTransparentMasks (binned, the
// blended fragments composited here: the visibility buffer's --vis-blended compute): bitmasks
// over the tile's candidates (bit p: candidate p, passes/candidates.glsl), ceil(candidates /
// 32) words, since each batch composites the lights of its own candidates.
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_TRANSPARENT_LISTS) coherent buffer TransparentLists {
    uint tLists[]; // LaListHeader per tile, then the tiles' runs (light indices; kTransparentMasks: bitmasks)
};
// Clustered: per-slice bitmask rows over the transparent lists (deferred_shared.h:
// tlClusterRowsBase); a 16-byte dummy otherwise.
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_TRANSPARENT_MASKS) writeonly buffer TransparentMasks {
    uint tMasks[];
};
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_LIST_OFFSETS) readonly buffer ListOffsets {
    uint tOffsets[]; // tileCount + 1: tile t's run is [tOffsets[t], tOffsets[t + 1])
};
// Blended depth bounds (the blended_bounds pass, after the G-buffer).
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_BLEND_BOUNDS) readonly buffer BlendBounds {
    uint blendBounds[]; // light_assign.h: TP_LA_BLEND_*
};
LaBlendedBounds tileBlendedBounds(uint tileIndex) {
    return laBlendedBounds(blendBounds[tileIndex], blendBounds[gl_NumWorkGroups.x * gl_NumWorkGroups.y + tileIndex]);
}
// A tile's transparent list: the blended range it is culled against and its run in tLists.
struct TransparentRun {
    LaBlendedBounds blended;
    TileFrustum frustum;
    uint start, capacity; // the run's first word and its length (index slots, or mask words)
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
layout(set = TP_SET_PASS, binding = TP_TL_BINDING_DEBUG, rgba32f) uniform writeonly image2D debugOut;
#endif
// Binned culling (--light-cull binned): a tile tests only its candidates (the directional
// lights, then the point/spot lights whose conservative tile rectangle covers it);
// otherwise every light of the scene.
layout(constant_id = TP_TL_SPEC_BINNED) const bool kBinned = false;
#ifdef TP_TL_COMPOSITES_BLENDED
const bool kTransparentMasks = kBinned;
#else
const bool kTransparentMasks = false;
#endif
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_CANDIDATES) readonly buffer Candidates {
    uint cand[]; // deferred_shared.h: TP_TL_CAND_*
};

#include "passes/candidates.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_TILE_STATS) buffer TileStats {
    uvec4 tileStats[]; // per tile: opaque lights, transparent lights, edge pixels, overflow
};

// Each tile's depth bounds, from the tile depth bounds pass.
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_TILE_DEPTH) readonly buffer TileDepth {
    uvec4 tileDepth[];
};

shared uint sCount;
shared uint sTransparentCount;
shared uint sMaskDropped; // binned: survivors past the tile's mask words (none while the runs match the bound)
shared uint sEdges; // the tile's edge pixels (its statistics)
// Under MSAA the tile's edge pixels (their index in the tile), shaded after the rest by the
// whole group (tiled_lighting_main.glsl: shadeTile): from the start the sFlatEdges lit
// flattened, from the end the sCompositeEdges that composite blended fragments. One word a
// pixel of the tile; a single word without MSAA or at sample rate (every pixel shaded in place).
const uint kEdgeWords = kSamples > 1u && !kEverySample ? kTileSize * kTileSize : 1u;
shared uint sEdgePixels[kEdgeWords];
shared uint sFlatEdges, sCompositeEdges;
// shadeEdges: each invocation's radiance for one surface of an edge pixel, read by the pixel's
// first invocation (x, y, z: a vec3 array would be padded). The group is at most 16 x 16.
shared float sSlot[kSamples > 1u && !kEverySample ? 3u * 256u : 1u];
shared uint sLights[TP_TL_TILE_LIGHT_CAPACITY];
// The culling's survivors of this batch as bits over its candidates (a batch holds at most
// the shared capacity: core/passes/tiled_lighting.cpp), made into sLights by compactList.
shared uint sBits[TP_TL_TILE_LIGHT_CAPACITY / 32u];
// Clustered (kSlices > 0): bit i of slice s's row is set when sLights[i] can reach the
// slice (include/light_assign.glsl: laSliceOf over the tile's opaque depth range, no front
// slice: only opaque surfaces are lit here). Rows are ceil(count / 32) words.
layout(constant_id = TP_TL_SPEC_SLICES) const uint kSlices = 0u;
// TP_TL_CLUSTER_MASK_WORDS when clustered, 1 when tiled: shared memory is declared per
// pipeline, and a tiled group would otherwise reserve 8 KiB it never touches.
layout(constant_id = TP_TL_SPEC_MASK_WORDS) const uint kMaskWords = 1u;
shared uint sMask[kMaskWords];
shared float sSliceNear, sSliceScale;
// The tile's slices: the opaque range only (no front slices: blended surfaces are not lit here).
LaSlicing rangeSlicing() { return laSlicing(1.0, sSliceNear, sSliceScale, kSlices, 0u); }

// The first batch writes hdr, the tile statistics and the transparent lists; later
// batches add to them.
bool firstBatch() { return draw.TP_TL_LIGHT_FIRST == 0u; }

#ifndef TP_LISTS_ONLY
// Surface ss lit by the tile's lights of this batch (the host keeps a batch within the shared
// capacity: sCount never exceeds it), each added to `sum` (its ambient and emission in the
// first batch) in list order.
vec3 shadeSurface(SurfaceSample ss, vec3 sum) {
    uint n = min(sCount, TP_TL_TILE_LIGHT_CAPACITY);
    if (kSlices > 0u) {
        // The lights of this sample's cluster: its slice's bits over the tile list.
        float dist = -(frame.view * vec4(ss.position, 1.0)).z;
        uint words = (n + 31u) / 32u;
        uint row = laSliceOf(dist, rangeSlicing()) * words;
        for (uint w = 0u; w < words; ++w) {
            uint bits = sMask[row + w];
            TP_FOR_EACH_BIT(bits, lsb, sum += evalLightShadowed(sceneLight(sLights[w * 32u + uint(lsb)]), ss);)
        }
        return sum;
    }
    for (uint i = 0u; i < n; ++i) sum += evalLightShadowed(sceneLight(sLights[i]), ss);
    return sum;
}

// One G-buffer sample, lit.
vec3 shade(ivec2 p, uint s, vec2 offset, float depth) {
    SurfaceSample ss = readSurfaceAt(p, s, offset, depth);
    return shadeSurface(ss, firstBatch() ? ambientEmissive(p, s) : vec3(0.0));
}

// Clustered: the slices each light of the shared list reaches (after the culling's barrier;
// a barrier must follow before shading).
void markSlices() {
    uint n = min(sCount, TP_TL_TILE_LIGHT_CAPACITY);
    uint words = (n + 31u) / 32u;
    for (uint i = gl_LocalInvocationIndex; i < n; i += TP_GROUP * TP_GROUP) {
        LightGpu light = sceneLight(sLights[i]);
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
#endif // TP_LISTS_ONLY
