#pragma once
// Which pixels of an MSAA image hold more than one triangle (deferred_test.cpp, pixel-rate
// shading): a CPU rasterization, in double, of which triangle is in front at each standard
// sample location (opaque and masked surfaces: those that write depth). No back-face culling:
// a scene with open single-sided meshes seen from behind would need it.
#include <cstdint>
#include <vector>

#include "core/scene/scene.h"

namespace tp::test {

struct TrianglePixels {
    std::vector<uint8_t> manyTriangles; // 1: the samples' front triangles differ, or a sample
                                        // is within `margin` pixels of its triangle's edge
};

// `margin`: how far a device may move a triangle's edge, in pixels (2^-subPixelPrecisionBits:
// vertex snapping), so that a sample that close may be covered by the neighbouring triangle.
TrianglePixels findManyTrianglePixels(const Scene& scene, uint32_t width, uint32_t height,
                                      uint32_t samples, double margin);

} // namespace tp::test
