// The visibility buffer's surface reader for the pass library's tiled lighting (the interface
// passes/tiled_lighting_inputs.glsl declares; visbuffer/vis_resolve.comp puts them together). A sample's id names a draw and a triangle (vis_shared.h); the reader fetches
// the triangle's three vertices (the scene's index and vertex buffers), intersects the ray
// through the shaded location with the triangle's plane, and from the hit's barycentrics
// interpolates the vertex attributes and evaluates the material (include/material.glsl: the
// same code every fragment stage runs), sampling its textures with textureGrad from the
// barycentrics' analytic screen-space derivatives or the differences over the pixel's quad
// (--vis-derivatives). docs/visbuffer.md derives it and bounds it against the
// hardware's derivatives.
#ifndef TP_VIS_READ_GLSL
#define TP_VIS_READ_GLSL
#ifdef TP_VIS_BLEND // --vis-blended compute: the resolve composites the blended fragments
#define TP_TL_COMPOSITES_BLENDED
#endif
#include "visbuffer/vis_shared.h"
#include "include/tile_culling.glsl" // viewZFromDepth
#include "include/unproject.glsl"

layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;
layout(constant_id = TP_TL_SPEC_EVERY_SAMPLE) const bool kEverySample = false;
layout(constant_id = TP_VIS_SPEC_TRIANGLE_BITS) const uint kTriangleBits = 20u;
// --vis-derivatives: the uv derivatives textureGrad is given (TP_VIS_DERIVATIVES_*).
layout(constant_id = TP_VIS_SPEC_DERIVATIVES) const uint kDerivatives = TP_VIS_DERIVATIVES_ANALYTIC;
#include "include/sample_locations.glsl"

#include "passes/surface_images.glsl"
layout(set = TP_SET_PASS, binding = TP_VIS_BINDING_IDS) uniform TP_SURFACE_TEX gIds;
layout(set = TP_SET_PASS, binding = TP_TL_BINDING_DEPTH) uniform TP_SURFACE_TEX gDepth;
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_INDICES) readonly buffer VisIndices {
    uint visIndices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_DRAWS) readonly buffer VisDraws {
    VisDraw visDraws[];
};

// The gradients of the shaded location, set by readSurfaceAt before it evaluates the material:
// textures are sampled with textureGrad (a compute stage has no implicit derivatives) and the
// geometric normal comes from the position's derivatives, as dFdx/dFdy give them in a
// fragment stage.
vec2 gVisUvDx, gVisUvDy;
vec3 gVisPosDx, gVisPosDy;

// The texture index differs between the invocations of a group (their materials do), and an
// index into a sampler array must be dynamically uniform unless the device has
// shaderSampledImageArrayNonUniformIndexing (lavapipe does not). So the array is walked with a
// uniform loop counter and each invocation samples where the counter meets its index: on a
// GPU one walk a slot (kOneTextureWalk off: a branch no lane takes costs nothing there). On a
// CPU device every branch runs in every lane, so every sample site costs the whole group: there
// the five slots are sampled together, once per material before evalMaterial (readTriangle),
// in one walk of kTextureCount sites instead of one a slot. All five read the one uv with the
// one footprint, so each slot's texel is what sampling it alone gives (docs/visbuffer.md, "The
// texture walk": the same bytes; lavapipe's resolve 40 % shorter, the H200's 22 % longer).
layout(constant_id = TP_VIS_SPEC_ONE_TEXTURE_WALK) const bool kOneTextureWalk = false;
int gVisSlot[5];
vec4 gVisTexel[5];
void visSampleMaterialTextures(MaterialGpu m, vec2 uv) {
    if (!kOneTextureWalk) return;
    gVisSlot = int[5](m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture,
                      m.occlusionTexture, m.emissiveTexture);
    for (int k = 0; k < 5; ++k) gVisTexel[k] = vec4(0.0);
    for (int i = 0; i < kTextureCount; ++i) {
        bool named = false;
        for (int k = 0; k < 5; ++k) named = named || gVisSlot[k] == i;
        if (!named) continue;
        const vec4 texel = textureGrad(textures[i], uv, gVisUvDx, gVisUvDy);
        for (int k = 0; k < 5; ++k)
            if (gVisSlot[k] == i) gVisTexel[k] = texel;
    }
}
// Texture `index` at uv (material.glsl asks only for an index in range): the texel the one
// walk took, or this slot's own walk.
vec4 visTexture(int index, vec2 uv) {
    vec4 r = vec4(0.0);
    if (kOneTextureWalk) {
        for (int k = 0; k < 5; ++k)
            if (gVisSlot[k] == index) r = gVisTexel[k];
        return r;
    }
    for (int i = 0; i < kTextureCount; ++i)
        if (i == index) r = textureGrad(textures[i], uv, gVisUvDx, gVisUvDy);
    return r;
}
#define TP_MATERIAL_TEXTURE(index, uv) visTexture(index, uv)
#define TP_MATERIAL_POSITION_DX(p) gVisPosDx
#define TP_MATERIAL_POSITION_DY(p) gVisPosDy
#include "include/material.glsl"

