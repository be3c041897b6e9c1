#!/usr/bin/env bash
# The shadows benchmark (docs/shadows.md, "Measured"): compare on the courtyard with 1,024 lights
# and N of them shadowed, every pipeline (deferred both as tiled compute and as light volumes:
# the atlas against one light's map), then the table and the memory-against-time plot.
# Usage: [FRAMES=5] shadow_bench.sh BIN OUT [RES] [LIGHTS] [SHADOWED...]
#   H100: shadow_bench.sh build/triptych out 1920x1080 1024 16 64 256
#   lavapipe: shadow_bench.sh build/triptych out 640x360 1024 16
set -u
bin=$1 out=$2 res=${3:-1920x1080} lights=${4:-1024}
shift 4 2>/dev/null || shift $#
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(16 64 256)
here=$(dirname "$0")
mkdir -p "$out"
for n in "${counts[@]}"; do
    # tiled: every pipeline, the atlas cached; off: the atlas pipelines rendering their maps
    # every frame (--shadow-cache off); volumes: deferred with one light's map at a time.
    for run in tiled off volumes; do
        pipes=deferred lighting=$run cache=on
        [ "$run" = tiled ] && pipes=forwardplus,deferred,visbuffer,multipass_forward
        [ "$run" = off ] && pipes=forwardplus,deferred,visbuffer lighting=tiled cache=off
        dir="$out/s${n}_$run"
        "$bin" compare builtin:courtyard --res "$res" --lights "$lights" --shadows "$n" \
            --pipelines "$pipes" --deferred-lighting "$lighting" --shadow-cache "$cache" --frames "${FRAMES:-5}" \
            --out "$dir" >"$dir.log" 2>&1
        echo "== --shadows $n, $run: exit $? ($dir.log)"
    done
done
python3 "$here/shadow_table.py" "$out" "${counts[@]}"
