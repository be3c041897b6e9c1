// The glTF node hierarchy: checked to be a forest, flattened over the default scene into
// world matrices; the lights and the camera it places.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

// The hierarchy must be a forest: every child index valid, at most one parent, no cycles.
Status checkNodeGraph(const tinygltf::Model& model, std::vector<int>& parent) {
    const size_t n = model.nodes.size();
    parent.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        for (int c : model.nodes[i].children) {
            std::string label = "node " + std::to_string(i);
            if (c < 0 || size_t(c) >= n)
                return Error{label + ": child " + std::to_string(c) + " does not exist"};
            if (parent[size_t(c)] != -1 || size_t(c) == i)
                return Error{"node " + std::to_string(c) + " has more than one parent, or is " +
                             "its own child (the node hierarchy must be a tree)"};
            parent[size_t(c)] = int(i);
        }
    }
    // With one parent at most, a node that no root reaches lies on or under a cycle.
    std::vector<char> reached(n, 0);
    std::vector<int> stack;
    for (size_t i = 0; i < n; ++i)
        if (parent[i] == -1) stack.push_back(int(i));
    while (!stack.empty()) {
        int node = stack.back();
        stack.pop_back();
        reached[size_t(node)] = 1;
        for (int c : model.nodes[size_t(node)].children)
            stack.push_back(c);
    }
    for (size_t i = 0; i < n; ++i)
        if (!reached[i])
            return Error{"the node hierarchy has a cycle (through node " + std::to_string(i) + ")"};
    return {};
}

Status localTransform(const tinygltf::Node& node, size_t index, glm::mat4& out) {
    std::string label = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) return Error{label + ": matrix does not have 16 numbers"};
        for (int i = 0; i < 16; ++i)
            out[i / 4][i % 4] = float(node.matrix[size_t(i)]);
        return {};
    }
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3))
        return Error{label + ": translation, rotation or scale has the wrong length"};
    glm::vec3 t(0.0f), s(1.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    if (!node.translation.empty())
        t = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
    if (!node.scale.empty()) s = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
    if (!node.rotation.empty()) {
        glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                    float(node.rotation[2]));
        float len = glm::length(q);
        if (len > 1e-12f && std::isfinite(len)) r = q / len;
    }
    out = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    return {};
}

// KHR_lights_punctual leaves `range` optional (infinite), but our light model needs a finite
// one (the contribution is exactly zero there). A missing range is put where the illuminance
// intensity * max(colour) / d^2 has fallen to kRangeCutoffLux.
constexpr double kRangeCutoffLux = 1e-3;

} // namespace

// The nodes of the default scene (scene 0 if none is named), depth first, with their world
// matrices. A file without scenes shows its root nodes; one without nodes, each mesh once.
Status collectInstances(const tinygltf::Model& model, std::vector<Instance>& out) {
    std::vector<int> parent;
    Status s = checkNodeGraph(model, parent);
    if (!s) return s;
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int sceneIndex = model.defaultScene < 0 ? 0 : model.defaultScene;
        if (size_t(sceneIndex) >= model.scenes.size())
            return Error{"default scene " + std::to_string(sceneIndex) + " does not exist"};
        roots = model.scenes[size_t(sceneIndex)].nodes;
    } else if (!model.nodes.empty()) {
        for (size_t i = 0; i < parent.size(); ++i)
            if (parent[i] == -1) roots.push_back(int(i));
    } else {
        for (size_t m = 0; m < model.meshes.size(); ++m)
            out.push_back({-1, int(m), glm::mat4(1.0f)});
        return {};
    }
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        if (*it < 0 || size_t(*it) >= model.nodes.size())
            return Error{"scene lists node " + std::to_string(*it) + ", which does not exist"};
        stack.push_back({*it, glm::mat4(1.0f)});
    }
    while (!stack.empty()) {
        auto [index, parentWorld] = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model.nodes[size_t(index)];
        glm::mat4 local(1.0f);
        if (Status t = localTransform(node, size_t(index), local); !t) return t;
        glm::mat4 world = parentWorld * local;
        for (int i = 0; i < 16; ++i)
            if (!std::isfinite(world[i / 4][i % 4]))
                return Error{"node " + std::to_string(index) + ": transform is not finite"};
        if (node.mesh >= 0 && size_t(node.mesh) >= model.meshes.size())
            return Error{"node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) +
                         " does not exist"};
        out.push_back({index, node.mesh, world});
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back({*c, world});
    }
    return {};
}

