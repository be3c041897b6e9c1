#!/usr/bin/env bash
# Where the README's test command spends its time on a fresh clone (docs/build.md, "The test
# command"): clones REPO at REV into a new folder and runs the command's cmake, build and ctest
# as phases, printing each phase's wall and CPU seconds and the load average around it, then
# the 25 slowest tests. The apt-get part is not run (install the packages first). No ccache:
# CCACHE_DISABLE is set, as on a CI machine that has none.
#   tests/tools/ci_phases.sh /work/main HEAD /tmp/ci-clone        # as the README, -j$(nproc)
#   JOBS=1 tests/tools/ci_phases.sh /work/main HEAD /tmp/ci-clone # on a shared machine
# On a shared machine read the CPU column (user + system of the phase's processes): the wall
# grows with the load, the CPU much less.
# Usage: ci_phases.sh REPO REV DIR
set -euo pipefail
repo=${1:?usage: ci_phases.sh REPO REV DIR}
rev=${2:?usage: ci_phases.sh REPO REV DIR}
dir=${3:?usage: ci_phases.sh REPO REV DIR}
jobs=${JOBS:-$(nproc)}
[ -e "$dir" ] && { echo "ci_phases.sh: $dir exists (a fresh clone needs a new folder)" >&2; exit 1; }
git clone -q "$repo" "$dir"
git -C "$dir" checkout -q "$rev"
cd "$dir"
export CCACHE_DISABLE=1
times=$(mktemp)
trap 'rm -f "$times"' EXIT
# phase NAME COMMAND...: runs it with its output in DIR/phase-NAME.log, prints one line.
phase() {
    local name=$1 start load
    shift
    start=$(date +%s.%N)
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -f "%U %S" -o "$times" "$@" >"phase-$name.log" 2>&1 ||
        { echo "ci_phases.sh: phase $name failed (see $dir/phase-$name.log)" >&2; exit 1; }
    python3 - "$name" "$start" "$(date +%s.%N)" "$(cat "$times")" "$load" \
        "$(cut -d' ' -f1 /proc/loadavg)" <<'PY'
import sys
name, start, end, cpu, l0, l1 = sys.argv[1:]
u, s = map(float, cpu.split())
print(f"{name:12s} wall {float(end) - float(start):7.1f} s   CPU {u + s:7.1f} s   load {l0} -> {l1}")
PY
}
phase configure cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTRIPTYCH_FUZZ=ON
phase shaders cmake --build build -j"$jobs" --target triptych_shaders
phase library cmake --build build -j"$jobs" --target triptych
phase fuzz cmake --build build -j"$jobs" --target fuzz_targets
phase tests-build cmake --build build -j"$jobs"
phase ctest ctest --test-dir build --output-on-failure -j2
echo "slowest tests (s):"
sed '/^---/q' build/Testing/Temporary/CTestCostData.txt | grep -v '^---' | sort -k3 -rn |
    head -25 | awk '{printf "  %6.1f  %s\n", $3, $1}'
