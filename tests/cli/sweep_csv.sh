# Shared by the sharded-sweep tests (sourced): strip_timings CSV prints the sweep.csv without
# its frame timing columns (frame_median_ms, frame_min_ms, frame_max_ms), the energy measured
# beside them (joules_per_frame: it differs between runs like a time, and a shard's reference
# read from the cache has none) and the efficiency columns made from them (ceiling_*,
# slowest_pass*), found by the header's names: what two runs of one sweep must agree on.
strip_timings() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) keep[i] = $i !~ /^(frame_(median|min|max)_ms|joules_per_frame|ceiling_.*|slowest_pass.*)$/ }
             { line = ""; for (i = 1; i <= NF; ++i) if (keep[i]) line = line $i ","; print line }' "$1"
}
