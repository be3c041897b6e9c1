#pragma once
// How many blended fragments the blended_ids pass can append at most, computed on the CPU
// from the blended triangles as the camera sees them: the size of the fragment pool that can
// never drop one (--vis-blended-capacity 0, the default). Each sample lattice (one per MSAA
// sample: a device may run the pass once per sample) holds at most, per triangle, as many
// points as the triangle dilated by a pixel-sized square has area, since the squares centred
// on its points are disjoint and lie inside it: area + (|dx| + |dy| summed over the edges) / 2
// + 1 pixels (of its part on the screen), and never more than the points of its bounding box
// there. Depth tests
// and back faces are not counted out, so it is an upper bound.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "visbuffer/draw_table.h"

namespace tp::vis {

// Pixel centres (x + 0.5, y + 0.5), 0 <= x < width, 0 <= y < height, triangle a, b, c (in
// pixels) can contain at most.
double triangleCentreBound(glm::vec2 a, glm::vec2 b, glm::vec2 c, uint32_t width,
                           uint32_t height);

// The blended draws' triangles through the scene's shading camera, times the samples, each
// triangle clipped to w >= znear / 2 (the rasterizer keeps only w >= znear, so this holds every
// fragment it makes) and a draw whose box lies outside the view frustum counted out; each
// vertex projected once, no allocation per triangle. It once counted a triangle reaching behind
// the eye as the whole screen: at a view beside the courtyard's cloth (1920x1080) that was
// more than one storage buffer, so a single view planned 536 million nodes (4.2 GB on an H200)
// for 124,859 fragments; clipped, the same view's bound is 258,606 nodes. Single views and many
// views (RenderSettings::manyViews, where the pool is sized from need: blended_ids_pass.cpp)
// take this bound alike.
uint64_t viewFragmentBound(const SceneGpu& scene, const std::vector<TableDraw>& blended,
                           uint32_t width, uint32_t height, uint32_t samples);

} // namespace tp::vis
