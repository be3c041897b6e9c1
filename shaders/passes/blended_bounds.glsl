// Records a blended fragment's view distance into its tile's [min, max] (light_assign.h:
// TP_LA_BLEND_*): the body of the blended depth bounds (blended_bounds.frag), shared with the
// visibility buffer's blended fragment lists (visbuffer/blended_ids.frag), which draw the same
// fragments and record the bounds in the same pass instead of a second draw of them.
// Include after scene_bindings.glsl, scene_inputs.glsl and light_assign.glsl.
layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(std430, set = TP_SET_PASS, binding = TP_LA_BLEND_BINDING_BOUNDS) buffer Bounds {
    uint bounds[]; // [0, tiles): min distance bits; [tiles, 2 tiles): max
};

// kBySubgroup: one atomic pair per tile the subgroup meets, its lanes' min and max, recorded by
// a lane that is not a helper (helpers are left out of the reduction: their distances are
// extrapolated, blended_bounds.frag). The includer enables the subgroup basic, ballot and
// arithmetic extensions. Off on a CPU device: lavapipe (Mesa 22.3) cannot compile
// gl_HelperInvocation ("Unsupported intrinsic: is_helper_invocation", then a crash), and with
// the constant off the branch is gone before it looks.
layout(constant_id = TP_LA_SPEC_BLEND_BY_SUBGROUP) const bool kBySubgroup = false;

void recordBlendedBound() {
    // The shading's position (scene_inputs.glsl: evalFragmentMaterial) and distance
    // (the clustered lookups' expression).
    vec3 position = TP_INPUT(inPosition) * (1.0 / TP_INPUT(inOne));
    float dist = max(-(frame.view * vec4(position, 1.0)).z, 0.0);
    uvec2 tiles = uvec2(laTileCount1D(frame.viewport.x, kTileSize), laTileCount1D(frame.viewport.y, kTileSize));
    uint tile = laTileIndex(uvec2(gl_FragCoord.xy), kTileSize, tiles);
    uint tileCount = tiles.x * tiles.y;
    uint bits = floatBitsToUint(dist); // non-negative: orders like the value
    if (kBySubgroup) {
        if (gl_HelperInvocation) return;
        // Each pass takes the tile of the first lane left: its lanes reduce and one records.
        for (;;) {
            const uint first = subgroupBroadcastFirst(tile);
            if (first == tile) {
                const uint lo = subgroupMin(bits), hi = subgroupMax(bits);
                if (subgroupElect()) {
                    atomicMin(bounds[tile], lo);
                    atomicMax(bounds[tileCount + tile], hi);
                }
                break;
            }
        }
        return;
    }
    atomicMin(bounds[tile], bits);
    atomicMax(bounds[tileCount + tile], bits);
}
