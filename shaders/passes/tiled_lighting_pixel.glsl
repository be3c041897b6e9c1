// The tiled lighting pass, part 3 of 4 (passes/tiled_lighting_inputs.glsl lists the parts):
// the pixel of a surface source that stores one surface per sample (deferred's G-buffer).
#ifndef TP_LISTS_ONLY
// Shades pixel p and writes hdr: once at the centre, or (edge: isEdge(p), which the caller
// tested) every sample.
void shadePixel(ivec2 p, bool edge) {
    if (!edge) {
        // One surface: shade once at the pixel centre with the mean sample depth.
        float d = meanDepth(p);
        vec3 c = d > 0.0 ? shade(p, 0u, vec2(0.5), d) : vec3(0.0);
#ifdef TP_HDR_MSAA
        for (uint s = 0u; s < kSamples; ++s) writeHdr(p, s, c);
#else
        writeHdr(p, 0u, c);
#endif
        return;
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
}
#endif
