#ifndef TP_MATERIALS_UBO_H
#define TP_MATERIALS_UBO_H
// The scene's materials again as a uniform buffer (core/passes/materials_ubo.h, read through
// include/materials_ubo.glsl), for fragment passes on a CPU device: lavapipe (Mesa 22.3) loads
// each component of a storage buffer in a loop over the 8 lanes with a branch per lane, so the
// draw's 80-byte material cost about a quarter of Forward+'s 0-light shading pass
// (docs/efficiency.md, "The material floor on lavapipe"); from a uniform buffer at an index the
// whole draw shares it is one scalar load per component. Same bytes (std140 and std430 lay
// MaterialGpu out alike), same material. 512 materials of 80 bytes: 40 KiB, within the 64 KiB
// a uniform range is guaranteed.
#define TP_MATERIALS_UBO_CAPACITY 512
#endif
