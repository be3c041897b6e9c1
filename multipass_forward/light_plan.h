#pragma once
// CPU side of multipass forward: which draws each light pass issues, and its scissor.
// Built once per configuration (camera, lights and resolution are fixed per run), before
// anything is recorded. All tests are conservative: a light is never cut from a pixel it
// lights, because the light model is exactly zero at and beyond the light's range.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/gpuscene/scene_gpu.h"
#include "multipass_forward/mp_settings.h"
#include "multipass_forward/multipass_shared.h"

namespace tp::mp {

// A pixel rectangle [x0, x1) x [y0, y1), row 0 at the top (as the scissor and readback).
struct ScreenRect {
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool overlaps(const ScreenRect& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

// Screen-space bounds of a sphere: the exact tangent-plane rectangle when the sphere lies
// entirely in front of the near plane; the full screen when it crosses the near plane
// (which includes the camera inside it); empty when it lies entirely behind. Grown by one
// pixel for rounding, clipped to the screen (empty when off-screen).
ScreenRect sphereScreenRect(const gpu::FrameUniforms& frame, glm::vec3 center, float radius);
// Screen-space bounds of a box: its corners' projections, or the full screen when a corner
// is not in front of the near plane (empty when all are behind it).
ScreenRect boxScreenRect(const gpu::FrameUniforms& frame, const Aabb& box);
bool sphereTouchesBox(glm::vec3 center, float radius, const Aabb& box);

// One light's pass: its scissor and the opaque/masked draws it touches (with GPU lists,
// LightLists::Gpu: none here, the light-draws pass writes them), and its place among the local
// lights (the region of the light-draws pass it reads).
struct LightBatch {
    uint32_t light = 0;
    ScreenRect scissor;
    std::vector<const DrawItem*> draws;
    uint32_t slot = 0;
};

// A blended draw and the lights that touch it, in light order.
struct BlendedDraw {
    const DrawItem* draw = nullptr;
    std::vector<std::pair<uint32_t, ScreenRect>> lights;
};

// lists: who builds each light's opaque and masked draw list: the CPU here (Cpu), or the GPU's
// light-draws pass every frame (Gpu: the plan then holds every local light with a scissor on
// screen, whether or not it touches a draw, and only the blended draws' light lists).
struct LightPlan {
    LightLists lists = LightLists::Cpu;
    std::vector<uint32_t> baseDirectional;       // evaluated in the base pass
    std::vector<LightBatch> batches;             // light passes over opaque + masked draws
    // Every local light in light order (a slot each): its index and scissor (empty: off-screen).
    std::vector<uint32_t> localIndex;
    std::vector<ScreenRect> localRect;
    std::vector<uint32_t> blendedMeshes; // per slot: the blended draws it lights
    std::vector<BlendedDraw> blended;            // back to front, as the reference draws them
    std::vector<const DrawItem*> opaque, masked; // draws on screen (prepass and base pass)
    uint32_t localLights = 0;   // point/spot lights (and directional ones beyond the base's)
    // Of those: off-screen or touching no draw on screen. Gpu: counted with the blended draws
    // only (the renderer adds the GPU's counts after the frame: mergeGpuMeshes).
    uint32_t lightsSkipped = 0;
    uint32_t meshesPerLightMax = 0;
    uint64_t meshesPerLightSum = 0; // over every local light (skipped ones count 0)
};

// The counters over every local light, from each slot's opaque and masked draws counted by the
// GPU (LightLists::Gpu) and its blended ones: the plan's, or (non-empty `gpuBlended`) the GPU's.
void mergeGpuMeshes(LightPlan& plan, const std::vector<uint32_t>& gpuMeshes,
                    const std::vector<uint32_t>& gpuBlended = {});

// `lightBlended` false: blended draws get no light passes (they are lit in one pass, so no
// light counts them among its meshes). `blendedLists` Gpu: the blended draws' lights are the
// blended-light-draws pass's (blended_light_draw_pass.h): each BlendedDraw's `lights` and
// `blendedMeshes` stay empty and no light is tested against a blended draw here.
LightPlan planLights(const SceneGpu& scene, bool lightBlended = true,
                     LightLists lists = LightLists::Cpu, LightLists blendedLists = LightLists::Cpu);

} // namespace tp::mp
