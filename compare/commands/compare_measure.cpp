// compare's measurements of the images it rendered: every pipeline against the reference
// (metrics, FLIP, the signed difference) and against each other, each difference written as a
// signed EXR and a heat map on the report's one scale, the FLIP maps beside them.
#include "compare/commands/compare_measure.h"

#include <algorithm>

#include "core/image/difference.h"
#include "core/image/flip.h"
#include "core/image/image_io.h"
#include "core/image/tonemap.h"
#include "core/util/parallel.h"

namespace tp::cli {
namespace {

// A file that cannot be written ends the run, with the error naming it.
void checkWritten(const Status& s) {
    if (!s) throw UsageError(s.error());
}

// The legend's font scales with its height: keep it readable when the page shrinks a large
// image to a column (about 320-600 px wide).
uint32_t legendHeight(const ImageRGBA& image) {
    return 24 * std::max(1u, image.width / 320);
}

// Signed EXR and heat map (on the report's one scale) of a difference image.
void writeDifference(const std::string& out, const std::string& stem, const ImageRGBA& diff,
                     float scale, std::vector<std::string>& files) {
    checkWritten(writeExr(out + "/" + stem + ".exr", diff, ExrPixelType::Float));
    checkWritten(writePng(out + "/" + stem + ".png", heatMap(diff, scale, legendHeight(diff))));
    files.push_back(stem + ".exr");
    files.push_back(stem + ".png");
}

} // namespace

ReferenceMeasures::ReferenceMeasures(const CompareRecord& r, size_t pipelines)
    : reference_(r.reference.run->hdr), exposureEv_(r.exposureEv),
      referenceDisplay_(tonemapToDisplay(reference_, r.exposureEv)),
      flipReference_(prepareFlipReference(reference_, r.exposureEv, r.request.flipDistance)),
      diffs_(pipelines) {
    hdrOptions_.psnrPeak = r.hdrPsnrPeak;
}

// Metrics against the reference and the signed difference of one pipeline that ran.
void ReferenceMeasures::measure(PipelineOutcome& p, size_t index) {
    if (!p.run) return;
    p.hdr = computeError(p.run->hdr, reference_, hdrOptions_);
    p.display = computeError(tonemapToDisplay(p.run->hdr, exposureEv_), referenceDisplay_);
    diffs_.at(index) = signedDifference(p.run->hdr, reference_);
    p.diffP99 = differencePercentile99(diffs_[index]);
    p.flip = measureFlip(p.run->hdr, flipReference_, /*keepMaps=*/true);
}

namespace {

// A FLIP map as EXR (the values, grey) and as the magma PNG with its legend.
void writeFlipMap(const std::string& out, const std::string& stem, const ImageR32& map,
                  std::vector<std::string>& files) {
    ImageRGBA grey(map.width, map.height);
    for (size_t i = 0; i < map.r.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            grey.rgba[i * 4 + size_t(c)] = map.r[i];
        grey.rgba[i * 4 + 3] = 1.0f;
    }
    checkWritten(writeExr(out + "/" + stem + ".exr", grey, ExrPixelType::Float));
    checkWritten(writePng(out + "/" + stem + ".png", flipErrorMap(map, legendHeight(grey))));
    files.push_back(stem + ".exr");
    files.push_back(stem + ".png");
}

} // namespace

// Each pipeline's maps are its own files: written side by side (EXR and PNG encoding is most
// of a compare's time after the renders).
void ReferenceMeasures::write(CompareRecord& r, const std::string& out) {
    for (const PipelineOutcome& p : r.pipelines)
        if (p.run) r.diffScale = std::max(r.diffScale, p.diffP99);
    // A scale of 0 (every pipeline equals the reference) would make the legend meaningless.
    if (!(r.diffScale > 0.0f)) r.diffScale = 1e-6f;
    const std::vector<ImageRGBA>& diffs = diffs_;
    forEachInParallel(r.pipelines.size(), [&](size_t i) {
        PipelineOutcome& p = r.pipelines[i];
        if (!p.run) return;
        writeDifference(out, p.name + "_diff", diffs[i], r.diffScale, p.files);
        if (!p.flip.measured) return;
        writeFlipMap(out, p.name + "_flip", p.flip.hdrMap, p.files);
        writeFlipMap(out, p.name + "_flip_ldr", p.flip.ldrMap, p.files);
        p.flip.hdrMap = {};
        p.flip.ldrMap = {};
    });
    diffs_.clear();
}

std::string pairDiffStem(const std::string& a, const std::string& b) {
    return a + "_vs_" + b + "_diff";
}


// Pipelines against each other: metrics of a against b, and the signed difference a - b as
// EXR and heat map on the same scale as the maps against the reference (what exceeds it
// saturates), so one legend reads every map of the report.
void measurePairs(CompareRecord& r, const std::string& out) {
    MetricsOptions hdrOptions;
    hdrOptions.psnrPeak = r.hdrPsnrPeak;
    std::vector<std::pair<size_t, size_t>> ran; // pairs of pipelines that both ran, in order
    for (size_t i = 0; i < r.pipelines.size(); ++i)
        for (size_t k = i + 1; k < r.pipelines.size(); ++k)
            if (r.pipelines[i].run && r.pipelines[k].run) ran.push_back({i, k});
    r.pairs.resize(ran.size());
    std::vector<ImageRGBA> shown(r.pipelines.size()); // each pipeline tonemapped once
    forEachInParallel(shown.size(), [&](size_t i) {
        if (r.pipelines[i].run) shown[i] = tonemapToDisplay(r.pipelines[i].run->hdr, r.exposureEv);
    });
    forEachInParallel(ran.size(), [&](size_t n) { // each pair its own slot and files
        const PipelineOutcome &a = r.pipelines[ran[n].first], &b = r.pipelines[ran[n].second];
        PairOutcome pair{a.name, b.name, computeError(a.run->hdr, b.run->hdr, hdrOptions),
                         computeError(shown[ran[n].first], shown[ran[n].second])};
        ImageRGBA diff = signedDifference(a.run->hdr, b.run->hdr);
        pair.diffP99 = differencePercentile99(diff);
        writeDifference(out, pairDiffStem(a.name, b.name), diff, r.diffScale,
                        pair.files);
        r.pairs[n] = std::move(pair);
    });
}

} // namespace tp::cli
