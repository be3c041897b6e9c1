// A glTF file's animated camera as a camera path (camera_path.h, form b). The file is read
// through the glTF loader's checked steps (core/scene/gltf_internal.h: bounded reads, GLB
// container, confined file access, accessors checked against the bytes loaded), so a hostile
// path file fails as a hostile scene does: one line, no crash.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/camera/camera_file.h"
#include "core/camera/camera_path.h"
#include "core/scene/gltf_internal.h"

namespace tp {
namespace {

namespace fs = std::filesystem;
using glm::dmat4;
using glm::dquat;
using glm::dvec3;

Result<tinygltf::Model> loadPathModel(const std::string& path) {
    std::vector<unsigned char> bytes;
    if (Status s = gltf::readFile(path, bytes); !s) return Error{s.error()};
    if (bytes.size() >= (1ull << 32))
        return Error{"file is over 4 GiB, which tinygltf cannot load"};
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    std::string_view jsonText(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (binary)
        if (Status s = gltf::checkGlb(bytes, jsonText); !s) return Error{s.error()};
    if (Status s = gltf::patchForTinygltf(bytes, binary, jsonText); !s) return Error{s.error()};
    const fs::path folder = fs::absolute(fs::path(path)).parent_path().lexically_normal();
    gltf::FileAccess access;
    std::vector<std::string> imageProblems; // images are not read for a path
    if (Status s = gltf::prescan(jsonText, folder, binary, access, imageProblems, [](auto&) {}); !s)
        return Error{s.error()};
    tinygltf::TinyGLTF loader;
    gltf::confine(loader, access);
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                         unsigned(bytes.size()), folder.string())
                           : loader.LoadASCIIFromString(&model, &err, &warn,
                                                        reinterpret_cast<const char*>(bytes.data()),
                                                        unsigned(bytes.size()), folder.string());
    if (!ok) {
        const std::string line = gltf::firstLine(err);
        return Error{"tinygltf: " + (line.empty() ? "cannot load the file" : line)};
    }
    bool anyMeshopt = false;
    if (Status s = gltf::decodeMeshopt(model, anyMeshopt); !s) return Error{s.error()};
    return model;
}

enum class AnimProperty { Translation, Rotation, Scale };
enum class AnimSampling { Linear, Step, Cubic };

// One channel of the animation, read: `values` holds `width` floats per output animElement.
struct AnimTrack {
    int node;
    AnimProperty property;
    AnimSampling sampling;
    std::vector<float> times;
    std::vector<float> values;
    size_t width = 0;
};

const gltf::AttributeSpec kAnimInputSpec{
    "animation input", {TINYGLTF_TYPE_SCALAR}, {gltf::kFloat}, false};
const gltf::AttributeSpec kAnimVec3Spec{
    "animation output", {TINYGLTF_TYPE_VEC3}, {gltf::kFloat}, false};
// Rotations may be normalized integers (glTF 2.0, 5.25).
const gltf::AttributeSpec kAnimRotationSpec{
    "animation output",
    {TINYGLTF_TYPE_VEC4},
    {gltf::kFloat, gltf::kByte, gltf::kUByte, gltf::kShort, gltf::kUShort},
    true};

Status readAnimTrack(const tinygltf::Model& model, const tinygltf::Animation& anim, size_t a,
                     const tinygltf::AnimationChannel& ch, AnimProperty property, AnimTrack& out) {
    const std::string label =
        "animation " + std::to_string(a) + " sampler " + std::to_string(ch.sampler);
    if (ch.sampler < 0 || size_t(ch.sampler) >= anim.samplers.size())
        return Error{"animation " + std::to_string(a) + ": sampler " + std::to_string(ch.sampler) +
                     " does not exist"};
    const tinygltf::AnimationSampler& sampler = anim.samplers[size_t(ch.sampler)];
    out.node = ch.target_node;
    out.property = property;
    if (sampler.interpolation == "LINEAR")
        out.sampling = AnimSampling::Linear;
    else if (sampler.interpolation == "STEP")
        out.sampling = AnimSampling::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
        out.sampling = AnimSampling::Cubic;
    else
        return Error{label + ": unknown interpolation \"" + sampler.interpolation + "\""};
    size_t width = 0;
    if (Status s = gltf::readFloats(model, sampler.input, kAnimInputSpec, out.times, width); !s)
        return s;
    const gltf::AttributeSpec& spec =
        property == AnimProperty::Rotation ? kAnimRotationSpec : kAnimVec3Spec;
    if (Status s = gltf::readFloats(model, sampler.output, spec, out.values, out.width); !s)
        return s;
    if (out.times.empty()) return Error{label + ": no keyframes"};
    for (size_t k = 1; k < out.times.size(); ++k)
        if (!(out.times[k] > out.times[k - 1]))
            return Error{label + ": keyframe times must increase (time " + std::to_string(k) +
                         " is not after the one before)"};
    const size_t perKey = out.sampling == AnimSampling::Cubic ? 3 : 1;
    if (out.values.size() != out.times.size() * perKey * out.width)
        return Error{label + ": " + std::to_string(out.values.size() / out.width) +
                     " output values for " + std::to_string(out.times.size()) + " keyframes"};
    return {};
}

// Element `e` of the track's output, as a vector of `width` doubles (xyz or quaternion xyzw).
glm::dvec4 animElement(const AnimTrack& t, size_t e) {
    glm::dvec4 v(0.0);
    for (size_t c = 0; c < t.width; ++c)
        v[int(c)] = t.values[e * t.width + c];
    return v;
}

glm::dvec4 animKeyValue(const AnimTrack& t, size_t k) {
    return animElement(t, t.sampling == AnimSampling::Cubic ? 3 * k + 1 : k);
}

// The track's value at `time` (glTF 2.0 appendix C); before the first keyframe and after the
// last it holds, and at a keyframe's time it is that keyframe's value exactly.
glm::dvec4 sampleAnimTrack(const AnimTrack& t, double time) {
    if (time <= t.times.front()) return animKeyValue(t, 0);
    if (time >= t.times.back()) return animKeyValue(t, t.times.size() - 1);
    const size_t k =
        size_t(std::upper_bound(t.times.begin(), t.times.end(), time) - t.times.begin()) - 1;
    if (double(t.times[k]) == time || t.sampling == AnimSampling::Step) return animKeyValue(t, k);
    const double dt = double(t.times[k + 1]) - double(t.times[k]);
    const double s = (time - double(t.times[k])) / dt;
    const glm::dvec4 a = animKeyValue(t, k), b = animKeyValue(t, k + 1);
    if (t.sampling == AnimSampling::Cubic) {
        const double s2 = s * s, s3 = s2 * s;
        const glm::dvec4 v = (2 * s3 - 3 * s2 + 1) * a +
                             (s3 - 2 * s2 + s) * dt * animElement(t, 3 * k + 2) +
                             (-2 * s3 + 3 * s2) * b + (s3 - s2) * dt * animElement(t, 3 * (k + 1));
        return t.property == AnimProperty::Rotation ? glm::normalize(v) : v;
    }
    if (t.property != AnimProperty::Rotation) return (1.0 - s) * a + s * b;
    const dquat q = glm::slerp(dquat(a.w, a.x, a.y, a.z), dquat(b.w, b.x, b.y, b.z), s);
    return {q.x, q.y, q.z, q.w};
}

struct AnimPose {
    dvec3 translation{0.0}, scale{1.0};
    dquat rotation{1.0, 0.0, 0.0, 0.0};
};

// The node's transform at `time`: its own TRS (or matrix) with the animated parts replaced.
Result<dmat4> animLocalAt(const tinygltf::Node& node, int index,
                          const std::vector<AnimTrack>& tracks, double time) {
    bool animated = false;
    for (const AnimTrack& t : tracks)
        animated = animated || t.node == index;
    if (!node.matrix.empty()) {
        if (animated)
            return Error{"node " + std::to_string(index) +
                         " has a matrix, which an animation cannot target"};
        dmat4 m(1.0);
        for (int i = 0; i < 16 && size_t(i) < node.matrix.size(); ++i)
            m[i / 4][i % 4] = node.matrix[size_t(i)];
        return m;
    }
    AnimPose p;
    if (node.translation.size() == 3)
        p.translation = dvec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.scale.size() == 3) p.scale = dvec3(node.scale[0], node.scale[1], node.scale[2]);
    if (node.rotation.size() == 4)
        p.rotation = dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    for (const AnimTrack& t : tracks) {
        if (t.node != index) continue;
        const glm::dvec4 v = sampleAnimTrack(t, time);
        if (t.property == AnimProperty::Translation) p.translation = dvec3(v);
        if (t.property == AnimProperty::Scale) p.scale = dvec3(v);
        if (t.property == AnimProperty::Rotation) p.rotation = dquat(v.w, v.x, v.y, v.z);
    }
    const double len = glm::length(p.rotation);
    if (len > 1e-12 && std::isfinite(len)) p.rotation = p.rotation / len;
    return glm::translate(dmat4(1.0), p.translation) * glm::mat4_cast(p.rotation) *
           glm::scale(dmat4(1.0), p.scale);
}

// The node and its ancestors, root first.
std::vector<int> nodeChainTo(int node, const std::vector<int>& parent) {
    std::vector<int> chain;
    for (int n = node; n >= 0; n = parent[size_t(n)])
        chain.push_back(n);
    std::reverse(chain.begin(), chain.end());
    return chain;
}

struct AnimatedCamera {
    int node = -1;
    size_t animation = 0;
};

// The first node (default scene, depth first) with a perspective camera whose translation or
// rotation some animation moves, and the first such animation.
Result<AnimatedCamera> chooseAnimatedCamera(const tinygltf::Model& model,
                                            const std::vector<gltf::Instance>& instances,
                                            const std::vector<int>& parent) {
    for (const gltf::Instance& inst : instances) {
        if (inst.node < 0) continue;
        const int c = model.nodes[size_t(inst.node)].camera;
        if (c < 0 || size_t(c) >= model.cameras.size() ||
            model.cameras[size_t(c)].type != "perspective")
            continue;
        const std::vector<int> chain = nodeChainTo(inst.node, parent);
        for (size_t a = 0; a < model.animations.size(); ++a)
            for (const tinygltf::AnimationChannel& ch : model.animations[a].channels)
                if ((ch.target_path == "translation" || ch.target_path == "rotation") &&
                    std::find(chain.begin(), chain.end(), ch.target_node) != chain.end())
                    return AnimatedCamera{inst.node, a};
    }
    return Error{"no node of the default scene has a perspective camera whose translation or "
                 "rotation is animated (on the node or an ancestor)"};
}

// The animation's tracks on the camera's chain, and its time range (all its samplers').
Status readCameraAnimation(const tinygltf::Model& model, size_t a, const std::vector<int>& chain,
                           std::vector<AnimTrack>& tracks, double& start, double& end) {
    const tinygltf::Animation& anim = model.animations[a];
    start = INFINITY;
    end = -INFINITY;
    for (const tinygltf::AnimationChannel& ch : anim.channels) {
        AnimProperty property;
        if (ch.target_path == "translation")
            property = AnimProperty::Translation;
        else if (ch.target_path == "rotation")
            property = AnimProperty::Rotation;
        else if (ch.target_path == "scale")
            property = AnimProperty::Scale;
        else
            continue; // morph weights do not move a camera
        AnimTrack t;
        if (Status s = readAnimTrack(model, anim, a, ch, property, t); !s) return s;
        start = std::min(start, double(t.times.front()));
        end = std::max(end, double(t.times.back()));
        if (std::find(chain.begin(), chain.end(), ch.target_node) != chain.end())
            tracks.push_back(std::move(t));
    }
    return {};
}

Result<Camera> animatedViewAt(const tinygltf::Model& model, const std::vector<int>& chain,
                              const std::vector<AnimTrack>& tracks, double time) {
    dmat4 world(1.0);
    for (int n : chain) {
        Result<dmat4> local = animLocalAt(model.nodes[size_t(n)], n, tracks, time);
        if (!local) return Error{local.error()};
        world = world * *local;
    }
    const dvec3 forward = glm::dmat3(world) * dvec3(0.0, 0.0, -1.0);
    const dvec3 up = glm::dmat3(world) * dvec3(0.0, 1.0, 0.0);
    if (!(glm::length(forward) > 1e-12) || !(glm::length(up) > 1e-12))
        return Error{"the camera node's transform is degenerate (a zero scale)"};
    const tinygltf::PerspectiveCamera& p =
        model.cameras[size_t(model.nodes[size_t(chain.back())].camera)].perspective;
    Camera c;
    c.position = glm::vec3(dvec3(world[3]));
    c.target = glm::vec3(dvec3(world[3]) + glm::normalize(forward));
    c.up = glm::vec3(glm::normalize(up));
    c.yfov = float(p.yfov);
    c.znear = float(p.znear);
    c.zfar = float(p.zfar); // absent: 0, an infinite far plane
    return c;
}

Result<std::vector<Camera>> sampleGltfPath(const std::string& path, uint32_t frames) {
    if (frames < 1 || frames > kMaxPathFrames)
        return Error{"frames must be from 1 to " + std::to_string(kMaxPathFrames) + " (got " +
                     std::to_string(frames) + ")"};
    Result<tinygltf::Model> model = loadPathModel(path);
    if (!model) return Error{model.error()};
    std::vector<gltf::Instance> instances;
    if (Status s = gltf::collectInstances(*model, instances); !s) return Error{s.error()};
    std::vector<int> parent(model->nodes.size(), -1); // a forest: gltf::collectInstances checked it
    for (size_t i = 0; i < model->nodes.size(); ++i)
        for (int c : model->nodes[i].children)
            parent[size_t(c)] = int(i);
    Result<AnimatedCamera> choice = chooseAnimatedCamera(*model, instances, parent);
    if (!choice) return Error{choice.error()};
    const std::vector<int> chain = nodeChainTo(choice->node, parent);
    std::vector<AnimTrack> tracks;
    double start = 0.0, end = 0.0;
    if (Status s = readCameraAnimation(*model, choice->animation, chain, tracks, start, end); !s)
        return Error{s.error()};
    std::vector<Camera> views;
    for (uint32_t i = 0; i < frames; ++i) {
        const std::string label = "view " + std::to_string(i);
        const double t =
            frames == 1 ? start
                        : (start * double(frames - 1 - i) + end * double(i)) / double(frames - 1);
        Result<Camera> view = animatedViewAt(*model, chain, tracks, t);
        if (!view) return Error{label + ": " + view.error()};
        Result<Camera> checked = cameraFromJson(cameraToJson(*view), label);
        if (!checked) return Error{checked.error()};
        views.push_back(*checked);
    }
    return views;
}

} // namespace

Result<std::vector<Camera>> readGltfCameraPath(const std::string& path, uint32_t frames) {
    std::string problem;
    try {
        Result<std::vector<Camera>> views = sampleGltfPath(path, frames);
        if (views) return views;
        problem = views.error();
    } catch (const std::bad_alloc&) {
        problem = "out of memory while reading the camera path";
    } catch (const std::exception& e) {
        problem = "unexpected failure: " + gltf::firstLine(e.what());
    }
    return Error{printableLine(path + ": " + problem)};
}

} // namespace tp
