#include "viewer/view_state.h"

#include <cstdio>

#include "core/reference/reference_renderer.h"
#include "core/renderer/renderer.h"
#include "core/renderer/view_settings.h"

namespace tp::view {
namespace {

std::string vec(const glm::vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "%.9g,%.9g,%.9g", v.x, v.y, v.z);
    return buf;
}

} // namespace

std::string cameraText(const Camera& c) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "|%.9g|%.9g|%.9g", c.yfov, c.znear, c.zfar);
    return vec(c.position) + "|" + vec(c.target) + "|" + vec(c.up) + buf;
}

std::string sceneKey(const ViewState& s) {
    return s.scene.scene + "|" + (s.scene.strict ? "strict" : "repair") + "|" + s.scene.cameraFile;
}

std::string lightsKey(const ViewState& s) {
    const cli::SceneOptions& o = s.scene;
    return sceneKey(s) + "|" + o.lightsFile + "|" + std::to_string(o.lightCount) + "|" +
           std::to_string(o.seed) + "|" + o.lightTypes + "|" + o.lightRadius + "|" +
           o.lightIntensity + "|" + (o.dropSceneLights ? "drop" : "keep");
}

std::string motionKey(const ViewState& s) {
    return s.lightMotion == "none"
               ? std::string()
               : "|motion=" + s.lightMotion + "@" + std::to_string(s.lightFrame);
}

std::string referenceKey(const ViewState& s) {
    // The scene's own camera until the user moves it (its values arrive with the scene).
    std::string camera = s.cameraFromScene ? std::string("scene camera") : cameraText(s.camera);
    std::string key = lightsKey(s) + motionKey(s) + "|" + camera + "|" + std::to_string(s.width) +
                      "x" + std::to_string(s.height) + "x" + std::to_string(s.msaa);
    // The reference's own knobs (e.g. the MSAA shading rate) change it too.
    if (Result<const RendererEntry*> ref = findRenderer(kReferenceRenderer); ref)
        for (const Knob& k : (*ref)->knobs)
            key += "|" + k.name + "=" + k.valueIn(s.knobs);
    return key;
}

bool parseViewResolution(const std::string& text, uint32_t& width, uint32_t& height) {
    uint32_t w = 0, h = 0;
    if (!parseResolution(text, w, h) || w < kViewMinSide || h < kViewMinSide || w > kViewMaxSide ||
        h > kViewMaxSide)
        return false;
    width = w, height = h;
    return true;
}

std::string planKey(const ViewState& s, bool debug) {
    std::string key = lightsKey(s) + "|" + std::to_string(s.width) + "x" +
                      std::to_string(s.height) + "x" + std::to_string(s.msaa) +
                      (debug ? "|debug" : "");
    for (const auto& [name, value] : s.knobs)
        key += "|" + name + "=" + value;
    return key;
}

std::string renderKey(const ViewState& s, bool debug) {
    std::string key = referenceKey(s) + (debug ? "|debug" : "");
    for (const auto& [name, value] : s.knobs)
        key += "|" + name + "=" + value;
    return key;
}

} // namespace tp::view
