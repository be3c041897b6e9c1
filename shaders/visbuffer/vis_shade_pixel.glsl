// The visibility buffer's pixel in the tiled lighting pass (vis_resolve.comp: in place of the
// library's passes/tiled_lighting_pixel.glsl; needs its shade and writeHdr). A pixel
// whose samples hold one triangle is shaded once at its centre. Otherwise, at --msaa-shading
// pixel, once per distinct triangle at the centre (what a forward pass's fragment does for
// each primitive covering the pixel, and the centre reference for each sample), reused by
// every sample of that triangle; at --msaa-shading sample, every sample at its own location.
// TP_VIS_BLEND (--vis-blended compute): the pixel's blended fragments are composited over its
// samples before they are averaged (vis_blend.glsl).
#ifdef TP_VIS_BLEND
#include "visbuffer/vis_blend.glsl"
#endif

// An edge's surfaces (tiled_lighting_main.glsl: shadeEdges). At --msaa-shading sample every
// sample is one, lit at its own location. At pixel rate a surface is a distinct triangle,
// lit at the centre at the depth of its first sample, and its radiance is every sample's that
// holds it: surface k is the k-th sample whose id no earlier sample holds.
uint edgeItemSample(ivec2 p, uint k) {
    if (kEverySample) return k;
    uint ids[8], n = 0u;
    for (uint s = 0u; s < kSamples; ++s) {
        ids[s] = fetchId(p, s);
        bool seen = false;
        for (uint t = 0u; t < s; ++t) seen = seen || ids[t] == ids[s];
        if (!seen) {
            if (n == k) return s;
            ++n;
        }
    }
    return kSamples; // the pixel has fewer surfaces
}

// The surface whose radiance sample s takes: how many distinct ids come before its id's first
// sample.
uint edgeSampleItem(ivec2 p, uint s) {
    if (kEverySample) return s;
    const uint id = fetchId(p, s);
    uint ids[8], n = 0u;
    for (uint t = 0u; t < s; ++t) {
        ids[t] = fetchId(p, t);
        if (ids[t] == id) return n;
        bool seen = false;
        for (uint u = 0u; u < t; ++u) seen = seen || ids[u] == ids[t];
        if (!seen) ++n;
    }
    return n;
}

// Sample s of an edge, holding triangle `id` (0: none): lit at its own location at sample rate,
// at the centre at pixel rate.
vec3 shadeEdgeSurface(ivec2 p, uint s, uint id) {
    return id != 0u ? shade(p, s, kEverySample ? sampleOffset(s) : vec2(0.5), fetchDepth(p, s)) : vec3(0.0);
}
vec3 shadeEdgeSample(ivec2 p, uint s) { return shadeEdgeSurface(p, s, fetchId(p, s)); }

// The samples' radiance c[0, kSamples), the blended fragments composited over them, written
// (per sample) or averaged; a pixel whose samples all hold one value is written as it is (their
// average could round).
void writePixel(ivec2 p, vec3 c[8], bool oneValue) {
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < kSamples; ++s) {
#ifdef TP_HDR_MSAA
        writeHdr(p, s, c[s]);
#endif
        sum += c[s];
    }
#ifndef TP_HDR_MSAA
    writeHdr(p, 0u, oneValue ? c[0] : sum / float(kSamples));
#endif
}

void finishPixel(ivec2 p, inout vec3 c[8], bool oneSurface) {
#ifdef TP_VIS_BLEND
    const uint head = blendHead(p);
    if (head != 0u) compositeBlended(p, head, c);
#else
    const uint head = 0u;
#endif
    writePixel(p, c, oneSurface && head == 0u);
}

void finishEdge(ivec2 p, vec3 c[8]) { finishPixel(p, c, false); }

// Whether edge p is shaded by one invocation (shadeEdgePixel), not flattened
// (tiled_lighting_main.glsl): with --vis-blended compute, every edge under --vis-edges pixel,
// and under split only those with blended fragments to composite (vis_shared.h:
// TP_VIS_SPEC_SPLIT_EDGES).
#ifdef TP_VIS_BLEND
layout(constant_id = TP_VIS_SPEC_SPLIT_EDGES) const bool kSplitEdges = false;
bool edgeComposites(ivec2 p) { return !kSplitEdges || blendHead(p) != 0u; }
#else
bool edgeComposites(ivec2 p) { return false; }
#endif

// An edge shaded by one invocation (one that composites, and at sample rate): samples
// [0, kSamples) each lit once per distinct triangle (pixel rate, reading the ids once) or at
// its own location (sample rate).
void shadeEdgePixel(ivec2 p) {
    vec3 c[8];
    uint ids[8];
    for (uint s = 0u; s < kSamples; ++s) {
        uint id = fetchId(p, s);
        ids[s] = id;
        bool reused = false;
        for (uint t = 0u; !kEverySample && t < s && !reused; ++t) {
            reused = ids[t] == id;
            if (reused) c[s] = c[t];
        }
        if (!reused) c[s] = shadeEdgeSurface(p, s, id);
    }
    finishPixel(p, c, false);
}

// Pixel p, not an edge: one triangle, shaded once at the centre, for every sample.
void shadePixel(ivec2 p) {
#ifdef TP_VIS_BLEND
    if (!kEverySample) { // its blended fragments in the same loop (vis_blend.glsl)
        vec3 c[8];
        const uint head = shadeLayers(p, c);
        writePixel(p, c, head == 0u);
        return;
    }
#endif
    vec3 c[8];
    uint id = fetchId(p, 0u);
    c[0] = id != 0u ? shade(p, 0u, vec2(0.5), fetchDepth(p, 0u)) : vec3(0.0);
    for (uint s = 1u; s < kSamples; ++s) c[s] = c[0];
    finishPixel(p, c, true);
}
