// The compute rasterizer's constants (include/raster_triangle.glsl), shared by the visibility
// buffer's (visbuffer/vis_raster.h: --vis-raster) and the shadow maps' (shadow/shadow_raster.h:
// --shadow-raster) for C++ and GLSL.
#ifndef TP_RASTER_TRIANGLE_H
#define TP_RASTER_TRIANGLE_H

// Invocations of one listed (large) triangle's workgroup: one pixel of each 8 x 8 tile each.
#define TP_RT_BIG_GROUP 64
// A triangle whose pixel bounding box is wider or taller than this is not rasterized by its
// own invocation but listed for a workgroup of TP_RT_BIG_GROUP. The invocations of a subgroup
// walk as many pixels as the largest box among them (8 lanes on lavapipe, 32 on NVIDIA): 8
// keeps that at 64; measured on lavapipe, 16 made vis_raster 40 ms of a 96x64 courtyard-small
// frame, most of it lanes waiting for the largest box.
#define TP_RT_SMALL_PIXELS 8
// Vertices are snapped to this many fractional bits of a pixel before the edge functions, as
// VkPhysicalDeviceLimits::subPixelPrecisionBits says the device does (8 on lavapipe and
// NVIDIA); the specialization constant takes the device's value.
#define TP_RT_SUBPIXEL_BITS 8
// The guard band: polygons are clipped to [-G, size + G] pixels around the viewport in x and y
// (besides the near plane), so every snapped coordinate (viewport origin included: at most
// 16,384 + G pixels) stays below 2^23 fixed-point units and every edge function product below
// 2^47 (int64).
#define TP_RT_GUARD_PIXELS 8192.0f

// The specialization constants of the triangle itself (raster_triangle.glsl declares them; the
// C++ side sets both from the device: core/passes/raster_triangle_constants.h). Ids clear of
// both includers' own (the visibility buffer's 19-22, the shadow maps' 22-23).
#define TP_RT_SPEC_SUBPIXEL_BITS 21 // the device's subPixelPrecisionBits
// 1: a GPU's triangle setup: the depth plane through the snapped vertices (the H200 was 6,039
// ulps off with the unsnapped ones), the viewport transform as the spec writes it. 0: llvmpipe's:
// the plane through the unsnapped vertices, the viewport as x * (1 / w) and a fused multiply-add
#define TP_RT_SPEC_GPU_SETUP 30

// What becomes of a triangle (rasterTriage); the values are the visibility buffer's counter
// slots (TP_VR_COUNT_*).
#define TP_RT_SMALL 0u  // rasterized by its own invocation
#define TP_RT_LIST 1u   // listed: too large, or clipped by the near plane or the guard band
#define TP_RT_CULLED 2u // outside the view, zero area, single-sided back face, or no pixel

#endif
