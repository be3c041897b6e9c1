#version 460
#extension GL_GOOGLE_include_directive : require
// The meshlet cull pass (core/passes/meshlet_cull.h): one workgroup per draw walks its
// meshlets TP_MC_GROUP at a time, drops those whose bounding sphere lies outside a plane of
// the view frustum or (single-sided materials only) whose normal cone faces away from the eye,
// and writes one VkDrawIndexedIndirectCommand per kept meshlet, compacted in meshlet order
// (a prefix sum over the group, so the order of the draws is the same every frame and on
// every device), then the draw count and the statistics. Camera-relative like every shader:
// the meshlets are world space and the eye is subtracted here, as scene.vert does.
// --cull-geometry full compiles it twice more (TP_MC_PHASE, passes/meshlet_cull.h): the early
// phase keeps only what passes those tests and was visible last frame (its history word); the
// late phase tests every meshlet again, then its sphere against the depth pyramid the early
// phase's draws built, writes each meshlet's visibility for the next frame and draws the
// visible ones the early phase did not.
#include "include/shared.h"
#include "include/meshlets.h"
#include "passes/meshlet_cull.h"
#include "passes/depth_pyramid.h"
#include "include/scene_bindings.glsl"

#ifndef TP_MC_PHASE
#define TP_MC_PHASE TP_MC_PHASE_FRUSTUM
#endif

