#pragma once
// Helpers for building procedural meshes: a vertex/index accumulator that derives tangents
// from the uvs when it finishes, and a few primitives (parametric surfaces, boxes, lathes,
// walls with rectangular openings). Front faces are counter-clockwise seen from the side the
// normal points to, as in glTF.
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "core/scene/scene.h"

namespace tp::procgen {

class MeshBuilder {
  public:
    MeshBuilder(std::string name, uint32_t material);

    uint32_t vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv);
    void triangle(uint32_t a, uint32_t b, uint32_t c);
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d); // a b c d counter-clockwise
    size_t triangleCount() const { return mesh_.indices.size() / 3; }
    bool empty() const { return mesh_.indices.empty(); }

    // Fills tangents (glTF convention: bitangent = cross(normal, tangent.xyz) * w points
    // toward decreasing v, i.e. "up" in the image) and colours (all 1), and hands the mesh over.
    Mesh finish();

  private:
    Mesh mesh_;
};

// A parametric surface sampled on an (nu+1) x (nv+1) grid over [0,1]^2. Normals come from
// cross(dP/du, dP/dv) by central differences, so the front face is the side that cross product
// points to; `position` must be smooth slightly outside [0,1].
using SurfaceFn = std::function<glm::vec3(float u, float v)>;
using UvFn = std::function<glm::vec2(float u, float v)>;
// `flip` reverses the winding and the normals.
void addSurface(MeshBuilder& b, int nu, int nv, const SurfaceFn& position, const UvFn& uv,
                bool flip = false);

// Axis-aligned box; uvs are the world coordinates of each face divided by `texSize` (metres
// per texture repeat), with v running down the world's y axis on vertical faces.
// Faces whose bit is set in `skipFaces` are left out (bits: -x, +x, -y, +y, -z, +z).
// `inside` turns the faces inwards: a room seen from within.
void addBox(MeshBuilder& b, const glm::vec3& min, const glm::vec3& max, float texSize,
            uint32_t skipFaces = 0, bool inside = false);
constexpr uint32_t kSkipBottom = 1u << 2;
constexpr uint32_t kSkipTop = 1u << 3;
constexpr uint32_t kSkipMinusZ = 1u << 4;
constexpr uint32_t kSkipPlusZ = 1u << 5;

// A surface of revolution around the vertical axis through `base`: profile points are
// (radius, height above base), from bottom to top, all radii > 0. `segments` around and
// `rows` along the profile, sampled evenly in the profile's point index (so fewer rows than
// profile segments coarsen the shape).
void addLathe(MeshBuilder& b, const glm::vec3& base, std::span<const glm::vec2> profile,
              int segments, int rows, float texSize);

// A flat wall in the plane spanned by `right` and `up` (unit, orthogonal) at `origin`
// (the lower-left corner of the face that faces `cross(right, up)`), `width` x `height`,
// extruded `thickness` backwards, with rectangular openings (x0, y0, x1, y1 in wall
// coordinates, inside the wall and not overlapping). Both faces, the reveals of every
// opening and the four outer edges are built; openings from y = 0 are doors, with neither
// sill nor bottom edge.
struct Rect {
    float x0, y0, x1, y1;
};
void addWall(MeshBuilder& b, const glm::vec3& origin, const glm::vec3& right, const glm::vec3& up,
             float width, float height, float thickness, std::span<const Rect> openings,
             float texSize);

// One planar convex quad with normal `n`, wound to face it whatever the order of the corners
// (given around the quad); uv = (dot(p, uAxis), -dot(p, vAxis)) / texSize.
void addFacingQuad(MeshBuilder& b, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
                   const glm::vec3& n, const glm::vec3& uAxis, const glm::vec3& vAxis,
                   float texSize);

// A flat quad p0 p1 p2 p3 (counter-clockwise seen from the front) with the given uvs,
// subdivided n x m.
void addQuad(MeshBuilder& b, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
             const glm::vec3& p3, const glm::vec2& uv0, const glm::vec2& uv2, int n = 1, int m = 1);

} // namespace tp::procgen
