// The built-in courtyard: deterministic, the right size, well-formed meshes, and the
// features (blend, mask, emissive, textures, normal maps) the pipelines must handle.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>

#include "core/scene/procedural.h"

using namespace tp;

namespace {

const Scene& smallScene() {
    static const Scene s = makeBuiltinScene("courtyard-small").value();
    return s;
}

const Scene& fullScene() {
    static const Scene s = [] {
        auto t0 = std::chrono::steady_clock::now();
        Scene scene = makeCourtyard({1.0f});
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count();
        std::cout << "[ courtyard ] detail 1: " << scene.triangleCount() << " triangles, "
                  << scene.vertexCount() << " vertices, " << scene.meshes.size()
                  << " meshes, built in " << ms << " ms\n";
        return scene;
    }();
    return s;
}

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

glm::vec3 faceNormal(const Mesh& m, size_t t) {
    const glm::vec3& a = m.positions[m.indices[t]];
    return glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a);
}

} // namespace

TEST(ProceduralCourtyard, BuildsAreIdentical) {
    Scene a = makeCourtyard({0.08f}), b = makeCourtyard({0.08f});
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh &ma = a.meshes[i], &mb = b.meshes[i];
        EXPECT_TRUE(sameBytes(ma.positions, mb.positions) && sameBytes(ma.normals, mb.normals) &&
                    sameBytes(ma.tangents, mb.tangents) && sameBytes(ma.uvs, mb.uvs) &&
                    sameBytes(ma.indices, mb.indices))
            << ma.name;
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (size_t i = 0; i < a.textures.size(); ++i)
        EXPECT_TRUE(sameBytes(a.textures[i].rgba8, b.textures[i].rgba8));
}

TEST(ProceduralCourtyard, TriangleCountLikeSponza) {
    size_t n = fullScene().triangleCount();
    EXPECT_GE(n, 235000u);
    EXPECT_LE(n, 275000u);
    size_t small = smallScene().triangleCount();
    std::cout << "[ courtyard ] small: " << small << " triangles\n";
    EXPECT_LT(small, 10000u);
    size_t tiny = makeCourtyard({0.05f}).triangleCount();
    EXPECT_LT(tiny, 7000u);
    EXPECT_GT(tiny, 1000u);
}

TEST(ProceduralCourtyard, BoundsCameraAndLights) {
    const Scene& s = smallScene();
    glm::vec3 e = s.bounds.extent();
    EXPECT_NEAR(e.x, 30.0f, 0.5f);
    EXPECT_NEAR(e.y, 13.0f, 0.5f);
    EXPECT_NEAR(e.z, 60.0f, 0.5f);
    EXPECT_EQ(s.source, "builtin:courtyard");
    EXPECT_TRUE(s.lights.empty());
    const Camera& c = s.camera;
    EXPECT_GE(c.position.y, 1.7f);
    EXPECT_LE(c.position.y, 2.0f);
    EXPECT_TRUE(glm::all(glm::greaterThan(c.position, s.bounds.min)) &&
                glm::all(glm::lessThan(c.position, s.bounds.max)));
    glm::vec3 view = glm::normalize(c.target - c.position);
    EXPECT_GT(std::abs(view.z), 0.95f);
    EXPECT_EQ(c.zfar, 0.0f);
    EXPECT_NEAR(c.yfov, 1.0f, 0.05f);
}

TEST(ProceduralCourtyard, HasEveryMaterialFeature) {
    const Scene& s = fullScene();
    SceneFeatures f = analyzeScene(s, 1);
    EXPECT_TRUE(f.blended);
    EXPECT_TRUE(f.masked);
    EXPECT_TRUE(f.emissive);
    EXPECT_TRUE(f.textures);
    EXPECT_TRUE(f.normalMaps);
    for (const Material& m : s.materials) {
        if (m.alphaMode == AlphaMode::Blend) {
            EXPECT_TRUE(m.doubleSided) << m.name;
            EXPECT_GE(m.baseColorFactor.a, 0.6f);
            EXPECT_LE(m.baseColorFactor.a, 0.8f);
        }
        if (m.alphaMode == AlphaMode::Mask) {
            EXPECT_EQ(m.alphaCutoff, 0.5f);
        }
        auto srgb = [&](int32_t i) { return i >= 0 ? int(s.textures.at(size_t(i)).srgb) : -1; };
        EXPECT_NE(srgb(m.baseColorTexture), 0) << m.name;
        EXPECT_NE(srgb(m.normalTexture), 1) << m.name;
        EXPECT_NE(srgb(m.metallicRoughnessTexture), 1) << m.name;
    }
    for (const Texture& t : s.textures) {
        EXPECT_GE(t.width, 128u);
        EXPECT_LE(t.width, 256u);
        EXPECT_EQ(t.rgba8.size(), size_t(t.width) * t.height * 4) << t.name;
    }
    for (const Mesh& m : s.meshes)
        EXPECT_LT(m.material, s.materials.size()) << m.name;
}

