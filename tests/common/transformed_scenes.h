#pragma once
// A generated glTF scene whose meshes reach world space only through node transforms:
// negative and non-uniform scales, rotations, translations, a mirrored parent over mirrored
// children, meshes that sit off their node's origin, two meshes instanced twice at one
// transform (coincident surfaces). Every conservative test that takes a box
// or a sphere through a transform (multipass's per-light draw selection, light culling and
// binning, blended bounds) is checked on it (tests/gpu/light_plan_test.cpp).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/scene/scene.h"

namespace tp::test {

// Writes `dir`/scene.gltf (+ scene.bin): `nodes` quad grids and boxes under transformed
// nodes, all from `seed`. Single-sided, untextured; opaque, or with `blended` every third mesh
// blended (alpha 0.5: the blended bounds and transparent lists take the same transforms).
std::filesystem::path writeTransformedNodesScene(const std::filesystem::path& dir, uint32_t seed,
                                                 uint32_t nodes = 13, bool blended = false);

// `count` point lights that touch the scene's surfaces barely: each sphere's centre sits at a
// small distance off a surface point near a triangle's corner or edge (where a mesh's box and
// its triangles part most), with a range a hair longer than that distance.
std::vector<Light> lightsGrazingSurfaces(const Scene& scene, uint32_t count, uint32_t seed);

} // namespace tp::test
