#!/usr/bin/env bash
# The CPU's per-view update along a camera path (issue 42, "Per-view work on the GPU"): per
# pipeline, `triptych render --camera-path` (no reference, no images but the first view's) and
# the median and max of its view_update_ms (RendererSession: updateView and the new recording,
# or a replan), with the views followed in place and planned again. Run it with a baseline
# build and this one; on the H200:
#   tests/bench/view_update_path.sh build/triptych OUT 1920x1080 1024
#   tests/bench/view_update_path.sh /path/to/base/triptych OUT_BASE 1920x1080 1024
# On lavapipe a shorter path keeps it to minutes (8 views: a copy of the path with "frames": 8).
# Usage: [FRAMES=N] [SCENE=S] view_update_path.sh BIN OUT [RES] [LIGHTS] [PATH_FILE] [PIPELINES]
#        [EXTRA ARGS...]
# (FRAMES: timed frames per view, 3 by default; SCENE: a glTF file or builtin:NAME, the
# courtyard by default, whose camera path PATH_FILE must fit; EXTRA ARGS go to render, e.g.
# --light-bin gpu)
set -u
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024} path=${5:-docs/recipes/courtyard_path.json}
pipelines=${6:-forwardplus,deferred,visbuffer,multipass_forward}
shift $(($# < 6 ? $# : 6))
mkdir -p "$out"
for p in ${pipelines//,/ }; do
    "$bin" render "${SCENE:-builtin:courtyard}" --pipeline "$p" --res "$res" --lights "$lights" \
        --camera-path "$path" --frames "${FRAMES:-3}" --out "$out/$p" "$@" >"$out/$p.log" 2>&1 ||
        { echo "$p: failed (exit $?), see $out/$p.log"; continue; }
    python3 - "$out/$p/render.json" <<'PY'
import json, statistics, sys
r = json.load(open(sys.argv[1]))
p = r["path"]
u = p["view_update_ms"][1:]  # view 0: where it was planned
f = p["summary"]["frame_ms"]
print(f"{p['name']:18} view_update_ms median {statistics.median(u):8.3f} max {max(u):9.3f}"
      f"  frame ms median {f['median']:9.3f}  updates {p['updates']} replans {p['replans']}"
      f"  [{r['device']['name']}]")
PY
done
