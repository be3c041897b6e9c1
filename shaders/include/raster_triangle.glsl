// The compute rasterizer's triangle, ONE copy for the visibility buffer's (visbuffer/
// vis_raster.glsl, --vis-raster; docs/visbuffer.md "The compute rasterizer") and the shadow
// maps' (shadow/shadow_raster.glsl, --shadow-raster compute; docs/shadows.md): what the
// fixed-function path does to a triangle, written out so a compute invocation can do it.
//   1. The clip position of each vertex with its vertex shader's very operations (the
//      includer's clipPosition), so the triangle is the one the hardware is given, bit for bit.
//   2. Clipping in clip space against the near plane (reverse-Z: z <= w) and a guard band of
//      TP_RT_GUARD_PIXELS around the viewport; the polygon left is drawn as a fan. A new
//      vertex is always interpolated from the inside vertex towards the outside one, so two
//      triangles sharing a clipped edge make the same point.
//   3. The viewport transform (y flipped where the includer's viewport has a negative height)
//      in the device's own arithmetic (kGpuSetup: llvmpipe's x * (1 / w) and a fused
//      multiply-add, gallivm's generate_viewport; a GPU's plain divide and multiply-add) and
//      the snap to kSubpixelBits fractional bits (round to nearest even, as llvmpipe's
//      lrint); pixels outside the viewport (the scissor) are never visited.
//   4. Facing from the sign of the snapped area (Vulkan's a = -area / 2: front faces are
//      counter-clockwise, area < 0), culled unless the draw is double-sided; zero area never
//      covers a sample.
//   5. Exact integer edge functions (int64) at the standard sample locations with the top-left
//      rule in framebuffer coordinates (y down): a sample on an edge is covered only when the
//      edge is a top edge (horizontal, the triangle below it) or a left edge.
//   6. Depth: the plane of z = z_clip / w_clip through the three vertices, evaluated at the
//      sample: through their snapped positions on a GPU (kGpuSetup: the H200 was 6,039 ulps
//      off with the unsnapped ones), the unsnapped ones on llvmpipe, as each rasterizer sets
//      its plane up; a sample with depth <= 0 (the clear value, the far plane) is not written.
//   7. Masked draws: the alpha test at the sample (material.glsl's base colour alpha), the
//      texture sampled with the hardware's fine derivatives: the uv's differences across the
//      pixel's 2x2 quad on the triangle's plane.
//
// The includer declares kSamples (a constant), includes
// include/sample_locations.glsl and the scene bindings, then this file, then defines:
//   vec4 clipPosition(uint index)    vertex `index`'s clip position (its vertex shader's ops)
//   vec3 rasterRelative(uint index)  its position relative to the eye of the view (the origin
//                                    of rasterRayDir's rays)
//   vec3 rasterRayDir(vec2 fc)       a direction of the ray through framebuffer point fc
//   ivec2 rasterViewOrigin(), rasterViewSize(); bool rasterFlipY()   the viewport
//   uint rasterSample(ivec2 px, uint k, vec2 fc, float z, uint id, bool masked, MaskTriangle mt)
//                                    writes sample k of pixel px (fc: its location) at depth z
//                                    if it wins; returns the atomics issued
#ifndef TP_RASTER_TRIANGLE_GLSL
#define TP_RASTER_TRIANGLE_GLSL
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "include/raster_triangle.h"

layout(constant_id = TP_RT_SPEC_SUBPIXEL_BITS) const uint kSubpixelBits = TP_RT_SUBPIXEL_BITS;
layout(constant_id = TP_RT_SPEC_GPU_SETUP) const uint kGpuSetup = 0u;

#define TP_RT_MAX_POLYGON 9 // 3 vertices + one per clip plane (near, 4 guard planes)

// A point of the polygon on the framebuffer's fixed-point grid, with its depth.
struct RasterVertex {
    ivec2 p; // framebuffer coordinates * 2^kSubpixelBits, y down
    vec2 f;  // the depth plane's position: p itself (kGpuSetup) or unsnapped
    float z; // z_clip / w_clip
};

// The triangle (i0, i1, i2) clipped and projected: its polygon's vertices (a fan from 0), their
// count (0: wholly outside a plane) and whether clipping cut it.
struct RasterPolygon {
    RasterVertex v[TP_RT_MAX_POLYGON];
    uint n;
    bool clipped;
};

