// Tile light culling shared by the tiled pipelines (Forward+ and tiled deferred); GLSL only.
// Include after shared.h.
//
// A tile's sub-frustum lives in view space (right-handed, looking down -Z): four side planes
// through the eye (inward unit normals, w = 0) from the tile's pixel rectangle, and a view-z
// range [farViewZ, nearViewZ] from two reverse-Z depths (1 = near plane, 0 = infinitely far
// or the far plane). Row 0 of the image is the top of the screen (negative-height viewport):
// pixel boundary py maps to NDC y = 1 - 2 * py / height, pixel centre to
// 1 - 2 * (py + 0.5) / height.
//
// Every test is conservative: a light that contributes to any point of the tile's rectangle
// within [farViewZ, nearViewZ] is never rejected. The light model's window makes a light's
// contribution exactly zero at and beyond its range, so the bounding volumes are exact up to
// float rounding, which the small paddings below (relative 1e-4) absorb.
#ifndef TP_TILE_CULLING_GLSL
#define TP_TILE_CULLING_GLSL
#include "include/shared.h"

// view-space tile sub-frustum: 4 side planes through the eye (inward normals, w = 0) + z range.
// nearViewZ > farViewZ (both negative); farViewZ = -1e30 for an unbounded tile.
struct TileFrustum {
    vec4 planes[4];
    float nearViewZ;
    float farViewZ;
};

#define TP_TILE_UNBOUNDED_Z (-1e30)
#define TP_TILE_CULL_PAD 1e-4

// View-space z of a reverse-Z depth at the screen centre (z does not depend on x, y for a
// perspective projection). Depth 0 with an infinite projection gives -1e30.
float viewZFromDepth(float depth, mat4 invProj) {
    vec4 v = invProj * vec4(0.0, 0.0, depth, 1.0);
    if (abs(v.w) < 1e-30) return TP_TILE_UNBOUNDED_Z;
    float z = v.z / v.w;
    return max(z, TP_TILE_UNBOUNDED_Z);
}

// View-space point on the near plane (depth 1) through an NDC position.
vec3 tileCornerView(vec2 ndc, mat4 invProj) {
    vec4 v = invProj * vec4(ndc, 1.0, 1.0);
    return v.xyz / v.w;
}

// tile: tile coordinates (0,0 = top-left tile); tileSize in pixels; tiles at the viewport's
// right/bottom edge may be partial (their rectangle is clipped to the viewport).
// nearDepth >= farDepth (reverse-Z): nearDepth bounds the z range toward the eye.
TileFrustum makeTileFrustum(uvec2 tile, uint tileSize, vec2 viewportSize, mat4 invProj,
                            float nearDepth, float farDepth) {
    vec2 p0 = vec2(tile * tileSize);
    vec2 p1 = min(vec2((tile + uvec2(1u)) * tileSize), viewportSize);
    // NDC: x to the right, y up (row 0 is the top).
    float x0 = 2.0 * p0.x / viewportSize.x - 1.0;
    float x1 = 2.0 * p1.x / viewportSize.x - 1.0;
    float y0 = 1.0 - 2.0 * p0.y / viewportSize.y; // top edge
    float y1 = 1.0 - 2.0 * p1.y / viewportSize.y; // bottom edge
    vec3 c[4];
    c[0] = tileCornerView(vec2(x0, y0), invProj);
    c[1] = tileCornerView(vec2(x1, y0), invProj);
    c[2] = tileCornerView(vec2(x1, y1), invProj);
    c[3] = tileCornerView(vec2(x0, y1), invProj);
    vec3 centre = (c[0] + c[1] + c[2] + c[3]) * 0.25;

    TileFrustum f;
    for (int i = 0; i < 4; ++i) {
        vec3 n = normalize(cross(c[i], c[(i + 1) & 3]));
        // Orient inward whatever the winding (the projection may mirror).
        if (dot(n, centre) < 0.0) n = -n;
        f.planes[i] = vec4(n, 0.0);
    }
    float zn = viewZFromDepth(nearDepth, invProj);
    float zf = viewZFromDepth(farDepth, invProj);
    // Widen the range a little: the shading pass interpolates positions, the prepass
    // rasterizes depth; both round differently.
    f.nearViewZ = min(zn * (1.0 - TP_TILE_CULL_PAD), 0.0);
    f.farViewZ = zf <= TP_TILE_UNBOUNDED_Z ? TP_TILE_UNBOUNDED_Z
                                           : max(zf * (1.0 + TP_TILE_CULL_PAD), TP_TILE_UNBOUNDED_Z);
    return f;
}

// Sphere (view-space centre, radius) against the 4 side planes and the z range.
bool tileSphereTest(vec3 c, float r, TileFrustum f) {
    for (int i = 0; i < 4; ++i)
        if (dot(f.planes[i].xyz, c) + f.planes[i].w < -r) return false;
    if (c.z - r > f.nearViewZ) return false;
    if (c.z + r < f.farViewZ) return false;
    return true;
}

// Largest value of dot(n, p) + w over a cone (tip, unit axis, height h, base radius rb):
// attained at the tip or on the base rim.
float coneMaxSignedDistance(vec4 plane, vec3 tip, vec3 axis, float h, float rb) {
    vec3 n = plane.xyz;
    float atTip = dot(n, tip) + plane.w;
    float na = dot(n, axis);
    float rim = dot(n, tip + axis * h) + plane.w + rb * sqrt(max(1.0 - na * na, 0.0));
    return max(atTip, rim);
}