layout(constant_id = TP_VIS_SPEC_IDS_BY_DEPTH) const bool kIdsByDepth = false;

float fetchDepth(ivec2 p, uint s) { return FETCH(gDepth, p, s).r; }
// kIdsByDepth: a sample the visibility pass did not write keeps a stale id; its depth is still
// the clear value 0 (reverse-Z far plane, which no written sample has: the test is GREATER).
uint fetchId(ivec2 p, uint s) {
    if (kIdsByDepth && fetchDepth(p, s) <= 0.0) return 0u;
    return uint(FETCH(gIds, p, s).r);
}

// Mean of the samples' depths (the tile depth bounds read depth only through fetchDepth).
float meanDepth(ivec2 p) {
    float d = 0.0;
    for (uint s = 0u; s < kSamples; ++s) d += fetchDepth(p, s);
    return d / float(kSamples);
}

// A pixel is an edge when its samples do not all hold one triangle (or not all hold one):
// the ids say it exactly, no depth or attribute heuristic. With --msaa-shading sample every
// pixel holding geometry is shaded per sample, as the supersampled reference is.
bool isEdge(ivec2 p) {
    uint id0 = fetchId(p, 0u);
    for (uint s = 1u; s < kSamples; ++s) {
        uint id = fetchId(p, s);
        if (id != id0 || (kEverySample && id != 0u)) return true;
    }
    return kEverySample && id0 != 0u;
}

// One vertex of triangle `triangle` of draw `d`, camera-relative as scene.vert makes it (the
// same `precise` subtraction, so the position is the one the rasterizer was given).
Vertex visVertex(VisDraw d, uint triangle, uint k) {
    return vertices[uint(int(visIndices[d.firstIndex + 3u * triangle + k]) + d.vertexOffset)];
}
vec3 relativePosition(Vertex v) {
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    return relative;
}

// Barycentrics of the ray through framebuffer location `fc` with the triangle's plane, and
// their derivatives per pixel in x and y (rows 1 and 2), with the hit and its derivatives.
struct VisHit {
    vec3 b, bdx, bdy;         // barycentrics and d/dx, d/dy per pixel
    vec3 position, pdx, pdy;  // camera-relative hit and d/dx, d/dy
};