layout(local_size_x = TP_MC_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_MESHLETS) readonly buffer MeshletBlock {
    MeshletGpu meshlets[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_DRAWS) readonly buffer CullDrawBlock {
    CullDraw cullDraws[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_COMMANDS) writeonly buffer CommandBlock {
    uint commands[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_COUNTS) writeonly buffer CountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_STATS) writeonly buffer StatsBlock {
    MeshletCullStats stats[];
};

#if TP_MC_PHASE != TP_MC_PHASE_FRUSTUM
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_HISTORY) buffer HistoryBlock {
    uint history[];
};
#endif
#if TP_MC_PHASE == TP_MC_PHASE_LATE
layout(std430, set = TP_SET_PASS, binding = TP_MC_BINDING_PYRAMID) readonly buffer PyramidBlock {
    float pyramid[];
};

// Whether every point of the sphere (camera-relative centre) lies behind the farthest depth
// of the pixels it can cover: its nearest depth against the pyramid's smallest over the texels
// of the first level where its rectangle spans at most 2x2 of them (each texel covers exactly
// its pixels: passes/depth_pyramid.h). Margins on all three measures (include/meshlets.h); a
// sphere that reaches the near plane, or anything not a number, is never occluded.
bool occluded(vec3 centre, float radius) {
    const vec3 v = (frame.view * vec4(centre, 0.0)).xyz;
    const float r = radius + length(centre) * TP_MESHLET_ROTATION_EPS;
    const float depth = sphereNearestDepth(v, r, frame.proj, frame.projParams.x);
    if (!(depth > 0.0)) return false;
    const uvec2 size = frame.viewport.xy;
    const vec4 rect = sphereScreenRect(v, r, frame.proj, vec2(size));
    if (any(isnan(rect))) return false;
    // Pixels x0..x1, y0..y1, clipped to the frame (a rectangle wholly off the frame has no
    // fragment to lose: testing its nearest edge pixels is still safe).
    const vec2 last = vec2(size) - 1.0;
    const uvec2 lo = uvec2(clamp(rect.xy, vec2(0.0), last));
    const uvec2 hi = uvec2(clamp(rect.zw, vec2(0.0), last));
    const uint levels = pyramidLevels(size.x, size.y);
    uint level = 0u;
    while (level + 1u < levels && (((hi.x >> (level + 1u)) - (lo.x >> (level + 1u))) > 1u ||
                                   ((hi.y >> (level + 1u)) - (lo.y >> (level + 1u))) > 1u))
        ++level;
    const uvec2 t0 = lo >> (level + 1u), t1 = hi >> (level + 1u);
    const uint width = pyramidLevelSize(size.x, size.y, level).x;
    const uint base = pyramidLevelOffset(size.x, size.y, level);
    const float farthest = min(min(pyramid[base + t0.y * width + t0.x], pyramid[base + t0.y * width + t1.x]),
                               min(pyramid[base + t1.y * width + t0.x], pyramid[base + t1.y * width + t1.x]));
    return depth < farthest;
}
#endif

shared uint scan[TP_MC_GROUP];
shared uint totals[4]; // frustum culled, cone culled, triangles kept, occlusion culled

vec4 matrixRow(mat4 m, int i) {
    return vec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

void main() {
    // A 2D grid of groups (core/passes/meshlet_cull.cpp): more draws than 65,535.
    const uint slot = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    // The table holds exactly the draws (no push constant: see meshlet_cull.cpp's record). The
    // whole group returns: no barrier is skipped by part of it.
    if (slot >= uint(cullDraws.length())) return;
    const uint lane = gl_LocalInvocationID.x;
    const CullDraw d = cullDraws[slot];
    if (lane < 4u) totals[lane] = 0u;
    barrier();

    // The clip volume's planes in camera-relative space (Gribb-Hartmann), reverse-Z:
    // -w <= x, y <= w and 0 <= z <= w. With an infinite far plane (zfar 0) z = znear is
    // constant and its plane never culls.
    const mat4 m = frame.viewProj;
    const vec4 r0 = matrixRow(m, 0), r1 = matrixRow(m, 1), r2 = matrixRow(m, 2),
               r3 = matrixRow(m, 3);
    vec4 planes[6] = vec4[6](r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 - r2, r2);
    const vec3 eye = frame.eyeWorld.xyz;
    const float eyeMagnitude = length(eye);

    uint kept = 0u;
    uint frustumCulled = 0u, coneCulled = 0u, triangles = 0u, occlusionCulled = 0u;
    for (uint start = 0u; start < d.meshletCount; start += TP_MC_GROUP) {
        const uint k = start + lane;
        bool keep = false;
        MeshletGpu ml;
        if (k < d.meshletCount) {
            ml = meshlets[d.firstMeshlet + k];
            // Spheres grow, cones narrow, by the error of the subtraction and of the plane's
            // dot product (include/meshlets.h).
            const float slack =
                (length(ml.center) + eyeMagnitude + ml.radius) * TP_MESHLET_POSITION_EPS;
            const vec3 centre = ml.center - eye;
            bool outside = false;
            for (int p = 0; p < 6; ++p)
                outside = outside || meshletOutsidePlane(planes[p], centre, ml.radius + slack);
            bool cone = !outside && (d.flags & TP_MC_FLAG_CONE) != 0u &&
                              meshletConeCulls(ml.coneApex - eye, ml.coneAxis, ml.coneCutoff,
                                               (length(ml.coneApex) + eyeMagnitude) *
                                                   TP_MESHLET_POSITION_EPS);
            const bool passes = !outside && !cone;
#if TP_MC_PHASE == TP_MC_PHASE_FRUSTUM
            keep = passes;
#elif TP_MC_PHASE == TP_MC_PHASE_EARLY
            // Last frame's visible set, as it passes this frame's frustum and cone. The late
            // phase counts what either test culls.
            const uint h = history[d.firstCommand + k];
            keep = passes && (h & TP_MC_HISTORY_VISIBLE) != 0u;
            if (keep) history[d.firstCommand + k] = h | TP_MC_HISTORY_DRAWN_EARLY;
            outside = cone = false;
#else
            const bool early = (history[d.firstCommand + k] & TP_MC_HISTORY_DRAWN_EARLY) != 0u;
            // Drawn early or not, a meshlet's visibility is tested again: what the early phase
            // drew and is now hidden is left to the next frame's late phase.
            const bool visible = passes && !occluded(centre, ml.radius + slack);
            history[d.firstCommand + k] = visible ? TP_MC_HISTORY_VISIBLE : 0u;
            keep = visible && !early;
            if (!early && passes && !visible) ++occlusionCulled;
            if (early) outside = cone = false; // counted by the early phase, as drawn
#endif
            if (outside) {
                ++frustumCulled;
            } else if (cone) {
                ++coneCulled;
            } else if (keep) {
                triangles += ml.triangleCount;
            }
        }
        // Inclusive prefix sum of `keep` over the group (Hillis-Steele): each kept meshlet's
        // place among this round's, so the commands stay in meshlet order.
        scan[lane] = keep ? 1u : 0u;
        barrier();
        for (uint offset = 1u; offset < TP_MC_GROUP; offset <<= 1u) {
            const uint add = lane >= offset ? scan[lane - offset] : 0u;
            barrier();
            scan[lane] += add;
            barrier();
        }
        if (keep) {
            const uint c = (d.firstCommand + kept + scan[lane] - 1u) * TP_MC_COMMAND_WORDS;
            commands[c + 0u] = ml.triangleCount * 3u; // indexCount
            commands[c + 1u] = 1u;                    // instanceCount
            commands[c + 2u] = ml.firstIndex;         // firstIndex
            commands[c + 3u] = uint(d.vertexOffset);  // vertexOffset (int, as bits)
            commands[c + 4u] = (d.flags & TP_MC_FLAG_FIRST_TRIANGLE) != 0u // firstInstance
                                   ? ml.firstIndex / 3u
                                   : 0u;
        }
        kept += scan[TP_MC_GROUP - 1u];
        barrier(); // every lane has read scan[] before the next round writes it
    }
    atomicAdd(totals[0], frustumCulled);
    atomicAdd(totals[1], coneCulled);
    atomicAdd(totals[2], triangles);
    atomicAdd(totals[3], occlusionCulled);
    barrier();
    if (lane == 0u) {
        counts[slot] = kept;
        stats[slot] = MeshletCullStats(kept, totals[0], totals[1], totals[2], totals[3], 0u, 0u, 0u);
    }
}
