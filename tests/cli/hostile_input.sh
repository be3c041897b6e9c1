#!/usr/bin/env bash
# Hostile input end to end (docs/hostile_input.md): the generated broken scenes, wrong types,
# negative, absurd and unknown values for every command's options, hostile lights files, and
# a machine without a Vulkan driver. Each refusal: exit 2, one line starting "triptych:" that
# says what is wrong, no crash, no output that looks complete, nothing written in the working
# directory or beside the scenes. A scene whose only fault is a texture renders, with a warning.
# Usage: hostile_input.sh TRIPTYCH MAKE_HOSTILE_SCENES
set -u
bin=$1
make_scenes=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A cache of its own: triptych reads its calibration and reference cache from $XDG_CACHE_HOME,
# else the user's ~/.cache (a calibration there changes what render prints), and the driver
# keeps its shader cache there (Mesa's lavapipe): this test must neither read nor fill the user's.
export XDG_CACHE_HOME="$work/cache"
. "$(dirname "$0")/cli_lib.sh"
out="$work/out"
fast=(--res 16x16 --frames 1 --warmup 0)

# expect_refusal WHAT MENTION ARGS...: must fail with exit 2 and MENTION in its one line.
expect_refusal() {
    local what=$1 mention=$2; shift 2
    rm -rf "$out"
    run_triptych "$@"
    report "$what" "$(error_problem "$out" "$mention" 2)"
}

# --- Generated hostile scenes -------------------------------------------------------------
scenes="$work/scenes"
"$make_scenes" "$scenes" || { echo "FAIL make_hostile_scenes"; exit 1; }
# A loader that believed a header or a count would ask for gigabytes: the address space is
# capped at 3 GiB (lavapipe renders these scenes in well under 2 GiB). A driver that cannot
# start under the cap (a GPU driver reserving address space) runs without it.
cap=3000000
if ! (ulimit -v $cap && "$bin" render builtin:courtyard-small "${fast[@]}" --lights 1 \
    --out "$work/probe" >/dev/null 2>&1); then
    echo "note: the device cannot start under ulimit -v $cap; running without the cap"
    cap=unlimited
fi
rm -rf "$work/probe"
snapshot() { (cd "$scenes" && find . -printf '%p %s\n' | sort); }
before=$(snapshot)
while IFS=$'\t' read -r name scene expect mention what; do
    rm -rf "$out"
    (ulimit -v $cap && run_triptych render "$scenes/$name/$scene" "${fast[@]}" --lights 1 \
        --out "$out"; echo "$code" >"$work/code")
    code=$(cat "$work/code")
    lines=$(grep -c '' "$work/stderr")
    first=$(head -n 1 "$work/stderr")
    problem=""
    if [ "$expect" = error ]; then
        problem=$(error_problem "$out" "$mention" 2)
        [ -z "$problem" ] && [[ "$first" != *"$scenes/$name/$scene"* ]] &&
            problem="the message does not name the file"
        [ -z "$problem" ] && [[ "$first" == *"out of memory"* ]] && problem="ran out of memory"
        [ -z "$problem" ] && [ -e "$out" ] && problem="created the output folder"
    else
        if [ "$code" -ne 0 ]; then problem="exit code $code, expected 0 (a warning)"
        elif ! grep -q "^triptych: warning: .*$mention" "$work/stderr"; then
            problem="no 'triptych: warning:' line mentions '$mention'"
        elif [ ! -s "$out/reference.png" ] || [ ! -s "$out/render.json" ]; then
            problem="did not render"
        fi
        first=$(grep -m1 '^triptych: warning:' "$work/stderr")
    fi
    [ -z "$problem" ] && [ -n "$(ls -A "$work/cwd")" ] && problem="wrote into the working directory"
    report "scene $name ($what)" "$problem"
done <"$scenes/CASES.tsv"
[ "$(snapshot)" = "$before" ] || { echo "FAIL something was written beside the scenes"; fail=$((fail + 1)); }
# --strict: what is repaired above is refused, for every command that loads a scene.
strict_nan="NORMAL accessor 2 holds a NaN or infinite value"
for cmd in render compare; do
    expect_refusal "$cmd --strict on a NaN normal" "$strict_nan" \
        $cmd "$scenes/nan_normals/scene.gltf" --strict "${fast[@]}" --out "$out"
done
expect_refusal "info --strict on a NaN normal" "$strict_nan" info "$scenes/nan_normals/scene.gltf" --strict
expect_refusal "sweep --strict on a NaN normal" "$strict_nan" \
    sweep "$scenes/nan_normals/scene.gltf" --strict --lights 1 --res 16x16 --out "$out"

