#!/bin/bash
# triptych view in a real window under Xvfb (GLFW + swapchain, validation on), and with no
# display at all: one line suggesting --headless or an X server, exit 2. Without xvfb-run the
# window is not checked: the rest runs, then exit 77 (a ctest skip) with the reason.
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/cli_lib.sh"

# No display: the one line, no window, no crash.
(cd "$work/cwd" && env -u DISPLAY -u WAYLAND_DISPLAY "$bin" view builtin:courtyard-small --lights 4) \
    >"$work/stdout" 2>"$work/stderr"
code=$?
lines=$(grep -c '' "$work/stderr")
first=$(head -n 1 "$work/stderr")
report "view without a display" "$(error_problem "" "--headless" 2)"
[[ "$first" == *"X server"* ]] || report "view without a display" "the message does not suggest an X server"

# Bad input to view: one line, exit 2, before any device or window.
run_triptych view --headless
report "view --headless without a script" "$(error_problem "" "--script" 2)"
run_triptych view --headless --script "$work/missing.txt"
report "view with a missing script" "$(error_problem "" "missing.txt" 2)"
printf 'split 0.5\nteleport 1 2\n' >"$work/bad.txt"
run_triptych view --headless --script "$work/bad.txt"
report "view with a bad script line" "$(error_problem "" "bad.txt:2" 2)"

skipped=""
if ! command -v xvfb-run >/dev/null; then
    skipped="view in a window: xvfb-run is not installed (apt-get install xvfb xauth)"
else
    # A short script in the window: select, render, switch mode, flip; close after it.
    printf 'split 0.3\nwait\nmode difference\nkey f\nwait\nframes 5\n' >"$work/script.txt"
    (cd "$work/cwd" && timeout 240 xvfb-run -a -s "-screen 0 1280x720x24" "$bin" view builtin:courtyard-small \
        --lights 8 --res 160x90 --validate --no-reference --script "$work/script.txt" --out "$work/out" \
        --quit-after 10) >"$work/stdout" 2>"$work/stderr"
    code=$?
    if [ "$code" -ne 0 ]; then
        report "view in a window under Xvfb" "exit code $code"
    else
        first="exit code 0, validation clean"
        report "view in a window under Xvfb" ""
    fi
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] || exit 1
# What could not run makes the test a skip (ctest: SKIP_RETURN_CODE 77), never a pass.
if [ -n "$skipped" ]; then echo "skipped: $skipped"; exit 77; fi
