#include "core/scene/procedural_textures.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "core/util/math.h"

namespace tp::procgen {

namespace {

// A texel's colour (sRGB or linear as the texture says) and alpha, in [0, 1].
using TexelFn = std::function<glm::vec4(int x, int y)>;

Texture makeTexture(const std::string& name, int size, bool srgb, const TexelFn& texel) {
    Texture t;
    t.name = name;
    t.width = t.height = uint32_t(size);
    t.srgb = srgb;
    t.rgba8.resize(size_t(size) * size_t(size) * 4);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            glm::vec4 c = glm::clamp(texel(x, y), 0.0f, 1.0f);
            uint8_t* p = &t.rgba8[(size_t(y) * size_t(size) + size_t(x)) * 4];
            for (int k = 0; k < 4; ++k)
                p[k] = uint8_t(std::lround(c[k] * 255.0f));
        }
    }
    return t;
}

int32_t push(std::vector<Texture>& textures, Texture t) {
    textures.push_back(std::move(t));
    return int32_t(textures.size() - 1);
}

float smooth(float t) {
    return t * t * (3.0f - 2.0f * t);
}

// Value noise on a lattice that wraps every `period` cells, so textures tile.
float valueNoise(float x, float y, int period, uint32_t seed) {
    float fx = std::floor(x), fy = std::floor(y);
    int ix = int(fx), iy = int(fy);
    float tx = smooth(x - fx), ty = smooth(y - fy);
    auto h = [&](int i, int j) {
        uint32_t a = uint32_t(((i % period) + period) % period);
        uint32_t b = uint32_t(((j % period) + period) % period);
        return hash01(a, b, seed);
    };
    float a = h(ix, iy) + tx * (h(ix + 1, iy) - h(ix, iy));
    float b = h(ix, iy + 1) + tx * (h(ix + 1, iy + 1) - h(ix, iy + 1));
    return a + ty * (b - a);
}

// Fractal noise in [0, 1) over a texture of `size` texels, `period` lattice cells across.
float fbm(int x, int y, int size, int period, int octaves, uint32_t seed) {
    float sum = 0.0f, amp = 0.5f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        float s = float(period) / float(size);
        sum += amp * valueNoise(float(x) * s, float(y) * s, period, seed + uint32_t(o) * 7919u);
        norm += amp;
        amp *= 0.5f;
        period *= 2;
    }
    return sum / norm;
}

// Tangent-space normal map from a tiling height field (heights in texels): +X right, +Y up
// in the image (glTF convention).
Texture normalMap(const std::string& name, int size, const std::vector<float>& h) {
    auto at = [&](int x, int y) {
        return h[size_t((y + size) % size) * size_t(size) + size_t((x + size) % size)];
    };
    return makeTexture(name, size, false, [&](int x, int y) {
        float dx = 0.5f * (at(x + 1, y) - at(x - 1, y));
        float dy = 0.5f * (at(x, y + 1) - at(x, y - 1)); // rows run down the image
        glm::vec3 n = glm::normalize(glm::vec3(-dx, dy, 1.0f));
        return glm::vec4(n * 0.5f + 0.5f, 1.0f);
    });
}

// Distance in texels from (x, y) to the nearest edge of a cell [0,w) x [0,h).
float edgeDistance(float x, float y, float w, float h) {
    return std::min(std::min(x, w - 1.0f - x), std::min(y, h - 1.0f - y));
}

// Large stone slabs, 4 x 4 per texture, with grout: the height field and per-slab ids.
struct SlabSample {
    float height;
    float tint;
    bool grout;
};

SlabSample floorSlab(int x, int y, int size) {
    const int cell = size / 4;
    float d = edgeDistance(float(x % cell), float(y % cell), float(cell), float(cell));
    uint32_t id = uint32_t(x / cell) * 17u + uint32_t(y / cell);
    SlabSample s;
    s.grout = d < 1.5f;
    s.tint = hash01(id, 3, 101);
    float bevel = std::min(1.0f, std::max(0.0f, d - 1.5f) / 4.0f);
    s.height = s.grout ? 0.0f : 2.0f * bevel + 0.8f * fbm(x, y, size, 8, 3, 11);
    return s;
}

