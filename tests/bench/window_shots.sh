#!/usr/bin/env bash
# Screenshots of the real viewer window under Xvfb while a camera path plays (docs/viewer.md,
# "Playing a path"): the X server's root window captured with xwd (x11-apps) at a few moments,
# converted with netpbm. Not a test (timing-dependent): what the closing note and docs show.
# Usage: window_shots.sh TRIPTYCH OUT [SCENE] [RES] [PATH_FILE] [SECONDS_BETWEEN]
# apt-get install xvfb x11-apps netpbm
set -u
bin=$(realpath "$1") out=$2 scene=${3:-builtin:courtyard-small} res=${4:-640x360}
path=$(realpath "${5:-docs/recipes/courtyard_path.json}") gap=${6:-20}
mkdir -p "$out"
out=$(realpath "$out")
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  "$0" view "$1" --res "$2" --camera-path "$3" --light-motion orbit --lights 64 --no-reference \
      >"$4/view.log" 2>&1 &
  pid=$!
  for i in 1 2 3; do
    sleep "$5"
    xwd -root -silent | xwdtopnm 2>/dev/null | pnmtopng >"$4/window_$i.png"
  done
  kill $pid; wait $pid 2>/dev/null
' "$bin" "$scene" "$res" "$path" "$out" "$gap"
ls -la "$out"
