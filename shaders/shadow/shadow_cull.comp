#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow faces' meshlet cull (core/passes/shadow_cull.h): one workgroup per (face, draw)
// row walks the draw's meshlets TP_SC_GROUP at a time, drops those whose bounding sphere lies
// outside a plane of the face's clip volume (no fragment inside the face's square of the map)
// or farther from the light than its range allows a shadow to matter (TP_SC_RANGE_FOOTPRINTS),
// and writes one VkDrawIndexedIndirectCommand per kept meshlet, compacted in meshlet order,
// then the row's count and statistics. No normal cone: the maps render both faces of every
// triangle (VK_CULL_MODE_NONE). Light-relative, as shadow.vert computes its positions: the
// world-space sphere minus the eye minus the camera-relative light.
#include "include/shared.h"
#include "include/meshlets.h"
#include "include/shadows.h"
#include "shadow/shadow_cull.h"
#include "include/scene_bindings.glsl"

layout(local_size_x = TP_SC_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_MESHLETS) readonly buffer MeshletBlock {
    MeshletGpu meshlets[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_ROWS) readonly buffer RowBlock {
    ShadowCullRow rows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_FACES) readonly buffer FaceBlock {
    ShadowFace faces[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_COMMANDS) writeonly buffer CommandBlock {
    uint commands[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_COUNTS) writeonly buffer CountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SC_BINDING_STATS) writeonly buffer StatsBlock {
    ShadowCullStats stats[];
};

shared uint scan[TP_SC_GROUP];
shared uint totals[3]; // frustum culled, range culled, triangles kept

vec4 matrixRow(mat4 m, int i) {
    return vec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

void main() {
    // A 2D grid of groups (core/passes/shadow_cull.cpp): more rows than 65,535. The whole group
    // returns: no barrier is skipped by part of it.
    const uint slot = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (slot >= uint(rows.length())) return;
    const uint lane = gl_LocalInvocationID.x;
    const ShadowCullRow row = rows[slot];
    if (lane < 3u) totals[lane] = 0u;
    barrier();

    const ShadowFace f = faces[row.face];
    const LightGpu light = lights[f.atlas.w]; // camera-relative, as shadow.vert subtracts it
    // The face's clip volume (Gribb-Hartmann), reverse-Z with an infinite far plane: -w <= x, y
    // <= w, 0 <= z <= w; z is the constant near, so z >= 0 never culls and z <= w is the near
    // plane (as clip.w < params.y in ShadowMaps::cullFaces).
    const mat4 m = f.lightProj;
    const vec4 r0 = matrixRow(m, 0), r1 = matrixRow(m, 1), r2 = matrixRow(m, 2),
               r3 = matrixRow(m, 3);
    vec4 planes[6] = vec4[6](r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 - r2, r2);
    const vec3 eye = frame.eyeWorld.xyz;
    const float offsetMagnitude = length(eye) + length(light.position);
    const float reach = light.range * (1.0 + TP_SC_RANGE_FOOTPRINTS * f.params.x);

    uint kept = 0u;
    uint frustumCulled = 0u, rangeCulled = 0u, triangles = 0u;
    for (uint start = 0u; start < row.meshletCount; start += TP_SC_GROUP) {
        const uint k = start + lane;
        bool keep = false;
        MeshletGpu ml;
        if (k < row.meshletCount) {
            ml = meshlets[row.firstMeshlet + k];
            // The sphere grows by the error of the two subtractions (include/meshlets.h).
            const float slack =
                (length(ml.center) + offsetMagnitude + ml.radius) * TP_MESHLET_POSITION_EPS;
            const vec3 centre = (ml.center - eye) - light.position;
            const float radius = ml.radius + slack;
            bool outside = false;
            for (int p = 0; p < 6; ++p)
                outside = outside || meshletOutsidePlane(planes[p], centre, radius);
            const bool far = !outside && length(centre) - radius > reach;
            keep = !outside && !far;
            if (outside) {
                ++frustumCulled;
            } else if (far) {
                ++rangeCulled;
            } else {
                triangles += ml.triangleCount;
            }
        }
        // Inclusive prefix sum of `keep` over the group: each kept meshlet's place among this
        // round's, so the commands stay in meshlet order.
        scan[lane] = keep ? 1u : 0u;
        barrier();
        for (uint offset = 1u; offset < TP_SC_GROUP; offset <<= 1u) {
            const uint add = lane >= offset ? scan[lane - offset] : 0u;
            barrier();
            scan[lane] += add;
            barrier();
        }
        if (keep) {
            const uint c = (row.firstCommand + kept + scan[lane] - 1u) * TP_SC_COMMAND_WORDS;
            commands[c + 0u] = ml.triangleCount * 3u; // indexCount
            commands[c + 1u] = 1u;                    // instanceCount
            commands[c + 2u] = ml.firstIndex;         // firstIndex
            commands[c + 3u] = uint(row.vertexOffset); // vertexOffset (int, as bits)
            commands[c + 4u] = 0u;                    // firstInstance
        }
        kept += scan[TP_SC_GROUP - 1u];
        barrier(); // every lane has read scan[] before the next round writes it
    }
    atomicAdd(totals[0], frustumCulled);
    atomicAdd(totals[1], rangeCulled);
    atomicAdd(totals[2], triangles);
    barrier();
    if (lane == 0u) {
        counts[slot] = kept;
        stats[slot] = ShadowCullStats(kept, totals[0], totals[1], totals[2]);
    }
}