// One triangle of the fan, set up: edge functions E = A x + B y + C >= 0 inside (C biased by
// the fill rule), its pixel bounds, and its depth plane per pixel from vertex 0's unsnapped
// position (as llvmpipe sets the plane up from the float positions: the snapped ones moved the
// depth by up to 6,000 ulps on courtyard-small where the ids agree).
struct RasterSetup {
    i64vec3 A, B, C;
    ivec2 first, last;
    vec2 origin;
    float z0, dzdx, dzdy;
};

// The alpha test's triangle: positions relative to the view's eye (rasterRelative).
struct MaskTriangle {
    vec3 p0, p1, p2;
    vec2 uv0, uv1, uv2;
    float a0, a1, a2; // vertex colour alpha
    uint material;
};

// ---- the includer's (see the top) ----
vec4 clipPosition(uint index);
vec3 rasterRelative(uint index);
vec3 rasterRayDir(vec2 fc);
ivec2 rasterViewOrigin();
ivec2 rasterViewSize();
bool rasterFlipY();
uint rasterSample(ivec2 px, uint k, vec2 fc, float z, uint id, bool masked, MaskTriangle mt);

// The clip planes as vec4 p with dot(p, clip) >= 0 inside.
vec4 clipPlane(uint i) {
    vec2 guard = 1.0 + 2.0 * TP_RT_GUARD_PIXELS / vec2(rasterViewSize());
    if (i == 0u) return vec4(0.0, 0.0, -1.0, 1.0); // near (reverse-Z): z <= w
    if (i == 1u) return vec4(1.0, 0.0, 0.0, guard.x);
    if (i == 2u) return vec4(-1.0, 0.0, 0.0, guard.x);
    if (i == 3u) return vec4(0.0, 1.0, 0.0, guard.y);
    return vec4(0.0, -1.0, 0.0, guard.y);
}

RasterVertex project(vec4 clip) {
    precise vec3 ndc = clip.xyz / clip.w;
    vec2 halfSize = vec2(rasterViewSize()) * 0.5;
    vec2 scale = rasterFlipY() ? vec2(halfSize.x, -halfSize.y) : halfSize;
    // The viewport's centre, as Vulkan's o = x + w / 2 (exact: integers and halves).
    vec2 centre = vec2(rasterViewOrigin()) + halfSize;
    // llvmpipe's own rounding on a CPU device: 28 -> 23 of the 921,600 pixels of the courtyard
    // at 1280x720 differ from its visibility pass, 18 -> 15 ulps of depth (hybrid, 96x64).
    precise vec2 fb = kGpuSetup != 0u ? ndc.xy * scale + centre
                                      : fma(clip.xy * (1.0 / clip.w), scale, centre);
    RasterVertex r;
    r.p = ivec2(roundEven(fb * float(1u << kSubpixelBits)));
    r.f = kGpuSetup != 0u ? vec2(r.p) / float(1u << kSubpixelBits) : fb;
    r.z = ndc.z;
    return r;
}

// Whether the triangle with clip positions c0..c2 lies wholly outside one clip plane (`out`
// true) or crosses one (returns true: it must be clipped).
bool needsClipping(vec4 c0, vec4 c1, vec4 c2, out bool outside) {
    bool crosses = false;
    outside = false;
    for (uint plane = 0u; plane < 5u; ++plane) {
        vec4 pl = clipPlane(plane);
        bvec3 out3 = lessThan(vec3(dot(pl, c0), dot(pl, c1), dot(pl, c2)), vec3(0.0));
        outside = outside || all(out3);
        crosses = crosses || any(out3);
    }
    // Wholly beside the view (outside one side of the frustum, |x| or |y| > w): covers no
    // pixel. Most triangles the near plane cuts lie beside the eye: culled here, not clipped.
    vec3 x = vec3(c0.x, c1.x, c2.x), y = vec3(c0.y, c1.y, c2.y), w = vec3(c0.w, c1.w, c2.w);
    outside = outside || all(lessThan(x, -w)) || all(greaterThan(x, w)) ||
              all(lessThan(y, -w)) || all(greaterThan(y, w));
    return crosses;
}