// A point or spot light's sphere in view space: xyz = centre, w = range padded by
// TP_TILE_CULL_PAD * (range + distance). Computed once per light and tile by a caller that
// tests several volumes (lightSphereInTile, sphereInTileBox). `precise` (no FMA
// contraction): Forward+'s light_spheres pass and its inline culling compile this in two
// shaders and must agree bit for bit (ForwardPlusCulling.SpherePassGivesTheInlineLists).
vec4 lightSphereView(LightGpu light, mat4 view) {
    precise vec3 c = (view * vec4(light.position, 1.0)).xyz;
    precise float r = light.range + TP_TILE_CULL_PAD * (light.range + length(c));
    return vec4(c, r);
}

bool lightSphereInTile(LightGpu light, vec4 sphere, TileFrustum f, mat4 view);

bool lightInTile(LightGpu light, TileFrustum f, mat4 view) {
    if (light.type == TP_LIGHT_DIRECTIONAL) return true;
    return lightSphereInTile(light, lightSphereView(light, view), f, view);
}

// lightInTile for a point or spot light whose lightSphereView is `sphere`.
bool lightSphereInTile(LightGpu light, vec4 sphere, TileFrustum f, mat4 view) {
    vec3 c = sphere.xyz;
    float r = sphere.w;
    if (!tileSphereTest(c, r, f)) return false;
    if (light.type != TP_LIGHT_SPOT) return true;
    float pad = TP_TILE_CULL_PAD * (light.range + length(c)); // as lightSphereView

    // Spot: the lit region (distance < range, angle < outer) lies inside the cone of height
    // range and base radius range * tan(outer). Wide cones (outer > ~80 degrees) keep the
    // sphere test only.
    float cosOuter = light.spotScale != 0.0 ? -light.spotOffset / light.spotScale : -1.0;
    if (cosOuter < 0.17) return true;
    float tanOuter = sqrt(max(1.0 - cosOuter * cosOuter, 0.0)) / cosOuter;
    vec3 axis = normalize((view * vec4(light.direction, 0.0)).xyz);
    float h = r;
    float rb = r * tanOuter * (1.0 + TP_TILE_CULL_PAD) + pad;
    for (int i = 0; i < 4; ++i)
        if (coneMaxSignedDistance(f.planes[i], c, axis, h, rb) < 0.0) return false;
    if (coneMaxSignedDistance(vec4(0.0, 0.0, -1.0, f.nearViewZ), c, axis, h, rb) < 0.0) return false;
    if (f.farViewZ > TP_TILE_UNBOUNDED_Z &&
        coneMaxSignedDistance(vec4(0.0, 0.0, 1.0, -f.farViewZ), c, axis, h, rb) < 0.0)
        return false;
    return true;
}

// Optional, additive: the view-space axis-aligned box of the tile's sub-frustum (its 8
// corners between nearViewZ and farViewZ). A sphere can pass all six plane tests near a
// frustum corner while missing the frustum; the box rejects most of those. Conservative
// (the box contains the frustum piece), so `lightInTile(...) && lightInTileBox(...)` is too.
struct TileBox {
    vec3 lo;
    vec3 hi;
};

TileBox makeTileBox(uvec2 tile, uint tileSize, vec2 viewportSize, mat4 invProj, TileFrustum f) {
    vec2 p0 = vec2(tile * tileSize);
    vec2 p1 = min(vec2((tile + uvec2(1u)) * tileSize), viewportSize);
    float xs[2] = float[2](2.0 * p0.x / viewportSize.x - 1.0, 2.0 * p1.x / viewportSize.x - 1.0);
    float ys[2] = float[2](1.0 - 2.0 * p0.y / viewportSize.y, 1.0 - 2.0 * p1.y / viewportSize.y);
    TileBox b;
    b.lo = vec3(1e30);
    b.hi = vec3(-1e30);
    for (int i = 0; i < 4; ++i) {
        vec3 c = tileCornerView(vec2(xs[i & 1], ys[i >> 1]), invProj); // on the near plane (z < 0)
        for (int k = 0; k < 2; ++k) {
            float z = k == 0 ? f.nearViewZ : f.farViewZ;
            vec3 p = c * (z / c.z);
            b.lo = min(b.lo, p);
            b.hi = max(b.hi, p);
        }
    }
    // Rounding of the corners: pad like the planes.
    vec3 pad = TP_TILE_CULL_PAD * (abs(b.lo) + abs(b.hi)) + vec3(1e-6);
    b.lo -= pad;
    b.hi += pad;
    return b;
}

// Sphere of a point or spot light (position, range) against the box; directional: true.
bool sphereInTileBox(vec4 sphere, TileBox b) {
    vec3 d = max(max(b.lo - sphere.xyz, sphere.xyz - b.hi), vec3(0.0));
    return dot(d, d) <= sphere.w * sphere.w;
}

bool lightInTileBox(LightGpu light, TileBox b, mat4 view) {
    if (light.type == TP_LIGHT_DIRECTIONAL) return true;
    return sphereInTileBox(lightSphereView(light, view), b);
}

// lightInTile && lightInTileBox, the light's sphere made once and the box tested first (it
// rejects more, more cheaply): the test Forward+'s culling makes (light_culling_common.glsl:
// passes), for the tiled lighting pass's lists.
bool lightInTileAndBox(LightGpu light, TileFrustum f, TileBox b, mat4 view) {
    if (light.type == TP_LIGHT_DIRECTIONAL) return true;
    const vec4 sphere = lightSphereView(light, view);
    return sphereInTileBox(sphere, b) && lightSphereInTile(light, sphere, f, view);
}
#endif
