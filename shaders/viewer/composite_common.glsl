// What composite.comp and composite_stats.comp both read: the two images by texel, and the
// difference's per-pixel value as compare measures it (core/image/difference.cpp).
layout(set = 1, binding = TP_VC_BINDING_LEFT) uniform sampler2D leftImage;
layout(set = 1, binding = TP_VC_BINDING_RIGHT) uniform sampler2D rightImage;
layout(push_constant) uniform Push { CompositePush pc; };

// max-channel |A - B| as the CPU takes it (std::max over r, g, b in that order: a NaN channel
// after the first is passed over, a NaN first is kept), and whether every channel is finite
// (heatMap's magenta test). The percentile counts a pixel whose value is finite
// (differencePercentile99); the heat map colours one whose channels all are.
float differenceAt(ivec2 p, out bool allFinite) {
    const vec3 d = texelFetch(leftImage, p, 0).rgb - texelFetch(rightImage, p, 0).rgb;
    const vec3 a = abs(d);
    float value = a.x;
    if (value < a.y) value = a.y;
    if (value < a.z) value = a.z;
    allFinite = !(any(isnan(d)) || any(isinf(d)));
    return value;
}
