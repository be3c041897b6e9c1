// The stress catalogue: every case with its facts, expectations and scene (the scenes are
// built in stress_scenes.cpp, stress_scenes_counts.cpp, stress_scenes_stiff.cpp and
// stress_scenes_shadows.cpp), and the selection by --case.
#include <functional>
#include <sstream>

#include "core/scene/stress_scenes.h"

namespace tp::stress {

namespace {

// The catalogue in three parts, each appended in order through `add`.
using AddCase = const std::function<void(StressCase)>&;

// Geometry, depth and precision extremes.
void geometryCases(AddCase add) {
    add({"tile-overflow",
         "5,000 point lights overlap the same tiles (beyond deferred's 4,096-light shared "
         "list)",
         "every light shaded: none dropped, image within the pipeline's precision bound", 96, 64, 1,
         tileOverflow, false, false, false, 5000});
    add({"depth-discontinuity",
         "a 2 cm pole 0.4 m from the eye in front of a wall 1 km away: tiles span 0.4 m to 1 "
         "km",
         "culling efficiency collapses, correctness must not: within the precision bound", 96, 64,
         1, depthDiscontinuity});
    add({"mirror-spike",
         "roughness 0.03 (the clamp) and 0 under 10^4 cd lights, grazing and near-normal "
         "incidence",
         "the spike is finite (roughness clamped), no NaN/Inf, within the bound (G-buffer "
         "roughness quantization counted)",
         96, 64, 1, mirrorSpike});
    add({"light-on-surface",
         "point lights centred on a surface, 0.1 mm in front, 1 mm behind, on a vertex",
         "finite (distance clamped at 1 cm, l = n at distance 0), the back side unlit, within "
         "the bound",
         96, 64, 1, lightOnSurface});
    add({"light-hugging-far",
         "a light 0.1 mm above an 80 m floor, 5 mm beside the point a pixel centre sees 22 m "
         "away (95x63)",
         "the shaded point on the surface to fp32's rounding at its own distance, not at the "
         "triangle's vertices: within the bound",
         95, 63, 1, lightHuggingFar});
    add({"beyond-half-float", "a 10^6 cd light: radiance up to 1.6e5, beyond fp16's 65,504",
         "no NaN; fp32 targets exact within the bound; fp16 targets saturate or overflow only "
         "where the "
         "reference exceeds 65,504 (the report says which); the rest within the bound",
         96, 64, 1, beyondHalfFloat});
    add({"far-from-origin",
         "the lit stage translated by 10^6 units on every axis (fp32 spacing 0.0625)",
         "same data, same vertex shader: within the same bound as at the origin", 96, 64, 1,
         farFromOrigin});
    add({"depth-precision",
         "near 1e-3, far 1e6: a 5 mm cube 2 cm away and panels 5e5 m away 1 m apart",
         "reverse-Z D32 resolves both; depth equals the reference's exactly; within the bound", 96,
         64, 1, [] { return depthPrecision(false); }, true});
    add({"depth-precision-infinite", "as depth-precision with an infinite far plane",
         "reverse-Z D32 resolves both; depth equals the reference's exactly; within the bound", 96,
         64, 1, [] { return depthPrecision(true); }, true});
    add({"degenerate-geometry",
         "zero-area triangles, zero-length and NaN normals, missing and zero tangents under a "
         "normal map",
         "no NaN/Inf (geometric normal fallback, normal map skipped), within the bound", 96, 64, 1,
         degenerateGeometry, false, true});
}

// Light counts and sizes, and MSAA edges.
void lightCases(AddCase add) {
    add({"lights-0", "no light at all: ambient only",
         "ambient exactly as the reference, nothing else", 96, 64, 1,
         [] { return lightCount(0); }});
    add({"lights-1", "a single point light", "within the bound", 96, 64, 1,
         [] { return lightCount(1); }});
    add({"lights-65536", "65,536 point lights (4 cm grid over the floor and the wall), at 48x32",
         "none dropped, within the bound (summation of up to 65,536 terms counted)", 48, 32, 1,
         [] { return lightCount(65536); }});
    add({"lights-whole-screen",
         "lights whose range covers the whole view, one around the camera, a 172-degree spot",
         "every tile holds every light; within the bound", 96, 64, 1, lightsWholeScreen});
    add({"lights-subpixel", "400 lights of 2 cm range 5 mm above the floor, a pixel is ~9 cm there",
         "culling keeps lights smaller than a pixel: within the bound", 96, 64, 1, lightsSubpixel});
    add({"msaa-edges", "4x MSAA, white boxes and thin posts against a near-black wall and the sky",
         "edges resolved per sample like the reference: within the bound", 96, 64, 4, msaaEdges,
         false, false, true});
}

// The stiff cases (stress_scenes_stiff.cpp builds their scenes).
void stiffCases(AddCase add) {
    add({.name = "dynamic-range",
         .stresses = "four lights from 1e3 cd down to 1e-6 cd (10^9) on one screen, no "
                     "ambient: radiance from "
                     "~600 down to ~6e-7 (fp16 subnormals)",
         .expectation = "within the bound per HDR pixel, the dim end too (the tonemapped check "
                        "cannot see it)",
         .build = dynamicRange,
         .hdrChecked = true});
    add({.name = "blended-64",
         .stresses = "64 blended panels (alpha 0.1-0.4) over 240 pixels, lit by two point "
                     "lights and the sun",
         .expectation = "composited back to front like the reference: within the bound, with "
                        "the roundings of "
                        "every blend (each layer, each blended light draw)",
         .build = blendedLayers,
         .blendedLayers = 64});
    add({.name = "lights-range-0",
         .stresses = "18 lights of range 0, 1e-40 and 1.4e-45 (subnormal), points and spots, "
                     "in mid-air, in "
                     "the floor and wall planes, on the box, at the eye; one ordinary light",
         .expectation = "no NaN/Inf, none dropped; each image equals bit for bit the same "
                        "renderer's image "
                        "with their intensity 0; within the bound",
         .build = zeroRangeLights,
         .inertLights = 18});
    add({.name = "camera-in-light",
         .stresses =
             "the eye inside six lights' spheres: behind it, on the near plane, crossing it, 1 "
             "mm "
             "inside the surface, reaching nothing visible, a spot with its apex at the eye",
         .expectation = "each light on exactly the part of the view it reaches, no more, no "
                        "less: within the "
                        "bound",
         .build = cameraInLights});
    add({.name = "spot-zero-cone",
         .stresses = "74 spots with outer = inner = 0, their axes through pixel centres (the "
                     "cosine to the axis "
                     "rounds to 1 or above) or straight down, and one with outer 0 below inner "
                     "0.3; one point light",
         .expectation = "no NaN/Inf; a zero cone lights nothing, not even on its axis: each "
                        "image equals bit "
                        "for bit the same renderer's image with the spots at intensity 0; "
                        "within the bound",
         .build = zeroConeSpots,
         .inertLights = 74});
    add({.name = "spot-hard-edge",
         .stresses = "three spots with inner = outer > 0 (a step at the cone's edge: its 1e-4 "
                     "ramp in the cosine is far thinner than a pixel) across the floor, the box "
                     "and the wall; one point light",
         .expectation = "within the bound on every pixel but those whose points may straddle a "
                        "cone edge, which may differ by the spot's whole light (a per-pixel "
                        "allowance); no NaN/Inf",
         .build = hardSpots});
}

} // namespace

const std::vector<StressCase>& stressCases() {
    static const std::vector<StressCase> cases = [] {
        std::vector<StressCase> c;
        auto add = [&](StressCase sc) { c.push_back(std::move(sc)); };
        geometryCases(add);
        lightCases(add);
        stiffCases(add);
        shadowCases(add);
        return c;
    }();
    return cases;
}

Result<std::vector<const StressCase*>> selectStressCases(const std::string& list) {
    std::vector<const StressCase*> out;
    if (list.empty()) {
        for (const StressCase& c : stressCases())
            out.push_back(&c);
        return out;
    }
    std::vector<std::string> names;
    std::stringstream ss(list);
    std::string item;
    while (std::getline(ss, item, ','))
        names.push_back(item);
    for (const std::string& n : names) {
        bool known = false;
        for (const StressCase& c : stressCases())
            known |= c.name == n;
        if (!known) return Error{"--case: unknown case '" + n + "' (see triptych stress --list)"};
    }
    for (const StressCase& c : stressCases())
        for (const std::string& n : names)
            if (c.name == n) {
                out.push_back(&c);
                break;
            }
    if (out.empty()) return Error{"--case '" + list + "': no case named"};
    return out;
}

} // namespace tp::stress
