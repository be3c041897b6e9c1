#version 460
#extension GL_GOOGLE_include_directive : require
// The compute rasterizer's first pass (pass "vis_raster", visbuffer/raster_pass.h): one
// invocation per triangle of the opaque (and, in compute mode, masked) draws, or of the
// meshlets meshlet_cull kept (TP_VR_MESHLETS). A triangle whose pixel bounds fit in
// TP_VR_SMALL_PIXELS each way is rasterized here by its own invocation (vis_raster.glsl);
// a larger one, or one the near plane or the guard band cuts, is listed: for vis_raster_big
// (compute: its dispatch's group count) or for the hardware (hybrid: staged per chunk, in
// order, for vis_raster_order to pack).
#include "visbuffer/vis_raster.glsl"

layout(local_size_x = TP_VR_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_LIST) buffer ListBlock {
    uint list[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_ARGS) buffer ArgsBlock {
    uint args[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_INDICES) readonly buffer IndexBlock {
    uint rasterIndices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_CHUNKS) readonly buffer ChunkBlock {
    RasterChunk chunks[];
};
#ifdef TP_VR_MESHLETS
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_SOURCE_TRIANGLES) readonly buffer
    SourceBlock {
    uint sourceTriangles[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_COMMANDS) readonly buffer CommandBlock {
    uint commands[]; // VkDrawIndexedIndirectCommand, 5 words each
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_COUNTS) readonly buffer CountBlock {
    uint counts[];
};
#endif

shared uint sCounts[TP_VR_COUNTERS];
shared uint sAtomics;
shared uint sListed[TP_VR_GROUP / 32]; // hybrid: a bit per lane whose triangle is listed

// Where this invocation's triangle is: its first index, the vertex offset and its triangle in
// its draw (the id's). False: no triangle (past the chunk, or a meshlet the cull dropped).
bool findTriangle(RasterChunk c, uint lane, out uint base, out int vertexOffset, out uint triangle) {
#ifdef TP_VR_MESHLETS
    if (c.count >= counts[c.firstIndex]) return false; // the cull kept fewer meshlets
    uint cmd = 5u * c.firstTriangle;
    if (lane >= commands[cmd] / 3u) return false;
    base = commands[cmd + 2u] + 3u * lane;
    vertexOffset = int(commands[cmd + 3u]);
    triangle = sourceTriangles[commands[cmd + 4u] + lane];
#else
    if (lane >= c.count) return false;
    triangle = c.firstTriangle + lane;
    base = c.firstIndex + 3u * triangle;
    vertexOffset = c.vertexOffset;
#endif
    return true;
}

// Whether a triangle the rasterizer must clip faces the viewer (or the draw is double-sided):
// from the camera-relative vertices, which stay meaningful behind the eye (vis_read.glsl's
// front-facing test), so a back face is not listed for the hardware to draw.
bool clippedFacesViewer(uint i0, uint i1, uint i2, bool doubleSided) {
    if (doubleSided) return true;
    vec3 p0 = vertices[i0].positionU.xyz - frame.eyeWorld.xyz;
    vec3 p1 = vertices[i1].positionU.xyz - frame.eyeWorld.xyz;
    vec3 p2 = vertices[i2].positionU.xyz - frame.eyeWorld.xyz;
    return dot(cross(p1 - p0, p2 - p0), p0) < 0.0;
}

void writeSlot(uint at, uint i0, uint i1, uint i2, uint id) {
    list[at] = i0;
    list[at + 1u] = i1;
    list[at + 2u] = i2;
    list[at + 3u] = id;
}

// Compute mode: appends the triangle to the list, one more for vis_raster_big, whose groups
// (at most the 65,535 a dispatch may have) stride over the list; their order does not matter
// there (every sample takes the atomic max). Hybrid mode stages it in main instead.
void listTriangle(uint i0, uint i1, uint i2, uint id) {
    uint slot = atomicAdd(list[TP_VR_LIST_SLOTS], 1u);
    atomicMax(args[0], min(slot + 1u, 65535u));
    writeSlot(TP_VR_LIST_HEADER + 4u * slot, i0, i1, i2, id);
}

// One triangle: TP_VR_COUNT_SMALL, _BIG or _CULLED (include/raster_triangle.glsl's triage);
// `atomics`: the 64-bit atomics it issued. Only an unclipped triangle within
// TP_VR_SMALL_PIXELS each way is rasterized here; one the near plane or the guard band cuts is
// listed (compute: vis_raster_big clips it; hybrid: the hardware), as is a larger one.
uint triangleOutcome(uint i0, uint i1, uint i2, uint id, out bool clipped, out uint atomics) {
    atomics = 0u;
    bool doubleSided = (rowOf(id).flags & TP_VR_FLAG_DOUBLE_SIDED) != 0u;
    RasterVertex v0, v1, v2;
    uint triage = rasterTriage(clipPosition(i0), clipPosition(i1), clipPosition(i2), doubleSided,
                               clipped, v0, v1, v2);
    if (triage == TP_RT_CULLED) return TP_VR_COUNT_CULLED;
    if (triage == TP_RT_LIST) {
        if (clipped && !clippedFacesViewer(i0, i1, i2, doubleSided)) return TP_VR_COUNT_CULLED;
        if (kHybrid == 0u) listTriangle(i0, i1, i2, id);
        return TP_VR_COUNT_BIG;
    }
    bool drew;
    atomics = rasterTriangle(v0, v1, v2, i0, i1, i2, id, false, 0u, drew);
    return drew ? TP_VR_COUNT_SMALL : TP_VR_COUNT_CULLED;
}

// Hybrid: the chunk's listed triangles into its slots in lane order (a lane's place: the
// listed lanes below it) and its count, so the staged list is the same whatever order the
// workgroups ran in (vis_raster.h).
void stage(uint chunk, uint lane, bool staged, uint i0, uint i1, uint i2, uint id) {
    uint below = 0u, all = 0u;
    for (uint w = 0u; w < TP_VR_GROUP / 32u; ++w) {
        const uint bits = sListed[w];
        if (w < (lane >> 5u)) below += bitCount(bits);
        all += bitCount(bits);
    }
    below += bitCount(sListed[lane >> 5u] & ((1u << (lane & 31u)) - 1u));
    if (staged)
        writeSlot(TP_VR_LIST_HEADER + chunks.length() + 4u * (chunk * TP_VR_GROUP + below), i0, i1, i2, id);
    if (lane == 0u) list[TP_VR_LIST_HEADER + chunk] = all;
}

void main() {
    uint lane = gl_LocalInvocationIndex;
    if (lane < TP_VR_COUNTERS) sCounts[lane] = 0u;
    if (lane == 0u) sAtomics = 0u;
    if (lane < TP_VR_GROUP / 32u) sListed[lane] = 0u;
    barrier();
    uint chunk = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
    uint base, triangle, i0, i1, i2, id;
    int vertexOffset;
    bool staged = false;
    if (chunk < chunks.length() && findTriangle(chunks[chunk], lane, base, vertexOffset, triangle)) {
        RasterChunk c = chunks[chunk];
        id = ((c.row + 1u) << kTriangleBits) | triangle;
        i0 = uint(int(rasterIndices[base]) + vertexOffset);
        i1 = uint(int(rasterIndices[base + 1u]) + vertexOffset);
        i2 = uint(int(rasterIndices[base + 2u]) + vertexOffset);
        bool clipped;
        uint atomics;
        const uint outcome = triangleOutcome(i0, i1, i2, id, clipped, atomics);
        atomicAdd(sCounts[outcome], 1u);
        if (clipped) atomicAdd(sCounts[TP_VR_COUNT_CLIPPED], 1u);
        if (atomics != 0u) atomicAdd(sAtomics, atomics);
        staged = kHybrid != 0u && outcome == TP_VR_COUNT_BIG;
        if (staged) atomicOr(sListed[lane >> 5u], 1u << (lane & 31u));
    }
    barrier();
    if (kHybrid != 0u && chunk < chunks.length()) stage(chunk, lane, staged, i0, i1, i2, id);
    if (lane < TP_VR_COUNTERS && sCounts[lane] != 0u) atomicAdd(list[lane], sCounts[lane]);
    if (lane == 0u && sAtomics != 0u) atomicAdd(list[TP_VR_ATOMICS_SMALL], sAtomics);
}