// Sutherland-Hodgman against plane `plane`, in place.
uint clipAgainst(inout vec4 poly[TP_RT_MAX_POLYGON], uint n, vec4 plane) {
    vec4 kept[TP_RT_MAX_POLYGON];
    uint m = 0u;
    for (uint i = 0u; i < n; ++i) {
        vec4 a = poly[i], b = poly[i + 1u == n ? 0u : i + 1u];
        float da = dot(plane, a), db = dot(plane, b);
        if (da >= 0.0) kept[m++] = a;
        if ((da >= 0.0) != (db >= 0.0)) {
            // From the inside vertex: the same point from both triangles of a shared edge.
            vec4 inside = da >= 0.0 ? a : b, outside = da >= 0.0 ? b : a;
            float di = max(da, db), dout = min(da, db);
            kept[m++] = inside + (di / (di - dout)) * (outside - inside);
        }
    }
    poly = kept;
    return m;
}

RasterPolygon buildPolygon(uint i0, uint i1, uint i2) {
    vec4 poly[TP_RT_MAX_POLYGON];
    poly[0] = clipPosition(i0);
    poly[1] = clipPosition(i1);
    poly[2] = clipPosition(i2);
    RasterPolygon r;
    r.n = 3u;
    r.clipped = false;
    for (uint plane = 0u; plane < 5u; ++plane) {
        vec4 pl = clipPlane(plane);
        uint outside = 0u;
        for (uint i = 0u; i < r.n; ++i) outside += dot(pl, poly[i]) < 0.0 ? 1u : 0u;
        if (outside == r.n) { r.n = 0u; return r; }
        if (outside == 0u) continue;
        r.clipped = true;
        r.n = clipAgainst(poly, r.n, pl);
    }
    for (uint i = 0u; i < r.n; ++i) r.v[i] = project(poly[i]);
    return r;
}

// Pixel bounds (inclusive) of the samples points p lo..hi can cover, clamped to the viewport.
void pixelBounds(ivec2 lo, ivec2 hi, out ivec2 first, out ivec2 last) {
    ivec2 origin = rasterViewOrigin();
    first = max(lo >> int(kSubpixelBits), origin);
    last = min(hi >> int(kSubpixelBits), origin + rasterViewSize() - 1);
}

// False: culled (zero area, back-facing and single-sided, or no pixel).
bool setupTriangle(RasterVertex v0, RasterVertex v1, RasterVertex v2, bool doubleSided,
                   out RasterSetup s) {
    int64_t area = int64_t(v1.p.x - v0.p.x) * int64_t(v2.p.y - v0.p.y) -
                   int64_t(v2.p.x - v0.p.x) * int64_t(v1.p.y - v0.p.y);
    if (area == 0l) return false;
    if (area > 0l && !doubleSided) return false; // back-facing (front: area < 0)
    if (area < 0l) { // wound so that the inside is E >= 0
        RasterVertex t = v1;
        v1 = v2;
        v2 = t;
        area = -area;
    }
    // Edge e runs between the two vertices other than e: v1 -> v2, v2 -> v0, v0 -> v1.
    ivec3 ax = ivec3(v1.p.x, v2.p.x, v0.p.x), ay = ivec3(v1.p.y, v2.p.y, v0.p.y);
    ivec3 bx = ivec3(v2.p.x, v0.p.x, v1.p.x), by = ivec3(v2.p.y, v0.p.y, v1.p.y);
    s.A = i64vec3(ay - by);
    s.B = i64vec3(bx - ax);
    i64vec3 C = -(s.A * i64vec3(ax) + s.B * i64vec3(ay));
    // Top-left: a left edge (A > 0) or a top one (A = 0, B > 0) keeps E = 0.
    bvec3 topLeft = bvec3(uvec3(greaterThan(s.A, i64vec3(0))) |
                          (uvec3(equal(s.A, i64vec3(0))) & uvec3(greaterThan(s.B, i64vec3(0)))));
    s.C = C - i64vec3(not(topLeft));
    // The depth plane first: a clipped polygon takes its largest fan triangle's for every fan
    // triangle (rasterPolygonAs), and that one may itself lie wholly beside the viewport (a
    // polygon cut by a guard band far larger than a small shadow face).
    vec2 d1 = v1.f - v0.f, d2 = v2.f - v0.f;
    float dz1 = v1.z - v0.z, dz2 = v2.z - v0.z, fa = d1.x * d2.y - d2.x * d1.y;
    if (fa == 0.0) fa = float(area) / float(1 << (2 * int(kSubpixelBits))); // a sliver
    s.origin = v0.f;
    s.z0 = v0.z;
    s.dzdx = (dz1 * d2.y - dz2 * d1.y) / fa;
    s.dzdy = (d1.x * dz2 - d2.x * dz1) / fa;
    pixelBounds(min(min(v0.p, v1.p), v2.p), max(max(v0.p, v1.p), v2.p), s.first, s.last);
    return all(lessThanEqual(s.first, s.last));
}

