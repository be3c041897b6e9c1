#include "compare/report/compare_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/gpu/context.h"
#include "core/image/metrics.h"
#include "core/runner/frame_runner.h"

namespace tp::cli {

void printSummary(const CompareRecord& r) {
    const std::string& device = r.ctx->info.name;
    std::printf("%-18s %12s %12s %12s %14s %11s %10s %11s  %s\n", "pipeline", "frame ms",
                "memory MiB", "bytes/px", "rmse (hdr)", "rel (hdr)", "psnr (tm)", "flip (hdr)",
                "status");
    bool dominated = false;
    auto row = [&](const PipelineOutcome& p, bool reference) {
        if (!p.run) {
            std::printf("%-18s %12s %12s %12s %14s %11s %10s %11s  FAILED: %s\n", p.name.c_str(),
                        "-", "-", "-", "-", "-", "-", "-", p.error.c_str());
            return;
        }
        uint64_t bytes = 0;
        for (const LedgerEntry& e : p.run->memory)
            bytes += e.bytes;
        double bpp = double(bytes) / double(std::max<size_t>(1, p.run->hdr.pixelCount()));
        char rmse[32] = "-", rel[32] = "-", psnr[32] = "-", flip[32] = "-";
        if (!reference) {
            // *: one pixel holds most of the squared error (the footnote below).
            const bool one = p.hdr.worstPixelShare > kOnePixelDominates;
            dominated |= one;
            std::snprintf(rmse, sizeof rmse, "%s%.3e", one ? "*" : "", p.hdr.rmse);
            std::snprintf(rel, sizeof rel, "%.3e", p.hdr.meanRelative);
            std::snprintf(psnr, sizeof psnr, std::isfinite(p.display.psnr) ? "%.2f" : "inf",
                          p.display.psnr);
            if (p.flip.measured) std::snprintf(flip, sizeof flip, "%.4f", p.flip.hdr.mean);
        }
        std::printf("%-18s %12.3f %12.2f %12.1f %14s %11s %10s %11s  ok\n", p.name.c_str(),
                    frameMedianMs(*p.run), double(bytes) / (1024.0 * 1024.0), bpp, rmse, rel, psnr,
                    flip);
    };
    row(r.reference, true);
    for (const PipelineOutcome& p : r.pipelines)
        row(p, false);
    uint64_t shared = 0;
    for (const LedgerEntry& e : r.sharedMemory)
        shared += e.bytes;
    if (dominated)
        std::printf("*: one pixel holds more than half of this squared error (report.html names it "
                    "and gives the RMSE without it); rel: mean relative error, which no pixel "
                    "decides\n");
    std::printf("frame ms: median GPU time on %s%s; shared scene data %.2f MiB counted once\n",
                device.c_str(), r.ctx->isCpuDevice() ? " (CPU-rasterizer times)" : "",
                double(shared) / (1024.0 * 1024.0));
}

void warnDropped(const PipelineOutcome& p) {
    const std::string suffix = "_dropped";
    for (const auto& [name, value] : p.run->stats.counters)
        if (value > 0 && name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            std::fprintf(stderr, "triptych: warning: %s: %s = %.0f (see its counters)\n",
                         p.name.c_str(), name.c_str(), value);
}

} // namespace tp::cli
