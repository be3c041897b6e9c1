#!/usr/bin/env bash
# --shadows end to end on the default device (docs/shadows.md): `none` leaves every pipeline's
# image bit for bit as a run without the option; the cached atlas and the per-frame one give
# one image; compare reports both references and the plan; render names its shadow costs; bad
# input and a budget too small for the lights are one line before any output.
# Usage: shadows.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
small=(builtin:courtyard-small --res 64x40 --lights 8 --frames 1)
json() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1" 2>&1; }

for p in forwardplus deferred visbuffer multipass_forward reference; do
    run_triptych render "${small[@]}" --pipeline $p --out "$work/plain_$p"
    a=$code
    run_triptych render "${small[@]}" --pipeline $p --shadows none --out "$work/none_$p"
    problem=""
    [ "$a" -ne 0 ] || [ "$code" -ne 0 ] && problem="exit codes $a, $code"
    [ -z "$problem" ] && ! cmp -s "$work/plain_$p/$p.exr" "$work/none_$p/$p.exr" && problem="--shadows none changed the image"
    report "render --pipeline $p --shadows none: bit-identical to no option" "$problem"
done

for p in forwardplus deferred; do
    run_triptych render "${small[@]}" --pipeline $p --shadows all --shadow-cache off --out "$work/off_$p"
    a=$code
    run_triptych render "${small[@]}" --pipeline $p --shadows all --out "$work/on_$p"
    problem=""
    [ "$a" -ne 0 ] || [ "$code" -ne 0 ] && problem="exit codes $a, $code"
    [ -z "$problem" ] && ! cmp -s "$work/off_$p/$p.exr" "$work/on_$p/$p.exr" && problem="the cached atlas gives another image"
    [ -z "$problem" ] && cmp -s "$work/plain_$p/$p.exr" "$work/on_$p/$p.exr" && problem="--shadows all changed nothing"
    [ -z "$problem" ] && [ "$(json "$work/on_$p/render.json" "j['run']['counters']['shadow_maps_cached']")" != 1.0 ] && problem="not cached"
    [ -z "$problem" ] && [ "$(json "$work/off_$p/render.json" "'shadow_maps' in j['run']['passes']")" != True ] && problem="--shadow-cache off has no shadow_maps pass"
    report "render --pipeline $p --shadows all: cached atlas = per-frame atlas" "$problem"
done

run_triptych compare "${small[@]}" --no-reference-cache --shadows 3 --out "$work/c"
problem=""
r=$work/c/report.json
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(json "$r" "j['shadows']['shadowed_lights']")" != 3 ] && problem="report.json shadows: not 3 lights"
[ -z "$problem" ] && [ "$(json "$r" "j['shadow_map_reference']['rendered']")" != True ] && problem="no shadow-map reference"
[ -z "$problem" ] && [ "$(json "$r" "all('error_vs_shadow_map_reference' in p for p in j['pipelines'])")" != True ] && problem="a pipeline lacks its error against the shadow-map reference"
[ -z "$problem" ] && [ "$(json "$r" "j['shadow_map_reference']['error_vs_reference']['hdr']['rmse'] > 0")" != True ] && problem="the two references are one image"
[ -z "$problem" ] && ! grep -q "Two errors with shadows" "$work/c/report.html" && problem="report.html has no shadow section"
report "compare --shadows 3: the plan, two references, both errors" "$problem"

for bad in 0 -2 many 70000; do
    run_triptych render "${small[@]}" --shadows "$bad" --out "$work/bad"
    report "render --shadows $bad refused" "$(error_problem "$work/bad" "--shadows" 2)"
done
run_triptych render "${small[@]}" --shadow-budget 0 --out "$work/bad"
report "render --shadow-budget 0 refused" "$(error_problem "$work/bad" "--shadow-budget" 2)"
run_triptych render "${small[@]}" --shadow-cache maybe --out "$work/bad"
report "render --shadow-cache maybe refused" "$(error_problem "$work/bad" "--shadow-cache" 2)"
run_triptych render builtin:courtyard-small --res 640x360 --lights 4096 --frames 1 --shadows all --shadow-budget 1 --pipeline forwardplus --out "$work/bad"
# Known only once the view is set up: after the run's first progress line, the error is the last.
problem=""
[ "$code" -ne 2 ] && problem="exit code $code, expected 2"
[ -z "$problem" ] && [[ "$(tail -n 1 "$work/stderr")" != "triptych: --shadow-budget 1 MB cannot hold"* ]] && problem="the last line is not the budget's error"
[ -z "$problem" ] && ls "$work/bad"/*.exr "$work/bad"/*.json >/dev/null 2>&1 && problem="left output files behind"
report "render --shadows all --shadow-budget 1 (4096 lights) refused" "$problem"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