// What becomes of the triangle with clip positions c0..c2 (TP_RT_*): culled; listed (clipped,
// `clipped` true, or larger than TP_RT_SMALL_PIXELS each way and not culled by its snapped
// area); or small, v0..v2 its projected vertices, for its own invocation.
uint rasterTriage(vec4 c0, vec4 c1, vec4 c2, bool doubleSided, out bool clipped,
                  out RasterVertex v0, out RasterVertex v1, out RasterVertex v2) {
    bool outside;
    clipped = needsClipping(c0, c1, c2, outside);
    if (outside) return TP_RT_CULLED;
    if (clipped) return TP_RT_LIST;
    v0 = project(c0);
    v1 = project(c1);
    v2 = project(c2);
    ivec2 first, last;
    pixelBounds(min(min(v0.p, v1.p), v2.p), max(max(v0.p, v1.p), v2.p), first, last);
    if (any(greaterThan(first, last))) return TP_RT_CULLED;
    if (any(greaterThan(last - first, ivec2(TP_RT_SMALL_PIXELS - 1)))) {
        int64_t area = int64_t(v1.p.x - v0.p.x) * int64_t(v2.p.y - v0.p.y) -
                       int64_t(v2.p.x - v0.p.x) * int64_t(v1.p.y - v0.p.y);
        if (area == 0l || (area > 0l && !doubleSided)) return TP_RT_CULLED;
        return TP_RT_LIST;
    }
    return TP_RT_SMALL;
}

// ---- the alpha test of masked draws ----
MaskTriangle maskTriangle(uint i0, uint i1, uint i2, uint material) {
    Vertex v0 = vertices[i0], v1 = vertices[i1], v2 = vertices[i2];
    MaskTriangle t;
    t.p0 = rasterRelative(i0);
    t.p1 = rasterRelative(i1);
    t.p2 = rasterRelative(i2);
    t.uv0 = vec2(v0.positionU.w, v0.normalV.w);
    t.uv1 = vec2(v1.positionU.w, v1.normalV.w);
    t.uv2 = vec2(v2.positionU.w, v2.normalV.w);
    t.a0 = v0.color.a;
    t.a1 = v1.color.a;
    t.a2 = v2.color.a;
    t.material = material;
    return t;
}

// Barycentrics (b0, b1, b2) where the ray through framebuffer location fc meets the plane.
vec3 planeBarycentrics(MaskTriangle t, vec2 fc) {
    vec3 dir = rasterRayDir(fc);
    vec3 e1 = t.p1 - t.p0, e2 = t.p2 - t.p0, n = cross(e1, e2);
    vec3 r = (dot(n, t.p0) / dot(n, dir)) * dir - t.p0;
    vec2 b = vec2(dot(cross(r, e2), n), dot(cross(e1, r), n)) / dot(n, n);
    return vec3(1.0 - b.x - b.y, b);
}

vec2 maskUv(MaskTriangle t, vec3 b) { return t.uv0 * b.x + t.uv1 * b.y + t.uv2 * b.z; }

// The uv at framebuffer location fc.
vec2 maskUvAt(MaskTriangle t, vec2 fc) { return maskUv(t, planeBarycentrics(t, fc)); }

// material.glsl's alpha (base colour factor x vertex colour x base colour texture) at fc.
// The texture's derivatives are the hardware's fine ones: the differences across the 2x2 quad
// the pixel belongs to (its row for x, its column for y), at the same offset in each pixel, so
// the level of detail is the fragment shader's. (A forward difference from the pixel itself,
// as this took before, is the other neighbour's for odd pixels: on the courtyard at 1080p it
// flipped the alpha test of leaf cards at 4 pixels, a leaf in front of the floor, 0.84 off the
// reference.) The texture index differs between invocations: the array is walked with a
// uniform counter (vis_read.glsl's visTexture: lavapipe lacks non-uniform sampler indexing).
float maskAlpha(MaskTriangle t, vec2 fc) {
    vec3 b = planeBarycentrics(t, fc);
    vec2 uv = maskUv(t, b);
    vec2 pixel = floor(fc), quad = pixel - mod(pixel, 2.0), offset = fc - pixel;
    vec2 left = vec2(quad.x, pixel.y) + offset, top = vec2(pixel.x, quad.y) + offset;
    vec2 dx = maskUvAt(t, left + vec2(1.0, 0.0)) - maskUvAt(t, left);
    vec2 dy = maskUvAt(t, top + vec2(0.0, 1.0)) - maskUvAt(t, top);
    if (any(isnan(vec4(dx, dy))) || any(isinf(vec4(dx, dy)))) dx = dy = vec2(0.0);
    MaterialGpu m = materials[t.material];
    float texel = 1.0;
    int index = m.baseColorTexture;
    for (int i = 0; i < kTextureCount; ++i)
        if (i == index) texel = textureGrad(textures[i], uv, dx, dy).a;
    float colour = t.a0 * b.x + t.a1 * b.y + t.a2 * b.z;
    return m.baseColorFactor.a * colour * texel;
}

