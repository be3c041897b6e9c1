#!/usr/bin/env bash
# The libFuzzer targets (docs/hostile_input.md, "Fuzzing"): build them once, run them anywhere.
#
#   tests/fuzz/run.sh build                  configure and build (clang, ASan + UBSan) in BUILD,
#                                            then assemble BUILD/kit: the binaries, the shared
#                                            libraries they need, seeds, dictionaries, this script
#   KIT/run.sh run SECONDS [TARGET...]       fuzz each target for SECONDS (all by default), one
#                                            after the other; needs only the kit, no compiler
#   KIT/run.sh summary                       totals per target over every run recorded
#   tests/fuzz/run.sh replay [TARGET...]     run every input of tests/fuzz/regressions/TARGET
#                                            once through its target (ctest fuzz_regressions)
#
# Targets: gltf (the glTF loader, Draco and meshopt decoders linked), lights (lights JSON),
# camera (camera files), script (the viewer's script reader).
# Environment: TRIPTYCH_FUZZ_BUILD (the CMake build, default build-fuzz at the repository
# root), TRIPTYCH_FUZZ_OUT (where run keeps corpus/, artifacts/, logs/ and results.tsv;
# default fuzz-out beside the kit), TRIPTYCH_SHARED_SCENES (default ../shared/scenes, seeds for gltf),
# FUZZ_JOBS (libFuzzer processes per target, default 1), FUZZ_ARGS (more libFuzzer flags),
# FUZZ_BUILD_JOBS (compile jobs, default 2).
# `run` prints per target the wall time, executions and findings (new files in
# OUT/artifacts) and exits 1 if a target found something. Needs for `build`: clang, lld,
# libclang-rt-14-dev and the packages of the main build.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
all_targets=(gltf lights camera script)
if [ -f "$here/fuzz_gltf" ] && [ ! -f "$here/CMakeLists.txt" ]; then # a kit's copy
    root= build= kit=$here
else
    root=$(cd "$here/../.." && pwd)
    build=${TRIPTYCH_FUZZ_BUILD:-$root/build-fuzz}
    kit=$build/kit
fi
# Beside the kit, not in it: a kit carried to another machine again must not replace them.
out=${TRIPTYCH_FUZZ_OUT:-$(dirname "$kit")/fuzz-out}
usage() {
    sed -n '4,13p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
}

# The shared libraries the binaries load, beside them in KIT/lib (their RUNPATH is
# $ORIGIN/lib): the machine that runs them may lack these packages. Not glibc, which must be
# the host's (a newer one runs them).
bundle_libraries() {
    mkdir -p "$kit/lib"
    for t in "${all_targets[@]}"; do ldd "$build/fuzz_$t"; done | awk '$3 ~ /^\// {print $3}' | sort -u |
        while read -r lib; do
            case $(basename "$lib") in
            libc.so* | libm.so* | libpthread.so* | libdl.so* | librt.so* | ld-linux*) ;;
            *) cp -L "$lib" "$kit/lib/" ;;
            esac
        done
}

