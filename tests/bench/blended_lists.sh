#!/usr/bin/env bash
# The blended pass against Forward+'s (docs/deferred.md, "The blended pass on the H200"):
# interleaved rounds of a baseline build and this one, each rendering deferred (binned and
# --light-cull all), the visibility buffer's --vis-blended forward and Forward+, printing each
# run's blended pass (deferred's transparent_forward, Forward+'s forward_transparent), the tiled
# lighting (which writes the transparent lists) and the frame, medians over the timed frames,
# from render.json.
# Usage: blended_lists.sh BASE_BIN NEW_BIN OUT [ROUNDS]
#   ARGS (default: the H200's figure) is what every render gets, e.g. for lavapipe
#   ARGS='builtin:courtyard-small --frames 3' tests/bench/blended_lists.sh ...
#   MSAA=4 adds --msaa 4.  CONFIGS overrides the configurations (one per line).
set -u
base=$1 new=$2 out=$3 rounds=${4:-3}
args=${ARGS:-builtin:courtyard --res 1920x1080 --lights 1024 --frames 20 --warmup 3}
[ -n "${MSAA:-}" ] && args="$args --msaa $MSAA"
configs=${CONFIGS:-"--pipeline deferred
--pipeline deferred --light-cull all
--pipeline deferred --hdr fp16
--pipeline visbuffer --vis-blended forward
--pipeline forwardplus"}
mkdir -p "$out"
for r in $(seq 1 "$rounds"); do
    while IFS= read -r c; do
        for which in base new; do
            bin=${!which}
            dir="$out/r${r}_${which}_$(echo "$c" | tr -c 'a-z0-9' '_')"
            # shellcheck disable=SC2086
            if ! "$bin" render $args $c --out "$dir" >"$dir.log" 2>&1; then
                echo "round $r $which [$c]: FAILED (see $dir.log)"
                continue
            fi
            python3 - "$dir/render.json" "$r" "$which" "$c" <<'PY'
import json, sys
path, r, which, config = sys.argv[1:]
t = {x['pass']: x['median_ms'] for x in json.load(open(path))['run']['timings']}
blended = t.get('transparent_forward', t.get('forward_transparent', float('nan')))
lists = t.get('tiled_lighting', float('nan'))  # binned now builds index lists there too
print(f"round {r} {which:4} {config:45} blended {blended:9.3f} ms  tiled_lighting {lists:9.3f} ms"
      f"  frame {t['frame']:9.3f} ms")
PY
        done
    done <<<"$configs"
done
