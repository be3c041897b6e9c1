#!/usr/bin/env bash
# The shadow maps' compute rasterizer benchmark (docs/shadows.md, "Rasterizing the maps in
# compute"; issue 41's "256 shadowed lights with per-frame maps <= 10 ms"): `triptych render` of
# the courtyard with N shadowed lights, maps every frame (--shadow-cache off), the faces'
# meshlets culled (--cull-geometry frustum), --shadow-raster hardware then compute, then one
# table (tests/bench/shadow_raster_table.py): the frame's median, the shadow work's (every
# shadow_* pass summed: the cull, the clear, the rasterizer's two passes and the copy, or the
# hardware's shadow_maps) and each pass's, and the rasterizer's counters.
# Usage: shadow_raster.sh TRIPTYCH OUT_DIR [RES] [LIGHTS] [SHADOWED] [FRAMES] [WARMUP] [PIPELINES...]
#   H200:     tests/bench/shadow_raster.sh build/triptych /tmp/shraster   (1920x1080, 1,024 lights,
#             256 shadowed, 5 frames after 1, visbuffer and forwardplus)
#   lavapipe: tests/bench/shadow_raster.sh build/triptych /tmp/shraster 320x180 64 16 3 1
set -uo pipefail
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024} shadowed=${5:-256} frames=${6:-5} warmup=${7:-1}
shift $(( $# < 7 ? $# : 7 ))
pipes=("$@")
[ ${#pipes[@]} -eq 0 ] && pipes=(visbuffer forwardplus)
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
for p in "${pipes[@]}"; do
  for raster in hardware compute; do
    name="${p}_${raster}"
    echo "== $name" >&2
    "$bin" render builtin:courtyard --pipeline "$p" --res "$res" --lights "$lights" \
      --shadows "$shadowed" --shadow-cache off --cull-geometry frustum --shadow-raster "$raster" \
      --frames "$frames" --warmup "$warmup" --calibration none --out "$out/$name" \
      >"$out/$name.log" 2>&1 || echo "($name exited $?)" >&2
  done
done
python3 "$here/shadow_raster_table.py" "$out"
