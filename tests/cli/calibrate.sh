#!/usr/bin/env bash
# triptych calibrate end to end on the default device, quick (docs/efficiency.md): every
# ceiling measured with its spread (min <= median <= max, all positive) and written as JSON;
# the second run reuses the file; a file of another key or an incomplete one is measured again
# and replaced, as is a torn one in the cache folder; a file of another kind named by --out is
# never overwritten; bad options are one-line refusals. render, compare, sweep and view place
# every pass against a quick calibration (report.json, report.html's roofline, sweep.csv's
# columns, the viewer's stats); a missing file or another device's is refused. Nothing asserts
# a speed.
# Usage: calibrate.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
file=$work/cal.json

calibrate() { run_triptych calibrate --quick --repeats 2 --validate --out "$file" "$@"; }

# ok_saying TEXT: what is wrong with the last run unless it exited 0 saying TEXT on stderr.
ok_saying() {
    if [ "$code" -ne 0 ]; then echo "exit code $code"
    elif ! grep -q "$1" "$work/stderr"; then echo "stderr does not say '$1'"; fi
}

# What is wrong with $file as a calibration of every ceiling ("" if nothing).
file_problem() {
    python3 - "$file" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))
names = ["dram_read", "dram_write", "dram_copy", "cache_read", "fp32_fma", "shared_atomic", "global_atomic",
         "texture_fetch", "image_read", "image_read_msaa4", "light_point", "light_spot", "fragment_fma", "fragment_texture_fetch",
         "fragment_light_point", "fragment_light_spot", "raster_depth", "rop_colour", "rop_blend",
         "raster_msaa4", "rop_colour_msaa4", "raster_depth_msaa4", "rop_gbuffer", "rop_gbuffer_msaa4", "tri_small", "tri_large", "tri_culled", "draw_culled"]
if f.get("schema") != "triptych.calibration/1": print("schema", f.get("schema")); sys.exit()
if [c["name"] for c in f["ceilings"]] != names: print("ceilings", [c["name"] for c in f["ceilings"]]); sys.exit()
for c in f["ceilings"]:
    if not (0 < c["min"] <= c["median"] <= c["max"]) or c["work"] <= 0 or c["repeats"] != 2:
        print("bad figures for", c["name"], c); sys.exit()
for k in ("device", "driver", "build_fnv1a64"):
    if not f["key"].get(k): print("key lacks", k); sys.exit()
PY
}

calibrate
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(file_problem)
[ -z "$problem" ] && ! grep -q "^fp32_fma " "$work/stdout" && problem="no table on stdout"
report "a quick calibration writes every ceiling with its spread" "$problem"

calibrate
report "a second run reuses the file" "$(ok_saying "reused from")"

sed -i 's/"device": "[^"]*"/"device": "another device"/' "$file"
calibrate
problem=$(ok_saying "another device, driver, build or mode: measuring again")
[ -z "$problem" ] && grep -q '"another device"' "$file" && problem="the file was not replaced"
report "a file of another device is measured again and replaced" "$problem"

# A calibration without its figures (hand-edited): measured again and replaced.
python3 -c "import json,sys; f=json.load(open(sys.argv[1])); [c.pop('median') for c in f['ceilings']]; json.dump(f, open(sys.argv[1], 'w'))" "$file"
calibrate
problem=$(ok_saying "not a complete calibration: measuring again")
[ -z "$problem" ] && problem=$(file_problem)
report "an incomplete calibration is measured again" "$problem"

# A file named with --out that is something else is never overwritten.
echo '{"schema": "triptych.report/2"}' > "$work/other.json"
run_triptych calibrate --quick --repeats 2 --out "$work/other.json"
problem=$(error_problem "" "not overwriting it" 2)
[ -z "$problem" ] && [ "$(cat "$work/other.json")" != '{"schema": "triptych.report/2"}' ] && problem="the file was overwritten"
report "another kind of file named by --out is not overwritten" "$problem"

