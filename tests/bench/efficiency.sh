#!/usr/bin/env bash
# The issue-27 benchmark (docs/efficiency.md): calibrate this device, then compare every
# pipeline at RES with LIGHTS lights at 1x and 4x MSAA against that calibration, and print
# each pass's binding ceiling. Writes OUT/calibration.json, OUT/report_1x.json,
# OUT/report_4x.json (and the full compare folders under OUT/compare_*).
# Usage: efficiency.sh TRIPTYCH OUT [RES] [LIGHTS] [FRAMES]
set -eu
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024} frames=${5:-9}
mkdir -p "$out"
"$bin" calibrate --out "$out/calibration.json" --force > "$out/calibration.txt"
cat "$out/calibration.txt"
for msaa in 1 4; do
    "$bin" compare --res "$res" --lights "$lights" --msaa "$msaa" --frames "$frames" --warmup 3 \
        --calibration "$out/calibration.json" --no-reference-cache --out "$out/compare_${msaa}x" 2>&1 |
        grep -v "frame [0-9]*/" | tail -8
    cp "$out/compare_${msaa}x/report.json" "$out/report_${msaa}x.json"
    python3 - "$out/report_${msaa}x.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print("device:", r["device"]["name"], "| msaa", r["settings"]["msaa"], "|", r["settings"]["width"], "x", r["settings"]["height"])
for p in r["pipelines"]:
    e = p["run"].get("efficiency")
    if not e: continue
    print(f'{p["name"]:18s} frame {e["frame_ms"]:9.3f} ms  passes at ceilings {e["passes_at_ceiling_ms"]:8.3f} ms ({e["percent_of_ceiling"]:5.1f} %)')
    for x in sorted(e["passes"], key=lambda x: -x["measured_ms"]):
        b = x["bound"]
        share = 100 * x["measured_ms"] / e["frame_ms"] if e["frame_ms"] else 0
        print(f'   {x["pass"]:24s} {x["measured_ms"]:9.3f} ms {share:5.1f} % of frame  '
              + (f'{b["limit"]:10s} {b["ceiling"]:40s} {b["ms"]:9.3f} ms  {x["percent_of_ceiling"]:6.1f} %' if b else '(no counted work)'))
PY
done