// The ray leaves the eye (the origin, camera-relative) through the location unprojected at
// reverse-Z depth 1 (the near plane); at a fixed depth the unprojection is affine in the
// framebuffer location, so one pixel's step is a difference of two unprojections. The hit
// X = t * dir with t = (n . p0) / (n . dir) moves per pixel by t * (ddir - dir (n . ddir) / (n . dir));
// barycentrics are linear in X on the plane (b1 = ((X - p0) x e2) . n / |n|^2, b2 =
// (e1 x (X - p0)) . n / |n|^2), so their derivatives are the same maps of X's.
VisHit intersect(vec3 p0, vec3 p1, vec3 p2, vec2 fc, float depth) {
    vec3 dir = unprojectPosition(fc, 1.0);
    vec3 ddx = unprojectPosition(fc + vec2(1.0, 0.0), 1.0) - dir;
    vec3 ddy = unprojectPosition(fc + vec2(0.0, 1.0), 1.0) - dir;
    vec3 e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
    float nd = dot(n, dir), nn = dot(n, n);
    VisHit h;
    float t = dot(n, p0) / nd;
    // An edge-on triangle (n . dir = 0) can hold a sample only at the rasterizer's rounding:
    // take the depth buffer's point there instead of an infinite one.
    bool finiteHit = nd != 0.0 && !isinf(t) && !isnan(t) && nn > 0.0;
    vec3 hit = finiteHit ? t * dir : unprojectPosition(fc, depth);
    h.pdx = finiteHit ? t * (ddx - dir * (dot(n, ddx) / nd)) : vec3(0.0);
    h.pdy = finiteHit ? t * (ddy - dir * (dot(n, ddy) / nd)) : vec3(0.0);
    float inv = nn > 0.0 ? 1.0 / nn : 0.0;
    vec3 r = hit - p0;
    vec2 b12 = vec2(dot(cross(r, e2), n), dot(cross(e1, r), n)) * inv;
    // The shaded point: the hit moved onto the plane along the unit normal. t * dir alone is
    // off the plane by the rounding of t, up to 3u (|p0| + |X|) (u = 2^-24), which next to a
    // light hugging the surface is a change of n . l of that over the light's height; the
    // plane's own distance n^ . (X - p0) rounds at |X - p0| (exactly 0 for a plane along an
    // axis), and the move along n^ leaves the point's place on the plane (its error at |X|,
    // as the hit's) as it was. The rasterizer's b0 p0 + b1 p1 + b2 p2 rounds at the vertices'
    // magnitudes both ways: this is of its order or better (docs/visbuffer.md, "The
    // position's error next to a light").
    vec3 unitN = n * inversesqrt(max(nn, 1e-38));
    h.position = finiteHit ? hit - unitN * dot(unitN, r) : hit;
    vec2 b12dx = vec2(dot(cross(h.pdx, e2), n), dot(cross(e1, h.pdx), n)) * inv;
    vec2 b12dy = vec2(dot(cross(h.pdy, e2), n), dot(cross(e1, h.pdy), n)) * inv;
    h.b = vec3(1.0 - b12.x - b12.y, b12);
    h.bdx = vec3(-b12dx.x - b12dx.y, b12dx);
    h.bdy = vec3(-b12dy.x - b12dy.y, b12dy);
    return h;
}

#define TP_VIS_LERP(a0, a1, a2, w) ((a0) * (w).x + (a1) * (w).y + (a2) * (w).z)

// (b1, b2) where the ray through framebuffer location fc meets the plane of the triangle
// p0 + b1 e1 + b2 e2 (n = e1 x e2, invNN = 1 / |n|^2): intersect()'s arithmetic, at any
// location, inside the triangle or not.
vec2 planeBarycentrics(vec3 p0, vec3 e1, vec3 e2, vec3 n, float invNN, vec2 fc) {
    vec3 dir = unprojectPosition(fc, 1.0);
    vec3 r = (dot(n, p0) / dot(n, dir)) * dir - p0;
    return vec2(dot(cross(r, e2), n), dot(cross(e1, r), n)) * invNN;
}

// --vis-derivatives quad: the uv differences a fragment quad takes (docs/visbuffer.md,
// "The texture footprint"). A quad is the 2x2 pixels at even coordinates; each of its lanes
// (helper lanes where the triangle does not cover them) holds the uv interpolated on the same
// triangle's plane at its pixel, at the same offset within the pixel as the shaded location.
// Fine: d/dx from the pair in the shaded pixel's row, d/dy from the pair in its column;
// coarse: from the quad's top row and left column, one pair for the four pixels.
void quadUvDerivatives(vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2, vec2 fc) {
    vec3 e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
    float nn = dot(n, n);
    float inv = nn > 0.0 ? 1.0 / nn : 0.0;
    vec2 base = fc - mod(floor(fc), 2.0); // the quad's top-left pixel, same offset
    bool coarse = kDerivatives == TP_VIS_DERIVATIVES_QUAD_COARSE;
    float row = coarse ? base.y : fc.y, column = coarse ? base.x : fc.x;
    vec2 l = planeBarycentrics(p0, e1, e2, n, inv, vec2(base.x, row));
    vec2 r = planeBarycentrics(p0, e1, e2, n, inv, vec2(base.x + 1.0, row));
    vec2 t = planeBarycentrics(p0, e1, e2, n, inv, vec2(column, base.y));
    vec2 b = planeBarycentrics(p0, e1, e2, n, inv, vec2(column, base.y + 1.0));
    vec2 dx = TP_VIS_LERP(uv0, uv1, uv2, vec3(1.0 - r.x - r.y, r)) -
              TP_VIS_LERP(uv0, uv1, uv2, vec3(1.0 - l.x - l.y, l));
    vec2 dy = TP_VIS_LERP(uv0, uv1, uv2, vec3(1.0 - b.x - b.y, b)) -
              TP_VIS_LERP(uv0, uv1, uv2, vec3(1.0 - t.x - t.y, t));
    // A neighbour's ray parallel to the plane (an edge-on triangle): no footprint, as the
    // analytic path's edge-on case.
    bool finite = !any(isnan(vec4(dx, dy))) && !any(isinf(vec4(dx, dy)));
    gVisUvDx = finite ? dx : vec2(0.0);
    gVisUvDy = finite ? dy : vec2(0.0);
}