# In the cache folder (no --out), a torn file is measured again.
export XDG_CACHE_HOME=$work/xdg
run_triptych calibrate --quick --repeats 2
cached=$(ls "$XDG_CACHE_HOME"/triptych/calibration/*.json 2>/dev/null | head -n 1)
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ -z "$cached" ] && problem="nothing written to the cache folder"
if [ -z "$problem" ]; then
    echo '{"schema": "triptych.calibration/1", "key": ' > "$cached"
    run_triptych calibrate --quick --repeats 2
    problem=$(ok_saying "not a complete calibration: measuring again")
    [ -z "$problem" ] && ! python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$cached" && problem="the cache file was not replaced"
fi
report "a torn file in the cache folder is measured again" "$problem"
unset XDG_CACHE_HOME

run_triptych calibrate --quick --repeats 0 --out "$work/zero.json"
report "--repeats 0 is refused" "$(error_problem "" "--repeats" 2)"
run_triptych calibrate --quick --device "no such device" --out "$work/nodev.json"
report "an unknown device is refused" "$(error_problem "" "" 2)"

# render places every pass against a named calibration: render.json says which file, every
# live pass has its counted work, and every pass with counted work a binding ceiling.
calibrate
run_triptych render --pipeline forwardplus --res 64x36 --lights 8 --frames 1 --warmup 0 --validate \
    --calibration "$file" --out "$work/render"
problem=$(ok_saying "of light_alu\|of raster\|of triangles\|of memory")
[ -z "$problem" ] && problem=$(python3 - "$work/render/render.json" "$file" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
if not r["calibration"]["available"] or r["calibration"]["path"] != sys.argv[2]: print("calibration", r["calibration"]); sys.exit()
run = r["run"]
if [w["pass"] for w in run["work"]] != run["passes"]: print("work", [w["pass"] for w in run["work"]]); sys.exit()
e = run["efficiency"]
if [p["pass"] for p in e["passes"]] != run["passes"]: print("efficiency passes"); sys.exit()
shade = [p for p in e["passes"] if p["pass"] == "forward_opaque"][0]
if shade["bound"] is None or shade["bound"]["ms"] <= 0 or "roofline" not in shade: print("forward_opaque", shade); sys.exit()
work = [w for w in run["work"] if w["pass"] == "forward_opaque"][0]
if work["light_evaluations"] <= 0 or work["pipeline_statistics"]["fragment_invocations"] <= 0: print("work", work); sys.exit()
if e["missing_ceilings"]: print("missing", e["missing_ceilings"])
PY
)
report "render places every pass against --calibration FILE" "$problem"

# compare and sweep place them too: report.json per pipeline, report.html's roofline section,
# sweep.csv's efficiency columns filled.
run_triptych compare --pipelines forwardplus --res 64x36 --lights 8 --frames 1 --warmup 0 --validate \
    --no-reference-cache --calibration "$file" --out "$work/compare"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 - "$work/compare" <<'PY'
import json, sys
d = sys.argv[1]
r = json.load(open(d + "/report.json"))
if not r["calibration"]["available"] or "fragment_light_point" not in r["calibration"]["ceilings"]: print("calibration", r["calibration"]); sys.exit()
e = r["pipelines"][0]["run"].get("efficiency")
if not e or e["passes_at_ceiling_ms"] <= 0: print("efficiency", e); sys.exit()
html = open(d + "/report.html").read()
start = html.find("against the device's ceilings")
section = html[start:html.find("<h2", start)] if start >= 0 else ""
if "<svg" not in section or "<table" not in section or "forward_opaque" not in section: print("report.html has no roofline or pass table")
PY
)
report "compare places every pass and draws the roofline" "$problem"
run_triptych sweep --pipelines forwardplus --res 64x36 --lights 8 --frames 1 --warmup 0 --reference-frames 0 \
    --calibration "$file" --out "$work/sweep"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 - "$work/sweep/sweep.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = [r for r in rows if not r["ceiling_percent"] or not r["slowest_pass_ceiling"]]
if not rows or bad: print("empty efficiency columns in", len(bad), "of", len(rows), "rows")
PY
)
report "sweep.csv has every run's efficiency columns" "$problem"

# The viewer's numbers panel places the passes too (its stats file holds what the panel shows).
printf 'reference off\npipeline a forwardplus\nwait\nstats s.json\n' > "$work/view.txt"
run_triptych view builtin:courtyard-small --res 64x36 --headless --script "$work/view.txt" --calibration "$file" --out "$work/view"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "
import json, sys
a = json.load(open(sys.argv[1]))['pipeline_a']
e = a.get('efficiency', {}).get('passes', {})
if 'forward_opaque' not in e: print('no forward_opaque ceiling in', a.get('efficiency'))" "$work/view/s.json")
report "view places every pass against --calibration FILE" "$problem"

run_triptych render --res 64x36 --calibration "$work/absent.json" --out "$work/r2"
report "--calibration with a missing file is refused" "$(error_problem "" "--calibration" 2)"
sed 's/"device": "[^"]*"/"device": "another device"/' "$file" > "$work/other_device.json"
run_triptych render --res 64x36 --frames 1 --warmup 0 --calibration "$work/other_device.json" --out "$work/r3"
report "--calibration of another device is refused" "$(error_problem "" "measured on another device" 2)"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
