// From framebuffer coordinates and a reverse-Z depth back to the camera-relative position
// (world minus eye, as scene.vert interpolates it), and the unit direction to the viewer.
// ONE copy, called by deferred's G-buffer read (deferred/gbuffer_read.glsl) and by the
// reference's `--reference-position depth` variant (reference/reference.frag), so that the
// reference can light a sample at exactly the position deferred reconstructs for it: the
// same formula, the same fp32 operations in the same order. Needs `frame` (scene_bindings.glsl).
#ifndef TP_UNPROJECT_GLSL
#define TP_UNPROJECT_GLSL

// fragCoord: framebuffer coordinates, y down (gl_FragCoord.xy; float(pixel) + sample offset in a
// compute pass, which is the same value exactly: small integers plus multiples of 1/16).
// invViewProj is built from the rotation-only view, so the result's error scales with the
// distance to the eye, not with the distance to the world origin.
// `precise` (SPIR-V NoContraction): no multiply-add fused in one shader and not in the other,
// so a compute pass and a fragment shader get the same bits from the same inputs.
vec3 unprojectPosition(vec2 fragCoord, float depth) {
    vec2 size = vec2(frame.viewport.xy);
    precise vec2 ndc = vec2(fragCoord.x / size.x * 2.0 - 1.0, 1.0 - fragCoord.y / size.y * 2.0);
    precise vec4 w = frame.invViewProj * vec4(ndc, depth, 1.0);
    precise vec3 position = w.xyz / w.w;
    return position;
}

// Unit vector from a camera-relative position to the viewer (the origin); `fallback` at the eye.
vec3 directionToViewer(vec3 position, vec3 fallback) {
    vec3 toViewer = -position;
    precise float vl = length(toViewer);
    precise vec3 direction = toViewer / vl;
    return vl > 0.0 ? direction : fallback;
}
#endif
