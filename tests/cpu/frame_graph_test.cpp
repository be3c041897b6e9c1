// The frame graph's planning half on the CPU (no device), as Filament tests its frame
// graph: culling, declaration order, barriers derived from uses, declaration errors, and
// the reflection check of a pass's bindings against embedded shaders.
#include <gtest/gtest.h>

#include "core/gpu/embedded_shaders.h"
#include "core/gpu/graph_plan.h"
#include "core/gpu/shader_reflection.h"
#include "deferred/deferred_shared.h"
#include "include/shared.h"

namespace tp {
namespace {

std::vector<std::string> liveNames(const GraphDecl& g, const GraphPlan& plan) {
    std::vector<std::string> out;
    for (const PlannedPass& p : plan.passes)
        out.push_back(g.passes()[p.pass].name);
    return out;
}

// The error message a declaration mistake throws, or "" when none is thrown.
template <class F> std::string errorOf(F&& f) {
    try {
        f();
    } catch (const GraphError& e) {
        return e.what();
    }
    return "";
}

TEST(FrameGraphPlan, CullsPassesWhoseOutputsNobodyReads) {
    GraphDecl g;
    ResourceHandle hdr = g.addResource("hdr", true), stats = g.addResource("stats", false),
                   debug = g.addResource("debug", true);
    g.addPass("shade", {{hdr, Use::ColorAttachment}});
    g.addPass("stats", {{hdr, Use::Sampled}, {stats, Use::StorageWrite}});
    g.addPass("debug_view",
              {{stats, Use::StorageRead}, {debug, Use::StorageWrite}}); // end of a culled chain
    g.exportResource("hdr", hdr);
    GraphPlan plan = g.plan();
    EXPECT_EQ(liveNames(g, plan), std::vector<std::string>{"shade"});
    EXPECT_EQ(plan.live, (std::vector<bool>{true, false, false}));
    EXPECT_TRUE(plan.resources[hdr.index].allocated);
    EXPECT_FALSE(plan.resources[stats.index].allocated); // only culled passes touch it
    EXPECT_FALSE(plan.resources[debug.index].allocated);
}

TEST(FrameGraphPlan, KeepsAChainThatAnExportNeedsAndItsDeclarationOrder) {
    GraphDecl g;
    ResourceHandle depth = g.addResource("depth", true), lists = g.addResource("lists", false),
                   hdr = g.addResource("hdr", true), unused = g.addResource("unused", true);
    g.addPass("prepass", {{depth, Use::DepthAttachment}});
    g.addPass("unused_pass", {{unused, Use::ColorAttachment}});
    g.addPass("culling", {{depth, Use::Sampled}, {lists, Use::StorageWrite}});
    g.addPass("shading",
              {{hdr, Use::ColorAttachment}, {depth, Use::DepthTest}, {lists, Use::StorageRead}});
    g.exportResource("hdr", hdr);
    GraphPlan plan = g.plan();
    EXPECT_EQ(liveNames(g, plan), (std::vector<std::string>{"prepass", "culling", "shading"}));
    EXPECT_EQ(plan.resources[lists.index].firstWriter, "culling");
    EXPECT_EQ(plan.resources[depth.index].imageUsage,
              VkImageUsageFlags(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                VK_IMAGE_USAGE_SAMPLED_BIT));
    EXPECT_EQ(
        plan.resources[hdr.index].imageUsage,
        VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT));
}

TEST(FrameGraphPlan, AttachmentWriteThenSampledReadGivesTheExpectedBarriers) {
    GraphDecl g;
    ResourceHandle gbuf = g.addResource("gbuffer", true), hdr = g.addResource("hdr", true);
    g.addPass("gbuffer", {{gbuf, Use::ColorAttachment}});
    g.addPass("lighting", {{gbuf, Use::Sampled, 0}, {hdr, Use::StorageWrite, 1}});
    g.exportResource("hdr", hdr);
    GraphPlan plan = g.plan();
    ASSERT_EQ(plan.passes.size(), 2u);

    // First use in a frame: from UNDEFINED, after whatever the previous frame did.
    ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
    const PlanBarrier& first = plan.passes[0].barriers[0];
    EXPECT_EQ(first.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
    EXPECT_EQ(first.newLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(first.srcStages, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT);
    EXPECT_EQ(first.srcAccess, VK_ACCESS_2_MEMORY_WRITE_BIT);

    ASSERT_EQ(plan.passes[1].barriers.size(), 2u);
    const PlanBarrier& read = plan.passes[1].barriers[0];
    EXPECT_EQ(read.resource, gbuf.index);
    EXPECT_TRUE(read.image);
    EXPECT_EQ(read.oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(read.newLayout, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    EXPECT_EQ(read.srcStages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(read.srcAccess,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(read.dstStages,
              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(read.dstAccess, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    EXPECT_EQ(plan.passes[1].barriers[1].newLayout, VK_IMAGE_LAYOUT_GENERAL);

    // After the frame every export is left for a transfer read.
    ASSERT_EQ(plan.exportBarriers.size(), 1u);
    EXPECT_EQ(plan.exportBarriers[0].oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(plan.exportBarriers[0].newLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(plan.exportBarriers[0].srcAccess,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(plan.exportBarriers[0].dstAccess, VK_ACCESS_2_TRANSFER_READ_BIT);
}

TEST(FrameGraphPlan, ReadAfterReadNeedsNoBarrierButTheNextWriteWaitsForBothReaders) {
    GraphDecl g;
    ResourceHandle lists = g.addResource("lists", false), out = g.addResource("out", false);
    g.addPass("write", {{lists, Use::StorageWrite}});
    g.addPass("read_a", {{lists, Use::StorageRead}, {out, Use::StorageWrite}});
    g.addPass("read_b", {{lists, Use::StorageRead}, {out, Use::StorageWrite}});
    g.addPass("rewrite", {{lists, Use::TransferDst}, {out, Use::StorageWrite}});
    g.exportResource("out", out);
    GraphPlan plan = g.plan();
    ASSERT_EQ(plan.passes.size(), 4u);
    auto barriersOn = [&](size_t pass, ResourceHandle h) {
        std::vector<PlanBarrier> out;
        for (const PlanBarrier& b : plan.passes[pass].barriers)
            if (b.resource == h.index) out.push_back(b);
        return out;
    };
    ASSERT_EQ(barriersOn(1, lists).size(), 1u); // write -> read
    EXPECT_FALSE(barriersOn(1, lists)[0].image);
    EXPECT_EQ(barriersOn(1, lists)[0].srcAccess,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_TRUE(barriersOn(2, lists).empty());  // read -> read
    ASSERT_EQ(barriersOn(3, lists).size(), 1u); // read -> write: an execution dependency only
    EXPECT_EQ(barriersOn(3, lists)[0].srcAccess, VkAccessFlags2(0));
    EXPECT_EQ(barriersOn(3, lists)[0].dstStages, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
}

// Forward+'s depth: written by the prepass, sampled by the culling pass, then depth-tested by
// the shading pass in the same layout. The depth test reads in other stages with other
// access than the sampling barrier made visible: it needs a barrier of its own, chained.
TEST(FrameGraphPlan, DepthTestAfterASampledReadGetsAChainedBarrier) {
    GraphDecl g;
    ResourceHandle depth = g.addResource("depth", true), lists = g.addResource("lists", false),
                   hdr = g.addResource("hdr", true);
    g.addPass("prepass", {{depth, Use::DepthAttachment}});
    g.addPass("culling", {{depth, Use::Sampled, 0}, {lists, Use::StorageWrite, 1}});
    g.addPass("shading",
              {{depth, Use::DepthTest}, {lists, Use::StorageRead, 0}, {hdr, Use::ColorAttachment}});
    g.addPass("again",
              {{depth, Use::DepthTest}, {lists, Use::StorageRead, 0}, {hdr, Use::ColorAttachment}});
    g.exportResource("hdr", hdr);
    g.exportResource("depth", depth);
    GraphPlan plan = g.plan();
    ASSERT_EQ(plan.passes.size(), 4u);
    auto onDepth = [&](size_t pass) {
        std::vector<PlanBarrier> out;
        for (const PlanBarrier& b : plan.passes[pass].barriers)
            if (b.resource == depth.index) out.push_back(b);
        return out;
    };
    ASSERT_EQ(onDepth(1).size(), 1u); // write -> sampled: layout change, shader stages
    ASSERT_EQ(onDepth(2).size(), 1u);
    const PlanBarrier chained = onDepth(2)[0];
    EXPECT_EQ(chained.oldLayout, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    EXPECT_EQ(chained.newLayout, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    EXPECT_EQ(chained.srcStages,
              onDepth(1)[0].dstStages);              // starts where the sampling barrier ended
    EXPECT_EQ(chained.srcAccess, VkAccessFlags2(0)); // the writes are already available
    EXPECT_TRUE(chained.dstStages & VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT);
    EXPECT_TRUE(chained.dstAccess & VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    EXPECT_TRUE(onDepth(3).empty()); // the same depth test again: covered
}

TEST(FrameGraphPlan, ReadingWhatNoPassWroteIsAnErrorNamingPassAndResource) {
    GraphDecl g;
    ResourceHandle lists = g.addResource("light_lists", false), hdr = g.addResource("hdr", true);
    g.addPass("shading", {{hdr, Use::ColorAttachment}, {lists, Use::StorageRead}});
    g.addPass("culling", {{lists, Use::StorageWrite}}); // declared too late
    g.exportResource("hdr", hdr);
    EXPECT_EQ(errorOf([&] { g.plan(); }),
              "pass 'shading' reads 'light_lists' (storage read) before any pass writes it");
}

TEST(FrameGraphPlan, AnExportNoPassWritesIsAnError) {
    GraphDecl g;
    ResourceHandle hdr = g.addResource("hdr", true);
    g.exportResource("hdr", hdr);
    EXPECT_EQ(errorOf([&] { g.plan(); }), "export 'hdr' ('hdr') is never written");
    EXPECT_EQ(errorOf([&] { g.exportResource("depth", ResourceHandle{}); }),
              "export 'depth' names an unknown resource");
}

TEST(FrameGraphPlan, ABufferUsedAsAnImageIsAnError) {
    GraphDecl g;
    ResourceHandle stats = g.addResource("tile_stats", false);
    g.addPass("fill", {{stats, Use::StorageWrite}}); // storage: fine on a buffer
    EXPECT_EQ(errorOf([&] {
                  g.addPass("view", {{stats, Use::Sampled}});
              }),
              "pass 'view' uses buffer 'tile_stats' as sampled, which needs an image");
    EXPECT_EQ(errorOf([&] {
                  g.addPass("draw", {{stats, Use::ColorAttachment}});
              }),
              "pass 'draw' uses buffer 'tile_stats' as colour attachment, which needs an image");
    EXPECT_EQ(errorOf([&] {
                  g.addPass("bad", {{ResourceHandle{7}, Use::Sampled}});
              }),
              "pass 'bad' uses an unknown resource");
    EXPECT_EQ(errorOf([&] {
                  g.addPass("fill", {{stats, Use::StorageWrite}});
              }),
              "pass 'fill' declared twice");
}

TEST(FrameGraphPlan, BindingsAreCheckedAndGiveTheDescriptorTypes) {
    GraphDecl g;
    ResourceHandle img = g.addResource("img", true), buf = g.addResource("buf", false);
    EXPECT_EQ(errorOf([&] {
                  g.addPass("twice", {{img, Use::Sampled, 3}, {buf, Use::StorageRead, 3}});
              }),
              "pass 'twice' declares binding 3 twice");
    EXPECT_EQ(errorOf([&] {
                  g.addPass("attach", {{img, Use::ColorAttachment, 0}});
              }),
              "pass 'attach' binds 'img' at binding 0 as colour attachment, which no descriptor "
              "can hold");
    EXPECT_EQ(descriptorType(Use::Sampled, true), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(descriptorType(Use::DepthTest, true), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    EXPECT_EQ(descriptorType(Use::StorageWrite, true), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    EXPECT_EQ(descriptorType(Use::StorageRead, false), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

TEST(FrameGraphPlan, AnAttachmentRecordedButNotDeclaredIsAnError) {
    GraphDecl g;
    ResourceHandle hdr = g.addResource("hdr", true), hdrMsaa = g.addResource("hdr_msaa", true);
    g.addPass("shade", {{hdrMsaa, Use::ColorAttachment}});
    EXPECT_EQ(errorOf([&] { g.expectUse(0, hdrMsaa, Use::ColorAttachment); }), "");
    EXPECT_EQ(errorOf([&] { g.expectUse(0, hdr, Use::ColorResolve); }),
              "pass 'shade' uses 'hdr' as colour resolve without declaring it");
}

TEST(ShaderReflection, EveryEmbeddedShaderReflects) {
    size_t withPassSet = 0;
    for (const EmbeddedShader& s : embeddedShaders()) {
        EXPECT_EQ(errorOf([&] { reflectShaderSet(s.name, TP_SET_PASS); }), "") << s.name;
        withPassSet += reflectShaderSet(s.name, TP_SET_PASS).empty() ? 0 : 1;
    }
    EXPECT_GT(withPassSet, 0u);
}

TEST(ShaderReflection, ReadsThePassSetOfAnEmbeddedShader) {
    const std::vector<SetBinding>& b = reflectShaderSet("blended_forward_frag", TP_SET_PASS);
    // The transparent lists (light indices), their slice rows (clustered), the blended depth
    // bounds, the lights' and the materials' uniform-buffer copies.
    ASSERT_EQ(b.size(), 5u);
    EXPECT_EQ(b[0].binding, uint32_t(TP_BF_BINDING_LISTS));
    EXPECT_EQ(b[0].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(b[1].binding, uint32_t(TP_BF_BINDING_MASKS));
    EXPECT_EQ(b[1].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(b[2].binding, uint32_t(TP_BF_BINDING_BLEND_BOUNDS));
    EXPECT_EQ(b[2].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_EQ(b[3].binding, uint32_t(TP_BF_BINDING_LIGHTS_UBO));
    EXPECT_EQ(b[3].type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(b[4].binding, uint32_t(TP_BF_BINDING_MATERIALS_UBO));
    EXPECT_EQ(b[4].type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_TRUE(reflectShaderSet("scene_vert", TP_SET_PASS).empty());
}

TEST(ShaderReflection, AMismatchedPassSetIsAOneLineErrorNamingPassBindingAndShader) {
    PassSet set;
    set.pass = "transparent_forward";
    set.bindings = {{TP_BF_BINDING_LISTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                    {TP_BF_BINDING_MASKS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                    {TP_BF_BINDING_BLEND_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                    {TP_BF_BINDING_LIGHTS_UBO, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                    {TP_BF_BINDING_MATERIALS_UBO, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    EXPECT_EQ(errorOf([&] {
                  checkPassBindings(&set, {"scene_vert", "blended_forward_frag"});
              }),
              "");

    PassSet wrongType = set;
    wrongType.bindings[0].type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    EXPECT_EQ(
        errorOf([&] { checkPassBindings(&wrongType, {"blended_forward_frag"}); }),
        "pass 'transparent_forward': binding " + std::to_string(TP_BF_BINDING_LISTS) +
            " (storage image) is declared as storage buffer by shader 'blended_forward_frag'");

    PassSet extra = set;
    extra.bindings.push_back({6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    EXPECT_EQ(errorOf([&] { checkPassBindings(&extra, {"blended_forward_frag"}); }),
              "pass 'transparent_forward': binding 6 (storage buffer) is not declared by shader "
              "'blended_forward_frag'");

    PassSet missing = set;
    missing.bindings.clear();
    EXPECT_NE(errorOf([&] {
                  checkPassBindings(&missing, {"blended_forward_frag"});
              }).find("shader 'blended_forward_frag' declares binding"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  checkPassBindings(nullptr, {"blended_forward_frag"});
              }).find("a pipeline without a pass set"),
              std::string::npos);
    EXPECT_EQ(errorOf([&] { checkPassBindings(nullptr, {"scene_vert"}); }), "");
}

} // namespace
} // namespace tp
