#include "core/gpuscene/scene_gpu.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "core/camera/camera.h"
#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"
#include "core/scene/meshlets.h"
#include "core/util/parallel.h"
#include "include/meshlets.h"

namespace tp {

gpu::LightGpu toGpu(const Light& light) {
    gpu::LightGpu g{};
    g.position = light.position;
    g.range = light.range;
    float len = glm::length(light.direction);
    g.direction = len > 0.0f ? light.direction / len : glm::vec3(0, -1, 0);
    g.type = uint32_t(light.type);
    g.color = light.color * light.intensity;
    // The model clamps the distance at TP_MIN_LIGHT_DISTANCE: a point or spot whose range is
    // below it would light only that clamp's flat core, its own position included (a range of
    // 1e-40 lit the point at distance 0 with 1e4 x its intensity). Such a light is inert.
    if (light.type != LightType::Directional && !(light.range >= TP_MIN_LIGHT_DISTANCE))
        g.color = glm::vec3(0.0f);
    float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
    g.spotScale = 1.0f / std::max(1e-4f, cosInner - cosOuter);
    g.spotOffset = -cosOuter * g.spotScale;
    return g;
}

namespace {

// One FrameUniforms from a view in double: viewProj rounded once from the exact product, its
// inverse taken from the rounded matrix the rasterizer uses (reconstruction inverts what
// produced the depth).
gpu::FrameUniforms makeFrame(const glm::dmat4& view, const glm::mat4& proj) {
    gpu::FrameUniforms f{};
    f.view = glm::mat4(view);
    f.proj = proj;
    f.viewProj = glm::mat4(glm::dmat4(proj) * view);
    f.invProj = glm::mat4(glm::inverse(glm::dmat4(proj)));
    f.invViewProj = glm::mat4(glm::inverse(glm::dmat4(f.viewProj)));
    return f;
}

float roundDown(double v) {
    float f = float(v);
    return double(f) > v ? std::nextafter(f, -INFINITY) : f;
}

float roundUp(double v) {
    float f = float(v);
    return double(f) < v ? std::nextafter(f, INFINITY) : f;
}

} // namespace

SceneGpu::SceneGpu(GpuContext& ctx, const Scene& scene)
    : ctx_(ctx), scene_(scene), eye_(glm::dvec3(scene.camera.position)) {
    uploadGeometry();
    uploadMaterials();
    uploadTextures();
    frameBuffer_ = createBuffer(ctx_, sizeof(gpu::FrameUniforms),
                                VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::Upload,
                                {"scene", "", "frame_uniforms", "camera and frame constants"});
    createDescriptors();
    setLights(scene.lights);
    setView(1, 1, 1);
}

SceneGpu::~SceneGpu() {
    vkDestroyDescriptorPool(ctx_.device, pool_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, setLayout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, emptySetLayout_, nullptr);
    vkDestroySampler(ctx_.device, sampler_, nullptr);
}

void SceneGpu::uploadGeometry() {
    std::vector<gpu::Vertex> vertices;
    std::vector<uint32_t> indices;
    vertices.reserve(scene_.vertexCount());
    indices.reserve(scene_.triangleCount() * 3);
    for (const Mesh& mesh : scene_.meshes) {
        const Material& mat = scene_.materials.at(mesh.material);
        DrawItem d;
        d.mesh = uint32_t(&mesh - scene_.meshes.data());
        d.index = uint32_t(draws_.size());
        d.firstIndex = uint32_t(indices.size());
        d.indexCount = uint32_t(mesh.indices.size());
        d.vertexOffset = int32_t(vertices.size());
        d.material = mesh.material;
        d.alphaMode = mat.alphaMode;
        d.doubleSided = mat.doubleSided;
        d.bounds = mesh.bounds;
        if (d.indexCount > 0) draws_.push_back(d);
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            glm::vec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
            gpu::Vertex v;
            v.positionU = glm::vec4(mesh.positions[i], uv.x);
            v.normalV =
                glm::vec4(i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1), uv.y);
            v.tangent = i < mesh.tangents.size() ? mesh.tangents[i] : glm::vec4(1, 0, 0, 1);
            v.color = i < mesh.colors.size() ? mesh.colors[i] : glm::vec4(1.0f);
            vertices.push_back(v);
        }
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    vertices_ = createBufferWithData(ctx_, vertices.data(), vertices.size() * sizeof(gpu::Vertex),
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     {"scene", "", "vertices", "interleaved vertices (pulled)"});
    indices_ = createBufferWithData(ctx_, indices.data(), indices.size() * sizeof(uint32_t),
                                    VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    {"scene", "", "indices", "triangle indices"});
}

