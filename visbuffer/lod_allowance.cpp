#include "visbuffer/lod_allowance.h"

#include <algorithm>
#include <cmath>

#include "core/camera/camera.h"
#include "core/renderer/position_allowance.h"
#include "include/shared.h"
#include "include/tonemap.h"

namespace tp::vis {
namespace {

// Per channel, the range of a texture's texels (linear after the sRGB decode where the
// texture is sRGB, which the alpha channel never is), and its level span.
struct TextureRange {
    float lo[4] = {1, 1, 1, 1}, hi[4] = {0, 0, 0, 0};
    float span(int c) const { return hi[c] > lo[c] ? hi[c] - lo[c] : 0.0f; }
    float spanRgb() const { return std::max({span(0), span(1), span(2)}); }
};

TextureRange rangeOf(const Texture& t) {
    TextureRange r;
    for (size_t i = 0; i + 3 < t.rgba8.size(); i += 4)
        for (int c = 0; c < 4; ++c) {
            float v = float(t.rgba8[i + size_t(c)]) / 255.0f;
            if (t.srgb && c < 3) v = gpu::srgbDecode(v);
            r.lo[c] = std::min(r.lo[c], v);
            r.hi[c] = std::max(r.hi[c], v);
        }
    return r;
}

uint32_t levelSpan(const Texture& t) {
    uint32_t levels = 1;
    for (uint32_t e = std::max(t.width, t.height); e > 1; e >>= 1)
        ++levels;
    return levels - 1;
}

// The scene's largest change of each kind per unit of level change.
struct Sensitivity {
    double base = 0;               // x the reflected-light bound
    double baseRelative = 0;       // x the reference radiance: span / darkest texel, where > 0
    bool baseAbsolute = false;     // a base texture with a black texel: the light bound instead
    double absoluteBeyondBase = 0; // `absolute` less the ambient term's base-colour part
    double relative = 0;           // metallic and roughness: x the reflected-light bound
    double angle = 0;              // normal rotation in radians: x 2 x the Lipschitz bound
    double absolute = 0;           // the ambient term and emission: radiance
    uint32_t levelSpan = 0;        // the largest level change any texture allows
    bool textured() const { return levelSpan > 0; }
};

double largestVertexColour(const Scene& scene) {
    double c = 1.0;
    for (const Mesh& m : scene.meshes)
        for (const glm::vec4& v : m.colors)
            c = std::max({c, double(v.r), double(v.g), double(v.b)});
    return c;
}

Sensitivity sensitivityOf(const Scene& scene) {
    Sensitivity s;
    std::vector<TextureRange> ranges;
    for (const Texture& t : scene.textures) {
        ranges.push_back(rangeOf(t));
        s.levelSpan = std::max(s.levelSpan, levelSpan(t));
    }
    auto has = [&](int32_t i) { return i >= 0 && size_t(i) < ranges.size(); };
    const double colour = largestVertexColour(scene);
    const double ambient =
        std::max({double(scene.ambient.r), double(scene.ambient.g), double(scene.ambient.b)});
    for (const Material& m : scene.materials) {
        const double factor =
            std::max({m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b}) * colour;
        // The ambient term, ambient * base * (1 - metallic) * occlusion, moves with the base
        // colour and metallic too: at most ambient times their change (occlusion <= 1).
        double ambientMove = 0, baseAmbient = 0;
        if (has(m.baseColorTexture)) {
            const TextureRange& r = ranges[size_t(m.baseColorTexture)];
            const double move = r.spanRgb() * factor;
            s.base = std::max(s.base, move);
            ambientMove += ambient * move;
            baseAmbient = ambient * move;
            const float darkest = std::min({r.lo[0], r.lo[1], r.lo[2]});
            if (darkest > 0.0f)
                s.baseRelative = std::max(s.baseRelative, double(r.spanRgb()) / darkest);
            else
                s.baseAbsolute = true;
        }
        if (has(m.metallicRoughnessTexture)) {
            const TextureRange& r = ranges[size_t(m.metallicRoughnessTexture)];
            const double roughLo =
                std::max(double(TP_MIN_ROUGHNESS), double(m.roughnessFactor) * r.lo[1]);
            s.relative = std::max(s.relative, r.span(2) * m.metallicFactor +
                                                  6.0 * r.span(1) * m.roughnessFactor / roughLo);
            ambientMove += ambient * factor * r.span(2) * m.metallicFactor;
        }
        if (has(m.normalTexture)) {
            // tn = 2 t - 1, xy scaled: the mapped normal moves by 2 sqrt(2) span |scale| over a
            // length of at least tn.z's smallest value; past that, any angle (pi).
            const TextureRange& r = ranges[size_t(m.normalTexture)];
            const double zLo = 2.0 * r.lo[2] - 1.0;
            const double move =
                2.0 * std::sqrt(2.0) * std::max(r.span(0), r.span(1)) * std::abs(m.normalScale);
            s.angle = std::max(s.angle, zLo > 0.05 ? move / zLo : 3.14159265358979);
        }
        if (has(m.occlusionTexture))
            ambientMove +=
                ambient * factor * m.occlusionStrength * ranges[size_t(m.occlusionTexture)].span(0);
        if (has(m.emissiveTexture))
            ambientMove += std::max({m.emissiveFactor.r, m.emissiveFactor.g, m.emissiveFactor.b}) *
                           ranges[size_t(m.emissiveTexture)].spanRgb();
        s.absolute = std::max(s.absolute, ambientMove);
        s.absoluteBeyondBase = std::max(s.absoluteBeyondBase, ambientMove - baseAmbient);
    }
    return s;
}

// |delta lambda| at pixel (x, y): from q = 1 / view depth and its gradient on the pixel's own
// surface (on each axis the nearer neighbour in q, the other when it is a depth edge), the
// level span where no neighbour reads the surface.
double levelChange(const std::vector<double>& q, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                   double cap) {
    const double q0 = q[size_t(y) * w + x];
    auto at = [&](int xx, int yy) {
        if (xx < 0 || yy < 0 || xx >= int(w) || yy >= int(h)) return std::nan("");
        return q[size_t(yy) * w + size_t(xx)];
    };
    auto gradient = [&](int dx, int dy, double& g) {
        const double a = q0 - at(int(x) - dx, int(y) - dy), b = at(int(x) + dx, int(y) + dy) - q0;
        const bool okA = !std::isnan(a), okB = !std::isnan(b);
        if (okA && okB &&
            std::max(std::abs(a), std::abs(b)) <= 1.5 * std::min(std::abs(a), std::abs(b)))
            g = std::max(std::abs(a), std::abs(b));
        else if (okA || okB)
            g = okA && (!okB || std::abs(a) < std::abs(b)) ? std::abs(a) : std::abs(b);
        else
            return false;
        return true;
    };
    double gx = 0, gy = 0;
    if (!gradient(1, 0, gx) || !gradient(0, 1, gy)) return cap;
    const double lo = q0 - gx - gy, hi = q0 + gx + gy;
    if (!(lo > 0.0)) return cap;
    return std::min(cap, 3.0 * std::log2(hi / lo) + 1.0 / 256.0);
}

} // namespace

ImageR32 levelChangeBounds(const Scene& scene, const ImageR32& depth, uint32_t levelSpan) {
    ImageR32 out{depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)};
    const std::vector<glm::dvec3> pos = pixelPositions(scene.camera, depth);
    const glm::dmat4 view = viewRotation(scene.camera);
    std::vector<double> q(pos.size(), std::nan(""));
    for (size_t i = 0; i < pos.size(); ++i)
        if (!std::isnan(pos[i].x)) q[i] = 1.0 / -(view * glm::dvec4(pos[i], 1.0)).z;
    for (uint32_t y = 0; y < depth.height; ++y)
        for (uint32_t x = 0; x < depth.width; ++x) {
            const size_t i = size_t(y) * depth.width + x;
            if (!std::isnan(q[i]))
                out.r[i] = float(levelChange(q, depth.width, depth.height, x, y, levelSpan));
        }
    return out;
}

ImageR32 textureLodAllowance(const Scene& scene, const ImageR32& depth,
                             const ImageRGBA* reference) {
    const Sensitivity s = sensitivityOf(scene);
    if (!s.textured()) return {depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)};
    ImageR32 out = levelChangeBounds(scene, depth, s.levelSpan);
    const ReflectedLightBounds light = reflectedLightBounds(scene, depth);
    // The base colour through the reference's radiance (ambient term included: it is part of
    // R), or through the light bound and the ambient where there is no reference or a texel is
    // black.
    const bool relative = reference && reference->pixelCount() == out.r.size() && !s.baseAbsolute;
    for (size_t i = 0; i < out.r.size(); ++i) {
        double radiance = 0;
        if (relative)
            for (int c = 0; c < 3; ++c)
                radiance = std::max(radiance, double(reference->rgba[i * 4 + size_t(c)]));
        const double base = relative ? radiance * s.baseRelative : light.value.r[i] * s.base;
        out.r[i] *=
            float(base + light.value.r[i] * s.relative + 2.0 * light.lipschitz.r[i] * s.angle +
                  (relative ? s.absoluteBeyondBase : s.absolute));
    }
    return out;
}

} // namespace tp::vis
