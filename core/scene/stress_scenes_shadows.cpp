// The shadowed stress cases (issue 26, item 4; docs/stress.md, "Shadowed cases"): a light a
// few millimetres above a floor (acne), a thin wall (peter-panning, light leaks), a point light
// inside a closed box (all six cube faces; nothing may leak out), 256 shadowed lights over one
// tile. Each renders with --shadows all; its facts (StressCase::shadowFacts) give the shadow
// technique's checks, compare/measure/stress_shadows.cpp derives their bounds from the maps' texel
// footprint and the filter (include/shadows.h).
#include "core/scene/stress_scenes.h"

namespace tp::stress {

using namespace build;
using glm::vec3;

namespace {

// The cone and position of the thin-wall case's spot; the wall's faces (StressCase facts).
constexpr float kWallFront = 0.0f, kWallBack = -0.01f;
constexpr float kSpotDistance = 2.5f; // from the wall's front face, along its axis (-z)
constexpr float kSpotHeight = 0.5f;
constexpr float kSpotOuter = 0.96f; // 55 degrees: one map face (below kMaxSpotHalfAngle)

// The box around the last light of light-in-box.
const vec3 kBoxLo(-0.5f, 0.8f, -0.5f), kBoxHi(0.5f, 1.8f, 0.5f);

Scene bare(const char* source) {
    Scene s;
    s.source = source;
    addMaterial(s, plain("grey", vec3(0.5f), 0.0f, 1.0f));
    addMaterial(s, plain("red", vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.5f));
    s.camera.yfov = 0.8f;
    s.camera.znear = 0.05f;
    s.camera.zfar = 0.0f;
    return s;
}

} // namespace

Scene shadowAcne() {
    // Nothing but a floor, no ambient: a pixel's value is the light's term times its
    // visibility, so maps / rays is the maps' visibility where the rays see the light.
    Scene s = bare("stress:shadow-acne");
    Mesh floor = meshOf("floor", 0);
    rect(floor, {-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, {0, 1, 0});
    s.meshes = {floor};
    s.camera.position = {0, 2, 2.5f};
    s.camera.target = {0, 0, 0};
    s.ambient = vec3(0.0f);
    // 4 mm above the floor: every receiver farther than 4 mm sees it at grazing incidence,
    // where one texel of its cube face spans the most floor (d / h footprints).
    s.lights.push_back(point({0.1f, 0.004f, 0.05f}, 20.0f, 3.0f));
    finish(s);
    return s;
}

Scene thinWall() {
    Scene s = bare("stress:thin-wall");
    Mesh floor = meshOf("floor", 0), wall = meshOf("wall", 1);
    rect(floor, {-6, 0, 6}, {12, 0, 0}, {0, 0, -12}, {0, 1, 0});
    // 1 cm thick, 12 m wide, 5 m tall: it covers the spot's whole cone (2.5 * tan 55 = 3.6 m
    // around the axis at its front face), so the floor behind it is shadowed everywhere and
    // the only shadow edge the camera sees is the wall's foot.
    box(wall, {-6, 0, kWallBack}, {6, 5, kWallFront});
    s.meshes = {floor, wall};
    // The eye behind the wall, looking at its foot.
    s.camera.position = {0, 0.6f, -0.8f};
    s.camera.target = {0, 0, 0};
    s.ambient = vec3(0.01f);
    s.lights.push_back(spot({0, kSpotHeight, kWallFront + kSpotDistance}, {0, 0, -1}, 40.0f, 5.5f,
                            0.7f, kSpotOuter));
    finish(s);
    return s;
}

Scene lightInBox() {
    Scene s = bare("stress:light-in-box");
    Mesh floor = meshOf("floor", 0), ceiling = meshOf("ceiling", 0), crate = meshOf("box", 1);
    rect(floor, {-10, 0, 10}, {20, 0, 0}, {0, 0, -20}, {0, 1, 0});
    rect(ceiling, {-10, 2.5f, 10}, {20, 0, 0}, {0, 0, -20}, {0, -1, 0});
    // Closed, floating 0.8 m above the floor: the eye sees the floor under it (the light's -Y
    // face), the ceiling above it (+Y) and the floor and ceiling around it (the four sides).
    box(crate, kBoxLo, kBoxHi);
    s.meshes = {floor, ceiling, crate};
    s.camera.position = {0, 0.6f, 4};
    s.camera.target = {0, 1.2f, 0};
    s.camera.yfov = 1.0f;
    s.ambient = vec3(0.01f);
    s.lights.push_back(point({1.8f, 2.0f, 2.2f}, 15.0f, 6.0f));  // outside: the box casts a shadow
    s.lights.push_back(point({0.1f, 1.3f, 0.05f}, 30.0f, 8.0f)); // inside, off centre; last
    finish(s);
    return s;
}

Scene shadowedLightsInOneTile() {
    Scene s = stage("stress:shadowed-256");
    // A post between the lights and the wall: each light casts its shadow on the wall and
    // the floor.
    Mesh post = meshOf("post", 1);
    box(post, {0.45f, 0, -4.75f}, {0.55f, 1.2f, -4.7f});
    s.meshes.push_back(post);
    s.camera.position = {0, 2, 1};
    s.camera.target = {0.3f, 0.6f, -4.5f};
    // 256 lights within 5 cm of one point, 1 m range: every tile near it holds all of them.
    Sequence seq{26};
    for (int i = 0; i < 256; ++i) {
        vec3 p(0.3f + 0.1f * seq.next() - 0.05f, 0.6f + 0.1f * seq.next() - 0.05f,
               -4.4f + 0.1f * seq.next() - 0.05f);
        s.lights.push_back(point(p, 0.02f, 1.0f, vec3(0.6f + 0.4f * seq.next(), 0.8f, 1.0f)));
    }
    finish(s);
    return s;
}

void shadowCases(const std::function<void(StressCase)>& add) {
    const ShadowSettings all{.all = true};
    add({.name = "shadow-acne",
         .stresses = "a point light 4 mm above a floor, shadowed (cube map): nearly every receiver "
                     "at grazing incidence, where a texel spans the most floor",
         .expectation = "no acne: where the rays see the floor lit, the maps darken no pixel by "
                        "more than one PCF tap (1/9); every pipeline within its bound of the "
                        "maps reference",
         .build = shadowAcne,
         .shadows = all,
         .shadowFacts = {.shadowedLights = 1, .floorAcne = true}});
    add({.name = "thin-wall",
         .stresses = "a 1 cm wall between a spot light and the floor behind it, thinner than "
                     "the map's footprint there (~6 cm): peter-panning and light leaks",
         .expectation = "behind the wall the maps light the floor only within the band the "
                        "offset, bias and PCF open (derived in footprints); every pipeline "
                        "within its bound of the maps reference",
         .width = 128,
         .height = 96,
         .build = thinWall,
         .shadows = all,
         .shadowFacts = {
             .shadowedLights = 1, .wallLight = 0, .wallFront = kWallFront, .wallBack = kWallBack}});
    add({.name = "light-in-box",
         .stresses = "a point light inside a closed floating box (six cube faces, each with "
                     "receivers outside), a second light outside",
         .expectation = "nothing outside the box is lit by the light inside, in either reference "
                        "or any pipeline (each image equals its image with that light at "
                        "intensity 0); within the bound of the maps reference",
         .build = lightInBox,
         .inertLights = 1,
         .shadows = all,
         .shadowFacts = {.shadowedLights = 2, .boxLight = 1, .boxLo = kBoxLo, .boxHi = kBoxHi}});
    add({.name = "shadowed-256",
         .stresses = "256 shadowed point lights within 5 cm of one point (1,536 cube faces in "
                     "the atlas), a post casting a shadow from each",
         .expectation = "the plan shadows all 256 and every pipeline reports them "
                        "(shadowed_lights); every pipeline within its bound of the maps "
                        "reference",
         .build = shadowedLightsInOneTile,
         .lightsInOneTile = 256,
         .shadows = all,
         .shadowFacts = {.shadowedLights = 256}});
}

} // namespace tp::stress
