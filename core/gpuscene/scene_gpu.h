#pragma once
// The scene on the GPU, uploaded once and shared by every pipeline (ledger owner "scene"):
// one vertex buffer (pulled in the vertex shader), one index buffer, materials, lights,
// textures with mipmaps, and descriptor set 0 that binds them (shaders/include/shared.h).
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/gpuscene/shadow_plan.h"
#include "core/scene/scene.h"
#include "core/scene/shadow_settings.h"
#include "include/shared.h"

namespace tp {

class GpuContext;

struct DrawItem {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;
    uint32_t material = 0;
    uint32_t mesh = 0; // Scene::meshes index (the CPU copy of its geometry)
    uint32_t index = 0; // its place among SceneGpu's draws (a cull pass's slot)
    // Its meshlets (SceneGpu::buildMeshlets; 0 before): [firstMeshlet, + meshletCount) of the
    // scene's, their indices in the meshlet index buffer relative to vertexOffset.
    uint32_t firstMeshlet = 0;
    uint32_t meshletCount = 0;
    AlphaMode alphaMode = AlphaMode::Opaque;
    bool doubleSided = false;
    Aabb bounds; // world space (SceneGpu::toShading for camera-relative)
};

enum class DrawFilter { Opaque, Mask, Blend };

class SceneGpu {
  public:
    SceneGpu(GpuContext& ctx, const Scene& scene);
    ~SceneGpu();
    SceneGpu(const SceneGpu&) = delete;
    SceneGpu& operator=(const SceneGpu&) = delete;

    // The camera matrices (from the scene's camera) for this size and MSAA; the lights, relative
    // to the eye. Both may change between frames of a planned renderer (RendererSession):
    // viewGeneration() counts the changes, so a renderer knows when to update its per-view data.
    // Lights of the same count are overwritten in place (descriptors stay valid).
    void setView(uint32_t width, uint32_t height, uint32_t msaaSamples);
    void setLights(const std::vector<Light>& lights);
    uint64_t viewGeneration() const { return viewGeneration_; }
    // --shadows / --shadow-budget: the plan of which lights cast shadows (core/gpuscene/
    // shadow_plan.h), made above from this scene's shadingLights() and shadingFrame()
    // (core/passes/shadow_planner.h) and given here by the frame runner after every view or
    // light change, before a render. SceneGpu holds it: its words go into the uploaded lights
    // (LightGpu.shadow), its faces into a storage buffer (ledger: scene, shadow_faces). A plan
    // that uploads the same as the one held changes nothing. shadowGeneration() counts changes
    // of the plan's layout (which lights, their map sizes): a renderer that sized its maps for
    // one layout plans again when it changes.
    void setShadows(const ShadowSettings& settings, ShadowPlan plan);
    const ShadowSettings& shadowSettings() const { return shadowSettings_; }
    const ShadowPlan& shadowPlan() const { return shadowPlan_; }
    VkBuffer shadowFaces() const { return shadowFaces_.buffer; }
    uint64_t shadowGeneration() const { return shadowGeneration_; }

    // Specialization constants every scene shader takes (texture count, spot path, alpha mode).
    std::vector<SpecConstant> specConstants(AlphaMode mode) const;
    // Layout with set 0 = the scene, optional set 1 = the pass's own, optional set 2 = the
    // shadow maps (core/passes/shadow_maps.h), and the DrawPush range.
    VkPipelineLayout createPipelineLayout(VkDescriptorSetLayout passSet = VK_NULL_HANDLE,
                                          VkDescriptorSetLayout shadowSet = VK_NULL_HANDLE) const;
    void bindSceneSet(VkCommandBuffer cmd, VkPipelineLayout layout,
                      VkPipelineBindPoint point) const;
    // Binds `pipeline` and records the draws of one alpha mode; Blend draws are sorted back
    // to front (by the distance from the camera to each mesh's bounds centre). A null
    // pipeline (the renderer built none: no such draws) records nothing.
    void recordDraws(VkCommandBuffer cmd, VkPipelineLayout layout, DrawFilter filter,
                     VkPipeline pipeline) const;
    bool hasDraws(DrawFilter filter) const;
    // The draws of one alpha mode in the order recordDraws records them (Blend: back to
    // front), for pipelines that record draws one by one (multipass forward: per light).
    std::vector<const DrawItem*> drawList(DrawFilter filter) const;
    // Binds the scene's index buffer; DrawItem's firstIndex/vertexOffset refer to it.
    void bindIndexBuffer(VkCommandBuffer cmd) const;
    // The same index buffer as a storage buffer, for passes that fetch a triangle's vertices
    // themselves (the visibility buffer's resolve: vertices from set 0, indices from this).
    VkBuffer indexBuffer() const { return indices_.buffer; }