void SceneGpu::buildMeshlets() {
    if (meshletsBuilt_) return;
    meshletsBuilt_ = true;
    // Every mesh's meshlets, the meshes side by side on the machine's cores.
    const auto start = std::chrono::steady_clock::now();
    std::vector<MeshMeshlets> built(scene_.meshes.size());
    forEachInParallel(built.size(),
                      [&](size_t i) { built[i] = tp::buildMeshlets(scene_.meshes[i]); });
    const auto elapsed = std::chrono::steady_clock::now() - start;
    meshletBuildMs_ = std::chrono::duration<double, std::milli>(elapsed).count();
    std::vector<uint32_t> meshletIndices;
    std::vector<gpu::MeshletGpu> meshlets;
    meshletIndices.reserve(scene_.triangleCount() * 3);
    for (DrawItem& d : draws_) { // in place: drawList()'s pointers stay valid
        const MeshMeshlets& ml = built[d.mesh];
        d.firstMeshlet = uint32_t(meshlets.size());
        d.meshletCount = uint32_t(ml.meshlets.size());
        const uint32_t base = uint32_t(meshletIndices.size());
        for (const Meshlet& m : ml.meshlets) {
            gpu::MeshletGpu g{};
            g.center = m.center;
            g.radius = m.radius;
            g.coneApex = m.coneApex;
            g.coneCutoff = m.coneCutoff;
            g.coneAxis = m.coneAxis;
            g.triangleCount = m.triangleCount;
            g.firstIndex = base + m.firstIndex;
            meshlets.push_back(g);
        }
        meshletIndices.insert(meshletIndices.end(), ml.indices.begin(), ml.indices.end());
        sourceTriangles_.insert(sourceTriangles_.end(), ml.sourceTriangles.begin(),
                                ml.sourceTriangles.end());
    }
    meshletCount_ = uint32_t(meshlets.size());
    if (meshlets.empty()) meshlets.push_back({}); // a buffer of one: nothing draws it
    if (meshletIndices.empty()) meshletIndices.push_back(0);
    meshlets_ = createBufferWithData(
        ctx_, meshlets.data(), meshlets.size() * sizeof(gpu::MeshletGpu),
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
        {"scene", "", "meshlets", "per meshlet: bounding sphere, normal cone, its indices"});
    meshletIndices_ = createBufferWithData(
        ctx_, meshletIndices.data(), meshletIndices.size() * sizeof(uint32_t),
        VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
        {"scene", "", "meshlet_indices", "triangle indices in meshlet order (culled draws)"});
}

VkBuffer SceneGpu::meshletSourceTriangleBuffer() {
    if (!meshletsBuilt_)
        throw std::logic_error("SceneGpu: meshlet source triangles asked before buildMeshlets()");
    if (!meshletSourceTriangles_.buffer) {
        if (sourceTriangles_.empty()) sourceTriangles_.push_back(0); // a buffer of one
        meshletSourceTriangles_ = createBufferWithData(
            ctx_, sourceTriangles_.data(), sourceTriangles_.size() * sizeof(uint32_t),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            {"scene", "", "meshlet_source_triangles",
             "per meshlet triangle: its triangle in its draw (visibility ids of culled draws)"});
        sourceTriangles_ = {};
    }
    return meshletSourceTriangles_.buffer;
}