// ---- the samples ----
// Pixel `px`'s samples the triangle covers, given to rasterSample; `corner`: the edge
// functions at the pixel's corner. Returns the atomics issued.
uint rasterPixel(RasterSetup s, ivec2 px, i64vec3 corner, uint id, bool masked,
                 MaskTriangle mt) {
    const int one = 1 << int(kSubpixelBits);
    uint atomics = 0u;
    for (uint k = 0u; k < kSamples; ++k) {
        // The sample's offset in fixed point: exact (the locations are multiples of 1/16).
        ivec2 at = ivec2(sampleOffset(k) * float(one));
        i64vec3 e = corner + s.A * int64_t(at.x) + s.B * int64_t(at.y);
        if (e.x < 0l || e.y < 0l || e.z < 0l) continue;
        vec2 d = vec2(px) + vec2(at) / float(one) - s.origin; // the location itself is exact
        float z = s.z0 + s.dzdx * d.x + s.dzdy * d.y;
        if (!(z > 0.0)) continue;
        atomics += rasterSample(px, k, vec2(px) + vec2(at) / float(one), z, id, masked, mt);
    }
    return atomics;
}

// The edge functions at fixed-point point p.
i64vec3 edgesAt(RasterSetup s, ivec2 p) {
    return s.A * int64_t(p.x) + s.B * int64_t(p.y) + s.C;
}

// Every pixel of s's bounds by this one invocation, row by row, the edge functions stepped by
// additions (the small triangles).
uint rasterPixels(RasterSetup s, uint id, bool masked, MaskTriangle mt) {
    const int one = 1 << int(kSubpixelBits);
    i64vec3 stepX = s.A * int64_t(one), stepY = s.B * int64_t(one);
    i64vec3 row = edgesAt(s, s.first * one);
    uint atomics = 0u;
    for (int y = s.first.y; y <= s.last.y; ++y) {
        i64vec3 e = row;
        for (int x = s.first.x; x <= s.last.x; ++x) {
            atomics += rasterPixel(s, ivec2(x, y), e, id, masked, mt);
            e += stepX;
        }
        row += stepY;
    }
    return atomics;
}

// Whether the triangle's edge functions can be >= 0 anywhere in the `size`-pixel square at
// pixel p (each edge's largest value over the square's samples, from its corner).
bool mayCover(RasterSetup s, ivec2 p, int size) {
    const int one = 1 << int(kSubpixelBits);
    i64vec3 most = edgesAt(s, p * one) +
                   (max(s.A, i64vec3(0)) + max(s.B, i64vec3(0))) * int64_t(size * one);
    return most.x >= 0l && most.y >= 0l && most.z >= 0l;
}

// s's bounds in 64x64 blocks and their 8x8 tiles, pixel `lane` of each tile by this invocation
// (TP_RT_BIG_GROUP = 64 invocations). A block or a tile wholly outside one edge is skipped by
// the whole group: a long thin triangle (one the near plane cut beside the eye spans the
// screen) walks the blocks along it, not its bounding box.
uint rasterTiles(RasterSetup s, uint id, bool masked, MaskTriangle mt, uint lane) {
    const int one = 1 << int(kSubpixelBits);
    ivec2 inTile = ivec2(lane % 8u, lane / 8u);
    i64vec3 laneE = s.A * int64_t(inTile.x * one) + s.B * int64_t(inTile.y * one);
    uint atomics = 0u;
    for (int by = s.first.y; by <= s.last.y; by += 64) {
        for (int bx = s.first.x; bx <= s.last.x; bx += 64) {
            if (!mayCover(s, ivec2(bx, by), 64)) continue;
            ivec2 blockLast = min(ivec2(bx, by) + 63, s.last);
            for (int ty = by; ty <= blockLast.y; ty += 8) {
                for (int tx = bx; tx <= blockLast.x; tx += 8) {
                    if (!mayCover(s, ivec2(tx, ty), 8)) continue;
                    ivec2 px = ivec2(tx, ty) + inTile;
                    if (px.x > blockLast.x || px.y > blockLast.y) continue;
                    atomics += rasterPixel(s, px, edgesAt(s, ivec2(tx, ty) * one) + laneE, id,
                                           masked, mt);
                }
            }
        }
    }
    return atomics;
}

