#!/usr/bin/env bash
# The meshlet culling benchmark (docs/geometry.md, "Occlusion"): `triptych render` for every
# pipeline that reads --cull-geometry, with none, frustum and full, in the courtyard's default
# view and from inside its colonnade (docs/recipes/courtyard_colonnade_camera.json), then one
# table of the frame, the geometry passes and the cull counters (tests/bench/cull_table.py).
# Usage: cull.sh TRIPTYCH OUT_DIR [RES] [LIGHTS] [FRAMES] [WARMUP] [MSAA...]
#   H200:      tests/bench/cull.sh build/triptych /tmp/cull                    (1920x1080, 1,024 lights, 1x and 4x)
#   lavapipe:  tests/bench/cull.sh build/triptych /tmp/cull 1280x720 128 3 1 1
set -uo pipefail
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024} frames=${5:-30} warmup=${6:-5}
shift $(( $# < 6 ? $# : 6 ))
msaas=("$@")
[ ${#msaas[@]} -eq 0 ] && msaas=(1 4)
here=$(cd "$(dirname "$0")" && pwd)
colonnade="$here/../../docs/recipes/courtyard_colonnade_camera.json"
mkdir -p "$out"
for view in default colonnade; do
  camera=()
  [ "$view" = colonnade ] && camera=(--camera "$colonnade")
  for msaa in "${msaas[@]}"; do
    for p in forwardplus deferred visbuffer multipass_forward; do
      for cull in none frustum full; do
        name="${view}_${msaa}x_${p}_${cull}"
        echo "== $name" >&2
        "$bin" render builtin:courtyard --pipeline "$p" --res "$res" --lights "$lights" \
          --msaa "$msaa" --frames "$frames" --warmup "$warmup" --cull-geometry "$cull" \
          "${camera[@]}" --out "$out/$name" >"$out/$name.log" 2>&1 || echo "($name exited $?)" >&2
      done
    done
  done
done
python3 "$here/cull_table.py" "$out"
