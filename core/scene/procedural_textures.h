#pragma once
// Textures of the built-in courtyard, generated in code from fixed-seed hash noise, so every
// build gives the same bytes. All tile seamlessly except the foliage cut-out.
#include <cstdint>
#include <vector>

#include "core/scene/scene.h"

namespace tp::procgen {

// Indices into Scene::textures.
struct CourtyardTextures {
    int32_t floorBase, floorMr, floorNormal; // stone slabs: sRGB, linear, linear
    int32_t brickBase, brickMr, brickNormal; // back and end walls
    int32_t stoneBase;                       // columns, arches, slabs (sRGB)
    int32_t clothRed, clothGreen, clothBlue; // cloth patterns (sRGB)
    int32_t grille;                          // iron lattice, alpha cut-out (sRGB + alpha)
    int32_t foliage;                         // leaves, alpha cut-out (sRGB + alpha)
};

// Appends the courtyard's textures to `textures` and returns where they went.
CourtyardTextures addCourtyardTextures(std::vector<Texture>& textures);

// Deterministic hash of integer coordinates to [0, 1).
float hash01(uint32_t x, uint32_t y, uint32_t seed);

} // namespace tp::procgen
