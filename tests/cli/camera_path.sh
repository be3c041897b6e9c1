#!/usr/bin/env bash
# --camera-path and --light-motion end to end on the default device (docs/camera_paths.md):
# compare renders every view with each pipeline planned once, reports per-view series,
# percentiles and ranking flips and writes its full report at the worst view; the reference is
# reused where nothing moved; render times a path; bad input is one line before any output.
# Usage: camera_path.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
small=(builtin:courtyard-small --res 64x40 --lights 16 --frames 1)

key() { # key X Z: a camera bookmark at (X, 1.8, Z) looking down the courtyard
    echo "{\"schema\":\"triptych.camera/1\",\"position\":[$1,1.8,$2],\"target\":[0,2,-30],\"up\":[0,1,0],\"yfov_degrees\":57,\"znear\":0.05,\"zfar\":0}"
}
echo "{\"schema\":\"triptych.camera_path/1\",\"frames\":4,\"interpolation\":\"catmull-rom\",\"keys\":[$(key 0 25),$(key 4 10),$(key -3 0)]}" >"$work/path.json"
echo "{\"schema\":\"triptych.camera_path/1\",\"frames\":3,\"interpolation\":\"linear\",\"keys\":[$(key 0 25)]}" >"$work/still.json"

# json FILE EXPR: a Python expression over j (the file's JSON), printed.
json() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1" 2>&1; }

run_triptych compare "${small[@]}" --no-reference-cache --camera-path "$work/path.json" --light-motion orbit:0.2 --out "$work/c"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
r=$work/c/report.json
[ -z "$problem" ] && [ "$(json "$r" "j['path']['views']")" != 4 ] && problem="path.views is not 4"
[ -z "$problem" ] && [ "$(json "$r" "all(len(p['frame_ms'])==4 and len(p['rmse_hdr'])==4 and not p['error'] for p in j['path']['pipelines'])")" != True ] && problem="a pipeline lacks 4 frame times and errors"
[ -z "$problem" ] && [ "$(json "$r" "len(j['path']['pipelines'])==len(j['pipelines'])")" != True ] && problem="not every pipeline ran the path"
[ -z "$problem" ] && [ "$(json "$r" "all(set(p['summary']['frame_ms'])=={'median','p95','p99','max'} for p in j['path']['pipelines'])")" != True ] && problem="no percentiles"
[ -z "$problem" ] && [ "$(json "$r" "j['camera']==j['path']['worst_view_camera']")" != True ] && problem="the full report is not at the worst view"
[ -z "$problem" ] && [ "$(json "$r" "j['path']['reference']['renders']")" != 4 ] && problem="moving lights: the reference must render every view"
[ -z "$problem" ] && [ "$(json "$r" "j['path']['light_motion']")" != "orbit:0.2" ] && problem="light motion not recorded"
[ -z "$problem" ] && ! grep -q "Camera path: 4 views" "$work/c/report.html" && problem="report.html has no path section"
[ -z "$problem" ] && [ "$(grep -c '<polyline' "$work/c/report.html")" -lt 4 ] && problem="report.html draws no series"
report "compare --camera-path --light-motion: series, percentiles, full report at the worst view" "$problem"

# Three views of one camera, lights still: one reference render, reused twice; views followed.
run_triptych compare "${small[@]}" --no-reference-cache --pipelines multipass_forward --camera-path "$work/still.json" --out "$work/s"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(json "$work/s/report.json" "(j['path']['reference']['renders'], j['path']['reference']['reused'])")" != "(1, 2)" ] && problem="reference not reused where nothing moved: $(json "$work/s/report.json" "j['path']['reference']")"
report "a view where nothing moved reuses the reference" "$problem"

# render: the path's timings in render.json; multipass forward follows every view in place.
run_triptych render "${small[@]}" --pipeline multipass_forward --camera-path "$work/path.json" --out "$work/r"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(json "$work/r/render.json" "(len(j['path']['frame_ms']), j['path']['replans'])")" != "(4, 0)" ] && problem="render.json path: $(json "$work/r/render.json" "j['path']")"
report "render --camera-path times every view, no replan" "$problem"

# Moving lights alone: --path-frames views at the scene's camera.
run_triptych render "${small[@]}" --pipeline reference --light-motion drift --path-frames 3 --out "$work/m"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(json "$work/m/render.json" "(j['path']['views'], j['path']['light_motion'])")" != "(3, 'drift:0.05')" ] && problem="$(json "$work/m/render.json" "j['path']")"
report "--light-motion alone renders --path-frames views" "$problem"

# sweep: each pipeline row runs the path too; sweep.csv gets its percentile columns.
run_triptych sweep builtin:courtyard-small --res 64x40 --lights 16 --frames 1 --no-reference-cache \
    --pipelines forwardplus,deferred --camera-path "$work/path.json" --out "$work/w"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(python3 -c "import csv,sys; print(sorted((r['pipeline'], r['path_views'], r['path_replans']) for r in csv.DictReader(open(sys.argv[1]))))" "$work/w/sweep.csv" 2>&1)" != "[('deferred', '4', '0'), ('forwardplus', '4', '0'), ('reference', '', '')]" ] && problem="sweep.csv path columns: $(head -2 "$work/w/sweep.csv")"
[ -z "$problem" ] && [ "$(json "$work/w/sweep.json" "j['path']['views']")" != 4 ] && problem="sweep.json has no path"
report "sweep --camera-path: path percentiles per pipeline row" "$problem"

# Refusals: one line, exit 2, nothing written.
echo '{"schema":"triptych.camera_path/1","frames":4,"interpolation":"linear","keys":[],"speed":1}' >"$work/bad.json"
for args in "--camera-path $work/missing.json|camera path file not found" \
    "--camera-path $work/bad.json|$work/bad.json" \
    "--light-motion spin|--light-motion" \
    "--light-motion orbit:0|--light-motion" \
    "--path-frames 0|--path-frames"; do
    mention=${args#*|}
    for cmd in compare render sweep; do
        # shellcheck disable=SC2086
        run_triptych $cmd builtin:courtyard-small ${args%|*} --out "$work/cwd/out"
        report "$cmd ${args%|*} refused" "$(error_problem "$work/cwd/out" "$mention" 2)"
    done
done

echo "camera_path: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
