#!/usr/bin/env bash
# A sweep on one GPU against the same sweep as 2 shards on 2 GPUs of one host (docs/scale-out.md,
# "Measured"): wall times, and the merged sweep.csv against the unsharded one (every column but
# the frame timings). Usage: shard_gpus.sh TRIPTYCH OUT
set -u
bin=$1 out=$2
mkdir -p "$out"
args=(builtin:courtyard --res 1280x720 --lights 64,256,1024 --msaa 1,4 --tile 8,16,32
      --pipelines forwardplus,deferred,visbuffer --frames 3 --warmup 1)
t0=$(date +%s.%N)
"$bin" sweep "${args[@]}" --device 0 --reference-cache "$out/cache1" --out "$out/whole" >"$out/whole.log" 2>&1
t1=$(date +%s.%N)
for k in 0 1; do
    "$bin" sweep "${args[@]}" --device "$k" --shard "$k/2" --reference-cache "$out/cache2" \
        --out "$out/shard$k" >"$out/shard$k.log" 2>&1 &
done
wait
t2=$(date +%s.%N)
"$bin" merge "$out/shard0" "$out/shard1" --out "$out/merged" | tail -1
. "$(dirname "$0")/../cli/sweep_csv.sh"
same=no
[ "$(strip_timings "$out/whole/sweep.csv")" = "$(strip_timings "$out/merged/sweep.csv")" ] && same=yes
echo "runs $(($(wc -l <"$out/whole/sweep.csv") - 1)); 1 GPU $(awk "BEGIN{print $t1 - $t0}") s; 2 GPUs $(awk "BEGIN{print $t2 - $t1}") s; merged equals unsharded: $same"
grep -h "device\|runs (" "$out"/*.log | sort | uniq -c | head -5
