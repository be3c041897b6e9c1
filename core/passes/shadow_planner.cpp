#include "core/passes/shadow_planner.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/tile_bound.h"

namespace tp {
namespace {

constexpr uint32_t kInfluenceTile = 8; // the selection's screen rectangles, in 8-pixel tiles

uint32_t pow2Ceil(double v) {
    uint32_t p = 1;
    while (p < v && p < (1u << 30)) p <<= 1;
    return p;
}

float spotHalfAngle(const gpu::LightGpu& l) {
    return std::acos(std::clamp(-l.spotOffset / l.spotScale, -1.0f, 1.0f));
}

bool castsCube(const gpu::LightGpu& l) {
    return l.type != TP_LIGHT_SPOT || spotHalfAngle(l) > kMaxSpotHalfAngle;
}

// The pixels each local light's reach covers on screen (0: it does not reach the view).
std::vector<double> screenInfluence(const std::vector<gpu::LightGpu>& lights,
                                    const std::vector<uint32_t>& local,
                                    const gpu::FrameUniforms& frame, uint32_t width,
                                    uint32_t height) {
    const la::TileGrid grid = la::makeTileGrid(width, height, kInfluenceTile);
    const auto rects = la::conservativeTileRects(grid, frame.view, frame.proj, lights, local);
    std::vector<double> out(rects.size(), 0.0);
    for (size_t i = 0; i < rects.size(); ++i) {
        const la::TileRect& r = rects[i];
        if (r.empty()) continue;
        const double w = std::min<double>(width, (r.x1 + 1.0) * kInfluenceTile) - r.x0 * kInfluenceTile;
        const double h = std::min<double>(height, (r.y1 + 1.0) * kInfluenceTile) - r.y0 * kInfluenceTile;
        out[i] = std::max(0.0, w) * std::max(0.0, h);
    }
    return out;
}

// The atlas a set of power-of-two faces packs into without gaps: W x W or W x W/2.
void atlasExtent(uint64_t texels, uint32_t& w, uint32_t& h) {
    w = 1;
    while (uint64_t(w) * w < texels) w <<= 1;
    h = texels <= uint64_t(w) * w / 2 ? std::max(1u, w / 2) : w;
}

uint64_t totalTexels(const std::vector<ShadowLight>& lights) {
    uint64_t t = 0;
    for (const ShadowLight& l : lights) t += uint64_t(l.faceCount) * l.edge * l.edge;
    return t;
}

// Halves the largest maps (ties: the least influential) until the atlas fits `capTexels` and
// the device's image edge.
void fitBudget(std::vector<ShadowLight>& lights, uint64_t capTexels, uint32_t maxDim,
               uint32_t budgetMb) {
    std::priority_queue<std::pair<uint32_t, uint32_t>> largest; // (edge, priority rank)
    for (uint32_t i = 0; i < lights.size(); ++i) largest.push({lights[i].edge, i});
    uint64_t total = totalTexels(lights);
    for (;;) {
        uint32_t w, h;
        atlasExtent(total, w, h);
        if (uint64_t(w) * h <= capTexels && w <= maxDim) return;
        auto [edge, i] = largest.top();
        largest.pop();
        if (edge <= kShadowMinEdge) {
            uint64_t minTexels = 0;
            for (const ShadowLight& l : lights) minTexels += uint64_t(l.faceCount) * kShadowMinEdge * kShadowMinEdge;
            atlasExtent(minTexels, w, h);
            throw ShadowError("--shadow-budget " + std::to_string(budgetMb) + " MB cannot hold " +
                              std::to_string(lights.size()) + " shadowed lights even at " +
                              std::to_string(kShadowMinEdge) + "x" + std::to_string(kShadowMinEdge) +
                              " texels a face (needs " +
                              std::to_string((uint64_t(w) * h * 4 + (1u << 20) - 1) >> 20) +
                              " MB): raise the budget or shadow fewer lights");
        }
        total -= uint64_t(lights[i].faceCount) * (edge * edge - edge * edge / 4);
        lights[i].edge = edge / 2;
        largest.push({edge / 2, i});
    }
}

// Z-order: x in the even bits, y in the odd ones.
void deinterleave(uint64_t k, uint32_t& x, uint32_t& y) {
    x = y = 0;
    for (uint32_t b = 0; b < 32; ++b) {
        x |= uint32_t((k >> (2 * b)) & 1u) << b;
        y |= uint32_t((k >> (2 * b + 1)) & 1u) << b;
    }
}

glm::mat4 faceProjection(float tanHalf) {
    // Reverse-Z, infinite far: clip z = near, clip w = distance along the axis.
    glm::mat4 p(0.0f);
    p[0][0] = 1.0f / tanHalf;
    p[1][1] = 1.0f / tanHalf;
    p[2][3] = -1.0f;
    p[3][2] = kShadowNear;
    return p;
}

gpu::ShadowFace makeFace(glm::vec3 forward, float tanHalf, uint32_t edge, uint32_t light,
                         uint32_t face) {
    const glm::vec3 up = std::abs(forward.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    gpu::ShadowFace f{};
    f.lightProj = faceProjection(tanHalf) * glm::lookAt(glm::vec3(0.0f), forward, up);
    f.atlas = glm::uvec4(0, 0, edge, light);
    f.local = glm::uvec4((face % 3) * edge, (face / 3) * edge, edge, face);
    f.params = glm::vec4(2.0f * tanHalf / float(edge), kShadowNear, 0.0f, 0.0f);
    return f;
}

void addFaces(ShadowPlan& plan, ShadowLight& sl, const gpu::LightGpu& l) {
    sl.firstFace = uint32_t(plan.faces.size());
    if (sl.faceCount == TP_SHADOW_FACES_POINT) {
        static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (uint32_t f = 0; f < 6; ++f) plan.faces.push_back(makeFace(axes[f], 1.0f, sl.edge, sl.light, f));
    } else {
        const float t = std::max(1e-3f, std::tan(spotHalfAngle(l)));
        plan.faces.push_back(makeFace(glm::normalize(l.direction), t, sl.edge, sl.light, 0));
    }
    for (uint32_t f = sl.firstFace; f < plan.faces.size(); ++f) plan.faces[f].params.z = float(sl.faceCount);
    plan.localWidth = std::max(plan.localWidth, sl.edge * (sl.faceCount == 6 ? 3u : 1u));
    plan.localHeight = std::max(plan.localHeight, sl.edge * (sl.faceCount == 6 ? 2u : 1u));
}

// Largest faces first along the Z-order curve: every offset is a multiple of the next face's
// area, so each face lands on a whole, aligned square.
void packAtlas(ShadowPlan& plan) {
    std::vector<uint32_t> order(plan.faces.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return plan.faces[a].atlas.z > plan.faces[b].atlas.z;
    });
    uint64_t offset = 0;
    for (uint32_t i : order) {
        const uint32_t e = plan.faces[i].atlas.z;
        uint32_t x, y;
        deinterleave(offset / (uint64_t(e) * e), x, y);
        plan.faces[i].atlas.x = x * e;
        plan.faces[i].atlas.y = y * e;
        offset += uint64_t(e) * e;
    }
    atlasExtent(offset, plan.atlasWidth, plan.atlasHeight);
}

} // namespace

ShadowPlan planShadows(const std::vector<gpu::LightGpu>& lights, const gpu::FrameUniforms& frame,
                       uint32_t width, uint32_t height, const ShadowSettings& settings,
                       uint32_t maxImageDimension) {
    ShadowPlan plan;
    if (!settings.enabled()) return plan;
    std::vector<uint32_t> local;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (lights[i].type != TP_LIGHT_DIRECTIONAL) local.push_back(i);
    const std::vector<double> influence = screenInfluence(lights, local, frame, width, height);
    std::vector<uint32_t> order;
    for (uint32_t k = 0; k < local.size(); ++k)
        if (influence[k] > 0.0) order.push_back(k);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return influence[a] > influence[b]; });
    plan.requested = settings.all ? uint32_t(order.size()) : settings.count;
    if (!settings.all && order.size() > settings.count) order.resize(settings.count);
    for (uint32_t k : order) {
        ShadowLight sl;
        sl.light = local[k];
        sl.influence = influence[k];
        sl.faceCount = castsCube(lights[sl.light]) ? TP_SHADOW_FACES_POINT : TP_SHADOW_FACES_SPOT;
        const double reach = std::sqrt(influence[k]) / (sl.faceCount == 6 ? 2.0 : 1.0);
        sl.edge = std::clamp(pow2Ceil(reach), kShadowMinEdge, kShadowMaxEdge);
        // One light's map holds a cube's faces 3 x 2: within the device's image edge.
        while (sl.faceCount == 6 && sl.edge > kShadowMinEdge && sl.edge * 3 > maxImageDimension) sl.edge /= 2;
        plan.lights.push_back(sl);
    }
    const uint64_t cap = (uint64_t(settings.budgetMb) << 20) / 4;
    fitBudget(plan.lights, cap, maxImageDimension, settings.budgetMb);
    for (ShadowLight& sl : plan.lights) addFaces(plan, sl, lights[sl.light]);
    if (!plan.empty()) packAtlas(plan);
    return plan;
}

ShadowPlan planShadows(const SceneGpu& scene, const ShadowSettings& settings,
                       uint32_t maxImageDimension) {
    const gpu::FrameUniforms& frame = scene.shadingFrame();
    return planShadows(scene.shadingLights(), frame, frame.viewport.x, frame.viewport.y, settings,
                       maxImageDimension);
}

} // namespace tp
