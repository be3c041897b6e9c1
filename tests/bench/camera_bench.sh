#!/usr/bin/env bash
# The camera-moves benchmark (docs/camera_paths.md, docs/viewer.md "Frame rate"): view_bench with
# a baseline build and this one (a new view: rebuild or follow, frame, readback), then a compare
# over the courtyard path at 1,024 lights, every pipeline, and its tables.
# Usage: camera_bench.sh NEW_BIN OUT [BASE_BIN] [RES] [LIGHTS] [SCENE] [PATH_FILE]
set -u
new=$1 out=$2 base=${3:-} res=${4:-1920x1080} lights=${5:-1024} scene=${6:-builtin:courtyard}
path=${7:-docs/recipes/courtyard_path.json}
mkdir -p "$out"
here=$(dirname "$0")
for which in base new; do
    bin=${!which}
    [ -z "$bin" ] && continue
    "$bin" view "$scene" --res "$res" --headless --script "$here/view_bench.txt" ${VIEW_ARGS:-} \
        --out "$out/view_$which" >"$out/view_$which.log" 2>&1
    echo "== view_bench $which ($bin): exit $?"
    for p in forwardplus deferred visbuffer multipass_forward; do
        python3 - "$out/view_$which/$p.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(f"{j['pipeline']:18} new view {j['render_ms_median']:8.2f} ms ({j['renders_per_second']:6.1f}/s)"
      f"  GPU frame {j['gpu_frame_ms_median']:8.3f} ms  planned {j.get('planned', 'all')}"
      f"  view update {j.get('view_update_ms_median', float('nan')):.2f} ms"
      f"  overhead {j['render_ms_median'] - j['gpu_frame_ms_median']:.2f} ms  [{j['device']}]")
PY
    done
done
"$new" compare "$scene" --res "$res" --lights "$lights" --camera-path "$path" --frames 3 \
    --no-reference-cache --out "$out/path" >"$out/path.log" 2>&1
echo "== compare over $path: exit $?"
python3 "$here/path_table.py" "$out/path/report.json"
