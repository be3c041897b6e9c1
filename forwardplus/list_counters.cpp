#include "forwardplus/list_counters.h"

#include <algorithm>

#include "forwardplus/forwardplus_debug.h"
#include "include/light_assign.h"

namespace tp::fp {
namespace {

// Only tiles with blended fragments test for the transparent list: their candidates.
double transparentTests(const ListCounterInput& in) {
    double tests = 0;
    for (size_t i = 0; i < in.blended.size(); ++i)
        if (in.blended[i].any) tests += double(in.tested.empty() ? in.localLights : in.tested[i]);
    return tests;
}

void addClusterCounters(std::vector<std::pair<std::string, double>>& out,
                        const ListCounterInput& in) {
    ClusterSummary c = summarizeClusters(in.tiles, in.maskOffsets, in.maskBits, in.slices);
    out.push_back({"lights_per_cluster_mean", c.mean});
    out.push_back({"lights_per_cluster_max", double(c.max)});
    out.push_back({"cluster_light_bits", c.bits});
    if (!in.blendPass) return;
    ClusterSummary f = summarizeFrontClusters(in.tiles, in.maskOffsets, in.maskBits, in.slices,
                                              std::max(in.slices / TP_LA_FRONT_SLICE_SHARE, 1u));
    out.push_back({"lights_per_front_cluster_mean", f.mean});
    out.push_back({"lights_per_front_cluster_max", double(f.max)});
}

} // namespace

void addListCounters(std::vector<std::pair<std::string, double>>& out, const ListCounterInput& in) {
    auto add = [&](const std::string& name, double v) { out.push_back({name, v}); };
    TileListSummary o =
        summarize(in.tiles, 0, in.clustered && in.blendPass, in.localLights, in.tested);
    add("lights_per_tile_mean", o.mean);
    add("lights_per_tile_max", double(o.max));
    add("tiles_without_geometry", double(o.skyTiles));
    double tested = o.tested, kept = o.passed, dropped = o.dropped, stored = o.stored;
    if (in.twoLists) {
        TileListSummary t = summarize(in.tiles, 1, true, in.localLights, in.tested);
        add("transparent_lights_per_tile_mean", t.mean);
        add("transparent_lights_per_tile_max", double(t.max));
        add("tiles_with_blended_fragments",
            double(std::count_if(in.blended.begin(), in.blended.end(),
                                 [](const auto& b) { return b.any; })));
        tested += transparentTests(in);
        kept += t.passed;
        dropped += t.dropped;
        stored += t.stored;
    }
    add("lights_tested", tested);
    add("lights_kept", kept);
    add("lights_stored", stored);
    add("lights_dropped", dropped);
    if (in.clustered) addClusterCounters(out, in);
    if (in.linked) {
        add("linked_nodes_used", double(in.nodesUsed));
        add("linked_pool_nodes", double(in.poolNodes));
    }
}

} // namespace tp::fp