    // The meshlets of every draw (core/scene/meshlets.h): built from the scene's meshes and
    // uploaded by the first buildMeshlets() (a pass that culls meshlets calls it when it is
    // made; later calls do nothing), not with the rest of the scene: on the million-triangle
    // scene the build doubles the load time of runs that never draw a meshlet (docs/geometry.md).
    // Then MeshletGpu[] (include/meshlets.h; ledger: scene, meshlets), the index buffer in meshlet
    // order (scene, meshlet_indices) that indirect draws of the culled meshlets read
    // (core/passes/meshlet_cull.h), and each DrawItem's firstMeshlet/meshletCount, filled in
    // place. Every draw's triangles are its meshlets', each once.
    void buildMeshlets();
    bool meshletsBuilt() const { return meshletsBuilt_; }
    VkBuffer meshletBuffer() const { return meshlets_.buffer; }
    void bindMeshletIndexBuffer(VkCommandBuffer cmd) const;
    // The same as a storage buffer (the visibility buffer's compute rasterizer reads it).
    VkBuffer meshletIndexBuffer() const { return meshletIndices_.buffer; }
    // Per triangle of the meshlet index buffer: its triangle within its draw in the scene's
    // index buffer (MeshMeshlets::sourceTriangles), for the visibility buffer's ids, which must
    // name the triangles a whole draw names. Uploaded by the first call (ledger: scene,
    // meshlet_source_triangles), after buildMeshlets(); other pipelines never spend it.
    VkBuffer meshletSourceTriangleBuffer();
    uint32_t meshletCount() const { return meshletCount_; }
    double meshletBuildMs() const { return meshletBuildMs_; } // CPU time of the build
    // Every draw in upload order (DrawItem::index is its place).
    const std::vector<DrawItem>& draws() const { return draws_; }

    const Scene& scene() const { return scene_; }
    // What the GPU gets: camera-relative (shared.h, FrameUniforms; docs/shading.md). CPU code
    // that must agree with the shaders (culling bounds, light scissors) uses these.
    const gpu::FrameUniforms& shadingFrame() const { return shadingFrame_; }
    const std::vector<gpu::LightGpu>& shadingLights() const { return shadingLights_; }
    // The material table as uploaded (at least one entry: a default when the scene has none).
    const std::vector<gpu::MaterialGpu>& materialsGpu() const { return materialsGpu_; }
    // World -> camera-relative, in double, rounded to fp32 like the uploaded data (the box
    // rounded outward, so it still holds every relative vertex position of its mesh).
    glm::vec3 toShading(glm::vec3 world) const;
    Aabb toShading(const Aabb& world) const;
    // World-space copies (fp32 matrices composed in double, lights as the scene has them) for
    // CPU code that works in world coordinates. Far from the origin fp32 cannot hold world
    // positions precisely: prefer the shading versions there.
    const gpu::FrameUniforms& frame() const { return frame_; }
    const std::vector<gpu::LightGpu>& lightsGpu() const { return lightsGpu_; }
    uint32_t lightCount() const { return lightCount_; }

  private:
    void uploadGeometry();
    void uploadMaterials();
    void uploadTextures();
    void createDescriptors();
    void writeLightDescriptor();

    GpuContext& ctx_;
    const Scene& scene_;
    Buffer vertices_, indices_, materials_, lights_, frameBuffer_;
    Buffer meshlets_, meshletIndices_, meshletSourceTriangles_;
    std::vector<uint32_t> sourceTriangles_; // kept from buildMeshlets until uploaded
    uint32_t meshletCount_ = 0;
    double meshletBuildMs_ = 0.0;
    bool meshletsBuilt_ = false;
    std::vector<Image> textures_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout emptySetLayout_ = VK_NULL_HANDLE; // set 1 of a layout with set 2 only
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::vector<DrawItem> draws_;
    void uploadLights();
    void applyShadowPlan();

    ShadowSettings shadowSettings_;
    ShadowPlan shadowPlan_;
    Buffer shadowFaces_;
    uint64_t shadowGeneration_ = 0;

    gpu::FrameUniforms frame_{}, shadingFrame_{};
    std::vector<gpu::LightGpu> lightsGpu_, shadingLights_;
    std::vector<gpu::MaterialGpu> materialsGpu_;
    glm::dvec3 eye_{0.0};
    uint32_t lightCount_ = 0;
    bool hasSpot_ = false;
    uint64_t viewGeneration_ = 0;
};

gpu::LightGpu toGpu(const Light& light);

// One scene draw as every pass records it: DrawPush (the material, and a pass's own word pad0:
// multipass forward's light index), cull mode from the material's double-sidedness, the
// indexed draw. The caller binds the pipeline, the scene set and the index buffer.
void recordDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const DrawItem& d, uint32_t pad0 = 0);

} // namespace tp