void SceneGpu::uploadMaterials() {
    std::vector<gpu::MaterialGpu> mats;
    for (const Material& m : scene_.materials) {
        gpu::MaterialGpu g{};
        g.baseColorFactor = m.baseColorFactor;
        g.emissive = m.emissiveFactor;
        g.alphaCutoff = m.alphaCutoff;
        g.metallic = m.metallicFactor;
        g.roughness = m.roughnessFactor;
        g.normalScale = m.normalScale;
        g.occlusionStrength = m.occlusionStrength;
        g.baseColorTexture = m.baseColorTexture;
        g.metallicRoughnessTexture = m.metallicRoughnessTexture;
        g.normalTexture = m.normalTexture;
        g.occlusionTexture = m.occlusionTexture;
        g.emissiveTexture = m.emissiveTexture;
        g.alphaMode = uint32_t(m.alphaMode);
        g.doubleSided = m.doubleSided ? 1u : 0u;
        mats.push_back(g);
    }
    if (mats.empty()) mats.push_back(gpu::MaterialGpu{});
    materials_ = createBufferWithData(ctx_, mats.data(), mats.size() * sizeof(gpu::MaterialGpu),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      {"scene", "", "materials", "material table"});
    materialsGpu_ = std::move(mats);
}

void SceneGpu::setLights(const std::vector<Light>& lights) {
    lightsGpu_.clear();
    hasSpot_ = false;
    for (const Light& l : lights) {
        lightsGpu_.push_back(toGpu(l));
        hasSpot_ |= l.type == LightType::Spot;
    }
    lightCount_ = uint32_t(lights.size());
    uploadLights();
}

// The uploaded lights: positions relative to the eye, subtracted in double and rounded once.
void SceneGpu::uploadLights() {
    shadingLights_ = lightsGpu_;
    for (gpu::LightGpu& l : shadingLights_)
        l.position = toShading(l.position);
    applyShadowPlan();
    const VkDeviceSize bytes = shadingLights_.size() * sizeof(gpu::LightGpu);
    ++viewGeneration_;
    // Same count: overwritten in place, so a planned renderer's descriptors stay valid.
    if (lights_.buffer && lights_.size == bytes && bytes > 0) {
        uploadBufferData(ctx_, lights_, shadingLights_.data(), bytes);
    } else {
        lights_ = createBufferWithData(ctx_, shadingLights_.data(), bytes,
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       {"scene", "", "lights", "light array"});
        writeLightDescriptor();
    }
    frame_.viewport.z = shadingFrame_.viewport.z = lightCount_;
    std::memcpy(frameBuffer_.mapped, &shadingFrame_, sizeof(shadingFrame_));
}

glm::vec3 SceneGpu::toShading(glm::vec3 world) const {
    return glm::vec3(glm::dvec3(world) - eye_);
}

Aabb SceneGpu::toShading(const Aabb& world) const {
    if (world.empty()) return world;
    Aabb r;
    for (int i = 0; i < 3; ++i) {
        r.min[i] = roundDown(double(world.min[i]) - eye_[i]);
        r.max[i] = roundUp(double(world.max[i]) - eye_[i]);
    }
    return r;
}

void SceneGpu::setView(uint32_t width, uint32_t height, uint32_t msaaSamples) {
    const Camera& cam = scene_.camera;
    glm::mat4 proj =
        reverseZPerspective(cam.yfov, float(width) / float(height), cam.znear, cam.zfar);
    frame_ = makeFrame(viewMatrixWorld(cam), proj);
    shadingFrame_ = makeFrame(viewRotation(cam), proj);
    for (gpu::FrameUniforms* f : {&frame_, &shadingFrame_}) {
        f->eyeWorld = glm::vec4(cam.position, 1.0f);
        f->ambient = glm::vec4(scene_.ambient, 0.0f);
        f->viewport = glm::uvec4(width, height, lightCount_, msaaSamples);
        // z = 1: the varying scene.vert divides every interpolant by (a uniform, so no linker
        // folds it into a constant and skips the interpolation it exists to measure).
        f->projParams = glm::vec4(cam.znear, cam.zfar, 1.0f, 0.0f);
    }
    if (glm::dvec3(cam.position) != eye_) { // the camera moved: the relative lights follow
        eye_ = glm::dvec3(cam.position);
        uploadLights();
    }
    if (std::memcmp(frameBuffer_.mapped, &shadingFrame_, sizeof(shadingFrame_)) != 0)
        ++viewGeneration_;
    std::memcpy(frameBuffer_.mapped, &shadingFrame_, sizeof(shadingFrame_));
}

void SceneGpu::setShadows(const ShadowSettings& settings, ShadowPlan plan) {
    shadowSettings_ = settings;
    if (!(plan == shadowPlan_)) ++shadowGeneration_;
    if (plan.sameUpload(shadowPlan_)) return; // its words and faces are uploaded already
    shadowPlan_ = std::move(plan);
    uploadLights();
}