void addLight(const tinygltf::Model& model, const Instance& inst, Scene& scene,
              const WarnFn& warn) {
    const tinygltf::Node& node = model.nodes[size_t(inst.node)];
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.IsObject() || !ext->second.Has("light"))
        return;
    const tinygltf::Value& index = ext->second.Get("light");
    int i = index.IsNumber() ? index.GetNumberAsInt() : -1;
    std::string label = "node " + std::to_string(inst.node) + ": light " + std::to_string(i);
    if (i < 0 || size_t(i) >= model.lights.size()) return warn(label + " does not exist; ignored");
    const tinygltf::Light& src = model.lights[size_t(i)];
    Light light;
    if (src.type == "point")
        light.type = LightType::Point;
    else if (src.type == "spot")
        light.type = LightType::Spot;
    else if (src.type == "directional")
        light.type = LightType::Directional;
    else
        return warn(label + " has unknown type '" + src.type + "'; ignored");
    if (src.color.size() == 3) light.color = glm::vec3(src.color[0], src.color[1], src.color[2]);
    light.color = glm::max(light.color, glm::vec3(0.0f));
    light.intensity = std::max(0.0f, float(src.intensity));
    light.position = glm::vec3(inst.world[3]);
    glm::vec3 dir = glm::mat3(inst.world) * glm::vec3(0.0f, 0.0f, -1.0f);
    if (glm::length(dir) > 1e-12f) light.direction = glm::normalize(dir);
    double brightest = light.intensity * std::max({light.color.r, light.color.g, light.color.b});
    light.range = src.range > 0.0 ? float(src.range)
                                  : float(std::max(std::sqrt(brightest / kRangeCutoffLux), 1e-3));
    const float halfPi = 1.5707963f;
    light.outerConeAngle = std::clamp(float(src.spot.outerConeAngle), 1e-4f, halfPi);
    light.innerConeAngle =
        std::clamp(float(src.spot.innerConeAngle), 0.0f, light.outerConeAngle * 0.999f);
    scene.lights.push_back(light);
}

// The file's first perspective camera on a drawn node, else one framing the bounds.
int placeCamera(const tinygltf::Model& model, const std::vector<Instance>& instances,
                Scene& scene) {
    Camera& cam = scene.camera;
    const glm::vec3 center = scene.bounds.center();
    const float radius = std::max(0.5f * glm::length(scene.bounds.extent()), 1e-4f);
    for (const Instance& inst : instances) {
        if (inst.node < 0) continue;
        int c = model.nodes[size_t(inst.node)].camera;
        if (c < 0 || size_t(c) >= model.cameras.size() ||
            model.cameras[size_t(c)].type != "perspective")
            continue;
        const tinygltf::PerspectiveCamera& p = model.cameras[size_t(c)].perspective;
        cam.position = glm::vec3(inst.world[3]);
        glm::vec3 forward = glm::mat3(inst.world) * glm::vec3(0, 0, -1);
        glm::vec3 up = glm::mat3(inst.world) * glm::vec3(0, 1, 0);
        if (glm::length(forward) < 1e-12f || glm::length(up) < 1e-12f) continue;
        float distance = std::max(glm::length(center - cam.position), 1e-3f);
        cam.target = cam.position + glm::normalize(forward) * distance;
        cam.up = glm::normalize(up);
        cam.yfov = p.yfov > 0.0 && p.yfov < 3.1 ? float(p.yfov) : 0.8f;
        cam.znear = p.znear > 0.0 ? float(p.znear)
                                  : std::min(std::max(1e-3f, 0.005f * radius), 0.1f * radius);
        cam.zfar = p.zfar > p.znear ? float(p.zfar) : 0.0f;
        return c;
    }
    cam.yfov = 0.8f;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, 0.35f, 1.0f));
    cam.target = center;
    cam.position = center + direction * (radius / std::sin(cam.yfov * 0.5f));
    cam.up = glm::vec3(0, 1, 0);
    // 1 mm at least, but never so far that a tiny scene (radius under ~7 mm) is clipped.
    cam.znear = std::min(std::max(1e-3f, 0.005f * radius), 0.1f * radius);
    cam.zfar = 0.0f;
    return -1;
}

} // namespace tp::gltf
