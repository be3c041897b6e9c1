// Each pass's counted work and its place against ceilings (core/calibrate/pass_work.h,
// efficiency.h, benches.h), against passes and benchmarks computed by hand.
#include <gtest/gtest.h>

#include <set>

#include "core/calibrate/benches.h"
#include "core/calibrate/calibration.h"
#include "core/calibrate/efficiency.h"
#include "core/calibrate/pass_work.h"

namespace tp {
namespace {

constexpr double kFrameW = 1920, kFrameH = 1080;

// A graph of the given images (bytes per texel, samples), the passes' inputs.
struct Graph {
    GraphDecl decl;
    std::vector<uint64_t> bytes;
    std::vector<uint32_t> samples;
    ResourceHandle image(const char* name, uint32_t texelBytes, uint32_t s = 1) {
        bytes.push_back(uint64_t(kFrameW * kFrameH) * texelBytes * s);
        samples.push_back(s);
        return decl.addResource(name, true);
    }
    PassWorkInput input(std::vector<PassCounts> counts = {}, std::vector<PassLightWork> light = {}) const {
        PassWorkInput in;
        in.decl = &decl;
        for (uint32_t i = 0; i < decl.passes().size(); ++i)
            in.livePasses.push_back(i);
        in.resourceBytes = [this](uint32_t r) { return bytes.at(r); };
        in.resourceSamples = [this](uint32_t r) { return samples.at(r); };
        in.counts = std::move(counts);
        in.lightWork = std::move(light);
        return in;
    }
};

TEST(PassWork, AFullScreenCopyReadsItsSourceAndWritesItsTarget) {
    Graph g;
    ResourceHandle src = g.image("src", 8), dst = g.image("dst", 8);
    g.decl.addPass("copy", {{src, Use::Sampled, 0}, {dst, Use::ColorAttachment}});
    const std::vector<PassWork> w = countPassWork(g.input());
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].bytesRead, kFrameW * kFrameH * 8);
    EXPECT_EQ(w[0].bytesWritten, kFrameW * kFrameH * 8);
    EXPECT_EQ(w[0].stage, PassStage::Graphics);
    EXPECT_EQ(w[0].raster, RasterPath::Colour);
    EXPECT_FALSE(w[0].counted);
}

TEST(PassWork, AGBufferWriteAt4xCountsEverySampleOfEveryTargetAndTheDepthTest) {
    Graph g;
    ResourceHandle albedo = g.image("albedo", 4, 4), normal = g.image("normal", 8, 4),
                   material = g.image("material", 4, 4), depth = g.image("depth", 4, 4);
    g.decl.addPass("gbuffer", {{albedo, Use::ColorAttachment},
                               {normal, Use::ColorAttachment},
                               {material, Use::ColorAttachment},
                               {depth, Use::DepthAttachment}});
    PassCounts counts{"gbuffer", {1000, 900, 950, 3'000'000}};
    const PassWork w = countPassWork(g.input({counts}))[0];
    // (4 + 8 + 4) bytes per sample written, and the depth test reads and writes 4 per sample.
    EXPECT_EQ(w.bytesWritten, kFrameW * kFrameH * 4 * (4 + 8 + 4 + 4));
    EXPECT_EQ(w.bytesRead, kFrameW * kFrameH * 4 * 4);
    EXPECT_EQ(w.raster, RasterPath::GBufferMsaa); // three targets: rop_gbuffer_msaa4
    EXPECT_TRUE(w.counted);
    EXPECT_EQ(w.counts.fragmentInvocations, 3'000'000u);
}

TEST(PassWork, ADrawOfAFewFragmentsMovesOnlyTheirPixelsOfItsAttachments) {
    Graph g;
    ResourceHandle hdr = g.image("hdr", 8), depth = g.image("depth", 4);
    g.decl.addPass("blended", {{hdr, Use::ColorAttachment}, {depth, Use::DepthTest}});
    PassWorkInput in = g.input({{"blended", {2, 2, 2, 1000}}});
    in.framePixels = kFrameW * kFrameH;
    const PassWork w = countPassWork(in)[0];
    EXPECT_EQ(w.bytesWritten, 1000.0 * 8);
    EXPECT_EQ(w.bytesRead, 1000.0 * 4);
}

TEST(PassWork, StorageAndTransferPassesAreComputeOrNeither) {
    Graph g;
    ResourceHandle a = g.image("a", 4), b = g.image("b", 4);
    g.decl.addPass("clear", {{a, Use::TransferDst}});
    g.decl.addPass("lighting", {{a, Use::StorageRead, 0}, {b, Use::StorageWrite, 1}});
    const std::vector<PassWork> w = countPassWork(g.input());
    EXPECT_EQ(w[0].stage, PassStage::Other);
    EXPECT_EQ(w[0].bytesWritten, kFrameW * kFrameH * 4);
    EXPECT_EQ(w[1].stage, PassStage::Compute);
    EXPECT_EQ(w[1].raster, RasterPath::None);
}

