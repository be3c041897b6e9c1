#!/usr/bin/env bash
# triptych calibrate end to end on the default device, quick (docs/efficiency.md): every
# ceiling measured with its spread (min <= median <= max, all positive) and written as JSON;
# the second run reuses the file; a file of another key or one that does not parse is
# measured again and replaced; bad options are one-line refusals. Nothing asserts a speed.
# Usage: calibrate.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
file=$work/cal.json

calibrate() { run_triptych calibrate --quick --repeats 2 --validate --out "$file" "$@"; }

# What is wrong with $file as a calibration of every ceiling ("" if nothing).
file_problem() {
    python3 - "$file" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))
names = ["dram_read", "dram_write", "dram_copy", "cache_read", "fp32_fma", "shared_atomic", "global_atomic", "fragment_fma"]
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
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && ! grep -q "reused from" "$work/stderr" && problem="the file was not reused"
report "a second run reuses the file" "$problem"

sed -i 's/"device": "[^"]*"/"device": "another device"/' "$file"
calibrate
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && ! grep -q "another device, driver, build or mode: measuring again" "$work/stderr" && problem="a file of another device was trusted"
[ -z "$problem" ] && grep -q '"another device"' "$file" && problem="the file was not replaced"
report "a file of another device is measured again and replaced" "$problem"

echo '{"schema": "triptych.calibration/1", "key": ' > "$file"
calibrate
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && ! grep -q "not a readable calibration: measuring again" "$work/stderr" && problem="a torn file was not measured again"
[ -z "$problem" ] && problem=$(file_problem)
report "a torn file is measured again" "$problem"

run_triptych calibrate --quick --repeats 0 --out "$work/zero.json"
report "--repeats 0 is refused" "$(error_problem "" "--repeats" 2)"
run_triptych calibrate --quick --device "no such device" --out "$work/nodev.json"
report "an unknown device is refused" "$(error_problem "" "" 2)"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