// Running-bond bricks, 8 rows of 4 per texture.
SlabSample brick(int x, int y, int size) {
    const int bh = size / 8, bw = size / 4;
    int row = y / bh;
    int xs = (x + (row % 2) * (bw / 2)) % size;
    float d = edgeDistance(float(xs % bw), float(y % bh), float(bw), float(bh));
    uint32_t id = uint32_t(row) * 31u + uint32_t(xs / bw);
    SlabSample s;
    s.grout = d < 2.0f;
    s.tint = hash01(id, 5, 202);
    float bevel = std::min(1.0f, std::max(0.0f, d - 2.0f) / 2.5f);
    s.height = s.grout ? 0.0f : 2.5f * bevel + 0.6f * fbm(x, y, size, 16, 2, 21);
    return s;
}

template <class SampleFn>
void addSurfaceSet(std::vector<Texture>& out, const std::string& name, int size, SampleFn sample,
                   glm::vec3 colorA, glm::vec3 colorB, glm::vec3 groutColor, float roughness,
                   int32_t* base, int32_t* mr, int32_t* normal) {
    std::vector<float> heights(size_t(size) * size_t(size));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            heights[size_t(y) * size_t(size) + x] = sample(x, y, size).height;
    *base = push(out, makeTexture(name + "_basecolor", size, true, [&](int x, int y) {
                     SlabSample s = sample(x, y, size);
                     float n = fbm(x, y, size, 16, 4, 31);
                     glm::vec3 c = s.grout ? groutColor : glm::mix(colorA, colorB, s.tint);
                     return glm::vec4(c * (0.8f + 0.4f * n), 1.0f);
                 }));
    *mr = push(out, makeTexture(name + "_metalrough", size, false, [&](int x, int y) {
                   SlabSample s = sample(x, y, size);
                   float r =
                       s.grout ? 0.95f : roughness + 0.2f * (fbm(x, y, size, 8, 3, 41) - 0.5f);
                   return glm::vec4(1.0f, r, 0.0f, 1.0f); // R unused, G roughness, B metallic
               }));
    *normal = push(out, normalMap(name + "_normal", size, heights));
}

glm::vec4 limestone(int x, int y, int size) {
    float n = fbm(x, y, size, 4, 5, 51);
    float vein = std::abs(std::sin((float(x + y) / float(size) * 2.0f + 3.0f * n) * 2.0f * kPi));
    float v = 0.85f + 0.15f * n - 0.12f * std::pow(1.0f - vein, 8.0f);
    return glm::vec4(glm::vec3(0.93f, 0.88f, 0.78f) * v, 1.0f);
}

// Woven cloth: `pattern` picks the motif, then a fine weave modulates it.
glm::vec4 cloth(int x, int y, int size, int pattern, glm::vec3 main, glm::vec3 accent) {
    float u = float(x) / float(size), v = float(y) / float(size);
    bool a = false;
    if (pattern == 0) a = std::fmod(u * 8.0f, 1.0f) < 0.22f;
    if (pattern == 1) {
        float du = std::abs(std::fmod(u * 4.0f, 1.0f) - 0.5f);
        float dv = std::abs(std::fmod(v * 4.0f, 1.0f) - 0.5f);
        a = du + dv < 0.3f && du + dv > 0.18f;
    }
    if (pattern == 2) a = ((x / (size / 8)) + (y / (size / 8))) % 2 == 0;
    float weave = ((x + y) % 2 == 0 ? 0.95f : 1.05f) * (0.9f + 0.2f * fbm(x, y, size, 32, 2, 61));
    return glm::vec4((a ? accent : main) * weave, 1.0f);
}

