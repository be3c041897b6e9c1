// The tiled lighting pass, part 3 of 4 (passes/tiled_lighting_inputs.glsl lists the parts):
// the pixel of a surface source that stores one surface per sample (deferred's G-buffer).
#ifndef TP_LISTS_ONLY
// Pixel p, not an edge: one surface, shaded once at the pixel centre with the mean sample
// depth, and written to every sample.
void shadePixel(ivec2 p) {
    float d = meanDepth(p);
    vec3 c = d > 0.0 ? shade(p, 0u, vec2(0.5), d) : vec3(0.0);
#ifdef TP_HDR_MSAA
    for (uint s = 0u; s < kSamples; ++s) writeHdr(p, s, c);
#else
    writeHdr(p, 0u, c);
#endif
}

// An edge (isEdge(p)) is lit per sample, each at its own location; flattened
// (tiled_lighting_main.glsl: shadeEdges) its k-th surface is sample k, and sample s's radiance
// is surface s's.
uint edgeItemSample(ivec2 p, uint k) { return k; }
uint edgeSampleItem(ivec2 p, uint s) { return s; }
vec3 shadeEdgeSample(ivec2 p, uint s) {
    float d = fetchDepth(p, s);
    return d > 0.0 ? shade(p, s, sampleOffset(s), d) : vec3(0.0);
}

// The edge's samples' radiance c[0, kSamples), written (per sample) or averaged.
void finishEdge(ivec2 p, vec3 c[8]);

// Whether edge p composites blended fragments (shaded one invocation a pixel, not flattened:
// tiled_lighting_main.glsl): never here.
bool edgeComposites(ivec2 p) { return false; }

// An edge shaded by one invocation (at --msaa-shading sample, where every pixel is one).
void shadeEdgePixel(ivec2 p) {
    vec3 c[8];
    for (uint s = 0u; s < kSamples; ++s) c[s] = shadeEdgeSample(p, s);
    finishEdge(p, c);
}

void finishEdge(ivec2 p, vec3 c[8]) {
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < kSamples; ++s) {
#ifdef TP_HDR_MSAA
        writeHdr(p, s, c[s]);
#endif
        sum += c[s];
    }
#ifndef TP_HDR_MSAA
    writeHdr(p, 0u, sum / float(kSamples));
#endif
}
#endif
