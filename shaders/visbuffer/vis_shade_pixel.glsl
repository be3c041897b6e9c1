// The visibility buffer's pixel in the tiled lighting pass (vis_resolve.comp: in place of the
// library's passes/tiled_lighting_pixel.glsl; needs its shade and writeHdr). A pixel
// whose samples hold one triangle is shaded once at its centre. Otherwise, at --msaa-shading
// pixel, once per distinct triangle at the centre (what a forward pass's fragment does for
// each primitive covering the pixel, and the centre reference for each sample), reused by
// every sample of that triangle; at --msaa-shading sample, every sample at its own location.
// TP_VIS_BLEND (--vis-blended compute): the pixel's blended fragments are composited over its
// samples before they are averaged (vis_blend.glsl).
// edge: isEdge(p), which the caller tested.
#ifdef TP_VIS_BLEND
#include "visbuffer/vis_blend.glsl"
#endif

// Samples [0, kSamples) of pixel p, each lit once per distinct triangle (pixel rate) or at
// its own location (sample rate), into c.
void shadeSamples(ivec2 p, inout vec3 c[8]) {
    uint ids[8];
    for (uint s = 0u; s < kSamples; ++s) {
        uint id = fetchId(p, s);
        ids[s] = id;
        bool reused = false;
        for (uint t = 0u; !kEverySample && t < s && !reused; ++t) {
            reused = ids[t] == id;
            if (reused) c[s] = c[t];
        }
        if (!reused)
            c[s] = id != 0u ? shade(p, s, kEverySample ? sampleOffset(s) : vec2(0.5), fetchDepth(p, s)) : vec3(0.0);
    }
}

// One shade() call site: a device that runs both sides of a divergent branch (lavapipe's
// SIMD lanes) would otherwise pay for a second inlined copy of the material and light loop
// in every pixel (measured: 1280x720, 128 lights, --vis-blended compute, 3.44 s -> see
// docs/visbuffer.md).
void shadePixel(ivec2 p, bool edge) {
    vec3 c[8];
    if (edge) {
        shadeSamples(p, c);
    } else { // one triangle: shaded once at the centre, for every sample
        uint id = fetchId(p, 0u);
        c[0] = id != 0u ? shade(p, 0u, vec2(0.5), fetchDepth(p, 0u)) : vec3(0.0);
        for (uint s = 1u; s < kSamples; ++s) c[s] = c[0];
    }
#ifdef TP_VIS_BLEND
    const uint head = blendHead(p);
    if (head != 0u) compositeBlended(p, head, c);
#else
    const uint head = 0u;
#endif
    // Samples that all hold one value are written as it is (their average could round).
    const bool oneValue = !edge && head == 0u;
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
