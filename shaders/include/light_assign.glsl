// Light assignment shared by the tiled pipelines (Forward+ and tiled deferred); GLSL only.
// Builds on tile_culling.glsl (the tile sub-frustum and its sphere, cone and box tests) with
// what both pipelines need around those tests: the tile of a fragment, the per-tile depth
// bounds (every sample under MSAA), the two depth ranges (opaque, transparent) and the
// compact list layout of light_assign.h. The C++ half is core/lightassign/.
#ifndef TP_LIGHT_ASSIGN_GLSL
#define TP_LIGHT_ASSIGN_GLSL
#include "include/shared.h"
#include "include/light_assign.h"
#include "include/tile_culling.glsl"

// ---- the tile grid (core/lightassign/tile_grid.h) ----
uint laTileCount1D(uint pixels, uint tileSize) { return (pixels + tileSize - 1u) / tileSize; }

// Row-major tile of a pixel (e.g. uvec2(gl_FragCoord.xy)); clamped into the grid so that a
// fragment on the viewport's edge can never index past the last tile.
uint laTileIndex(uvec2 pixel, uint tileSize, uvec2 tiles) {
    uvec2 t = min(pixel / tileSize, tiles - uvec2(1u));
    return t.y * tiles.x + t.x;
}

// ---- the two depth ranges of a tile (reverse-Z: 1 = near plane, 0 = far/infinite) ----
// Opaque: [nearest, farthest] depth of the tile's geometry (empty when it has none).
// Transparent far end: blended surfaces lie anywhere in front of the opaque ones, so up to
// the farthest opaque depth - unbounded (0) where any sample sees no geometry, since a
// blended surface over the sky can be at any depth. The transparent list itself is culled
// against the blended fragments' own depths (laBlendedFrustum below).
float laTransparentFarDepth(bool hasGeometry, bool seesSky, float farDepth) {
    return (seesSky || !hasGeometry) ? 0.0 : farDepth;
}

TileFrustum laOpaqueFrustum(uvec2 tile, uint tileSize, vec2 viewportSize, mat4 invProj, float nearDepth,
                            float farDepth) {
    return makeTileFrustum(tile, tileSize, viewportSize, invProj, nearDepth, farDepth);
}

// ---- blended depth bounds (light_assign.h: TP_LA_BLEND_*; docs/clustered.md) ----
// The transparent list and the front slices cover only the view distances where the tile's
// blended fragments are (shaders/passes/blended_bounds.frag records them), not everything from the
// near plane: most lights in front of the opaque surfaces float where no blended surface is.
// Why the bound holds: the bounds pass draws the blended draws with the shading pass's vertex
// shader (scene.vert, `precise`: bit-identical gl_Position and interpolants; its position-only
// variant, whose position and 1 come from the same lines), rasterization
// state, sample count, sample shading and input interpolation, depth test GREATER against the
// same opaque depth and no depth write, so it runs for exactly the fragments (under MSAA with
// per-sample shading: samples) that the shading pass shades, at the same positions, and takes
// their view distance with the shading's own expression; TP_LA_BLEND_PAD absorbs the
// rounding of that expression in two compilations.
struct LaBlendedBounds {
    bool any;       // the tile has a blended fragment to shade
    float nearDist; // padded view distance of its nearest blended fragment (0 without)
    float farDist;  // padded view distance of its farthest one (0 without)
};

LaBlendedBounds laBlendedBounds(uint minBits, uint maxBits) {
    LaBlendedBounds b;
    b.any = minBits < TP_LA_BLEND_EMPTY;
    b.nearDist = b.any ? uintBitsToFloat(minBits) * (1.0 - TP_LA_BLEND_PAD) : 0.0;
    b.farDist = b.any ? uintBitsToFloat(maxBits) * (1.0 + TP_LA_BLEND_PAD) : 0.0;
    return b;
}

// The tile's sub-frustum between the blended bounds (view z = -distance); makeTileFrustum's
// side planes, its depth range replaced.
TileFrustum laBlendedFrustum(uvec2 tile, uint tileSize, vec2 viewportSize, mat4 invProj, LaBlendedBounds b) {
    TileFrustum f = makeTileFrustum(tile, tileSize, viewportSize, invProj, 1.0, 0.0);
    f.nearViewZ = -b.nearDist;
    f.farViewZ = -b.farDist;
    return f;
}

// Clustered: where the front slices start: the nearest blended fragment, never beyond the
// tile's nearest opaque depth (sliceNear); without blended fragments sliceNear (the front
// slices are then empty of fragments but for rounding at sliceNear, which laSliceOf clamps
// into the first front slice). Computed the same way by the culling and the shading.
float laFrontNear(LaBlendedBounds b, float sliceNear) {
    return b.any ? min(max(b.nearDist, 1e-30), sliceNear) : sliceNear;
}

