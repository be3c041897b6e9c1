#!/usr/bin/env bash
# The shadow faces' culling benchmark (docs/shadows.md, "Culling the faces' meshlets"; issue 41's
# "256 shadowed lights with per-frame maps <= 10 ms"): `triptych render` of the courtyard with
# N shadowed lights, --cull-geometry none then frustum, for the atlas rendered every frame
# (--shadow-cache off: Forward+, tiled deferred, the visibility buffer), the kept atlas (its
# one-time render: counter shadow_maps_render_ms) and one light's map at a time (deferred's
# volumes, multipass forward), then one table (tests/bench/shadow_cull_table.py): the frame,
# the shadow passes and the faces' cull counters.
# Usage: shadow_cull.sh TRIPTYCH OUT_DIR [RES] [LIGHTS] [SHADOWED] [FRAMES] [WARMUP] [PIPELINES...]
#   H200:     tests/bench/shadow_cull.sh build/triptych /tmp/shcull          (1920x1080, 1,024 lights, 256 shadowed)
#   lavapipe: tests/bench/shadow_cull.sh build/triptych /tmp/shcull 640x360 128 64 3 1 forwardplus
set -uo pipefail
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024} shadowed=${5:-256} frames=${6:-10} warmup=${7:-3}
shift $(( $# < 7 ? $# : 7 ))
pipes=("$@")
[ ${#pipes[@]} -eq 0 ] && pipes=(visbuffer forwardplus deferred deferred-volumes multipass_forward)
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
for p in "${pipes[@]}"; do
  caches=(off on) extra=() pipeline=$p
  [ "$p" = deferred-volumes ] && pipeline=deferred extra=(--deferred-lighting volumes) caches=(on)
  [ "$p" = multipass_forward ] && caches=(on) # one light's map: rendered every frame anyway
  for cache in "${caches[@]}"; do
    for cull in none frustum; do
      name="${p}_cache-${cache}_${cull}"
      echo "== $name" >&2
      "$bin" render builtin:courtyard --pipeline "$pipeline" "${extra[@]}" --res "$res" \
        --lights "$lights" --shadows "$shadowed" --shadow-cache "$cache" --frames "$frames" \
        --warmup "$warmup" --cull-geometry "$cull" --out "$out/$name" >"$out/$name.log" 2>&1 ||
        echo "($name exited $?)" >&2
    done
  done
done
python3 "$here/shadow_cull_table.py" "$out"
