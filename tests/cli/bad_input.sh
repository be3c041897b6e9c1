#!/usr/bin/env bash
# Bad input gets one line on stderr starting with "triptych:", a non-zero exit, no crash,
# and no output that looks complete. Usage: bad_input.sh TRIPTYCH SHARED_SCENES_DIR
# Without SHARED_SCENES_DIR/negative the broken glTF files are not tried: the rest runs, then
# exit 77 (a ctest skip) with the reason.
set -u
skipped=""
bin=$1
scenes=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"

expect_error() { # description, args...
    local what=$1; shift
    local out="$work/out$pass$fail"
    run_triptych "$@" --out "$out"
    report "$what" "$(error_problem "$out" "")"
}

expect_error "zero resolution" render --res 0x0
expect_error "resolution beyond the device" render --res 100000x100
expect_error "malformed resolution" render --res big
expect_error "negative light count" render --lights -1 --res 8x8
expect_error "absurd light count" render --lights 2000000000 --res 8x8
expect_error "unsupported msaa" render --msaa 3
expect_error "msaa not a number" render --msaa four
expect_error "unknown pipeline" render --pipeline nope
expect_error "unknown command" frobnicate
expect_error "missing scene file" render /nonexistent/scene.gltf
expect_error "unknown builtin scene" render builtin:nope
expect_error "missing lights file" render builtin:courtyard-small --lights-file /nonexistent.json
printf '{"version":1,"lights":[{"type":"point","range":-1}]' >"$work/bad.json"
expect_error "malformed lights JSON" render builtin:courtyard-small --lights-file "$work/bad.json"
expect_error "inverted light radius range" render builtin:courtyard-small --light-radius 5,1
expect_error "unknown light type" render builtin:courtyard-small --light-types laser
expect_error "zero frames" render --frames 0
expect_error "bad exposure" render --exposure banana
expect_error "FLIP viewing distance out of range" compare --flip-distance 0 --res 8x8
expect_error "FLIP viewing distance not a number" sweep --flip-distance far --res 8x8
expect_error "no such device" render --device 99 --res 8x8
expect_error "scene that is a directory" render /tmp
# An image that cannot be written in the middle of a compare (a run's images are encoded while
# the next pipeline warms up): a non-zero exit whose last line names the file, and no
# report.json to say that the run completed.
out="$work/unwritable"
mkdir -p "$out/forwardplus.png.partial" # where the PNG is written before its rename
run_triptych compare builtin:courtyard-small --res 16x16 --frames 1 --warmup 1 \
    --pipelines forwardplus,deferred --out "$out"
problem=""
if [ "$code" -eq 0 ] || [ "$code" -ge 128 ]; then problem="exit code $code"
elif ! tail -n 1 "$work/stderr" | grep -q "^triptych: .*forwardplus.png"; then
    problem="the last line does not name forwardplus.png: $(tail -n 1 "$work/stderr")"
elif [ -e "$out/report.json" ]; then problem="wrote report.json"
fi
report "compare that cannot write an image" "$problem"
if [ -n "$scenes" ] && [ -d "$scenes/negative" ]; then
    while IFS= read -r f; do
        case "$f" in */non_relative_uri.gltf) continue ;; esac # valid apart from its URI: a warning
        expect_error "broken glTF ${f#$scenes/}" render "$f" --res 16x16 --frames 1 --warmup 0
    done < <(find "$scenes/negative" -name '*.gltf' -o -name '*.glb' | sort)
else
    skipped="broken glTF files: no shared scenes at '$scenes'"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] || exit 1
# What could not run makes the test a skip (ctest: SKIP_RETURN_CODE 77), never a pass.
if [ -n "$skipped" ]; then echo "skipped: $skipped"; exit 77; fi