// The plan held, on the lights about to be uploaded: their shadow words, and the faces' buffer
// (overwritten in place while its size holds, so planned descriptors stay valid). A plan made
// for another light count is not applied (setLights changed the count: the next plan follows).
void SceneGpu::applyShadowPlan() {
    for (const ShadowLight& sl : shadowPlan_.lights)
        if (sl.light < shadingLights_.size()) shadingLights_[sl.light].shadow = sl.firstFace + 1;
    const VkDeviceSize bytes = shadowPlan_.faces.size() * sizeof(gpu::ShadowFace);
    if (bytes == 0) return;
    if (shadowFaces_.buffer && shadowFaces_.size == bytes)
        uploadBufferData(ctx_, shadowFaces_, shadowPlan_.faces.data(), bytes);
    else
        shadowFaces_ = createBufferWithData(ctx_, shadowPlan_.faces.data(), bytes,
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            {"scene", "", "shadow_faces", "shadow map faces"});
}

std::vector<SpecConstant> SceneGpu::specConstants(AlphaMode mode) const {
    return {{TP_SPEC_TEXTURE_COUNT, uint32_t(std::max<size_t>(1, textures_.size()))},
            {TP_SPEC_HAS_SPOT, hasSpot_ ? 1u : 0u},
            {TP_SPEC_ALPHA_MODE, uint32_t(mode)}};
}

VkPipelineLayout SceneGpu::createPipelineLayout(VkDescriptorSetLayout passSet,
                                                VkDescriptorSetLayout shadowSet) const {
    // A shadow set without a pass set of its own sits behind an empty set 1.
    VkDescriptorSetLayout sets[3] = {setLayout_, passSet ? passSet : emptySetLayout_, shadowSet};
    VkPushConstantRange push{VK_SHADER_STAGE_ALL, 0, sizeof(gpu::DrawPush)};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = shadowSet ? 3 : passSet ? 2 : 1;
    info.pSetLayouts = sets;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &push;
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(ctx_.device, &info, nullptr, &layout));
    return layout;
}

void SceneGpu::bindSceneSet(VkCommandBuffer cmd, VkPipelineLayout layout,
                            VkPipelineBindPoint point) const {
    vkCmdBindDescriptorSets(cmd, point, layout, TP_SET_SCENE, 1, &set_, 0, nullptr);
}

bool SceneGpu::hasDraws(DrawFilter filter) const {
    return std::any_of(draws_.begin(), draws_.end(), [&](const DrawItem& d) {
        return uint32_t(d.alphaMode) == uint32_t(filter);
    });
}

std::vector<const DrawItem*> SceneGpu::drawList(DrawFilter filter) const {
    std::vector<const DrawItem*> items;
    for (const DrawItem& d : draws_)
        if (uint32_t(d.alphaMode) == uint32_t(filter)) items.push_back(&d);
    if (filter == DrawFilter::Blend) {
        // In double: far from the origin fp32 world distances differ by whole spacings.
        auto dist = [&](const DrawItem* d) {
            return glm::length((glm::dvec3(d->bounds.min) + glm::dvec3(d->bounds.max)) * 0.5 -
                               eye_);
        };
        std::stable_sort(items.begin(), items.end(),
                         [&](const DrawItem* a, const DrawItem* b) { return dist(a) > dist(b); });
    }
    return items;
}

void SceneGpu::bindIndexBuffer(VkCommandBuffer cmd) const {
    vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
}

void SceneGpu::bindMeshletIndexBuffer(VkCommandBuffer cmd) const {
    vkCmdBindIndexBuffer(cmd, meshletIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
}

void SceneGpu::recordDraws(VkCommandBuffer cmd, VkPipelineLayout layout, DrawFilter filter,
                           VkPipeline pipeline) const {
    if (!pipeline) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    std::vector<const DrawItem*> items = drawList(filter);
    bindIndexBuffer(cmd);
    for (const DrawItem* d : items)
        recordDraw(cmd, layout, *d);
}

void recordDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const DrawItem& d, uint32_t pad0) {
    gpu::DrawPush push{d.material, 0, 0, 0};
    push.pad0 = pad0;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(cmd, d.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
}

} // namespace tp
