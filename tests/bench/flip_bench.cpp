// flip_bench: FLIP and HDR-FLIP on one pair, with the time each took. Not a test (timings on
// a shared machine make poor assertions); the benchmark of docs/report.md.
//   flip_bench                         a synthetic 1920x1080 pair, LDR and HDR
//   flip_bench REF TEST [PPD]          a PNG pair (LDR-FLIP) or an EXR pair (HDR-FLIP)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>

#include "core/image/flip.h"
#include "core/image/image_io.h"
#include "core/image/tonemap.h"

using namespace tp;

namespace {

bool isExr(const std::string& path) {
    return path.size() > 4 && path.substr(path.size() - 4) == ".exr";
}

void print(const char* what, const FlipResult& r, double seconds, double cpuSeconds) {
    std::printf("%s: mean %.9f  w.median %.9f  w.Q1 %.9f  w.Q3 %.9f  min %.9f  max %.9f  (%.3f s, "
                "CPU %.3f s)\n",
                what, r.stats.mean, r.stats.weightedMedian, r.stats.weightedQ1, r.stats.weightedQ3,
                r.stats.min, r.stats.max, seconds, cpuSeconds);
    if (r.exposures.count > 0)
        std::printf("  exposures: start %.7f stop %.7f count %d\n", double(r.exposures.start),
                    double(r.exposures.stop), r.exposures.count);
}

// Wall time, and the CPU time of every thread (std::clock): on a machine shared with other
// work the wall time says little, the CPU time divided by the cores says what an idle one
// would take.
template <class F> FlipResult timed(const char* what, F f) {
    auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    FlipResult r = f();
    std::chrono::duration<double> took = std::chrono::steady_clock::now() - t0;
    print(what, r, took.count(), double(std::clock() - c0) / CLOCKS_PER_SEC);
    return r;
}

// A deterministic 1080p HDR scene-like pair: smooth gradients, a bright spot, stripes; the
// test has noise and a shifted edge.
void synthetic(ImageRGBA& ref, ImageRGBA& test) {
    ref = ImageRGBA(1920, 1080);
    test = ImageRGBA(1920, 1080);
    uint32_t seed = 12345;
    for (uint32_t y = 0; y < 1080; ++y)
        for (uint32_t x = 0; x < 1920; ++x) {
            const float u = float(x) / 1920.0f, v = float(y) / 1080.0f;
            const float d2 = (u - 0.7f) * (u - 0.7f) + (v - 0.3f) * (v - 0.3f);
            const float spot = 40.0f * std::exp(-d2 / 0.002f);
            const float stripes = ((x / 16 + y / 16) % 2) ? 0.8f : 0.1f;
            float* r = ref.at(x, y);
            float* t = test.at(x, y);
            for (int c = 0; c < 3; ++c) {
                r[c] = (0.2f + 0.5f * u * float(c + 1) / 3.0f) * stripes + spot;
                seed = seed * 1664525u + 1013904223u;
                const float noise = 1.0f + 0.1f * (float(seed >> 8) / 16777216.0f - 0.5f);
                t[c] = (x > 960 ? r[c] * noise : (x % 16 < 2 ? 0.5f : r[c]));
            }
            r[3] = t[3] = 1.0f;
        }
}

} // namespace

int main(int argc, char** argv) {
    const float ppd = argc > 3 ? float(std::atof(argv[3])) : flipPixelsPerDegree();
    std::printf("ppd %.4f\n", double(ppd));
    if (argc >= 3) {
        const std::string refPath = argv[1], testPath = argv[2];
        Result<ImageRGBA> ref = isExr(refPath) ? readExr(refPath) : readPng(refPath);
        Result<ImageRGBA> test = isExr(testPath) ? readExr(testPath) : readPng(testPath);
        if (!ref || !test) {
            std::fprintf(stderr, "%s\n", (!ref ? ref : test).error().c_str());
            return 1;
        }
        if (isExr(refPath))
            timed("HDR-FLIP", [&] { return hdrFlip(*test, *ref, ppd); });
        else
            timed("LDR-FLIP", [&] { return ldrFlip(*test, *ref, ppd); });
        return 0;
    }
    ImageRGBA ref, test;
    synthetic(ref, test);
    const float ev = autoExposureEv(ref);
    const ImageRGBA refDisplay = tonemapToDisplay(ref, ev),
                    testDisplay = tonemapToDisplay(test, ev);
    for (int run = 0; run < 3; ++run) {
        auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        timed("LDR-FLIP 1920x1080", [&] { return ldrFlip(testDisplay, refDisplay, ppd); });
        timed("HDR-FLIP 1920x1080", [&] { return hdrFlip(test, ref, ppd); });
        std::chrono::duration<double> took = std::chrono::steady_clock::now() - t0;
        std::printf("LDR + HDR: %.3f s (CPU %.3f s over %u threads)\n", took.count(),
                    double(std::clock() - c0) / CLOCKS_PER_SEC,
                    std::thread::hardware_concurrency());
    }
    return 0;
}
