#include "multipass_forward/light_plan.h"

#include <algorithm>
#include <cmath>

#include "multipass_forward/light_draws.h"

namespace tp::mp {
namespace {

ScreenRect fullScreen(const gpu::FrameUniforms& f) {
    return {0, 0, int32_t(f.viewport.x), int32_t(f.viewport.y)};
}

// NDC bounds [lo, hi] (x right, y up) -> pixel rectangle, grown by a pixel for rounding.
ScreenRect toPixels(const gpu::FrameUniforms& f, glm::vec2 lo, glm::vec2 hi) {
    const float w = float(f.viewport.x), h = float(f.viewport.y);
    // Clamp before converting: a tangent close to 90 degrees off-axis projects far away.
    auto px = [&](float ndc) { return std::clamp((ndc * 0.5f + 0.5f) * w, -1.0f, w + 1.0f); };
    auto py = [&](float ndc) { return std::clamp((0.5f - ndc * 0.5f) * h, -1.0f, h + 1.0f); };
    ScreenRect r;
    r.x0 = std::max(0, int32_t(std::floor(px(lo.x))) - 1);
    r.x1 = std::min(int32_t(w), int32_t(std::ceil(px(hi.x))) + 1);
    r.y0 = std::max(0, int32_t(std::floor(py(hi.y))) - 1);
    r.y1 = std::min(int32_t(h), int32_t(std::ceil(py(lo.y))) + 1);
    return r;
}

// The two tangents from the eye to the circle (u, depth) of radius r in one view-space
// axis plane, as NDC coordinates along that axis (scale = the projection's focal term).
// Requires depth > r: the circle lies in front of the eye, so both tangents do too.
glm::vec2 tangentNdc(float u, float depth, float r, float scale) {
    float l2 = u * u + depth * depth;
    float l = std::sqrt(l2);
    float cosA = std::sqrt(std::max(l2 - r * r, 0.0f)) / l, sinA = r / l;
    glm::vec2 ndc;
    for (int s = 0; s < 2; ++s) {
        float sign = s == 0 ? -1.0f : 1.0f;
        // Rotate (u, depth) by +-alpha; the slope u'/depth' is what the projection keeps.
        float ut = u * cosA - sign * depth * sinA;
        float dt = sign * u * sinA + depth * cosA;
        ndc[s] = scale * ut / dt;
    }
    return {std::min(ndc[0], ndc[1]), std::max(ndc[0], ndc[1])}; // lower, upper
}

} // namespace

ScreenRect sphereScreenRect(const gpu::FrameUniforms& f, glm::vec3 center, float radius) {
    const float znear = f.projParams.x;
    glm::vec3 c = glm::vec3(f.view * glm::vec4(center, 1.0f));
    float depth = -c.z;                     // distance in front of the eye along the view axis
    if (depth + radius <= znear) return {}; // entirely behind the near plane
    if (depth - radius <= znear) return fullScreen(f); // crosses it (or holds the eye)
    // The projection here is symmetric (proj[2][0] = proj[2][1] = 0), so NDC = focal * slope.
    glm::vec2 x = tangentNdc(c.x, depth, radius, f.proj[0][0]);
    glm::vec2 y = tangentNdc(c.y, depth, radius, f.proj[1][1]);
    return toPixels(f, {x[0], y[0]}, {x[1], y[1]});
}

ScreenRect boxScreenRect(const gpu::FrameUniforms& f, const Aabb& box) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    int behind = 0;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                    (i & 4) ? box.max.z : box.min.z);
        glm::vec4 clip = f.viewProj * glm::vec4(p, 1.0f);
        // w = distance along the view axis; a corner at or behind the near plane cannot be
        // projected, so the box may cover anything.
        if (clip.w <= f.projParams.x) {
            ++behind;
            continue;
        }
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    if (behind == 8) {
        // All corners behind the near plane: the box is too (it is their convex hull).
        return {};
    }
    if (behind > 0) return fullScreen(f);
    return toPixels(f, lo, hi);
}

bool sphereTouchesBox(glm::vec3 center, float radius, const Aabb& box) {
    return gpu::mpSphereTouchesBox(center, radius, box.min, box.max); // the GPU's rule
}

