#!/usr/bin/env bash
# The visibility buffer's benchmark (docs/visbuffer.md, "Measured"): every pipeline side by side
# on the built-in courtyard, one run per configuration, on whatever device `triptych` picks
# (a discrete GPU if present, else lavapipe). Usage:
#   visbuffer_bench.sh TRIPTYCH OUT_DIR [gpu|lavapipe]
# gpu:      1920x1080, 1,024 lights at 1x and 4x (pixel rate, both references), 65,536
#           (range 0.5-1.5) at 1x with the reference, 1,000,000 (range 0.1-0.3) at 1x without
#           it (a brute-force reference over a million lights is not a benchmark).
# lavapipe: 1280x720, 256 and 1,024 lights at 1x and 4x.
# Then prints one table from the report.json files (tests/bench/visbuffer_table.py).
set -euo pipefail
bin=$1 out=$2 mode=${3:-gpu}
mkdir -p "$out"
run() { local name=$1; shift; echo "== $name: $*" >&2; "$bin" compare builtin:courtyard "$@" --out "$out/$name" >"$out/$name.log" 2>&1 || echo "($name exited $?)" >&2; }
if [ "$mode" = gpu ]; then
  common=(--res 1920x1080 --frames 5 --warmup 2)
  run l1024_1x "${common[@]}" --lights 1024
  run l1024_4x "${common[@]}" --lights 1024 --msaa 4
  run l65536_1x "${common[@]}" --lights 65536 --light-radius 0.5,1.5
  "$bin" sweep builtin:courtyard "${common[@]}" --lights 1000000 --light-radius 0.1,0.3 \
    --pipelines forwardplus,deferred,visbuffer --reference-frames 0 --out "$out/l1m_1x" \
    >"$out/l1m_1x.log" 2>&1 || echo "(l1m_1x exited $?)" >&2
else
  common=(--res 1280x720 --frames 3 --warmup 1)
  for n in 256 1024; do
    run "l${n}_1x" "${common[@]}" --lights "$n"
    run "l${n}_4x" "${common[@]}" --lights "$n" --msaa 4
  done
fi
python3 "$(dirname "$0")/visbuffer_table.py" "$out"
# The reports and logs alone, for machines that hand back only a few files.
[ -n "${KEEP:-}" ] && { mkdir -p "$KEEP"; for d in "$out"/*/; do n=$(basename "$d"); for f in report.json sweep.csv; do [ -f "$d/$f" ] && cp "$d/$f" "$KEEP/$n.$f"; done; done; cp "$out"/*.log "$KEEP"/; } || true
