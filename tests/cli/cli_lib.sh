# Shared by the CLI tests (sourced): runs triptych in an empty working directory and judges a
# run that must fail on bad input: one line on stderr starting with "triptych:", the expected
# exit code, no crash, no output that looks complete, nothing written in the working directory.
# The sourcing script sets $bin and $work first.
fail=0
pass=0
bin=$(realpath "$bin") # runs are made from another directory
mkdir -p "$work/cwd"

# run_triptych ARGS...: sets $code, $lines (of stderr) and $first (its first line).
run_triptych() {
    (cd "$work/cwd" && exec "$bin" "$@") >"$work/stdout" 2>"$work/stderr"
    code=$?
    lines=$(grep -c '' "$work/stderr")
    first=$(head -n 1 "$work/stderr")
}

# error_problem OUT MENTION [CODE]: what is wrong with the last run as a refusal ("" if nothing).
error_problem() {
    local out=$1 mention=$2 want=${3:-}
    if [ "$code" -eq 0 ]; then echo "exit code 0"
    elif [ "$code" -ge 128 ]; then echo "crashed (exit $code)"
    elif [ -n "$want" ] && [ "$code" -ne "$want" ]; then echo "exit code $code, expected $want"
    elif [ "$lines" -ne 1 ]; then echo "$lines lines on stderr"
    elif [[ "$first" != triptych:* ]]; then echo "stderr does not start with 'triptych:'"
    elif [ -n "$mention" ] && [[ "$first" != *"$mention"* ]]; then
        echo "the message does not mention '$mention'"
    elif [ -n "$out" ] && ls "$out"/*.exr "$out"/*.png "$out"/*.json "$out"/*.csv \
        "$out"/*.html >/dev/null 2>&1; then echo "left output files behind"
    elif [ -n "$(ls -A "$work/cwd")" ]; then
        echo "wrote into the working directory: $(ls -A "$work/cwd" | head -3 | tr '\n' ' ')"
    fi
}

# report WHAT PROBLEM: counts and prints one line (and the stderr of a failure).
report() {
    if [ -n "$2" ]; then
        echo "FAIL $1: $2"
        sed 's/^/    /' "$work/stderr" | head -5
        fail=$((fail + 1))
    else
        echo "ok   $1: $first"
        pass=$((pass + 1))
    fi
    rm -rf "${work:?}/cwd" && mkdir -p "$work/cwd"
}