# --- Options of every command -------------------------------------------------------------
o=(--out "$out")
expect_refusal "render --seed negative" "--seed" render --seed -1 "${o[@]}"
expect_refusal "render --seed not a number" "--seed" render --seed abc "${o[@]}"
expect_refusal "render --seed past 2^64" "--seed" render --seed 18446744073709551616 "${o[@]}"
expect_refusal "render --lights fractional" "--lights" render --lights 1.5 "${o[@]}"
expect_refusal "render --light-radius trailing junk" "--light-radius" render --light-radius 1,2x "${o[@]}"
expect_refusal "render --light-radius zero" "--light-radius" render --light-radius 0,1 "${o[@]}"
expect_refusal "render --light-radius absurd" "--light-radius" render --light-radius 1e20,1e21 "${o[@]}"
expect_refusal "render --light-radius one number" "--light-radius" render --light-radius 5 "${o[@]}"
expect_refusal "render --light-intensity absurd" "--light-intensity" render --light-intensity 1e30,1e38 "${o[@]}"
expect_refusal "render --light-intensity nan" "--light-intensity" render --light-intensity nan,nan "${o[@]}"
expect_refusal "render --light-types infinite weight" "--light-types" render --light-types point:inf "${o[@]}"
expect_refusal "render --light-types negative weight" "--light-types" render --light-types point:-1 "${o[@]}"
expect_refusal "render --light-types nan weight" "--light-types" render --light-types spot:nan "${o[@]}"
expect_refusal "render --light-types empty item" "--light-types" render --light-types point,,spot "${o[@]}"
expect_refusal "render --light-types repeated" "--light-types" render --light-types point,point "${o[@]}"
expect_refusal "render --res wraps 32 bits" "--res" render --res 4294967304x8 "${o[@]}"
expect_refusal "render --res negative" "--res" render --res -8x8 "${o[@]}"
expect_refusal "render --res with spaces" "--res" render --res " 8x 8" "${o[@]}"
expect_refusal "render --msaa negative" "--msaa" render --msaa -4 "${o[@]}"
expect_refusal "render --frames negative" "--frames" render --frames -1 "${o[@]}"
expect_refusal "render --frames absurd" "--frames" render --frames 99999 "${o[@]}"
expect_refusal "render --warmup negative" "--warmup" render --warmup -1 "${o[@]}"
expect_refusal "render --exposure absurd" "--exposure" render --exposure 1e9 "${o[@]}"
expect_refusal "render --exposure nan" "--exposure" render --exposure nan "${o[@]}"
expect_refusal "render --exr-type unknown" "--exr-type" render --exr-type int "${o[@]}"
expect_refusal "render --tile unsupported" "--tile" render --tile 0 "${o[@]}"
expect_refusal "render --tile-capacity absurd" "--tile-capacity" render --tile-capacity 70000 "${o[@]}"
expect_refusal "render --light-lists unknown" "--light-lists" render --light-lists bogus "${o[@]}"
expect_refusal "render --gbuffer unknown" "--gbuffer" render --gbuffer huge "${o[@]}"
expect_refusal "render --msaa-shading unknown" "--msaa-shading" render --msaa-shading centroid "${o[@]}"
expect_refusal "render --deferred-lighting unknown" "--deferred-lighting" render --deferred-lighting magic "${o[@]}"
expect_refusal "render --accum unknown" "--accum" render --accum fp8 "${o[@]}"
expect_refusal "render --reference-precision unknown" "--reference-precision" render --reference-precision fp16 "${o[@]}"
expect_refusal "render --reference-msaa unknown" "--reference-msaa" render --reference-msaa centroid "${o[@]}"
expect_refusal "render --reference-position unknown" "--reference-position" render --reference-position vertex "${o[@]}"
expect_refusal "render --pipeline empty" "--pipeline" render --pipeline "" "${o[@]}"
expect_refusal "render unknown option" "--frobnicate" render --frobnicate "${o[@]}"
expect_refusal "render two scenes" "" render builtin:courtyard-small builtin:courtyard "${o[@]}"
touch "$work/a_file"
expect_refusal "render --out is a file" "--out" render builtin:courtyard-small "${fast[@]}" --lights 1 --out "$work/a_file"
expect_refusal "render --out empty" "--out" render builtin:courtyard-small "${fast[@]}" --lights 1 --out ""
expect_refusal "compare --pipelines unknown" "--pipelines" compare --pipelines forwardplus,warp "${o[@]}"
expect_refusal "compare --pipelines reference" "--pipelines" compare --pipelines reference "${o[@]}"
expect_refusal "compare --exposure not a number" "--exposure" compare --exposure bright "${o[@]}"
expect_refusal "compare --frames zero" "--frames" compare --frames 0 "${o[@]}"
expect_refusal "compare --light-radius inverted" "--light-radius" compare --light-radius 3,1 "${o[@]}"
expect_refusal "sweep --lights not a number" "--lights" sweep --lights 16,many "${o[@]}"
expect_refusal "sweep --lights absurd" "--lights" sweep --lights 5000000 "${o[@]}"
expect_refusal "sweep --res zero" "--res" sweep --res 0x0 "${o[@]}"
expect_refusal "sweep --msaa unsupported" "--msaa" sweep --msaa 1,16 "${o[@]}"
expect_refusal "sweep --frames zero" "--frames" sweep --frames 0 "${o[@]}"
expect_refusal "sweep --light-types unknown" "--light-types" sweep --light-types laser "${o[@]}"
expect_refusal "sweep --tile unsupported" "--tile" sweep --tile 16,7 "${o[@]}"
expect_refusal "sweep --gbuffer unknown" "--gbuffer" sweep --gbuffer compact,bogus "${o[@]}"
expect_refusal "sweep --msaa-shading unknown" "--msaa-shading" sweep --msaa-shading pixel,centroid "${o[@]}"
expect_refusal "sweep --reference-msaa unknown" "--reference-msaa" sweep --reference-msaa pixel "${o[@]}"
expect_refusal "sweep --pipelines unknown" "--pipelines" sweep --pipelines nope "${o[@]}"
expect_refusal "sweep scene missing" "/nonexistent.glb" sweep /nonexistent.glb --lights 1 --res 8x8 "${o[@]}"
expect_refusal "info --res malformed" "--res" info --res 8by8
expect_refusal "info --msaa unsupported" "--msaa" info --msaa 3
expect_refusal "info scene missing" "/nonexistent.gltf" info /nonexistent.gltf
expect_refusal "info --lights negative" "--lights" info builtin:courtyard-small --lights -5