// ---- clustered: depth slices of a tile (docs/clustered.md) ----
// The range slices follow the tile's opaque depth range [nearest, farthest] (view
// distances sliceNear, sliceFar): exponential between them, so every slice is as deep
// relative to its distance and each lies inside the range a tiled opaque list is culled
// against. With front slices (the scene has blended surfaces: laFrontSlices), the first
// `front` slices cut [frontNear, sliceNear) - the tile's nearest blended fragment
// (laFrontNear) to the nearest opaque depth, where only blended surfaces are - exponentially too, so a blended fragment in front of
// the opaque ones sees a thin cluster instead of everything nearer than sliceNear; the
// range slices are the rest. The first front slice also takes anything nearer than
// frontNear, the first range slice anything nearer than sliceNear when there is no front,
// the last everything farther (blended surfaces over the sky). A tile without geometry has
// sliceNear = sliceFar = 1e30: everything is in the front slices (or slice 0 without).
// The culling and the shading both use laSliceOf; a light's slice range is padded
// (laLightSlices), so rounding cannot separate them.
struct LaSlicing {
    float frontNear;  // view distance where the front slices start (laFrontNear)
    float frontScale; // front slices per unit of log(distance / frontNear); 0 without
    float sliceNear;  // view distance of the tile's nearest opaque depth (1e30 without geometry)
    float sliceScale; // range slices per unit of log(distance / sliceNear)
    uint slices;      // all slices of the tile
    uint front;       // front slices (0: none)
};

// Front slices: a fixed share of the slices (TP_LA_FRONT_SLICE_SHARE), at least one, when
// the scene has blended surfaces; none otherwise.
uint laFrontSlices(uint slices, bool blended) {
    return blended ? max(slices / TP_LA_FRONT_SLICE_SHARE, 1u) : 0u;
}

float laSliceScale(float sliceNear, float sliceFar, uint slices, uint front) {
    return float(slices - front) / log(max(sliceFar / sliceNear, 1.001));
}

// The tile's slicing from what the tile record keeps (sliceNear, sliceScale); the front
// scale is recomputed the same way by the culling and the shading.
LaSlicing laSlicing(float frontNear, float sliceNear, float sliceScale, uint slices, uint front) {
    LaSlicing s;
    s.frontNear = frontNear;
    s.frontScale = front > 0u ? float(front) / log(max(sliceNear / frontNear, 1.001)) : 0.0;
    s.sliceNear = sliceNear;
    s.sliceScale = sliceScale;
    s.slices = slices;
    s.front = front;
    return s;
}

// The slice of view distance `dist` (> 0 in front of the eye). Monotone in dist: the front
// slices are [0, front), the range slices [front, slices).
uint laSliceOf(float dist, LaSlicing s) {
    if (s.front > 0u && dist < s.sliceNear) {
        float f = log(max(dist / s.frontNear, 1.0)) * s.frontScale;
        return uint(clamp(f, 0.0, float(s.front - 1u))); // f >= 0: the cast floors
    }
    float r = log(max(dist / s.sliceNear, 1.0)) * s.sliceScale;
    return s.front + uint(clamp(r, 0.0, float(s.slices - 1u - s.front)));
}

// The slices [x, y] that a sphere (view-space centre c, padded radius r) can reach.
uvec2 laLightSlices(vec3 c, float r, LaSlicing s) {
    float d0 = (-c.z - r) * (1.0 - TP_TILE_CULL_PAD);
    float d1 = (-c.z + r) * (1.0 + TP_TILE_CULL_PAD);
    return uvec2(laSliceOf(d0, s), laSliceOf(d1, s));
}

// ---- compact lists (light_assign.h: LaListHeader) in a uint[] buffer ----
// Word `field` of tile t's header; fields in LaListHeader order.
#define TP_LA_COUNT 0u
#define TP_LA_START 1u
#define TP_LA_DROPPED 2u
#define TP_LA_FOUND 3u
uint laHeaderWord(uint tile, uint field) { return tile * TP_LA_HEADER_WORDS + field; }
// First light word of a tile whose run starts at `offset` (the compact layout's prefix sum).
uint laListStart(uint tileCount, uint offset) { return tileCount * TP_LA_HEADER_WORDS + offset; }

// ---- compact list fill in ascending light order (compute) ----
// Lights are tested in chunks whose survivors form a bitmask of 32-light words; the
// invocation that owns a word stores its lights after those of the words before it
// (`pos` = survivors of the earlier chunks + popcounts of the earlier words), so a list
// holds its lights in ascending order whatever the scheduling: deterministic lists, and
// the same per-light summation order on every device. The includer defines
// TP_LA_LIST_STORE(slot, k): write candidate light k (its light index, however the includer
// maps it) into slot `slot`.
#ifdef TP_LA_LIST_STORE
#include "include/light_list_walk.glsl"
// Stores the lights of one survivor word (candidates firstCandidate + bit) at
// listStart + pos, pos + 1, ...; a light at or beyond `capacity` is not stored (the caller
// counts it as dropped). Returns the next pos.
uint laStoreWord(uint bits, uint firstCandidate, uint listStart, uint pos, uint capacity) {
    TP_FOR_EACH_BIT(bits, lsb,
        if (pos < capacity) TP_LA_LIST_STORE(listStart + pos, firstCandidate + uint(lsb));
        ++pos;)
    return pos;
}
#endif

