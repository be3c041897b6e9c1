// The colonnades of the courtyard: fluted columns on plinths with moulded bases and capitals,
// round arches with mouldings, the slab above each storey, lamp bars under it, and on the
// gallery a balustrade with hanging cloth panels.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/scene/mesh_builder.h"
#include "core/scene/procedural_parts.h"
#include "core/scene/procedural_textures.h"
#include "core/util/math.h"

namespace tp::procgen {

namespace {

constexpr float kEmbed = 0.05f; // overlap into walls, so that no faces meet back to back in a plane
using glm::vec2;
using glm::vec3;

// Profiles as (radius / shaft radius, height / part height).
constexpr std::array<vec2, 8> kBaseProfile = {{{1.45f, 0.0f},
                                               {1.5f, 0.12f},
                                               {1.45f, 0.25f},
                                               {1.22f, 0.38f},
                                               {1.28f, 0.52f},
                                               {1.2f, 0.66f},
                                               {1.04f, 0.85f},
                                               {1.0f, 1.0f}}};
constexpr float kShaftTopRadius = 0.9f; // taper, as a fraction of the foot radius
constexpr std::array<vec2, 6> kCapitalProfile = {
    {{0.9f, 0.0f}, {0.98f, 0.15f}, {0.95f, 0.3f}, {1.15f, 0.55f}, {1.42f, 0.82f}, {1.5f, 1.0f}}};
constexpr std::array<vec2, 9> kBalusterProfile = {{{0.05f, 0.0f},
                                                   {0.07f, 0.06f},
                                                   {0.045f, 0.13f},
                                                   {0.06f, 0.26f},
                                                   {0.085f, 0.42f},
                                                   {0.06f, 0.56f},
                                                   {0.04f, 0.63f},
                                                   {0.055f, 0.7f},
                                                   {0.065f, 0.75f}}};

template <size_t N> std::array<vec2, N> scaled(const std::array<vec2, N>& p, vec2 s) {
    std::array<vec2, N> out;
    for (size_t i = 0; i < N; ++i)
        out[i] = p[i] * s;
    return out;
}

// Fluted shaft with entasis: a slight swelling over a linear taper.
void addShaft(MeshBuilder& b, const Tessellation& t, vec3 foot, float r, float height) {
    int flutes = t.columnSegments >= 24 ? t.columnSegments / 4 : 0;
    auto pos = [=](float u, float v) {
        float phi = u * 2.0f * kPi;
        float radius = r * (1.0f + (kShaftTopRadius - 1.0f) * v + 0.025f * std::sin(kPi * v));
        float s = std::sin(0.5f * float(flutes) * phi);
        radius *= 1.0f - (flutes ? 0.035f * s * s : 0.0f);
        return foot + vec3(radius * std::cos(phi), v * height, -radius * std::sin(phi));
    };
    auto uv = [=](float u, float v) { return vec2(u * 2.0f * kPi * r, -v * height) / kStoneTex; };
    addSurface(b, t.columnSegments, t.shaftRows, pos, uv);
}

void addColumn(MeshBuilder& b, const Tessellation& t, const Storey& s, vec3 foot) {
    const float r = s.radius;
    vec3 ph(s.plinthHalf, 0.0f, s.plinthHalf);
    // Gallery plinths overhang the slab's edge, so only the ground floor's hide their bottoms.
    addBox(b, foot - ph, foot + ph + vec3(0, s.plinthH, 0), kStoneTex,
           s.index == 0 ? kSkipBottom : 0u);
    // At low detail the base and capital are left out and the shaft fills their height.
    const float baseH = t.baseRows > 0 ? s.baseH : 0.0f;
    const float capitalH = t.capitalRows > 0 ? s.capitalH : 0.0f;
    vec3 p = foot + vec3(0, s.plinthH, 0);
    if (baseH > 0.0f)
        addLathe(b, p, scaled(kBaseProfile, vec2(r, baseH)), t.columnSegments, t.baseRows,
                 kStoneTex);
    p.y += baseH;
    const float shaftH = s.shaftH + (s.baseH - baseH) + (s.capitalH - capitalH);
    addShaft(b, t, p, r, shaftH);
    p.y += shaftH;
    if (capitalH > 0.0f)
        addLathe(b, p, scaled(kCapitalProfile, vec2(r, capitalH)), t.columnSegments, t.capitalRows,
                 kStoneTex);
    p.y += capitalH;
    vec3 ah(s.abacusHalf, 0.0f, s.abacusHalf);
    addBox(b, p - ah, p + ah + vec3(0, s.abacusH, 0), kStoneTex);
}

// Where the ray from the arch centre at angle `a` leaves the rectangle [-half, half] x [0, h].
vec2 rectExit(float a, float half, float h) {
    vec2 d(std::cos(a), std::sin(a));
    if (std::abs(d.x) * h >= half * d.y) return d * (half / std::abs(d.x));
    return d * (h / d.y);
}

struct ArchFrame {
    float x, z; // centre of the arch wall (x at mid-thickness)
    float springY, topY;
    float half;   // half the bay: the wall runs z - half .. z + half
    float radius; // of the opening
};

// The wall between two columns with a semicircular opening: its two faces, the soffit and,
// if wanted, a half-round moulding around the opening on each face.
void addArch(MeshBuilder& b, const Tessellation& t, const ArchFrame& a) {
    const int n = t.archSegments;
    const float h = a.topY - a.springY;
    const float corner = std::atan2(h, a.half);
    // Angle along the opening, u in [0, 1] from the left springing (pi) to the right one (0),
    // a quarter of the segments per stretch so that the faces hit the wall's corners exactly;
    // faces, soffit and mouldings all share it, so their edges meet.
    auto angle = [=](float u) {
        const float stops[5] = {kPi, kPi - corner, 0.5f * kPi, corner, 0.0f};
        float k = std::clamp(u, 0.0f, 1.0f) * 4.0f;
        int i = std::min(int(k), 3);
        return stops[i] + (k - float(i)) * (stops[i + 1] - stops[i]);
    };
    for (float fx : {-1.0f, 1.0f}) {
        float x = a.x + fx * 0.5f * kArcadeT;
        auto at = [&](vec2 zy) { return vec3(x, a.springY + zy.y, a.z + zy.x); };
        for (int i = 0; i < n; ++i) {
            float a0 = angle(float(i) / float(n)), a1 = angle(float(i + 1) / float(n));
            vec2 i0 = a.radius * vec2(std::cos(a0), std::sin(a0));
            vec2 i1 = a.radius * vec2(std::cos(a1), std::sin(a1));
            addFacingQuad(b, at(i0), at(i1), at(rectExit(a1, a.half, h)),
                          at(rectExit(a0, a.half, h)), vec3(fx, 0, 0), vec3(0, 0, 1), vec3(0, 1, 0),
                          kStoneTex);
        }
    }
    auto soffit = [&](float u, float v) {
        float th = angle(1.0f - u); // runs from 0 to pi: the normal faces the opening
        return vec3(a.x + (v - 0.5f) * kArcadeT, a.springY + a.radius * std::sin(th),
                    a.z + a.radius * std::cos(th));
    };
    auto soffitUv = [&](float u, float v) {
        return vec2(kPi * a.radius * u, v * kArcadeT) / kStoneTex;
    };
    addSurface(b, n, 1, soffit, soffitUv);
    if (t.rimRows < 2) return;
    const float tube = 0.07f, ringR = a.radius + tube;
    for (float fx : {-1.0f, 1.0f}) {
        float x = a.x + fx * 0.5f * kArcadeT;
        auto rim = [=](float u, float v) {
            float th = angle(1.0f - u), psi = kPi * v;
            float rho = ringR + tube * std::cos(psi);
            return vec3(x + fx * tube * std::sin(psi), a.springY + rho * std::sin(th),
                        a.z + rho * std::cos(th));
        };
        auto rimUv = [=](float u, float v) {
            return vec2(kPi * ringR * u, kPi * tube * v) / kStoneTex;
        };
        addSurface(b, n, t.rimRows, rim, rimUv, fx > 0.0f);
    }
}

// A cloth hanging from a rod in front of a gallery bay: gathered at the top, rippling and
// billowing more towards its free lower edge.
void addCloth(MeshBuilder& b, const Tessellation& t, float x, float inward, float zc, float top,
              float width, float length, uint32_t seed) {
    const float phase = 2.0f * kPi * hash01(seed, 1, 303);
    const float waves = 3.0f + std::floor(3.0f * hash01(seed, 2, 303));
    auto pos = [=](float u, float v) {
        float ripple = 0.06f * std::sin(2.0f * kPi * waves * u + phase) * (0.3f + 0.7f * v);
        float billow = 0.18f * std::sin(kPi * u) * v * v;
        float sway = 0.05f * std::sin(kPi * v + phase) * v;
        return vec3(x + inward * (ripple + billow), top - v * length,
                    zc + (u - 0.5f) * width * (1.0f - 0.04f * v) + sway);
    };
    auto uv = [=](float u, float v) { return vec2(u * width / 2.8f, v * length / 3.0f); };
    addSurface(b, t.clothU, t.clothV, pos, uv);
}

// An iron rod along +z with flat end caps.
void addRod(MeshBuilder& b, const Tessellation& t, vec3 from, float length) {
    const float r = 0.03f;
    const int n = t.rodSegments;
    auto ring = [=](float u) {
        return vec2(r * std::cos(2.0f * kPi * u), r * std::sin(2.0f * kPi * u));
    };
    auto pos = [=](float u, float v) { return from + vec3(ring(u), v * length); };
    auto uv = [=](float u, float v) { return vec2(u, v * length); };
    addSurface(b, n, 1, pos, uv);
    for (float end : {0.0f, 1.0f}) {
        vec3 normal(0, 0, end > 0.0f ? 1.0f : -1.0f), c = from + vec3(0, 0, end * length);
        uint32_t centre = b.vertex(c, normal, vec2(0.5f));
        uint32_t prev = 0;
        for (int i = 0; i <= n; ++i) {
            vec2 p = ring(float(i) / float(n));
            uint32_t id = b.vertex(c + vec3(p, 0), normal,
                                   vec2(0.5f) + p * vec2(end > 0.0f ? 1.0f : -1.0f, -1.0f) / r);
            // The ring runs counter-clockwise seen from +z.
            if (i > 0) end > 0.0f ? b.triangle(centre, prev, id) : b.triangle(centre, id, prev);
            prev = id;
        }
    }
}

// Between the columns at za and zb: the rails end inside the plinths and shafts, so no end
// face is left coplanar with a plinth's face or floating beside a shaft.
void addBalustrade(MeshBuilder& b, const Tessellation& t, const Storey& s, float x, float za,
                   float zb) {
    const float railH = 0.15f, balH = 0.75f;
    const float z0 = za + s.plinthHalf, z1 = zb - s.plinthHalf;
    addBox(b, vec3(x - 0.15f, s.floorY, z0 - 0.05f), vec3(x + 0.15f, s.floorY + railH, z1 + 0.05f),
           kStoneTex, kSkipBottom);
    float top = s.floorY + railH + balH;
    addBox(b, vec3(x - 0.17f, top, za + 0.5f * s.radius),
           vec3(x + 0.17f, top + railH, zb - 0.5f * s.radius), kStoneTex);
    for (int i = 0; i < t.balustersPerBay; ++i) {
        float z = z0 + (z1 - z0) * (float(i) + 0.5f) / float(t.balustersPerBay);
        addLathe(b, vec3(x, s.floorY + railH, z), kBalusterProfile, t.balusterSegments,
                 t.balusterRows, kStoneTex);
    }
}

} // namespace

void addColonnade(Scene& scene, const Tessellation& t, const CourtyardMaterials& m, float side,
                  int storeyIndex) {
    const Storey s = storey(storeyIndex);
    const std::string tag = std::string(side > 0 ? "east" : "west") + std::to_string(storeyIndex);
    const float x = side * kColumnX, inward = -side;
    MeshBuilder stone("colonnade_" + tag, m.stone), lamps("lamps_" + tag, m.lamp);
    MeshBuilder iron("rods_" + tag, m.iron);
    MeshBuilder cloth[3] = {{"cloth_red_" + tag, m.cloth[0]},
                            {"cloth_green_" + tag, m.cloth[1]},
                            {"cloth_blue_" + tag, m.cloth[2]}};
    for (int i = 0; i < kColumns; ++i)
        addColumn(stone, t, s, vec3(x, s.floorY, columnZ(i)));
    const float spring = s.springY(), halfT = 0.5f * kArcadeT;
    const float endZ = kEndZ + kEmbed; // slabs and piers run a little into the end walls
    for (int i = 0; i + 1 < kColumns; ++i) {
        float zc = 0.5f * (columnZ(i) + columnZ(i + 1));
        addArch(stone, t, {x, zc, spring, s.wallTop, 0.5f * kBay, 0.5f * kBay - s.abacusHalf});
        // One lamp bar per bay, hanging just under the slab near the back wall.
        float lampX = side * (kHalfX - kWallT - 1.2f);
        addBox(lamps, vec3(lampX - 0.05f, s.wallTop - 0.15f, zc - 0.8f),
               vec3(lampX + 0.05f, s.wallTop - 0.05f, zc + 0.8f), 1.0f, kSkipTop);
        if (storeyIndex == 1) {
            addBalustrade(stone, t, s, x, columnZ(i), columnZ(i + 1));
            if (i == 0 || i == kColumns - 2) continue; // the end bays stay open
            float cx = x + inward * (s.abacusHalf + 0.15f);
            addRod(iron, t, vec3(cx, spring - 0.1f, zc - 1.5f), 3.0f);
            uint32_t seed = uint32_t(i) * 2u + (side > 0 ? 1u : 0u);
            addCloth(cloth[i % 3], t, cx, inward, zc, spring - 0.1f, 2.8f, 3.1f, seed);
        }
    }
    // Solid piers between the end walls and the first and last columns.
    for (float dir : {-1.0f, 1.0f}) {
        float zi = dir * columnZ(kColumns - 1);
        vec3 a(x - halfT, spring, zi), c(x + halfT, s.wallTop, dir * endZ);
        addBox(stone, glm::min(a, c), glm::max(a, c), kStoneTex);
    }
    // The slab over this storey, from the arch wall back to the wall.
    float inner = x + inward * halfT, outer = side * (kHalfX - kWallT + kEmbed);
    addBox(stone, vec3(std::min(inner, outer), s.wallTop, -endZ),
           vec3(std::max(inner, outer), s.slabTop, endZ), kStoneTex);
    if (storeyIndex == 1) // parapet on top of the upper arcade
        addBox(stone, vec3(x - halfT, s.slabTop, -endZ), vec3(x + halfT, kHeight, endZ), kStoneTex,
               kSkipBottom);
    for (MeshBuilder* b : {&stone, &lamps, &iron, &cloth[0], &cloth[1], &cloth[2]})
        if (!b->empty()) scene.meshes.push_back(b->finish());
}

} // namespace tp::procgen