// Triangle (v0, v1, v2), unclipped: by this invocation alone (`big` false: the small
// triangles) or in tiles by the 64 of a big group. No local array, which lavapipe keeps in
// memory per lane. `drew` as rasterPolygonAs's.
uint rasterTriangleAs(RasterVertex v0, RasterVertex v1, RasterVertex v2, uint i0, uint i1,
                      uint i2, uint id, bool doubleSided, bool masked, uint material, bool big,
                      uint lane, out bool drew) {
    RasterSetup s;
    drew = setupTriangle(v0, v1, v2, doubleSided, s);
    if (!drew) return 0u;
    MaskTriangle mt;
    if (masked) mt = maskTriangle(i0, i1, i2, material);
    return big ? rasterTiles(s, id, masked, mt, lane) : rasterPixels(s, id, masked, mt);
}

// The polygon's fan rasterized: by this invocation alone (`big` false) or in tiles by the 64
// of a big group. `drew`: whether a triangle of it was set up (false: culled); returns the
// atomics this invocation issued.
uint rasterPolygonAs(RasterPolygon poly, uint i0, uint i1, uint i2, uint id, bool doubleSided,
                     bool masked, uint material, bool big, uint lane, out bool drew) {
    MaskTriangle mt;
    if (masked) mt = maskTriangle(i0, i1, i2, material);
    drew = false;
    uint atomics = 0u;
    // The depth plane of the fan's largest triangle for all of them (one plane: the triangle's):
    // a sliver the clip made has an ill-conditioned plane far from its vertices (measured: 0.24
    // relative off the hardware's depth on courtyard-small with each fan triangle's own).
    uint best = 1u;
    int64_t bestArea = 0l;
    for (uint k = 1u; k + 1u < poly.n; ++k) {
        ivec2 a = poly.v[k].p - poly.v[0].p, b = poly.v[k + 1u].p - poly.v[0].p;
        int64_t area = abs(int64_t(a.x) * int64_t(b.y) - int64_t(b.x) * int64_t(a.y));
        if (area > bestArea) {
            bestArea = area;
            best = k;
        }
    }
    RasterSetup plane;
    setupTriangle(poly.v[0], poly.v[best], poly.v[best + 1u], true, plane);
    for (uint k = 1u; k + 1u < poly.n; ++k) {
        RasterSetup s;
        if (!setupTriangle(poly.v[0], poly.v[k], poly.v[k + 1u], doubleSided, s)) continue;
        s.origin = plane.origin;
        s.z0 = plane.z0;
        s.dzdx = plane.dzdx;
        s.dzdy = plane.dzdy;
        drew = true;
        atomics += big ? rasterTiles(s, id, masked, mt, lane) : rasterPixels(s, id, masked, mt);
    }
    return atomics;
}

// A listed triangle (or one whose list was full): clipped to its polygon where it must be, else
// as it is; by the 64 of a big group (`big`) or this invocation alone.
uint rasterListed(uint i0, uint i1, uint i2, uint id, bool doubleSided, bool masked,
                  uint material, bool big, uint lane, out bool drew) {
    vec4 c0 = clipPosition(i0), c1 = clipPosition(i1), c2 = clipPosition(i2);
    bool outside;
    // Clipped: the polygon's fan (local arrays, rare); else the triangle itself.
    if (needsClipping(c0, c1, c2, outside))
        return rasterPolygonAs(buildPolygon(i0, i1, i2), i0, i1, i2, id, doubleSided, masked,
                               material, big, lane, drew);
    return rasterTriangleAs(project(c0), project(c1), project(c2), i0, i1, i2, id, doubleSided,
                            masked, material, big, lane, drew);
}

#endif
