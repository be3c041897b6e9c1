// Blended surfaces resolved in compute (--vis-blended compute), included by vis_shade_pixel.glsl
// under TP_VIS_BLEND inside the tiled lighting pass (it needs the pass's transparent lists,
// candidates, batch push constants and firstBatch). The blended_ids pass left, per pixel, a
// list of the blended fragments in front of the opaque depth (vis_shared.h); here each list is
// walked in ascending id order (the reference's blending order: blended_ids.frag), each
// fragment's material evaluated at the pixel centre (--msaa-shading pixel: what the blended
// forward pass's fragment computes) or at each covered sample (sample), lit by its tile's
// transparent light list, and blended over the covered samples' radiance:
// c = alpha * C + (1 - alpha) * c, as the hardware's blend state (core/gpu/pipelines.cpp).
// Blending is linear in the radiance, so a later lighting batch composites its own lights'
// part (opaque and blended, no ambient or emission) with the same alphas, and the sum over the
// batches is the composite of the sums.
#ifndef TP_VIS_BLEND_GLSL
#define TP_VIS_BLEND_GLSL
#include "include/light_list_walk.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_HEADS) readonly buffer BlendHeads {
    uint bHeads[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_NODES) readonly buffer BlendNodes {
    uvec2 bNodes[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_COUNTERS) buffer BlendCounters {
    uint bCounters[TP_VIS_BLEND_COUNTER_WORDS];
};

uint blendHead(ivec2 p) { return bHeads[uint(p.y) * frame.viewport.x + uint(p.x)]; }

#define TP_VIS_NO_FRAGMENT 0xffffffffu

// The fragment of the list at `head` with the smallest id above `after` (TP_VIS_NO_FRAGMENT:
// none), and its coverage. A selection walk, no local array: a list of n nodes costs n^2
// node reads and has no length limit but the pool's. A device may run the blended_ids
// fragment shader once per sample (lavapipe does under MSAA, though no sample shading is
// asked for), so one primitive can leave a node per sample: the coverage of every node with
// the chosen id is merged.
uint nextFragment(uint head, uint after, out uint coverage) {
    uint best = TP_VIS_NO_FRAGMENT;
    coverage = 0u;
    for (uint n = head; n != 0u; n = bNodes[n - 1u].y) {
        uint word = bNodes[n - 1u].x;
        uint id = word & ((1u << TP_VIS_BLEND_COVERAGE_SHIFT) - 1u);
        uint cov = word >> TP_VIS_BLEND_COVERAGE_SHIFT;
        if (id > after && id < best) {
            best = id;
            coverage = cov;
        } else if (id == best) {
            coverage |= cov;
        }
    }
    return best;
}

// The covered samples of pixel p where triangle t lies in front of the opaque surface (the
// depth test GREATER, redone per sample: the coverage the list holds is the rasterizer's
// before the test). Both points lie on the sample's ray from the eye, so the nearer is the
// shorter; a sample with no opaque geometry (depth 0, reverse-Z) passes.
uint samplesInFront(VisTriangle t, ivec2 p, uint coverage) {
    vec3 n = cross(t.p1 - t.p0, t.p2 - t.p0);
    uint passed = 0u;
    for (uint s = 0u; s < kSamples; ++s) {
        if ((coverage & (1u << s)) == 0u) continue;
        vec2 fc = vec2(p) + sampleOffset(s);
        float d = fetchDepth(p, s);
        vec3 dir = unprojectPosition(fc, 1.0);
        float nd = dot(n, dir);
        float along = nd != 0.0 ? dot(n, t.p0) / nd : 0.0;
        vec3 hit = along * dir, opaque = unprojectPosition(fc, d);
        if (d == 0.0 || nd == 0.0 || dot(hit, hit) < dot(opaque, opaque)) passed |= 1u << s;
    }
    return passed;
}

// The first index >= `light` in the ascending index run [start, start + count).
uint lowerBound(uint start, uint count, uint light) {
    uint lo = 0u, hi = count;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (tLists[start + mid] < light) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

// The tile's transparent lights in this batch's range of candidates [first, end), at ss: the
// bitmask's bits in the range (binned), or the index run's lights in it (every light a
// candidate, in ascending order: found by binary search).
vec3 blendedLights(uint tileIndex, SurfaceSample ss) {
    // The tile's run in the compact layout (transparentRun's start and capacity, without the
    // culling frustum it also builds).
    const uint offset = tOffsets[tileIndex];
    const uint start = laListStart(gl_NumWorkGroups.x * gl_NumWorkGroups.y, offset);
    const uint capacity = tOffsets[tileIndex + 1u] - offset;
    const uint first = draw.TP_TL_LIGHT_FIRST, end = draw.TP_TL_LIGHT_END;
    vec3 sum = vec3(0.0);
    if (kTransparentMasks) {
        const TlCandidates c = tlCandidates(tileIndex); // read once, as blended_forward.frag does
        for (uint w = first / 32u; w < min((end + 31u) / 32u, capacity); ++w) {
            uint bits = tLists[start + w];
            TP_FOR_EACH_BIT(bits, lsb,
                uint i = w * 32u + uint(lsb);
                if (i >= first && i < end) sum += evalLightShadowed(sceneLight(tlCandidateLight(c, i)), ss);)
        }
        return sum;
    }
    // The first batch has the count in shared memory (the header is written when it ends).
    const uint count = firstBatch() ? min(sTransparentCount, capacity) : tLists[laHeaderWord(tileIndex, TP_LA_COUNT)];
    for (uint i = lowerBound(start, count, first); i < count; ++i) {
        uint light = tLists[start + i];
        if (light >= end) break;
        sum += evalLightShadowed(sceneLight(light), ss);
    }
    return sum;
}

// A blended fragment's material lit: this batch's radiance and the material's alpha.
vec4 blendedRadiance(MaterialSample ms) {
    vec3 sum = firstBatch() ? ambientAndEmissive(ms) : vec3(0.0);
    sum += blendedLights(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x, ms.surface);
    return vec4(sum, ms.alpha);
}

// A blended fragment of triangle t at framebuffer location fc, lit.
vec4 shadeBlended(VisTriangle t, vec2 fc, float depth) {
    return blendedRadiance(readTriangle(t, fc, depth));
}

// `lit` (radiance, alpha) blended over the radiance under it, as the hardware's blend state.
vec3 blendOver(vec4 lit, vec3 under) { return lit.a * lit.rgb + (1.0 - lit.a) * under; }

// Pixel p's blended fragments (the list at `head`) over its samples' radiance c[0, kSamples).
void compositeBlended(ivec2 p, uint head, inout vec3 c[8]) {
    uint coverage, fragments = 0u;
    for (uint id = nextFragment(head, 0u, coverage); id != TP_VIS_NO_FRAGMENT; id = nextFragment(head, id, coverage)) {
        ++fragments;
        VisTriangle t = visTriangle(id);
        if (kSamples > 1u) coverage = samplesInFront(t, p, coverage);
        if (coverage == 0u) continue;
        vec4 lit = kEverySample ? vec4(0.0) : shadeBlended(t, vec2(p) + vec2(0.5), fetchDepth(p, 0u));
        for (uint s = 0u; s < kSamples; ++s) {
            if ((coverage & (1u << s)) == 0u) continue;
            if (kEverySample) lit = shadeBlended(t, vec2(p) + sampleOffset(s), fetchDepth(p, s));
            c[s] = blendOver(lit, c[s]);
        }
    }
    if (firstBatch()) atomicMax(bCounters[TP_VIS_BLEND_MAX_DEPTH], fragments);
}

// Pixel p, not an edge, at pixel rate: its samples' radiance c[0, kSamples) with the blended
// fragments composited over them; returns the pixel's list head (0: no list). What shade() of
// sample 0's triangle and then compositeBlended compute, the same operations in the same order
// (the same image), but as the turns of one loop (the opaque surface, where there is one, then
// each blended fragment in ascending id order) around one material evaluation (readTriangle):
// lavapipe runs every call site in every lane of a group, taken or not, so the composite's own
// surface read cost every pixel a second material evaluation, about half of the resolve at
// 1280x720 (docs/visbuffer.md, "The composite where a pixel has a list"). A do-while: a loop
// that tests at the top runs its body once more than its longest lane there.
uint shadeLayers(ivec2 p, out vec3 c[8]) {
    const uint head = blendHead(p);
    const float depth = fetchDepth(p, 0u);
    for (uint s = 0u; s < kSamples; ++s) c[s] = vec3(0.0);
    uint current = fetchId(p, 0u), coverage = 0u, fragments = 0u; // turn 0: the opaque surface (0: none)
    bool blended = false;
    do {
        if (current != 0u) { // a blended turn's id is never 0
            const VisTriangle t = visTriangle(current);
            if (blended) {
                ++fragments;
                if (kSamples > 1u) coverage = samplesInFront(t, p, coverage);
            }
            if (!blended || coverage != 0u) {
                MaterialSample ms = readTriangle(t, vec2(p) + vec2(0.5), depth);
                if (!blended) {
                    const vec3 lit =
                        shadeSurface(ms.surface, firstBatch() ? ambientAndEmissive(ms) : vec3(0.0));
                    for (uint s = 0u; s < kSamples; ++s) c[s] = lit;
                } else {
                    const vec4 lit = blendedRadiance(ms);
                    for (uint s = 0u; s < kSamples; ++s)
                        if ((coverage & (1u << s)) != 0u) c[s] = blendOver(lit, c[s]);
                }
            }
        }
        current = nextFragment(head, blended ? current : 0u, coverage);
        blended = true;
    } while (current != TP_VIS_NO_FRAGMENT);
    if (head != 0u && firstBatch()) atomicMax(bCounters[TP_VIS_BLEND_MAX_DEPTH], fragments);
    return head;
}
#endif
