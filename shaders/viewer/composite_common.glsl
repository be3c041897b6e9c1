// What composite.comp and composite_stats.comp both read: the two images by texel, and the
// difference's per-pixel value as compare measures it (core/image/difference.cpp).
layout(set = 1, binding = TP_VC_BINDING_LEFT) uniform sampler2D leftImage;
layout(set = 1, binding = TP_VC_BINDING_RIGHT) uniform sampler2D rightImage;
layout(push_constant) uniform Push { CompositePush pc; };

// max-channel |A - B|; false when a channel of the difference is not finite.
bool differenceAt(ivec2 p, out float value) {
    const vec3 d = texelFetch(leftImage, p, 0).rgb - texelFetch(rightImage, p, 0).rgb;
    value = max(max(abs(d.x), abs(d.y)), abs(d.z));
    return !(any(isnan(d)) || any(isinf(d)));
}
