#pragma once
// The stress catalogue (`triptych stress`, docs/stress.md): named procedural scenes, each
// built to push one pipeline choice to its limit (a tile full of lights, a specular spike,
// values beyond fp16, positions 10^6 from the origin, ...). Scenes are built in code, so a
// case is the same on every machine; the expectations (error bounds and checks per
// pipeline) come from each pipeline's error model (core/renderer/error_model.h), which reads
// the facts a case states here.
#include <functional>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "core/scene/shadow_settings.h"
#include "core/util/result.h"

namespace tp::stress {

// A counter a pipeline must report for the case to have stressed what it claims (e.g. a
// shared light list overflowed); the pipeline names it from the case's facts
// (RendererEntry::stressedCounters). Runs without the counter skip it.
struct CounterAtLeast {
    std::string counter;
    double atLeast = 0;
    std::string why;
};

// What a shadowed case (StressCase::shadows) states for its shadow-technique verdict: the
// reference on the pipelines' shadow maps (--reference-shadows maps) against the exact one
// (rays), with bounds derived from the maps' texel footprint and the filter
// (include/shadows.h; docs/stress.md, "Shadowed cases"). compare/measure/stress_shadows.cpp checks them.
struct ShadowFacts {
    // The plan must shadow this many lights, and every pipeline report them (its
    // `shadowed_lights` counter): a pipeline that ignores --shadows fails the case.
    uint32_t shadowedLights = 0;
    // Acne: on the floor (the plane y = 0), no pixel the rays see lit may be darker in the
    // maps image by more than one PCF tap of the (2r + 1)^2.
    bool floorAcne = false;
    // A thin wall: the slab wallBack < z < wallFront, facing +z, lit by the spot light
    // `wallLight` whose axis is -z. Behind it the maps may leak light onto the floor only
    // within the derived peter-panning band (-1: no wall).
    int wallLight = -1;
    float wallFront = 0, wallBack = 0;
    // A closed box holding light `boxLight` (the scene's last light, an inert light of the
    // case: StressCase::inertLights = 1): nothing outside may be lit by it in either
    // reference, and its receivers outside must fall in all six cube faces (-1: no box).
    int boxLight = -1;
    glm::vec3 boxLo{0.0f}, boxHi{0.0f};
};

struct StressCase {
    std::string name;
    std::string stresses;    // one line: what the case does to the pipelines
    std::string expectation; // one line: what every pipeline must still do
    uint32_t width = 96, height = 64, msaa = 1;
    std::function<Scene()> build;
    // The published depth must equal the reference's bit for bit (same triangles, same
    // vertex shader with a precise gl_Position, D32 reverse-Z): checked where depth is
    // what the case is about.
    bool depthExact = false;
    // Normals that are not axis-aligned reach the shading (G-buffer normal quantization
    // matters); every other case keeps surfaces axis-aligned.
    bool freeNormals = false;
    // Only directional lights and rough (roughness 1) dielectrics: the case where a
    // pipeline that shades a pixel once instead of per sample can be bounded.
    bool directionalRoughOnly = false;
    // Lights whose ranges all cover one tile: a pipeline with a per-tile limit checks that
    // its overflow path ran (0: the case does not aim at tile capacity).
    uint32_t lightsInOneTile = 0;
    // The most blended layers over one pixel (0: nothing blended). Every layer's blend
    // rounds the composite again: the bound counts one set of roundings per layer.
    uint32_t blendedLayers = 0;
    // The last `inertLights` lights of the scene must contribute exactly nothing (range 0,
    // subnormal range, zero cones): every image, the reference's too, must equal bit for bit
    // the same renderer's image of the scene with their intensity 0 (same lights, culling,
    // batches and shader variants: only what they add can differ).
    uint32_t inertLights = 0;
    // Check the bound per pixel on HDR values too, not only tonemapped: where the case's
    // values span more than one exposure can show (a 10^9 range), the dim end is black once
    // tonemapped and only the HDR check sees its error.
    bool hdrChecked = false;
    // Shadows: the run's --shadows (none: the case renders as it always did). A shadowed case
    // measures the pipelines against the reference on the same shadow maps and adds the
    // shadow technique's verdict (shadowFacts) against the ray-traced reference.
    ShadowSettings shadows;
    ShadowFacts shadowFacts;
};

const std::vector<StressCase>& stressCases();
// "a,b,c" -> cases in catalogue order; empty = all. Error names the unknown case.
Result<std::vector<const StressCase*>> selectStressCases(const std::string& list);

// Building blocks shared by the scene files (stress_scenes*.cpp).
namespace build {
Material plain(const char* name, glm::vec3 base, float metallic, float roughness);
uint32_t addMaterial(Scene& s, Material m);
// An axis-aligned rectangle origin, origin+u, origin+u+v, origin+v with the exact normal n
// (unit, along an axis) so G-buffer normal encodings round-trip exactly.
void rect(Mesh& m, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 n);
Mesh meshOf(const char* name, uint32_t material);
// Axis-aligned box, faces outward, exact normals.
void box(Mesh& m, glm::vec3 lo, glm::vec3 hi);
Light point(glm::vec3 p, float intensity, float range, glm::vec3 color = glm::vec3(1.0f));
// A spot light at p along `direction` (normalized here), cone angles in radians.
Light spot(glm::vec3 p, glm::vec3 direction, float intensity, float range, float inner,
           float outer, glm::vec3 color = glm::vec3(1.0f));
// A directional light shining along `direction` (normalized here), `lux` strong.
Light sun(glm::vec3 direction, float lux);
// Deterministic [0,1) sequence (splitmix64): the scenes never depend on a library's RNG.
struct Sequence {
    uint64_t state;
    float next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return float((z ^ (z >> 31)) >> 40) / float(1ull << 24);
    }
};
// A 10 x 10 grey floor at y = 0 under a 10 x 5 back wall at z = -5, camera at (0, 3, 7)
// looking at (0, 1, 0): the stage most cases put their stress on.
Scene stage(const char* source);
void finish(Scene& s);
} // namespace build

// Scene builders (stress_scenes.cpp, stress_scenes_counts.cpp, stress_scenes_stiff.cpp).
Scene tileOverflow();
Scene depthDiscontinuity();
Scene mirrorSpike();
Scene lightOnSurface();
Scene lightHuggingFar();
Scene beyondHalfFloat();
Scene farFromOrigin();
Scene depthPrecision(bool infiniteFar);
Scene degenerateGeometry();
Scene lightCount(uint32_t count);
Scene lightsWholeScreen();
Scene lightsSubpixel();
Scene msaaEdges();
// stress_scenes_stiff.cpp
Scene dynamicRange();
Scene blendedLayers();
Scene zeroRangeLights();
Scene hardSpots();
Scene cameraInLights();
Scene zeroConeSpots();
// stress_scenes_shadows.cpp: the shadowed cases and their catalogue part.
Scene shadowAcne();
Scene thinWall();
Scene lightInBox();
Scene shadowedLightsInOneTile();
void shadowCases(const std::function<void(StressCase)>& add);

} // namespace tp::stress
