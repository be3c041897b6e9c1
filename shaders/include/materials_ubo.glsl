// The materials' uniform-buffer copy (include/materials_ubo.h). The includer defines
// TP_MATERIALS_UBO_BINDING (the binding in its pass set) and TP_MATERIALS_UBO_SPEC (the
// constant that says whether the copy is read; the host binds a one-material stand-in
// otherwise), after include/scene_bindings.glsl and before include/scene_inputs.glsl, whose
// material it becomes (TP_MATERIAL_OF).
#ifndef TP_MATERIALS_UBO_GLSL
#define TP_MATERIALS_UBO_GLSL
#include "include/materials_ubo.h"

layout(constant_id = TP_MATERIALS_UBO_SPEC) const bool kMaterialsUbo = false;
layout(std140, set = TP_SET_PASS, binding = TP_MATERIALS_UBO_BINDING) uniform MaterialUboBlock {
    MaterialGpu uboMaterials[TP_MATERIALS_UBO_CAPACITY];
};

// The scene's material `index`. Member by member: the block's std140 struct is another SPIR-V
// type than MaterialGpu, and a whole-struct copy between the two is not valid SPIR-V 1.0.
MaterialGpu sceneMaterial(uint index) {
    if (!kMaterialsUbo) return materials[index];
    uint i = min(index, TP_MATERIALS_UBO_CAPACITY - 1u);
    MaterialGpu m;
    m.baseColorFactor = uboMaterials[i].baseColorFactor;
    m.emissive = uboMaterials[i].emissive;
    m.alphaCutoff = uboMaterials[i].alphaCutoff;
    m.metallic = uboMaterials[i].metallic;
    m.roughness = uboMaterials[i].roughness;
    m.normalScale = uboMaterials[i].normalScale;
    m.occlusionStrength = uboMaterials[i].occlusionStrength;
    m.baseColorTexture = uboMaterials[i].baseColorTexture;
    m.metallicRoughnessTexture = uboMaterials[i].metallicRoughnessTexture;
    m.normalTexture = uboMaterials[i].normalTexture;
    m.occlusionTexture = uboMaterials[i].occlusionTexture;
    m.emissiveTexture = uboMaterials[i].emissiveTexture;
    m.alphaMode = uboMaterials[i].alphaMode;
    m.doubleSided = uboMaterials[i].doubleSided;
    m.pad0 = 0u;
    return m;
}
#define TP_MATERIAL_OF(index) sceneMaterial(index)
#endif