gather_seeds() {
    local shared=${TRIPTYCH_SHARED_SCENES:-$root/../shared/scenes}
    mkdir -p "$kit/files" "$kit/dicts"
    for t in "${all_targets[@]}"; do
        mkdir -p "$kit/seeds/$t"
        cp "$root"/tests/fuzz/regressions/"$t"/* "$kit/seeds/$t/" 2>/dev/null || true
        cp "$root"/tests/fuzz/seeds/"$t"/* "$kit/seeds/$t/" 2>/dev/null || true
        [ -f "$root/tests/fuzz/$t.dict" ] && cp "$root/tests/fuzz/$t.dict" "$kit/dicts/"
    done
    # glTF: the hostile scenes, the GLBs of make_gltf_seeds, and the shared scenes under
    # 256 KB; their buffers and small images go to files/, where the target resolves URIs.
    local hostile=$build/hostile
    rm -rf "$hostile"
    "$build/make_hostile_scenes" "$hostile" >/dev/null
    while IFS=$'\t' read -r name scene _; do
        [ -f "$hostile/$name/$scene" ] && cp "$hostile/$name/$scene" "$kit/seeds/gltf/hostile_$name"
        find "$hostile/$name" -type f ! -name 'scene.*' -size -64k -exec cp {} "$kit/files/" \;
    done <"$hostile/CASES.tsv"
    rm -rf "$hostile"
    "$build/make_gltf_seeds" "$kit/seeds/gltf"
    if [ -d "$shared" ]; then
        while IFS= read -r f; do
            cp "$f" "$kit/seeds/gltf/shared_$(basename "$(dirname "$f")")_$(basename "$f")"
            find "$(dirname "$f")" -maxdepth 1 -type f \( -name '*.bin' -size -1024k -o -size -64k \) \
                ! -name '*.gltf' ! -name '*.glb' -exec cp {} "$kit/files/" \;
        done < <(find "$shared" \( -name '*.gltf' -o -name '*.glb' \) -size -256k)
    else
        echo "note: no shared scenes at $shared; seeding glTF without them"
    fi
    for t in "${all_targets[@]}"; do echo "seeds $t: $(ls "$kit/seeds/$t" | wc -l)"; done
}

do_build() {
    [ -n "$root" ] || { echo "run.sh build: run the repository's tests/fuzz/run.sh" >&2; exit 2; }
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    cmake -S "$root/tests/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" >/dev/null
    nice -n 10 cmake --build "$build" -j"${FUZZ_BUILD_JOBS:-2}"
    # A fresh kit (the corpus and findings of earlier runs are in OUT).
    rm -rf "$kit"
    mkdir -p "$kit"
    for t in "${all_targets[@]}"; do cp "$build/fuzz_$t" "$kit/"; done
    bundle_libraries
    gather_seeds
    cp "$0" "$kit/run.sh"
    echo "kit: $kit ($(du -sh "$kit" | cut -f1))"
    echo "run with: $kit/run.sh run SECONDS [${all_targets[*]}]"
}

# Clang 14's AddressSanitizer cannot map its shadow memory under the 32 bits of mmap
# randomization that recent kernels (Ubuntu 24.04's among them) set: the binaries then die at
# start. Without address randomization (setarch -R, inherited by libFuzzer's job processes)
# they run; reading /proc needs no privilege, changing the sysctl would.
no_aslr=()
if [ "$(cat /proc/sys/vm/mmap_rnd_bits 2>/dev/null || echo 0)" -gt 28 ] && command -v setarch >/dev/null; then
    no_aslr=(setarch "$(uname -m)" -R)
fi

# Sums what libFuzzer's logs say: executions (each log's final count, or its last progress
# line when the process ended on a finding), and the largest coverage and peak RSS.
summarize_logs() {
    awk '/^stat::number_of_executed_units:/ {stat[FILENAME] = $2}
         /^#[0-9]+/ {n = substr($1, 2) + 0; if (n > last[FILENAME]) last[FILENAME] = n}
         / cov: / {for (i = 1; i < NF; ++i) if ($i == "cov:" && $(i+1) > cov) cov = $(i+1)}
         /^stat::peak_rss_mb:/ {if ($2 > rss) rss = $2}
         END {for (f in last) runs += (f in stat) ? stat[f] : last[f]
              printf "%d %d %d\n", runs, cov, rss}' "$@"
}

# Crashes, sanitizer reports, leaks, timeouts and out-of-memory inputs; not slow-unit-* (inputs
# over 10 s, saved as leads).
count_findings() {
    find "$out/artifacts" -name "$1-*" ! -name "$1-slow-unit-*" | wc -l
}

# run_target TARGET SECONDS: one libFuzzer process per job, each for SECONDS; logs in
# BUILD/logs/TARGET (libFuzzer writes fuzz-N.log into the working directory).
run_target() {
    local t=$1 seconds=$2 jobs=${FUZZ_JOBS:-1} logs="$out/logs/$1" dict=()
    [ -x "$kit/fuzz_$t" ] || { echo "run.sh: no $kit/fuzz_$t (run tests/fuzz/run.sh build)" >&2; return 2; }
    [ -f "$kit/dicts/$t.dict" ] && dict=(-dict="$kit/dicts/$t.dict")
    rm -rf "$logs" && mkdir -p "$logs" "$out/artifacts" "$out/corpus/$t"
    local before start status=0
    before=$(count_findings "$t")
    start=$(date +%s)
    (cd "$logs" && TRIPTYCH_FUZZ_FILES="$kit/files" "${no_aslr[@]}" "$kit/fuzz_$t" "$out/corpus/$t" "$kit/seeds/$t" \
        "${dict[@]}" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2560 -malloc_limit_mb=1536 \
        -max_len=65536 -jobs="$jobs" -workers="$jobs" -print_final_stats=1 \
        -artifact_prefix="$out/artifacts/$t-" ${FUZZ_ARGS:-} >"$logs/main.log" 2>&1) || status=$?
    local wall=$(($(date +%s) - start)) found runs cov rss
    found=$(($(count_findings "$t") - before))
    read -r runs cov rss < <(summarize_logs "$logs"/*.log)
    printf '%-8s %8s s %6s jobs %12s executions %6s edges %6s MB peak %3s findings\n' \
        "$t" "$wall" "$jobs" "$runs" "$cov" "$rss" "$found"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$wall" "$jobs" "$runs" "$cov" "$rss" \
        "$found" >>"$out/results.tsv"
    grep -h -E 'ERROR: |SUMMARY: |runtime error|^fuzz_[a-z]+: ' "$logs"/*.log | sort -u | head -5 || true
    [ "$found" -eq 0 ] && [ "$status" -eq 0 ]
}

do_run() {
    local seconds=${1:-}
    [[ $seconds =~ ^[0-9]+$ ]] || usage
    shift
    local targets=("$@") status=0
    [ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
    echo "fuzzing ${targets[*]} for $seconds s each, ${FUZZ_JOBS:-1} job(s), kit $kit, output in $out"
    for t in "${targets[@]}"; do run_target "$t" "$seconds" || status=1; done
    ls "$out/artifacts" | head -20
    exit $status
}

# Each regression input once through its target, with no external files: what once failed
# must load or be refused cleanly now.
do_replay() {
    [ -n "$root" ] || { echo "run.sh replay: run the repository's tests/fuzz/run.sh" >&2; exit 2; }
    local targets=("$@") status=0 empty
    [ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
    empty=$(mktemp -d)
    for t in "${targets[@]}"; do
        local inputs=("$root"/tests/fuzz/regressions/"$t"/*) failed=0
        [ -e "${inputs[0]}" ] || continue
        # One process per input: libFuzzer stops at the first failing one.
        for input in "${inputs[@]}"; do
            TRIPTYCH_FUZZ_FILES=$empty "${no_aslr[@]}" "$build/fuzz_$t" -rss_limit_mb=2560 -malloc_limit_mb=1536 \
                "$input" >"$empty/$t.log" 2>&1 && continue
            echo "$t: $(basename "$input") fails again:"
            grep -E 'ERROR: |SUMMARY: |runtime error|^fuzz_[a-z]+: ' "$empty/$t.log" | head -4
            failed=$((failed + 1))
        done
        echo "$t: $((${#inputs[@]} - failed)) of ${#inputs[@]} regression inputs pass"
        [ $failed -eq 0 ] || status=1
    done
    rm -rf "$empty"
    exit $status
}

# Totals per target over every run in OUT/results.tsv (runs in chunks add up).
do_summary() {
    [ -f "$out/results.tsv" ] || { echo "no runs recorded in $out/results.tsv"; exit 0; }
    awk -F'\t' '{wall[$2] += $3; runs[$2] += $5; found[$2] += $8; if ($6 > cov[$2]) cov[$2] = $6
                  jobs[$2] = $4 > jobs[$2] ? $4 : jobs[$2]; n[$2]++}
         END {for (t in wall) printf "%-8s %3d runs %8d s %4d jobs (most) %12d executions %6d edges %3d findings\n",
                  t, n[t], wall[t], jobs[t], runs[t], cov[t], found[t]}' "$out/results.tsv"
}

case ${1:-} in
build) do_build ;;
summary) do_summary ;;
run) shift && do_run "$@" ;;
replay) shift && do_replay "$@" ;;
*) usage ;;
esac
