#version 460
#extension GL_GOOGLE_include_directive : require
// The meshlet cull pass (core/passes/meshlet_cull.h): one workgroup per draw walks its
// meshlets TP_MC_GROUP at a time, drops those whose bounding sphere lies outside a plane of
// the view frustum or (single-sided materials only) whose normal cone faces away from the eye,
// and writes one VkDrawIndexedIndirectCommand per kept meshlet, compacted in meshlet order
// (a prefix sum over the group, so the order of the draws is the same every frame and on
// every device), then the draw count and the statistics. Camera-relative like every shader:
// the meshlets are world space and the eye is subtracted here, as scene.vert does.
#include "include/shared.h"
#include "include/meshlets.h"
#include "passes/meshlet_cull.h"
#include "include/scene_bindings.glsl"

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

shared uint scan[TP_MC_GROUP];
shared uint totals[3]; // frustum culled, cone culled, triangles kept

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
    if (lane < 3u) totals[lane] = 0u;
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
    uint frustumCulled = 0u, coneCulled = 0u, triangles = 0u;
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
            if (outside) {
                ++frustumCulled;
            } else if ((d.flags & TP_MC_FLAG_CONE) != 0u &&
                       meshletConeCulls(ml.coneApex - eye, ml.coneAxis, ml.coneCutoff,
                                        (length(ml.coneApex) + eyeMagnitude) *
                                            TP_MESHLET_POSITION_EPS)) {
                ++coneCulled;
            } else {
                keep = true;
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
    barrier();
    if (lane == 0u) {
        counts[slot] = kept;
        stats[slot] = MeshletCullStats(kept, totals[0], totals[1], totals[2]);
    }
}
