// The visibility buffer's CPU parts: the id's bit split (visbuffer/draw_table.h) and the
// texture level-of-detail bound (visbuffer/lod_allowance.h), checked on a floor whose texture
// coordinates are its world x and z: the level from the analytic derivative at each pixel
// centre against the level from the finite differences a 2x2 quad takes (fine and coarse),
// everywhere within the bound; no texture, no allowance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/camera/camera.h"
#include "visbuffer/draw_table.h"
#include "visbuffer/lod_allowance.h"

namespace tp {
namespace {

constexpr uint32_t kLodWidth = 96, kLodHeight = 64;

Scene texturedFloor(bool textured) {
    Scene s;
    Material m;
    m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    m.roughnessFactor = 0.5f;
    m.metallicFactor = 0.0f;
    if (textured) {
        Texture t;
        t.width = t.height = 256;
        t.srgb = true;
        t.rgba8.assign(size_t(256) * 256 * 4, 255);
        for (size_t i = 0; i < t.rgba8.size(); i += 8)
            t.rgba8[i] = t.rgba8[i + 1] = t.rgba8[i + 2] = 20; // a fine stripe pattern
        s.textures = {t};
        m.baseColorTexture = 0;
    }
    s.materials = {m};
    s.camera.position = {0, 2, 7};
    s.camera.target = {0, 0, 0};
    s.camera.yfov = 0.8f;
    s.camera.znear = 0.05f;
    s.camera.zfar = 0.0f;
    Light l;
    l.type = LightType::Point;
    l.position = {0, 1, 2};
    l.range = 10.0f;
    l.intensity = 5.0f;
    s.lights = {l};
    return s;
}

// The floor (y = 0) point under framebuffer location (fx, fy), camera-relative ray in double.
struct Floor {
    glm::dmat4 invViewProj, proj, view;
    glm::dvec3 eye;
    explicit Floor(const Camera& cam)
        : proj(glm::dmat4(
              reverseZPerspective(cam.yfov, float(kLodWidth) / float(kLodHeight), cam.znear, cam.zfar))),
          view(viewRotation(cam)), eye(cam.position) {
        invViewProj = glm::inverse(proj * view);
    }
    glm::dvec3 hit(double fx, double fy) const {
        const glm::dvec4 h =
            invViewProj * glm::dvec4(fx / kLodWidth * 2.0 - 1.0, 1.0 - fy / kLodHeight * 2.0, 0.5, 1.0);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(h) / h.w);
        if (dir.y >= 0.0) return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
        return dir * (-eye.y / dir.y);
    }
    glm::dvec2 uv(double fx, double fy) const {
        const glm::dvec3 p = hit(fx, fy) + eye;
        return {p.x, p.z};
    }
    ImageR32 depth() const {
        ImageR32 d{kLodWidth, kLodHeight, std::vector<float>(size_t(kLodWidth) * kLodHeight, 0.0f)};
        for (uint32_t y = 0; y < kLodHeight; ++y)
            for (uint32_t x = 0; x < kLodWidth; ++x) {
                const glm::dvec3 p = hit(x + 0.5, y + 0.5);
                if (std::isnan(p.x)) continue;
                const glm::dvec4 clip = proj * view * glm::dvec4(p, 1.0);
                d.r[size_t(y) * kLodWidth + x] = float(clip.z / clip.w);
            }
        return d;
    }
};

// log2 of the larger screen derivative's length in texels of a 256-texel texture.
double level(glm::dvec2 dx, glm::dvec2 dy) {
    return std::log2(std::max(glm::length(dx), glm::length(dy)) * 256.0);
}

TEST(VisbufferIds, BitsHoldEveryValue) {
    EXPECT_EQ(vis::bitsFor(0), 1u);
    EXPECT_EQ(vis::bitsFor(1), 1u);
    EXPECT_EQ(vis::bitsFor(2), 1u);
    EXPECT_EQ(vis::bitsFor(3), 2u);
    EXPECT_EQ(vis::bitsFor(1u << 20), 20u);
    EXPECT_EQ(vis::bitsFor((1u << 20) + 1), 21u);
}

TEST(VisbufferLod, AnalyticLevelWithinTheBoundOfEveryQuadDerivative) {
    const Scene scene = texturedFloor(true);
    const Floor floor(scene.camera);
    const ImageR32 depth = floor.depth();
    const ImageR32 bound = vis::levelChangeBounds(scene, depth, 8);
    int checked = 0;
    double worstRatio = 0;
    for (uint32_t y = 1; y + 2 < kLodHeight; ++y)
        for (uint32_t x = 1; x + 2 < kLodWidth; ++x) {
            bool allFloor = true; // the pixel's quad and the neighbours the bound reads
            for (int j = -1; j <= 2; ++j)
                for (int i = -1; i <= 2; ++i)
                    allFloor &= depth.r[size_t(int(y) + j) * kLodWidth + size_t(int(x) + i)] > 0.0f;
            if (!allFloor) continue;
            const double cx = x + 0.5, cy = y + 0.5, h = 1e-4;
            const glm::dvec2 adx = (floor.uv(cx + h, cy) - floor.uv(cx - h, cy)) / (2 * h);
            const glm::dvec2 ady = (floor.uv(cx, cy + h) - floor.uv(cx, cy - h)) / (2 * h);
            const double analytic = level(adx, ady);
            const double x0 = (x & ~1u) + 0.5, y0 = (y & ~1u) + 0.5;
            const glm::dvec2 fineDx = floor.uv(x0 + 1, cy) - floor.uv(x0, cy);
            const glm::dvec2 fineDy = floor.uv(cx, y0 + 1) - floor.uv(cx, y0);
            const glm::dvec2 coarseDx = floor.uv(x0 + 1, y0) - floor.uv(x0, y0);
            const glm::dvec2 coarseDy = floor.uv(x0, y0 + 1) - floor.uv(x0, y0);
            const double b = bound.r[size_t(y) * kLodWidth + x];
            for (double hw : {level(fineDx, fineDy), level(coarseDx, coarseDy)}) {
                EXPECT_LE(std::abs(hw - analytic), b) << "pixel " << x << "," << y;
                worstRatio = std::max(worstRatio, std::abs(hw - analytic) / b);
            }
            ++checked;
        }
    EXPECT_GT(checked, 2000);
    std::printf("[ lod      ] %d pixels: largest |level change| / bound %.3f\n", checked,
                worstRatio);
}

TEST(VisbufferLod, NoTextureNoAllowance) {
    const Scene plain = texturedFloor(false), textured = texturedFloor(true);
    const ImageR32 depth = Floor(plain.camera).depth();
    double sumPlain = 0, sumTextured = 0;
    for (float v : vis::textureLodAllowance(plain, depth).r)
        sumPlain += v;
    for (float v : vis::textureLodAllowance(textured, depth).r)
        sumTextured += v;
    EXPECT_EQ(sumPlain, 0.0);
    EXPECT_GT(sumTextured, 0.0);
}

} // namespace
} // namespace tp