TEST(ProceduralCourtyard, AttributesAreWellFormed) {
    for (const Scene* s : {&smallScene(), &fullScene()}) {
        for (const Mesh& m : s->meshes) {
            const size_t n = m.positions.size();
            ASSERT_TRUE(n > 0 && m.normals.size() == n && m.tangents.size() == n &&
                        m.uvs.size() == n && m.colors.size() == n)
                << m.name;
            ASSERT_EQ(m.indices.size() % 3, 0u);
            size_t bad = 0;
            for (uint32_t i : m.indices)
                bad += i >= n;
            for (size_t i = 0; i < n; ++i) {
                const glm::vec3& nr = m.normals[i];
                const glm::vec4& t = m.tangents[i];
                bad += std::abs(glm::length(nr) - 1.0f) > 1e-4f;
                bad += std::abs(glm::length(glm::vec3(t)) - 1.0f) > 1e-4f;
                bad += std::abs(glm::dot(nr, glm::vec3(t))) > 1e-3f;
                bad += std::abs(t.w) != 1.0f;
                bad += m.colors[i] != glm::vec4(1.0f);
                bad += !std::isfinite(m.uvs[i].x + m.uvs[i].y + m.positions[i].x +
                                      m.positions[i].y + m.positions[i].z);
            }
            EXPECT_EQ(bad, 0u) << m.name;
        }
    }
}

// Winding agrees with the shading normals, and tangents follow +u with the bitangent
// cross(n, t) * w pointing toward -v (glTF's "up" in the image).
TEST(ProceduralCourtyard, WindingAndTangentFrames) {
    for (const Mesh& m : fullScene().meshes) {
        size_t tris = 0, flipped = 0, tangentOff = 0, signOff = 0;
        for (size_t t = 0; t < m.indices.size(); t += 3) {
            glm::vec3 fn = faceNormal(m, t);
            if (glm::length(fn) < 1e-10f) continue;
            ++tris;
            const uint32_t* id = &m.indices[t];
            glm::vec3 nsum = m.normals[id[0]] + m.normals[id[1]] + m.normals[id[2]];
            flipped += glm::dot(fn, nsum) <= 0.0f;
            glm::vec3 e1 = m.positions[id[1]] - m.positions[id[0]],
                      e2 = m.positions[id[2]] - m.positions[id[0]];
            glm::vec2 d1 = m.uvs[id[1]] - m.uvs[id[0]], d2 = m.uvs[id[2]] - m.uvs[id[0]];
            float r = d1.x * d2.y - d2.x * d1.y;
            if (std::abs(r) < 1e-9f) continue;
            glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / r, dpdv = (e2 * d1.x - e1 * d2.x) / r;
            for (int k = 0; k < 3; ++k) {
                const glm::vec4& tg = m.tangents[id[k]];
                tangentOff += glm::dot(glm::vec3(tg), dpdu) <= 0.0f;
                glm::vec3 bt = glm::cross(m.normals[id[k]], glm::vec3(tg)) * tg.w;
                signOff += glm::dot(bt, dpdv) >= 0.0f;
            }
        }
        EXPECT_EQ(flipped, 0u) << m.name << " of " << tris;
        EXPECT_EQ(tangentOff, 0u) << m.name;
        EXPECT_EQ(signOff, 0u) << m.name;
    }
}

// From points inside the courtyard, every opaque single-sided surface a ray hits first must
// face the ray: the solids are closed towards the viewer and nothing is inside out.
TEST(ProceduralCourtyard, VisibleSurfacesFaceTheViewer) {
    const Scene& s = smallScene();
    const glm::vec3 eyes[] = {s.camera.position,
                              {0.0f, 6.0f, 0.0f},
                              {12.8f, 1.7f, -5.0f},
                              {-12.8f, 8.0f, 10.0f},
                              {0.0f, 12.0f, -20.0f}};
    size_t hits = 0, backHits = 0;
    for (const glm::vec3& eye : eyes) {
        for (int i = 0; i < 48; ++i) {
            for (int j = 0; j < 24; ++j) {
                float az = 6.2831853f * (float(i) + 0.5f) / 48.0f,
                      el = 3.1415926f * ((float(j) + 0.5f) / 24.0f - 0.5f);
                glm::vec3 dir(std::cos(el) * std::cos(az), std::sin(el),
                              std::cos(el) * std::sin(az));
                float best = 1e30f;
                bool front = true;
                for (const Mesh& m : s.meshes) {
                    const Material& mat = s.materials[m.material];
                    if (mat.alphaMode != AlphaMode::Opaque) continue;
                    for (size_t t = 0; t < m.indices.size(); t += 3) {
                        const glm::vec3& a = m.positions[m.indices[t]];
                        glm::vec3 e1 = m.positions[m.indices[t + 1]] - a,
                                  e2 = m.positions[m.indices[t + 2]] - a;
                        glm::vec3 p = glm::cross(dir, e2);
                        float det = glm::dot(e1, p);
                        if (std::abs(det) < 1e-12f) continue;
                        glm::vec3 o = eye - a;
                        float u = glm::dot(o, p) / det;
                        if (u < 0 || u > 1) continue;
                        glm::vec3 q = glm::cross(o, e1);
                        float v = glm::dot(dir, q) / det;
                        if (v < 0 || u + v > 1) continue;
                        float d = glm::dot(e2, q) / det;
                        if (d > 1e-4f && d < best) {
                            best = d;
                            front = mat.doubleSided || glm::dot(glm::cross(e1, e2), dir) < 0.0f;
                        }
                    }
                }
                if (best < 1e29f) {
                    ++hits;
                    backHits += !front;
                }
            }
        }
    }
    EXPECT_GT(hits, 3000u);
    EXPECT_EQ(backHits, 0u) << "of " << hits;
}

TEST(ProceduralCourtyard, BuiltinNames) {
    auto big = makeBuiltinScene("courtyard");
    ASSERT_TRUE(big.ok());
    EXPECT_EQ(big->triangleCount(), fullScene().triangleCount());
    auto bad = makeBuiltinScene("sponza");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("courtyard-small"), std::string::npos);
    EXPECT_EQ(bad.error().find('\n'), std::string::npos);
}
