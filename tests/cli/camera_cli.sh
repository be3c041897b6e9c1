#!/usr/bin/env bash
# --camera FILE and `info --print-camera` end to end: the printed camera is a camera file that
# reads back as the same camera, an edited one replaces the scene's (in a 16x16 render on the
# default device too: render.json and camera.json record it), and every command refuses an
# unusable file with one line naming --camera and the file, before any output or GPU work.
# Usage: camera_cli.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"

# print_camera ARGS...: `info --print-camera` into $work/printed.json; sets $problem ("" or
# what went wrong) and $first, as run_triptych does.
print_camera() {
    (cd "$work/cwd" && exec "$bin" info "$@" --print-camera) >"$work/printed.json" 2>"$work/stderr"
    code=$?
    first=$(head -n 1 "$work/printed.json")
    problem=""
    if [ "$code" -ne 0 ]; then problem="exit code $code"
    elif [ -s "$work/stderr" ]; then problem="wrote to stderr"
    elif ! grep -q '"schema": "triptych.camera/1"' "$work/printed.json"; then problem="no camera schema on stdout"
    fi
}

print_camera builtin:courtyard-small
report "print-camera of a built-in scene" "$problem"
cp "$work/printed.json" "$work/view.json"
print_camera builtin:courtyard-small --camera "$work/view.json"
[ -z "$problem" ] && ! cmp -s "$work/view.json" "$work/printed.json" && problem="printed back differently"
report "a printed camera reads back as the same camera" "$problem"

# An edited bookmark replaces the scene's camera (and prints back as edited).
sed 's/"yfov_degrees": [0-9.]*/"yfov_degrees": 35.5/' "$work/view.json" >"$work/edited.json"
print_camera builtin:courtyard-small --camera "$work/edited.json"
[ -z "$problem" ] && ! grep -q '"yfov_degrees": 35.5' "$work/printed.json" && problem="the edit did not take"
[ -z "$problem" ] && cmp -s "$work/view.json" "$work/printed.json" && problem="still the scene's camera"
report "an edited camera file replaces the scene's camera" "$problem"

# refusal OUT MENTION: error_problem, and the line must start by naming --camera and the file.
refusal() {
    local problem
    problem=$(error_problem "$1" "$2" 2)
    [ -z "$problem" ] && [[ "$first" != "triptych: --camera: $work/"* ]] && problem="does not start with --camera: FILE"
    echo "$problem"
}

# run_each DESCRIPTION MENTION ARGS...: every command that takes --camera, with ARGS.
run_each() {
    local what=$1 mention=$2
    shift 2
    for command in render compare sweep; do
        run_triptych "$command" builtin:courtyard-small --res 8x8 "$@" --out "$work/out"
        report "$command: $what" "$(refusal "$work/out" "$mention")"
    done
    run_triptych info builtin:courtyard-small "$@" --print-camera
    report "info --print-camera: $what" "$(refusal "" "$mention")"
}

# render records the camera it used: camera.json is what --print-camera prints for the same
# options, and render.json holds the camera and its source.
render_camera() { # description, kind, args...
    local what=$1 kind=$2
    shift 2
    rm -rf "$work/render"
    run_triptych render builtin:courtyard-small --res 16x16 --frames 1 --warmup 0 --lights 1 "$@" --out "$work/render"
    local problem=""
    if [ "$code" -ne 0 ]; then problem="exit code $code"
    elif ! cmp -s "$work/render/camera.json" "$work/printed.json"; then problem="camera.json is not the camera printed"
    elif ! grep -q "\"kind\": \"$kind\"" "$work/render/render.json"; then problem="render.json: camera_source is not $kind"
    elif ! grep -q '"yfov_degrees": ' "$work/render/render.json"; then problem="render.json holds no camera"
    fi
    first=$(tail -n 1 "$work/stderr")
    report "$what" "$problem"
}
print_camera builtin:courtyard-small
render_camera "render records the scene's camera" scene
print_camera builtin:courtyard-small --camera "$work/edited.json"
render_camera "render records the --camera file's camera" file --camera "$work/edited.json"

expect_camera_error() { # description, mention, file contents
    printf '%s' "$3" >"$work/bad.json"
    run_each "$1" "$2" --camera "$work/bad.json"
}

good='"schema":"triptych.camera/1","target":[0,0,0],"up":[0,1,0],"znear":0.1,"zfar":0'
expect_camera_error "not JSON" "not valid JSON" '{"schema": '
expect_camera_error "wrong schema" '"schema" must be' '{"schema":"triptych.camera/9","position":[0,0,5],"target":[0,0,0],"up":[0,1,0],"yfov_degrees":60,"znear":0.1,"zfar":0}'
expect_camera_error "missing field" 'missing "position"' "{$good,\"yfov_degrees\":60}"
expect_camera_error "position on the target" 'same point' "{$good,\"position\":[0,0,0],\"yfov_degrees\":60}"
expect_camera_error "up along the view" 'parallel' "{\"schema\":\"triptych.camera/1\",\"position\":[0,5,0],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_degrees\":60,\"znear\":0.1,\"zfar\":0}"
expect_camera_error "yfov of 180 degrees" 'yfov_degrees' "{$good,\"position\":[0,0,5],\"yfov_degrees\":180}"
expect_camera_error "non-finite number" 'finite' "{$good,\"position\":[0,0,1e300],\"yfov_degrees\":60}"
expect_camera_error "zfar before znear" '"zfar" must be 0' '{"schema":"triptych.camera/1","position":[0,0,5],"target":[0,0,0],"up":[0,1,0],"yfov_degrees":60,"znear":1,"zfar":0.5}'
run_each "missing camera file" "camera file not found" --camera "$work/missing.json"
mkdir -p "$work/dir.json"
run_triptych render --camera "$work/dir.json" --res 8x8 --out "$work/out"
report "camera file that is a directory" "$(refusal "$work/out" "not a regular file")"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
