#!/usr/bin/env bash
# The scale-out recipe of docs/scale-out.md with GNU parallel: a sweep of 12 runs as 2 shards,
# one process each, sharing one reference cache, then `triptych merge`: the merged sweep.csv
# equals the unsharded one in every column but the frame timings. Skips (exit 77) where GNU
# parallel is not installed.
# Usage: sweep_parallel.sh TRIPTYCH
set -u
bin=$(realpath "$1")
command -v parallel >/dev/null || { echo "skipped: GNU parallel is not installed (apt-get install parallel)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(builtin:courtyard-small --res 48x27 --lights 4,8 --msaa 1,4 --tile 8,16
      --pipelines forwardplus --frames 1 --warmup 0 --reference-cache "$work/cache")

# A failure prints the end of what the command said (a crash's signal and last progress line).
fail() { echo "FAIL: $1"; tail -n 5 "$2"; exit 1; }
"$bin" sweep "${args[@]}" --out "$work/whole" >"$work/whole.log" 2>&1 ||
    fail "the unsharded sweep (exit $?)" "$work/whole.log"
# The recipe itself: one shard per job slot.
parallel --halt now,fail=1 -j 2 "$bin" sweep "${args[@]}" --shard {}/2 --out "$work/shard{}" \
    ::: 0 1 >"$work/shards.log" 2>&1 || fail "a shard under GNU parallel" "$work/shards.log"
"$bin" merge "$work/shard0" "$work/shard1" --out "$work/merged" >/dev/null ||
    { echo "FAIL: merge"; exit 1; }

. "$(dirname "$0")/sweep_csv.sh"
rows=$(($(wc -l <"$work/whole/sweep.csv") - 1))
if [ "$(strip_timings "$work/whole/sweep.csv")" != "$(strip_timings "$work/merged/sweep.csv")" ]; then
    echo "FAIL: the merged sweep.csv differs from the unsharded one"
    diff <(strip_timings "$work/whole/sweep.csv") <(strip_timings "$work/merged/sweep.csv") | head -5
    exit 1
fi
echo "ok: $rows runs in 2 shards under GNU parallel, merged: the unsharded sweep.csv"