glm::vec4 grille(int x, int y, int size) {
    float u = float(x) / float(size), v = float(y) / float(size);
    float d1 = std::abs(std::fmod(u * 6.0f + v * 6.0f, 1.0f) - 0.5f);
    float d2 = std::abs(std::fmod(u * 6.0f - v * 6.0f + 12.0f, 1.0f) - 0.5f);
    bool frame = std::min(std::min(u, 1.0f - u), std::min(v, 1.0f - v)) < 0.04f;
    bool bar = frame || d1 > 0.42f || d2 > 0.42f;
    float rust = fbm(x, y, size, 8, 3, 71);
    return glm::vec4(glm::vec3(0.20f, 0.16f, 0.13f) * (0.7f + 0.6f * rust), bar ? 1.0f : 0.0f);
}

// About 70 leaves, each an ellipse, clustered in a rough disc.
glm::vec4 foliage(int x, int y, int size) {
    glm::vec2 p(float(x) / float(size), float(y) / float(size));
    for (uint32_t i = 0; i < 70; ++i) {
        float r = 0.42f * std::sqrt(hash01(i, 1, 81)), phi = 2.0f * kPi * hash01(i, 2, 81);
        glm::vec2 c(0.5f + r * std::cos(phi), 0.55f + 0.9f * r * std::sin(phi));
        float ang = 2.0f * kPi * hash01(i, 3, 81);
        float len = 0.06f + 0.05f * hash01(i, 4, 81);
        glm::vec2 d = p - c;
        glm::vec2 q(d.x * std::cos(ang) + d.y * std::sin(ang),
                    -d.x * std::sin(ang) + d.y * std::cos(ang));
        if ((q.x * q.x) / (len * len) + (q.y * q.y) / (0.16f * len * len) < 1.0f) {
            float shade = 0.6f + 0.5f * hash01(i, 5, 81) + 0.3f * q.x / len;
            return glm::vec4(glm::vec3(0.22f, 0.42f, 0.12f) * shade, 1.0f);
        }
    }
    return glm::vec4(0.2f, 0.3f, 0.1f, 0.0f);
}

} // namespace

float hash01(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = seed * 0x9E3779B9u ^ (x * 0x85EBCA6Bu) ^ (y * 0xC2B2AE35u + 0x27D4EB2Fu);
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

CourtyardTextures addCourtyardTextures(std::vector<Texture>& out) {
    CourtyardTextures t{};
    addSurfaceSet(out, "floor", 256, floorSlab, {0.62f, 0.58f, 0.52f}, {0.78f, 0.72f, 0.62f},
                  {0.35f, 0.33f, 0.30f}, 0.7f, &t.floorBase, &t.floorMr, &t.floorNormal);
    addSurfaceSet(out, "brick", 256, brick, {0.55f, 0.27f, 0.18f}, {0.72f, 0.50f, 0.32f},
                  {0.70f, 0.68f, 0.62f}, 0.85f, &t.brickBase, &t.brickMr, &t.brickNormal);
    t.stoneBase = push(out, makeTexture("stone_basecolor", 128, true,
                                        [](int x, int y) { return limestone(x, y, 128); }));
    const int n = 128;
    t.clothRed = push(out, makeTexture("cloth_red", n, true, [](int x, int y) {
                          return cloth(x, y, n, 0, {0.62f, 0.08f, 0.07f}, {0.85f, 0.65f, 0.20f});
                      }));
    t.clothGreen = push(out, makeTexture("cloth_green", n, true, [](int x, int y) {
                            return cloth(x, y, n, 1, {0.10f, 0.42f, 0.18f}, {0.90f, 0.85f, 0.60f});
                        }));
    t.clothBlue = push(out, makeTexture("cloth_blue", n, true, [](int x, int y) {
                           return cloth(x, y, n, 2, {0.10f, 0.18f, 0.55f}, {0.16f, 0.28f, 0.70f});
                       }));
    t.grille =
        push(out, makeTexture("grille", n, true, [](int x, int y) { return grille(x, y, n); }));
    t.foliage =
        push(out, makeTexture("foliage", n, true, [](int x, int y) { return foliage(x, y, n); }));
    return t;
}

} // namespace tp::procgen
