#ifndef TP_LIGHTS_UBO_H
#define TP_LIGHTS_UBO_H
// The scene's lights again as a uniform buffer (core/passes/lights_ubo.h, read through
// include/lights_ubo.glsl), for shading loops on a CPU device. On lavapipe (Mesa 22.3) a
// storage-buffer load is a loop over the 8 lanes with a branch per lane and per component,
// whether or not the lanes share the address; a uniform-buffer load is a gather without
// branches, and one scalar load where the index is uniform (a tile's shared list). The bytes
// are the same, so the sums are too.
// Slots: 1,024 lights of 64 bytes fill the 64 KiB every Vulkan device allows a uniform
// buffer range; a scene with more reads the storage buffer.
#define TP_LIGHTS_UBO_CAPACITY 1024
#endif
