// The visibility buffer's side of the compute rasterizer (vis_raster.comp, vis_raster_big.comp;
// docs/visbuffer.md, "The compute rasterizer"): the triangle itself is include/
// raster_triangle.glsl's (shared with the shadow maps' --shadow-raster compute); here the view
// (scene.vert's clip positions, the camera's viewport, y flipped as setViewportAndScissor's
// negative height) and the samples: (depth, id) per sample with a 64-bit atomic max.
// Ties at equal depth go to the smaller id (~id in the low word): the draw and the triangle
// the hardware rasterizes first, as its GREATER depth test keeps the first.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "include/shared.h"
#include "visbuffer/vis_shared.h"
#include "visbuffer/vis_raster.h"
#include "include/scene_bindings.glsl"
#include "include/unproject.glsl"

layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;
layout(constant_id = TP_VIS_SPEC_TRIANGLE_BITS) const uint kTriangleBits = 20u;
layout(constant_id = TP_VR_SPEC_HYBRID) const uint kHybrid = 0u;
#include "include/sample_locations.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_SAMPLES) buffer SampleBlock {
    uint64_t visSamples[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_ROWS) readonly buffer RowBlock {
    RasterRow rasterRows[];
};

#include "include/raster_triangle.glsl"

// Scene.vert's clip position of vertex `index` (the same `precise` operations).
vec4 clipPosition(uint index) {
    Vertex v = vertices[index];
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    precise vec4 clip = frame.viewProj * vec4(relative, 1.0);
    return clip;
}

vec3 rasterRelative(uint index) { return vertices[index].positionU.xyz - frame.eyeWorld.xyz; }
vec3 rasterRayDir(vec2 fc) { return unprojectPosition(fc, 1.0); }
ivec2 rasterViewOrigin() { return ivec2(0); }
ivec2 rasterViewSize() { return ivec2(frame.viewport.xy); }
bool rasterFlipY() { return true; }

uint64_t packSample(float depth, uint id) {
    return (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(~id);
}

uint rasterSample(ivec2 px, uint k, vec2 fc, float z, uint id, bool masked, MaskTriangle mt) {
    uint slot = (uint(px.y) * frame.viewport.x + uint(px.x)) * kSamples + k;
    uint64_t packed = packSample(z, id);
    if (masked) {
        if (visSamples[slot] >= packed) return 0u; // hidden: no texture fetch
        if (maskAlpha(mt, fc) < materials[mt.material].alphaCutoff) return 0u;
    }
    atomicMax(visSamples[slot], packed);
    return 1u;
}

// The draw row's flags of id's triangle.
RasterRow rowOf(uint id) { return rasterRows[(id >> kTriangleBits) - 1u]; }

// Triangle (v0, v1, v2), unclipped, of the row `id` names: by this invocation alone (`big`
// false: vis_raster's small triangles) or in tiles by the 64 of a vis_raster_big group.
uint rasterTriangle(RasterVertex v0, RasterVertex v1, RasterVertex v2, uint i0, uint i1,
                    uint i2, uint id, bool big, uint lane, out bool drew) {
    RasterRow row = rowOf(id);
    return rasterTriangleAs(v0, v1, v2, i0, i1, i2, id,
                            (row.flags & TP_VR_FLAG_DOUBLE_SIDED) != 0u,
                            (row.flags & TP_VR_FLAG_MASKED) != 0u, row.material, big, lane, drew);
}

// A listed triangle of the row `id` names (vis_raster_big).
uint rasterListedTriangle(uint i0, uint i1, uint i2, uint id, uint lane) {
    RasterRow row = rowOf(id);
    bool drew;
    return rasterListed(i0, i1, i2, id, (row.flags & TP_VR_FLAG_DOUBLE_SIDED) != 0u,
                        (row.flags & TP_VR_FLAG_MASKED) != 0u, row.material, true, lane, drew);
}