TEST(PassWork, LightEvaluationsMultiplyTheRenderersPerItemCountByFragmentsOrCoveredPixels) {
    Graph g;
    ResourceHandle c = g.image("c", 8);
    g.decl.addPass("shade", {{c, Use::ColorAttachment}});
    g.decl.addPass("tiles", {{c, Use::StorageWrite, 0}});
    PassWorkInput in = g.input({{"shade", {10, 10, 10, 5000}}},
                               {{"shade", PassLightWork::Base::Fragments, 3.5, false, "mean"},
                                {"tiles", PassLightWork::Base::CoveredPixels, 2.0, true, "exact"}});
    in.coveredPixels = 1234;
    const std::vector<PassWork> w = countPassWork(in);
    EXPECT_EQ(w[0].lightEvaluations, 5000 * 3.5);
    EXPECT_FALSE(w[0].lightExact);
    EXPECT_EQ(w[1].lightEvaluations, 1234 * 2.0);
    EXPECT_TRUE(w[1].lightExact);
}

TEST(Efficiency, TheBindingCeilingIsTheLimitTheWorkWouldTakeLongestAt) {
    PassWork w;
    w.pass = "shade";
    w.stage = PassStage::Graphics;
    w.raster = RasterPath::Colour;
    w.counted = true;
    w.bytesRead = 2e9;  // 1 s at 2 GB/s
    w.bytesWritten = 0;
    w.counts = {1000, 1000, 1000, 1'000'000'000};
    w.rasterPixels = 1e9; // 0.5 s at 2 Gpixel/s
    w.lightEvaluations = 1.2e9; // 75 % point at 1 G/s (0.9 s) + 25 % spot at 0.5 G/s (0.6 s)
    const CeilingRates rates = {{"dram_read", 2e9}, {"dram_write", 2e9},         {"fragment_light_point", 1e9},
                                {"fragment_light_spot", 0.5e9}, {"rop_colour", 2e9}, {"tri_culled", 1e9},
                                {"fragment_fma", 100e9}};
    const std::vector<TimingStats> t = {{"frame", 4000}, {"shade", 3000}};
    const FrameEfficiency f = placeFrame({w}, t, rates, 0.25);
    ASSERT_EQ(f.passes.size(), 1u);
    const PassEfficiency& e = f.passes[0];
    EXPECT_EQ(e.limits.size(), 4u);
    EXPECT_EQ(e.bound.limit, "light_alu");
    EXPECT_NEAR(e.bound.ms, 1500, 1e-9);
    EXPECT_NEAR(e.percent, 50, 1e-9);
    EXPECT_NEAR(f.boundSumMs, 1500, 1e-9);
    EXPECT_NEAR(f.percent, 37.5, 1e-9);
    // The roofline: 1.5 s of the 100 GFLOP/s fragment FMA loop, against 2 GB.
    EXPECT_NEAR(e.flops, 150e9, 1);
    EXPECT_EQ(e.roof, "fragment_fma");
    EXPECT_TRUE(f.missingCeilings.empty());
}

TEST(Efficiency, ACeilingTheCalibrationLacksIsNamedNotGuessed) {
    PassWork w;
    w.pass = "lighting";
    w.stage = PassStage::Compute;
    w.lightEvaluations = 100;
    const FrameEfficiency f = placeFrame({w}, {{"frame", 1}, {"lighting", 1}}, {{"dram_read", 1e9}}, 0);
    EXPECT_EQ(f.missingCeilings, (std::vector<std::string>{"light_point"}));
    EXPECT_EQ(f.passes[0].bound.ms, 0);
}

TEST(Efficiency, TransfersAreNotPlaced) {
    PassWork w;
    w.pass = "clear";
    w.stage = PassStage::Other;
    w.bytesWritten = 1e9;
    const FrameEfficiency f = placeFrame({w}, {{"frame", 1}, {"clear", 1}}, {{"dram_write", 1e9}}, 0);
    EXPECT_TRUE(f.passes[0].limits.empty());
    EXPECT_EQ(f.boundSumMs, 0);
}

TEST(Calibrate, EveryBenchmarksWorkIsCountedFromItsSize) {
    const std::vector<calibrate::Bench> b = calibrate::benches(16u << 20, true);
    std::set<std::string> names;
    for (const calibrate::Bench& x : b) {
        EXPECT_TRUE(names.insert(x.name).second) << x.name;
        EXPECT_GT(x.work, 0) << x.name;
    }
    EXPECT_EQ(std::vector<std::string>(ceilingNames()).size(), b.size());
    auto find = [&](const std::string& n) {
        for (const calibrate::Bench& x : b)
            if (x.name == n) return x;
        ADD_FAILURE() << n;
        return b[0];
    };
    EXPECT_EQ(find("dram_read").work, double(16u << 20));     // the buffer, once
    EXPECT_EQ(find("dram_copy").work, 2.0 * double(16u << 20)); // read and written
    const calibrate::Bench small = find("tri_small");          // 128 / 2 = 64 cells a row, 2 layers
    EXPECT_EQ(small.work, 64.0 * 64 * 2 * 2);
    EXPECT_EQ(small.vertexCount(), 64u * 64 * 6);
    EXPECT_EQ(small.instanceCount(), 2u);
    EXPECT_EQ(find("fragment_fma").work, 128.0 * 128 * 16 * 64); // pixels x steps x 64 FLOPs
    EXPECT_EQ(find("raster_msaa4").draw.samples, VK_SAMPLE_COUNT_4_BIT);
    EXPECT_TRUE(find("tri_culled").draw.cullAll);
}

} // namespace
} // namespace tp