namespace {

// Where a fragment's attributes are interpolated decides which point is shaded. At 1x that
// is the pixel centre, a covered sample, so the shaded position lies on the triangle and in
// the mesh's box. Under MSAA with per-sample shading, lavapipe interpolates inputs without
// the `sample` qualifier (scene_inputs.glsl, shared with the reference) at a point of the
// pixel that may lie outside the triangle: the position is then extrapolated along the
// triangle's plane, and for a plane seen edge-on that is arbitrarily far from the mesh (a
// cloth edge shaded 2 m past its box at 96x64; docs/multipass_forward.md). No world-space
// margin is conservative, but the extrapolated position still projects into the pixel being
// shaded, so the screen-space tests stay exact: under MSAA only those are used.
bool shadedInsideBox(const gpu::FrameUniforms& f) {
    return f.viewport.w <= 1;
}

struct VisibleDraw {
    const DrawItem* draw;
    ScreenRect rect;
    Aabb bounds;
};

// The draws of `filter` on screen, with their screen rectangles. Everything here is
// camera-relative, like the shading (docs/shading.md): world-space fp32 at 10^6 from the
// origin would be off by more than the rectangles' one-pixel margin.
std::vector<VisibleDraw> visibleDraws(const SceneGpu& scene, DrawFilter filter) {
    std::vector<VisibleDraw> out;
    for (const DrawItem* d : scene.drawList(filter)) {
        Aabb bounds = scene.toShading(d->bounds);
        ScreenRect r = boxScreenRect(scene.shadingFrame(), bounds);
        if (!r.empty()) out.push_back({d, r, bounds});
    }
    return out;
}

// A draw is lit by a light when their rectangles overlap and (where shading stays on the
// triangles, see shadedInsideBox) its box touches the sphere.
bool touches(const gpu::LightGpu& l, const ScreenRect& lightRect, const VisibleDraw& d,
             bool boxTest) {
    if (l.type == TP_LIGHT_DIRECTIONAL) return true;
    return lightRect.overlaps(d.rect) &&
           (!boxTest || sphereTouchesBox(l.position, l.range, d.bounds));
}

} // namespace

LightPlan planLights(const SceneGpu& scene, bool lightBlended, LightLists lists,
                     LightLists blendedLists) {
    LightPlan plan;
    plan.lists = lists;
    const gpu::FrameUniforms& f = scene.shadingFrame();
    auto opaque = visibleDraws(scene, DrawFilter::Opaque);
    auto masked = visibleDraws(scene, DrawFilter::Mask);
    auto blended = visibleDraws(scene, DrawFilter::Blend);
    for (const VisibleDraw& v : opaque)
        plan.opaque.push_back(v.draw);
    for (const VisibleDraw& v : masked)
        plan.masked.push_back(v.draw);
    for (const VisibleDraw& v : blended)
        plan.blended.push_back({v.draw, {}});

    const std::vector<gpu::LightGpu>& lights = scene.shadingLights();
    const bool boxTest = shadedInsideBox(f);
    for (uint32_t i = 0; i < scene.lightCount(); ++i) {
        const gpu::LightGpu& l = lights[i];
        if (l.type == TP_LIGHT_DIRECTIONAL &&
            plan.baseDirectional.size() < TP_MP_MAX_BASE_DIRECTIONAL) {
            plan.baseDirectional.push_back(i);
            continue;
        }
        ++plan.localLights;
        LightBatch batch{i,
                         l.type == TP_LIGHT_DIRECTIONAL ? fullScreen(f)
                                                        : sphereScreenRect(f, l.position, l.range),
                         {}};
        batch.slot = uint32_t(plan.localIndex.size());
        plan.localIndex.push_back(i);
        plan.localRect.push_back(batch.scissor);
        uint32_t meshes = 0, blendedMeshes = 0;
        if (!batch.scissor.empty()) {
            for (auto* list : {&opaque, &masked})
                for (const VisibleDraw& v : *list)
                    if (lists == LightLists::Cpu && touches(l, batch.scissor, v, boxTest))
                        batch.draws.push_back(v.draw);
            meshes = uint32_t(batch.draws.size());
            const bool blendedHere = lightBlended && blendedLists == LightLists::Cpu;
            for (size_t b = 0; blendedHere && b < blended.size(); ++b)
                if (touches(l, batch.scissor, blended[b], boxTest)) {
                    plan.blended[b].lights.push_back({i, batch.scissor});
                    ++blendedMeshes;
                }
            meshes += blendedMeshes;
        }
        plan.blendedMeshes.push_back(blendedMeshes);
        if (meshes == 0) ++plan.lightsSkipped;
        // Gpu: every light on screen gets its pass; the GPU's lists may leave it empty.
        if (!batch.draws.empty() || (lists == LightLists::Gpu && !batch.scissor.empty()))
            plan.batches.push_back(std::move(batch));
        plan.meshesPerLightSum += meshes;
        plan.meshesPerLightMax = std::max(plan.meshesPerLightMax, meshes);
    }
    return plan;
}

void mergeGpuMeshes(LightPlan& plan, const std::vector<uint32_t>& gpuMeshes,
                    const std::vector<uint32_t>& gpuBlended) {
    for (size_t s = 0; s < gpuBlended.size() && s < plan.blendedMeshes.size(); ++s)
        plan.blendedMeshes[s] = gpuBlended[s];
    plan.lightsSkipped = 0;
    plan.meshesPerLightMax = 0;
    plan.meshesPerLightSum = 0;
    for (size_t s = 0; s < plan.localIndex.size(); ++s) {
        const uint32_t meshes = (s < gpuMeshes.size() ? gpuMeshes[s] : 0) + plan.blendedMeshes[s];
        if (meshes == 0) ++plan.lightsSkipped;
        plan.meshesPerLightSum += meshes;
        plan.meshesPerLightMax = std::max(plan.meshesPerLightMax, meshes);
    }
}

} // namespace tp::mp
