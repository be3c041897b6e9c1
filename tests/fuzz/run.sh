#!/usr/bin/env bash
# Builds the libFuzzer targets for the glTF loader and the lights JSON parser with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs them for DURATION seconds in all
# (three quarters to the glTF loader). Not part of CI: findings are written to
# BUILD/artifacts and the script exits 1. See docs/hostile_input.md.
#
# Usage: tests/fuzz/run.sh DURATION_SECONDS [gltf|lights|both]
# Environment: TRIPTYCH_FUZZ_BUILD (default build-fuzz), TRIPTYCH_SHARED_SCENES (default
# ../shared/scenes), FUZZ_JOBS (libFuzzer -jobs, default 1), FUZZ_ARGS (more libFuzzer flags).
# Needs: apt-get install clang (libFuzzer's runtime is in libclang-rt-14-dev), and the
# packages of the main build.
set -euo pipefail
duration=${1:?usage: run.sh DURATION_SECONDS [gltf|lights|both]}
which=${2:-both}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${TRIPTYCH_FUZZ_BUILD:-$root/build-fuzz}
shared=${TRIPTYCH_SHARED_SCENES:-$root/../shared/scenes}
jobs=${FUZZ_JOBS:-1}

command -v clang++ >/dev/null || { echo "run.sh: clang++ not found (apt-get install clang)" >&2; exit 2; }
rtdir=$(clang++ -print-runtime-dir)
[ -f "$rtdir/libclang_rt.fuzzer-x86_64.a" ] ||
    { echo "run.sh: libFuzzer's runtime is not in $rtdir (apt-get install libclang-rt-14-dev)" >&2; exit 2; }

mkdir -p "$build/obj" "$build/seeds/gltf" "$build/seeds/lights" "$build/corpus/gltf" \
    "$build/corpus/lights" "$build/files" "$build/artifacts"
common=(-std=c++20 -g -O1 -fno-omit-frame-pointer -I"$root" -I/usr/include/stb
    -DGLM_FORCE_DEPTH_ZERO_TO_ONE -DGLM_FORCE_RADIANS)
sanitize=(-fsanitize=address,undefined -fno-sanitize-recover=undefined)

# compile SOURCE: one object per source, rebuilt when the source or a header of ours is newer.
compile() {
    local src=$1 obj
    obj="$build/obj/$(echo "${src#"$root"/}" | tr / _).o"
    if [ ! -f "$obj" ] || [ -n "$(find "$src" "$root/core/scene" "$root/tests/cli" -newer "$obj" \
        \( -name '*.h' -o -path "$src" \) -print -quit)" ]; then
        echo "compiling ${src#"$root"/}" >&2
        nice -n 10 clang++ "${common[@]}" "${sanitize[@]}" -fsanitize=fuzzer-no-link -c "$src" -o "$obj"
    fi
    echo "$obj"
}
link() { # OUTPUT SOURCES...
    local out=$1 objs=()
    shift
    for s in "$@"; do objs+=("$(compile "$root/$s")"); done
    # libdraco and meshoptimizer are the Debian builds (not instrumented): the sanitizers see
    # what the loader hands them and what it does with their output.
    nice -n 10 clang++ "${sanitize[@]}" -fsanitize=fuzzer "${objs[@]}" -o "$build/$out" -lpthread \
        -ldraco -lmeshoptimizer
}
link fuzz_gltf core/scene/gltf_loader.cpp core/scene/gltf_files.cpp core/scene/gltf_accessors.cpp \
    core/scene/gltf_geometry.cpp core/scene/gltf_materials.cpp core/scene/gltf_nodes.cpp \
    core/scene/gltf_draco.cpp core/scene/gltf_meshopt.cpp \
    core/scene/scene.cpp tests/fuzz/tinygltf_impl.cpp tests/fuzz/fuzz_gltf.cpp
link fuzz_lights core/scene/lights.cpp core/scene/scene.cpp tests/fuzz/fuzz_lights.cpp
nice -n 10 clang++ "${common[@]}" -O0 "$root/tests/cli/make_hostile_scenes.cpp" \
    "$root/tests/cli/hostile_scenes.cpp" -o "$build/make_hostile_scenes" -lmeshoptimizer

# Seeds: the hostile scenes, the shared scenes (small ones; their buffers and small images go
# to files/, where the target resolves URIs), and a few lights files.
rm -rf "$build/hostile" && "$build/make_hostile_scenes" "$build/hostile"
while IFS=$'\t' read -r name scene _; do
    [ -f "$build/hostile/$name/$scene" ] && cp "$build/hostile/$name/$scene" "$build/seeds/gltf/hostile_$name"
    find "$build/hostile/$name" -type f ! -name 'scene.*' -size -64k -exec cp {} "$build/files/" \;
done <"$build/hostile/CASES.tsv"
if [ -d "$shared" ]; then
    while IFS= read -r f; do
        cp "$f" "$build/seeds/gltf/shared_$(basename "$f")"
        find "$(dirname "$f")" -maxdepth 1 -type f \( -name '*.bin' -size -1024k -o -size -64k \) \
            ! -name '*.gltf' ! -name '*.glb' -exec cp {} "$build/files/" \;
    done < <(find "$shared" \( -name '*.gltf' -o -name '*.glb' \) -size -256k)
else
    echo "note: no shared scenes at $shared; seeding with the hostile scenes only"
fi
# Inputs that once failed (tests/fuzz/regressions) are seeds too: they run first, every time.
cp "$root"/tests/fuzz/regressions/gltf/* "$build/seeds/gltf/"
cp "$root"/tests/fuzz/regressions/lights/* "$build/seeds/lights/"
p='"position":[1,2,3],"intensity":5,"range":4,"color":[1,0.5,0.25]'
printf '{"version":1,"lights":[{"type":"point",%s}]}' "$p" >"$build/seeds/lights/point.json"
printf '{"version":1,"lights":[{"type":"spot",%s,"direction":[0,-1,0],"inner_cone":0.2,"outer_cone":0.6}]}' \
    "$p" >"$build/seeds/lights/spot.json"
printf '{"lights":[{"type":"directional","direction":[0.3,-1,0],"intensity":2}]}' >"$build/seeds/lights/sun.json"
printf '{"version":1,"lights":[]}' >"$build/seeds/lights/empty.json"

# run TARGET SECONDS DICT
run() {
    local target=$1 seconds=$2 log="$build/$1.log"
    echo "fuzzing $target for $seconds s (log: $log)"
    local status=0
    TRIPTYCH_FUZZ_FILES="$build/files" nice -n 10 "$build/fuzz_$target" "$build/corpus/$target" \
        "$build/seeds/$target" -dict="$root/tests/fuzz/$target.dict" -max_total_time="$seconds" \
        -timeout=20 -rss_limit_mb=2560 -malloc_limit_mb=1536 -max_len=65536 -jobs="$jobs" \
        -workers="$jobs" -print_final_stats=1 -artifact_prefix="$build/artifacts/$target-" \
        ${FUZZ_ARGS:-} >"$log" 2>&1 || status=$?
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|Done [0-9]+ runs' "$log" || true
    grep -E 'ERROR|SUMMARY|runtime error' "$log" | head -5 || true
    return $status
}
status=0
case $which in
gltf) run gltf "$duration" || status=1 ;;
lights) run lights "$duration" || status=1 ;;
*)
    run gltf $((duration * 3 / 4)) || status=1
    run lights $((duration - duration * 3 / 4)) || status=1
    ;;
esac
ls "$build/artifacts" | head
exit $status