# --- Lights files -------------------------------------------------------------------------
lights() { # NAME CONTENT: writes $work/NAME.json
    printf '%s' "$2" >"$work/$1.json"
}
p='"type":"point","position":[0,1,0],"intensity":5,"range":2'
lights unknown_top '{"version":1,"lights":[],"colour":1}'
lights string_number "{\"lights\":[{\"type\":\"point\",\"position\":[0,1,0],\"intensity\":\"5\",\"range\":2}]}"
lights absurd_intensity "{\"lights\":[{\"type\":\"point\",\"position\":[0,1,0],\"intensity\":1e30,\"range\":2}]}"
lights zero_range "{\"lights\":[{\"type\":\"point\",\"position\":[0,1,0],\"intensity\":5,\"range\":0}]}"
lights far_position "{\"lights\":[{\"type\":\"point\",\"position\":[1e20,1,0],\"intensity\":5,\"range\":2}]}"
lights tiny_direction '{"lights":[{"type":"directional","direction":[0,-1e-9,0],"intensity":1}]}'
lights nan_literal "{\"lights\":[{$p,\"color\":[NaN,1,1]}]}"
lights negative_color "{\"lights\":[{$p,\"color\":[-1,1,1]}]}"
lights unknown_type '{"lights":[{"type":"area","intensity":1}]}'
lights deep "$(printf '%0.s[' $(seq 1 5000))"
lights empty ""
lights not_object '"lights"'
for f in unknown_top string_number absurd_intensity zero_range far_position tiny_direction \
    nan_literal negative_color unknown_type deep empty not_object; do
    expect_refusal "lights file $f" "$f.json" render builtin:courtyard-small --lights-file "$work/$f.json" "${o[@]}"
done
expect_refusal "lights file is a directory" "not a regular file" render builtin:courtyard-small --lights-file "$work" "${o[@]}"

# --- No Vulkan driver at all --------------------------------------------------------------
for cmd in "render" "compare" "sweep" "info" "info --devices"; do
    rm -rf "$out"
    # shellcheck disable=SC2086 # the command's words
    VK_DRIVER_FILES=/nonexistent VK_ICD_FILENAMES=/nonexistent VK_ADD_DRIVER_FILES= \
        run_triptych $cmd $([ "${cmd%% *}" = info ] || echo --out "$out")
    report "no Vulkan driver: $cmd" "$(error_problem "$out" "Vulkan" 2)"
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