// ---- per-tile depth bounds (compute shaders that define TP_LA_DEPTH_FETCH) ----
// TP_LA_DEPTH_FETCH(ivec2 pixel, uint sample) returns the depth of one sample. The workgroup
// is 8 x 8 invocations whatever the tile size; each reads (tileSize / 8)^2 pixels, every
// sample of each. Usage: laDepthBoundsBegin(); barrier(); laDepthBoundsReduce(...);
// barrier(); then laTile*() are uniform over the group.
#ifdef TP_LA_DEPTH_FETCH
shared uint laNearBits; // nearest geometry depth (reverse-Z: largest); 0: no geometry
shared uint laFarBits;  // farthest geometry depth
shared uint laSkyBits;  // 1: some sample of the tile has no geometry

void laDepthBoundsBegin() {
    if (gl_LocalInvocationIndex == 0u) {
        laNearBits = 0u;
        laFarBits = floatBitsToUint(2.0); // above any depth: no geometry yet
        laSkyBits = 0u;
    }
}

// Depths are non-negative, so their bit patterns order like the values: min/max on the bits.
void laDepthBoundsReduce(uvec2 tile, uint tileSize, uvec2 viewport, uint samples) {
    float lo = 2.0, hi = 0.0;
    bool sky = false;
    const uint perSide = tileSize / gl_WorkGroupSize.x;
    for (uint py = 0u; py < perSide; ++py) {
        for (uint px = 0u; px < perSide; ++px) {
            uvec2 pixel = tile * tileSize + uvec2(px, py) * gl_WorkGroupSize.xy + gl_LocalInvocationID.xy;
            if (any(greaterThanEqual(pixel, viewport))) continue;
            for (uint s = 0u; s < samples; ++s) {
                float d = TP_LA_DEPTH_FETCH(ivec2(pixel), s);
                if (d > 0.0) {
                    lo = min(lo, d);
                    hi = max(hi, d);
                } else {
                    sky = true;
                }
            }
        }
    }
    if (hi > 0.0) {
        atomicMin(laFarBits, floatBitsToUint(lo));
        atomicMax(laNearBits, floatBitsToUint(hi));
    }
    if (sky) atomicOr(laSkyBits, 1u);
}

// The same bounds computed by one invocation for its whole tile, without shared memory or
// barriers (Forward+'s culling runs one invocation per tile: on lavapipe a barrier
// switches every 8-lane coroutine of a workgroup, which cost more than the tests).
struct LaTileDepth {
    float nearDepth; // nearest geometry depth (reverse-Z: largest); 0 without geometry
    float farDepth;  // farthest geometry depth; 0 without geometry
    bool hasGeometry;
    bool seesSky;    // some sample of the tile has no geometry
};

// The record of a tile whose geometry samples span depths [lo, hi] (hi 0: none) and which
// `sky` says sees the sky somewhere: the one ending of every way of reducing a tile's depth
// (serial here; gathered and per subgroup in Forward+'s culling shaders).
LaTileDepth laTileDepthOf(float lo, float hi, bool sky) {
    LaTileDepth t;
    t.hasGeometry = hi > 0.0;
    t.nearDepth = hi;
    t.farDepth = t.hasGeometry ? lo : 0.0;
    t.seesSky = sky;
    return t;
}

LaTileDepth laTileDepthSerial(uvec2 tile, uint tileSize, uvec2 viewport, uint samples) {
    float lo = 2.0, hi = 0.0;
    bool sky = false;
    uvec2 p0 = tile * tileSize, p1 = min(p0 + uvec2(tileSize), viewport);
    for (uint y = p0.y; y < p1.y; ++y) {
        for (uint x = p0.x; x < p1.x; ++x) {
            for (uint s = 0u; s < samples; ++s) {
                float d = TP_LA_DEPTH_FETCH(ivec2(x, y), s);
                if (d > 0.0) {
                    lo = min(lo, d);
                    hi = max(hi, d);
                } else {
                    sky = true;
                }
            }
        }
    }
    return laTileDepthOf(lo, hi, sky);
}

// The tile's bounds as the tile depth bounds pass stores them (passes/tiled_lighting.h:
// TP_TL_TILE_DEPTH_*), and back: the tiled lighting takes them from that pass.
uvec4 laDepthBoundsWords() { return uvec4(laNearBits, laFarBits, laSkyBits, 0u); }
void laDepthBoundsLoad(uvec4 words) {
    laNearBits = words.x;
    laFarBits = words.y;
    laSkyBits = words.z;
}
bool laTileHasGeometry() { return laNearBits > 0u; }
bool laTileSeesSky() { return laSkyBits != 0u; }
float laTileNearDepth() { return uintBitsToFloat(laNearBits); } // 0 without geometry
float laTileFarDepth() { return laTileHasGeometry() ? uintBitsToFloat(laFarBits) : 0.0; }
#endif
#endif
