// The visibility buffer's pixel in the tiled lighting pass (deferred/tiled_lighting.comp under
// TP_VISBUFFER, in place of the G-buffer's shadePixel; needs its shade and writeHdr). A pixel
// whose samples hold one triangle is shaded once at its centre. Otherwise, at --msaa-shading
// pixel, once per distinct triangle at the centre (what a forward pass's fragment does for
// each primitive covering the pixel, and the centre reference for each sample), reused by
// every sample of that triangle; at --msaa-shading sample, every sample at its own location.
// Returns whether the pixel was an edge.
bool shadePixel(ivec2 p) {
    bool edge = kSamples > 1u && isEdge(p);
    if (!edge) {
        uint id = fetchId(p, 0u);
        vec3 c = id != 0u ? shade(p, 0u, vec2(0.5), fetchDepth(p, 0u)) : vec3(0.0);
#ifdef TP_HDR_MSAA
        for (uint s = 0u; s < kSamples; ++s) writeHdr(p, s, c);
#else
        writeHdr(p, 0u, c);
#endif
        return false;
    }
    uint ids[8];
    vec3 shaded[8];
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < kSamples; ++s) {
        uint id = fetchId(p, s);
        ids[s] = id;
        vec3 c = vec3(0.0);
        bool reused = false;
        for (uint t = 0u; !kEverySample && t < s && !reused; ++t) {
            reused = ids[t] == id;
            if (reused) c = shaded[t];
        }
        if (id != 0u && !reused)
            c = shade(p, s, kEverySample ? sampleOffset(s) : vec2(0.5), fetchDepth(p, s));
        shaded[s] = c;
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
