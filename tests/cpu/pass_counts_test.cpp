// Counts that are lower bounds (docs/efficiency.md, "Placing a pass: what is counted", issue 43
// item 1): the blended pass's transmittance resets, the raster ceilings a pass is placed
// against, the indexed triangle ceiling, and the texture fetches, atomics, MSAA edge samples
// and light-vs-tile tests counted beside the light evaluations.
#include <algorithm>
#include <gtest/gtest.h>

#include "compare/report/efficiency_json.h"
#include "core/calibrate/benches.h"
#include "core/calibrate/efficiency.h"
#include "core/calibrate/material_fetches.h"
#include "core/calibrate/pass_work.h"
#include "core/calibrate/tiled_work.h"
#include "core/passes/light_binning.h"
#include "multipass_forward/mp_settings.h"

namespace tp {
namespace {

// One pass of `uses` with the given pipeline statistics and the renderer's counted work.
struct OnePass {
    GraphDecl decl;
    std::vector<uint32_t> samples;
    PassWorkInput input(std::vector<PassCounts> counts, RendererStats stats = {},
                        double covered = 0) const {
        PassWorkInput in;
        in.decl = &decl;
        in.livePasses = {0};
        in.resourceBytes = [](uint32_t) { return uint64_t(0); };
        in.resourceSamples = [this](uint32_t r) { return samples.at(r); };
        in.counts = std::move(counts);
        in.lightWork = stats.lightWork;
        in.opWork = stats.opWork;
        in.coveredPixels = covered;
        return in;
    }
};

OnePass colourPass(const char* name, uint32_t samples, Use depthUse = Use::DepthTest) {
    OnePass p;
    ResourceHandle colour = p.decl.addResource("hdr", true),
                   depth = p.decl.addResource("depth", true);
    p.samples = {samples, samples};
    p.decl.addPass(name, {{colour, Use::ColorAttachment}, {depth, depthUse}});
    return p;
}

// The over-count behind multipass forward's blended pass: 1,000 composite fragments, 3,000 of
// its light draws and 3,000 transmittance resets (the light draws' triangles again, writing
// alpha only). One light per fragment counted 7,000 evaluations; the shaders make 3,000 plus the
// composites' directional ones.
TEST(PassWork, TheBlendedPassCountsNoLightForItsTransmittanceResets) {
    const double composites = 1000, lit = 3000, resets = 3000,
                 fragments = composites + lit + resets;
    for (double directional : {0.0, 1.0, 2.0}) {
        const double evaluated = lit + directional * composites; // what the shaders do
        RendererStats s;
        s.lightWork.push_back(
            {"blended", PassLightWork::Base::Fragments,
             mp::blendedLightsPerFragment(mp::BlendedLights::Under, directional, 64), false, ""});
        const OnePass p = colourPass("blended", 1);
        const PassWork w =
            countPassWork(p.input({{"blended", {0, 0, 0, uint64_t(fragments)}}}, s))[0];
        EXPECT_GT(fragments * 1.0, evaluated)
            << "the old count, one light per fragment, was more than done";
        EXPECT_LE(w.lightEvaluations, evaluated) << directional;
        EXPECT_FALSE(w.lightExact);
    }
    // --blended-lights additive has no resets: every fragment is a composite or a light draw.
    EXPECT_EQ(mp::blendedLightsPerFragment(mp::BlendedLights::Additive, 1, 64), 1.0);
    EXPECT_EQ(mp::blendedLightsPerFragment(mp::BlendedLights::OnePass, 1, 64), 64.0);
    EXPECT_EQ(mp::blendedSamplingShare(mp::BlendedLights::Under), 0.5);
}

// Multipass forward's light passes at 4x test depth (EQUAL) and write none; raster_msaa4 also
// writes 4x depth, which they do not pay: placed against it, they measured 110 % on an H200.
// A pass is placed against the ceiling that does no more per pixel than it: colour alone.
TEST(Efficiency, AnMsaaPassIsPlacedAgainstTheCeilingThatDoesNoMorePerPixel) {
    const CeilingRates rates = {{"rop_colour", 6.6e9},       {"raster_msaa4", 1.04e9},
                                {"rop_colour_msaa4", 1.5e9}, {"raster_depth", 13.5e9},
                                {"raster_depth_msaa4", 4e9}, {"tri_culled", 1e12},
                                {"dram_read", 1e15},         {"dram_write", 1e15}};
    const OnePass light = colourPass("light_passes", 4, Use::DepthAttachment); // the stencil mark
    PassWork w = countPassWork(light.input({{"light_passes", {1, 1, 1, 515'000'000}}}))[0];
    EXPECT_EQ(w.raster, RasterPath::Msaa);
    FrameEfficiency f = placeFrame({w}, {{"frame", 500}, {"light_passes", 450}}, rates, 0);
    EXPECT_EQ(f.passes[0].bound.ceiling, "rop_colour_msaa4");
    EXPECT_NEAR(f.passes[0].bound.ms, 515e6 / 1.5e9 * 1e3,
                1e-6); // not 515e6 / 1.04e9: 495 ms, 110 %

    OnePass prepass; // a depth prepass at 4x: depth alone
    ResourceHandle depth = prepass.decl.addResource("depth", true);
    prepass.samples = {4};
    prepass.decl.addPass("depth_prepass", {{depth, Use::DepthAttachment}});
    w = countPassWork(prepass.input({{"depth_prepass", {10, 10, 10, 0}}}, {}, 1000))[0];
    EXPECT_EQ(w.raster, RasterPath::DepthOnlyMsaa);
    f = placeFrame({w}, {{"frame", 1}, {"depth_prepass", 1}}, rates, 0);
    ASSERT_FALSE(f.passes[0].limits.empty());
    EXPECT_EQ(f.passes[0].limits[0].limit, "raster"); // no bytes: memory is not a limit
    EXPECT_EQ(f.passes[0].limits[0].ceiling, "raster_depth_msaa4");
}

TEST(Calibrate, TheTriangleCeilingDrawsAnIndexedGridOfSharedVertices) {
    const std::vector<uint32_t> two = calibrate::gridIndices(2);              // 3 x 3 vertices
    EXPECT_EQ(two, (std::vector<uint32_t>{0, 1, 3, 1, 4, 3, 1, 2, 4, 2, 5, 4, //
                                          3, 4, 6, 4, 7, 6, 4, 5, 7, 5, 8, 7}));
    for (const calibrate::Bench& b : calibrate::benches(16u << 20, true)) {
        if (std::string(b.name) != "tri_culled") continue;
        EXPECT_TRUE(b.indexed());
        EXPECT_TRUE(b.draw.cullAll);
        EXPECT_EQ(b.vertexCount(), 64u * 64 * 6); // indices of 64 x 64 cells
        EXPECT_EQ(b.work, 64.0 * 64 * 2 * 2);     // two triangles a cell, two layers
    }
}

TEST(MaterialFetches, APassIsCountedAtItsDrawsFewestTextures) {
    Scene scene;
    scene.textures.resize(3);
    Material full, bare, outOfRange;
    full.baseColorTexture = 0, full.metallicRoughnessTexture = 1, full.occlusionTexture = 2,
    full.emissiveTexture = 0;
    full.normalTexture = 1;          // sampled only with a tangent: not counted
    outOfRange.baseColorTexture = 7; // material.glsl samples nothing past the scene's textures
    scene.materials = {full, bare, outOfRange};
    EXPECT_EQ(materialFetches(scene, full), 4);
    EXPECT_EQ(materialFetches(scene, outOfRange), 0);
    DrawItem a, b;
    a.material = 0, b.material = 1;
    EXPECT_EQ(minMaterialFetches(scene, {&a}), 4.0);
    EXPECT_EQ(minMaterialFetches(scene, {&a, &b}), 0.0);
    EXPECT_EQ(minMaterialFetches(scene, {}), 0.0);
}

// deferred's and the visibility buffer's tiled_lighting at 4x: 100 edge pixels shade 3 more
// samples each, 500 lights kept over the tiles, 2,000 candidates tested.
TEST(PassWork, TiledLightingCountsEdgeSamplesAtomicsAndTests) {
    RendererStats s;
    s.lightWork.push_back(
        {"tiled_lighting", PassLightWork::Base::CoveredPixels, 2.5, false, "pixels"});
    addTiledWork(s, {"tiled_lighting", 500, 100, 2.5, 2000, 4});
    s.opWork.push_back({"tiled_lighting", PassOpWork::Kind::TextureFetches,
                        PassLightWork::Base::CoveredPixels, 3, false, ""});
    OnePass p;
    ResourceHandle g = p.decl.addResource("gbuffer", true), hdr = p.decl.addResource("hdr", true);
    p.samples = {4, 1};
    p.decl.addPass("tiled_lighting", {{g, Use::Sampled}, {hdr, Use::StorageWrite}});
    const PassWork w = countPassWork(p.input({}, s, 1000))[0];
    EXPECT_EQ(w.stage, PassStage::Compute);
    EXPECT_DOUBLE_EQ(w.lightEvaluations, 1000 * 2.5 + 100 * 3 * 2.5);
    EXPECT_EQ(w.opCount(PassOpWork::Kind::SharedAtomics), 600.0);
    EXPECT_EQ(w.opCount(PassOpWork::Kind::TileTests), 2000.0);
    EXPECT_EQ(w.opCount(PassOpWork::Kind::TextureFetches), 3000.0);

    const CeilingRates rates = {
        {"light_point", 1e9}, {"texture_fetch", 1e6}, {"shared_atomic", 1e6}};
    const FrameEfficiency f = placeFrame({w}, {{"frame", 10}, {"tiled_lighting", 10}}, rates, 0);
    const PassEfficiency& e = f.passes[0];
    ASSERT_EQ(e.limits.size(), 3u); // light ALU, texture, atomics (no bytes): tests are not placed
    EXPECT_EQ(e.bound.limit, "texture"); // 3,000 fetches at 1 M/s: 3 ms
    EXPECT_EQ(e.bound.ceiling, "texture_fetch");
    EXPECT_NEAR(e.bound.ms, 3.0, 1e-9);
    EXPECT_EQ(e.limits[2].ceiling, "shared_atomic");
    EXPECT_NEAR(e.limits[2].ms, 0.6, 1e-9);
    EXPECT_TRUE(f.missingCeilings.empty());
}

// A draw's fetches meet the fragment stage's ceiling; a pass with both kinds of atomics adds
// each at its own.
TEST(Efficiency, FetchesMeetTheirStagesCeilingAndAtomicsEachTheirOwn) {
    PassWork w;
    w.pass = "forward_opaque";
    w.stage = PassStage::Graphics;
    w.ops = {{PassOpWork::Kind::TextureFetches, 2e6},
             {PassOpWork::Kind::GlobalAtomics, 1e6},
             {PassOpWork::Kind::SharedAtomics, 4e6}};
    const CeilingRates rates = {
        {"fragment_texture_fetch", 1e9}, {"global_atomic", 1e9}, {"shared_atomic", 2e9}};
    const PassEfficiency e =
        placeFrame({w}, {{"frame", 10}, {"forward_opaque", 10}}, rates, 0).passes[0];
    ASSERT_EQ(e.limits.size(), 2u);
    EXPECT_EQ(e.limits[0].ceiling, "fragment_texture_fetch");
    EXPECT_NEAR(e.limits[0].ms, 2.0, 1e-9);
    EXPECT_EQ(e.limits[1].ceiling, "global_atomic + shared_atomic");
    EXPECT_NEAR(e.limits[1].ms, 1.0 + 2.0, 1e-9);
}

// Forward+'s light_culling on lavapipe read its depth image faster than dram_read (a storage
// buffer's load path there; on a GPU the depth the prepass wrote may still be in cache): 204 % of
// the memory limit. Image bytes are read at the faster of dram_read and image_read.
TEST(Efficiency, AnImageIsReadAtTheFasterOfTheStreamAndImageRead) {
    OnePass p;
    ResourceHandle depth = p.decl.addResource("depth", true),
                   lists = p.decl.addResource("lists", false);
    p.samples = {1, 1};
    p.decl.addPass("light_culling", {{depth, Use::Sampled}, {lists, Use::StorageRead}});
    PassWorkInput in = p.input({});
    in.resourceBytes = [](uint32_t r) { return uint64_t(r == 0 ? 1'000'000 : 1000); };
    const PassWork w = countPassWork(in)[0];
    EXPECT_EQ(w.bytesRead, 1'001'000.0);
    EXPECT_EQ(w.imageBytesRead, 1'000'000.0);
    const CeilingRates rates = {{"dram_read", 1e9}, {"dram_write", 1e9}, {"image_read", 4e9}};
    const LimitTime m =
        placeFrame({w}, {{"frame", 1}, {"light_culling", 1}}, rates, 0).passes[0].limits[0];
    EXPECT_EQ(m.limit, "memory");
    EXPECT_NEAR(m.ms, 1'000'000 / 4e9 * 1e3 + 1000 / 1e9 * 1e3, 1e-12);
}

// The GPU binning's passes were placed at 0.0 % of memory on the H200: their runs, the lights
// and the fill's atomics are outside the frame graph's uses, so nothing was counted. Now the
// fill counts an atomic and a 4-byte store per (light, tile) pair, the sort reads and writes
// every run, the binning reads every light and makes its corners' atomics: the fill is placed
// against global_atomic.
TEST(Efficiency, TheGpuBinningsAtomicsAndRunsAreCounted) {
    OnePass p;
    ResourceHandle counts = p.decl.addResource("light_bin_counts", false);
    p.samples = {1};
    for (const char* pass : {"light_binning", "light_bin_fill", "light_bin_sort"})
        p.decl.addPass(pass, {{counts, Use::StorageWrite}});
    RendererStats stats;
    la::addBinningWork(stats, 3'000'000, 65'536, 200'000);
    PassWorkInput in = p.input({}, stats);
    in.livePasses = {0, 1, 2};
    in.resourceBytes = [](uint32_t) { return uint64_t(1000); };
    const std::vector<PassWork> w = countPassWork(in);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0].bytesRead, 65'536.0 * 20); // each light's index, position and range
    EXPECT_EQ(w[0].opCount(PassOpWork::Kind::GlobalAtomics), 200'000.0); // the corners
    EXPECT_EQ(w[1].opCount(PassOpWork::Kind::GlobalAtomics), 3'000'000.0);
    EXPECT_EQ(w[1].bytesWritten, 1000 + 3'000'000.0 * 4);
    EXPECT_EQ(w[2].bytesRead, 3'000'000.0 * 4);
    EXPECT_EQ(w[2].bytesWritten, 1000 + 3'000'000.0 * 4);
    const CeilingRates rates = {{"dram_read", 4.5e12}, {"dram_write", 4.2e12}, {"global_atomic", 1e11}};
    const FrameEfficiency f = placeFrame(
        w, {{"frame", 1}, {"light_binning", 0.05}, {"light_bin_fill", 0.1}, {"light_bin_sort", 0.2}},
        rates, 0);
    EXPECT_EQ(f.passes[1].bound.limit, "atomics");
    EXPECT_NEAR(f.passes[1].bound.ms, 3e6 / 1e11 * 1e3, 1e-9);
    EXPECT_EQ(f.passes[2].bound.limit, "memory");
    EXPECT_GT(f.passes[2].bound.ms, 0.002); // 24 MB at 4.2-4.5 TB/s
    EXPECT_EQ(cli::passWorkJson(w)[1]["untracked_bytes_written"], 12'000'000.0);
}

// Multipass forward's blended pass on the H200 took 28.8 ms with no light and no texture: its
// draws, a draw per light and blended mesh, which nothing counted. A pass's draws are placed
// against draw_culled (indirect draws of a culled triangle: the least a draw costs).
TEST(Efficiency, DrawsArePlacedAgainstTheDrawCeiling) {
    const OnePass p = colourPass("blended", 1);
    RendererStats stats;
    stats.opWork.push_back({"blended", PassOpWork::Kind::Draws, PassLightWork::Base::Items, 1.0,
                            true, "the draws recorded", 20'000});
    const PassWork w = countPassWork(p.input({{"blended", {60'000, 60'000, 1000, 1000}}}, stats))[0];
    EXPECT_EQ(w.opCount(PassOpWork::Kind::Draws), 20'000.0);
    const CeilingRates rates = {{"rop_colour", 6.6e9}, {"tri_culled", 5e9}, {"draw_culled", 1e6},
                                {"dram_read", 1e15},   {"dram_write", 1e15}};
    const FrameEfficiency f = placeFrame({w}, {{"frame", 40}, {"blended", 30}}, rates, 0);
    EXPECT_EQ(f.passes[0].bound.limit, "draws");
    EXPECT_EQ(f.passes[0].bound.ceiling, "draw_culled");
    EXPECT_NEAR(f.passes[0].bound.ms, 20.0, 1e-9); // 20,000 draws at a million a second
    EXPECT_EQ(cli::passWorkJson({w})[0]["draws"], 20'000.0);
}

// Deferred's G-buffer writes three or four targets a fragment; placed against rop_colour (one
// RGBA16F target) its 1x pass on the H200 read 27 %, a ceiling that does less than the pass.
// Three colour attachments or more: rop_gbuffer (three, the compact G-buffer's formats); two: a
// pass that does less than that ceiling stays at the one-target ones.
TEST(Efficiency, APassWritingThreeTargetsIsPlacedAgainstTheGBufferCeiling) {
    const CeilingRates rates = {{"rop_colour", 6.6e9},      {"rop_colour_msaa4", 1.5e9},
                                {"rop_gbuffer", 2e9},       {"rop_gbuffer_msaa4", 0.5e9},
                                {"tri_culled", 1e12},       {"dram_read", 1e15},
                                {"dram_write", 1e15}};
    for (uint32_t targets : {2u, 3u, 4u})
        for (uint32_t samples : {1u, 4u}) {
            OnePass p;
            std::vector<PassUse> uses;
            for (uint32_t t = 0; t < targets; ++t)
                uses.push_back({p.decl.addResource("g" + std::to_string(t), true), Use::ColorAttachment});
            uses.push_back({p.decl.addResource("depth", true), Use::DepthAttachment});
            p.samples.assign(targets + 1, samples);
            p.decl.addPass("gbuffer", uses);
            const PassWork w = countPassWork(p.input({{"gbuffer", {1, 1, 1, 1'000'000}}}))[0];
            const FrameEfficiency f = placeFrame({w}, {{"frame", 10}, {"gbuffer", 5}}, rates, 0);
            const bool g = targets >= 3;
            const std::string want = std::string(g ? "rop_gbuffer" : "rop_colour") +
                                     (samples > 1 ? "_msaa4" : "");
            EXPECT_EQ(f.passes[0].bound.ceiling, want) << targets << " targets, " << samples << "x";
            EXPECT_EQ(w.raster, g ? (samples > 1 ? RasterPath::GBufferMsaa : RasterPath::GBuffer)
                                  : (samples > 1 ? RasterPath::Msaa : RasterPath::Colour));
        }
}

// Deferred's tile_depth_bounds at 4x on lavapipe read its multisampled depth at 119 % of
// image_read: a texel's four samples read together go faster a byte than single texels. A
// multisampled image's bytes are read at the fastest of dram_read, image_read and
// image_read_msaa4; a single-sample image's never at image_read_msaa4.
TEST(Efficiency, AMultisampledImageIsReadAtImageReadMsaa4) {
    OnePass p;
    ResourceHandle depth = p.decl.addResource("depth_msaa", true),
                   single = p.decl.addResource("depth", true);
    p.samples = {4, 1};
    p.decl.addPass("tile_depth_bounds", {{depth, Use::Sampled}, {single, Use::Sampled}});
    PassWorkInput in = p.input({});
    in.resourceBytes = [](uint32_t r) { return uint64_t(r == 0 ? 4'000'000 : 1'000'000); };
    const PassWork w = countPassWork(in)[0];
    EXPECT_EQ(w.imageBytesRead, 5'000'000.0);
    EXPECT_EQ(w.msaaImageBytesRead, 4'000'000.0);
    const CeilingRates rates = {{"dram_read", 1e9},
                                {"dram_write", 1e9},
                                {"image_read", 2e9},
                                {"image_read_msaa4", 8e9}};
    const LimitTime m =
        placeFrame({w}, {{"frame", 1}, {"tile_depth_bounds", 1}}, rates, 0).passes[0].limits[0];
    EXPECT_EQ(m.ceiling, "dram_read, image_read, image_read_msaa4 + dram_write");
    EXPECT_NEAR(m.ms, 4'000'000 / 8e9 * 1e3 + 1'000'000 / 2e9 * 1e3, 1e-12);
    // A calibration from before the bench: the multisampled bytes at image_read, named missing.
    CeilingRates old = rates;
    old.erase("image_read_msaa4");
    const FrameEfficiency f = placeFrame({w}, {{"frame", 1}, {"tile_depth_bounds", 1}}, old, 0);
    EXPECT_NEAR(f.passes[0].limits[0].ms, 5'000'000 / 2e9 * 1e3, 1e-12);
    EXPECT_NE(std::find(f.missingCeilings.begin(), f.missingCeilings.end(), "image_read_msaa4"),
              f.missingCeilings.end());
}

// report.json's run.work: each count beside the light evaluations, with how it was counted.
TEST(PassWork, RunWorkJsonHasEachCountWithItsHowAndExactness) {
    RendererStats s;
    addTiledWork(s, {"tiled_lighting", 500, 100, 2.5, 2000, 4});
    OnePass p;
    ResourceHandle hdr = p.decl.addResource("hdr", true);
    p.samples = {1};
    p.decl.addPass("tiled_lighting", {{hdr, Use::StorageWrite}});
    const nlohmann::json j = cli::passWorkJson(countPassWork(p.input({}, s, 1000)))[0];
    EXPECT_EQ(j["shared_atomics"], 600.0);
    EXPECT_EQ(j["shared_atomics_exact"], false);
    EXPECT_EQ(j["light_tile_tests"], 2000.0);
    EXPECT_NE(j["light_tile_tests_how"].get<std::string>().find("at most"), std::string::npos);
    EXPECT_EQ(j["light_evaluations"], 100 * 3 * 2.5);
}

} // namespace
} // namespace tp
