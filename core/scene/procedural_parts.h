#pragma once
// Internals of the courtyard (procedural.cpp): its dimensions, tessellation and the builders
// of the colonnades (procedural_colonnade.cpp). Not a public interface.
#include <cstdint>

#include "core/scene/scene.h"

namespace tp::procgen {

// Dimensions in metres. X across, Y up, Z along the courtyard.
constexpr float kHalfX = 15.0f;   // outer faces of the back walls
constexpr float kHalfZ = 30.0f;   // far sides of the rooms behind the end walls' doors
constexpr float kEndZ = 27.0f;    // inner faces of the end walls
constexpr float kHeight = 13.0f;  // top of the walls
constexpr float kWallT = 0.4f;    // wall thickness
constexpr float kColumnX = 11.0f; // |x| of the column lines
constexpr float kBay = 4.0f;      // column spacing
constexpr int kColumns = 14;      // per row, centred on z = 0
constexpr float kArcadeT = 0.6f;  // thickness of the arch walls
constexpr float kStoneTex = 2.0f; // metres per repeat of the stone texture
constexpr float kBrickTex = 1.2f;
constexpr float kFloorTex = 4.0f;

inline float columnZ(int i) {
    return (float(i) - float(kColumns - 1) * 0.5f) * kBay;
}

// One storey of the colonnade, heights absolute.
struct Storey {
    int index;    // 0 ground, 1 gallery
    float floorY; // where the plinths stand
    float plinthH, plinthHalf;
    float baseH, shaftH, capitalH;
    float abacusH, abacusHalf;
    float radius;  // shaft radius at the foot
    float wallTop; // top of the arch wall = underside of the slab above
    float slabTop;
    float springY() const { return floorY + plinthH + baseH + shaftH + capitalH + abacusH; }
};
Storey storey(int index);

// Segment and row counts for a detail level; they scale with detail^0.75 above small minimums,
// so the triangle count goes roughly with detail^1.5 (1.0 → ~250k, 0.08 → a few thousand).
struct Tessellation {
    int columnSegments, shaftRows, baseRows, capitalRows;
    int archSegments; // multiple of 4
    int rimRows;      // 0: no moulding around the arches
    int balusterSegments, balusterRows, balustersPerBay;
    int clothU, clothV;
    int floorX, floorZ;
    int potSegments, potRows, rodSegments;
};
Tessellation tessellation(float detail);

struct CourtyardMaterials {
    uint32_t floor, brick, stone, cloth[3], lamp, grille, foliage, terracotta, iron;
};

// Columns, arches, slab, lamps, balustrade and cloth of one side (+1 or -1 in x) and storey.
void addColonnade(Scene& scene, const Tessellation& t, const CourtyardMaterials& m, float side,
                  int storeyIndex);

} // namespace tp::procgen