// Ambient + emissive of the surface readSurfaceAt evaluated last (ambientEmissive's answer).
vec3 gVisAmbient = vec3(0.0);

// A triangle an id names: its draw, its vertices and their camera-relative positions.
struct VisTriangle {
    VisDraw draw;
    Vertex v0, v1, v2;
    vec3 p0, p1, p2;
};
VisTriangle visTriangle(uint id) {
    VisTriangle t;
    t.draw = visDraws[(id >> kTriangleBits) - 1u];
    uint triangle = id & ((1u << kTriangleBits) - 1u);
    t.v0 = visVertex(t.draw, triangle, 0u);
    t.v1 = visVertex(t.draw, triangle, 1u);
    t.v2 = visVertex(t.draw, triangle, 2u);
    t.p0 = relativePosition(t.v0);
    t.p1 = relativePosition(t.v1);
    t.p2 = relativePosition(t.v2);
    return t;
}

// Triangle t's material at framebuffer location fc: its attributes interpolated at the hit
// there. `depth` is used only for an edge-on triangle.
MaterialSample readTriangle(VisTriangle t, vec2 fc, float depth) {
    VisHit h = intersect(t.p0, t.p1, t.p2, fc, depth);
    vec2 uv0 = vec2(t.v0.positionU.w, t.v0.normalV.w), uv1 = vec2(t.v1.positionU.w, t.v1.normalV.w),
         uv2 = vec2(t.v2.positionU.w, t.v2.normalV.w);
    if (kDerivatives == TP_VIS_DERIVATIVES_ANALYTIC) {
        gVisUvDx = TP_VIS_LERP(uv0, uv1, uv2, h.bdx);
        gVisUvDy = TP_VIS_LERP(uv0, uv1, uv2, h.bdy);
    } else {
        quadUvDerivatives(t.p0, t.p1, t.p2, uv0, uv1, uv2, fc);
    }
    gVisPosDx = h.pdx;
    gVisPosDy = h.pdy;
    // Front-facing as the rasterizer decides it (counter-clockwise in the flipped-viewport
    // framebuffer: the triangle winds counter-clockwise as the viewer, at the origin, sees it).
    bool front = dot(cross(t.p1 - t.p0, t.p2 - t.p0), t.p0) < 0.0;
    const MaterialGpu m = materials[t.draw.material];
    const vec2 uv = TP_VIS_LERP(uv0, uv1, uv2, h.b);
    visSampleMaterialTextures(m, uv);
    return evalMaterial(m, h.position, TP_VIS_LERP(t.v0.normalV.xyz, t.v1.normalV.xyz, t.v2.normalV.xyz, h.b),
                        uv, TP_VIS_LERP(t.v0.tangent, t.v1.tangent, t.v2.tangent, h.b),
                        TP_VIS_LERP(t.v0.color, t.v1.color, t.v2.color, h.b), front);
}

// The surface sample s of pixel p holds (its id's triangle), at framebuffer location p +
// offset.
SurfaceSample readSurfaceAt(ivec2 p, uint s, vec2 offset, float depth) {
    MaterialSample ms = readTriangle(visTriangle(fetchId(p, s)), vec2(p) + offset, depth);
    gVisAmbient = ambientAndEmissive(ms);
    return ms.surface;
}

// material.glsl's ambientAndEmissive of the surface readSurfaceAt read last (the tiled pass
// asks for it right after, for the same sample).
vec3 ambientEmissive(ivec2 p, uint s) { return gVisAmbient; }

// Roughness and metallic of sample 0 at the pixel centre (--debug's channel image).
vec2 debugRoughMetal(ivec2 p) {
    if (fetchId(p, 0u) == 0u) return vec2(0.0);
    SurfaceSample ss = readSurfaceAt(p, 0u, vec2(0.5), fetchDepth(p, 0u));
    return vec2(ss.roughness, ss.metallic);
}
#endif
