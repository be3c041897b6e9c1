#!/usr/bin/env bash
# The reference cache end to end (docs/reference-cache.md), at 64x36 with one pipeline: the
# first compare renders and stores the reference, the second reuses it (report.json says so,
# and the reference image and every metric are the same bytes), a corrupted entry is rendered
# again with a warning and replaced, a changed input (the light count) misses, and
# --no-reference-cache neither reads nor writes.
# Usage: reference_cache.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
cache=$work/cache

# compare_into OUT ARGS...: a small compare into $work/OUT with the test's cache; sets $code.
compare_into() {
    local out=$1
    shift
    run_triptych compare builtin:courtyard-small --res 64x36 --frames 1 --warmup 0 \
        --pipelines forwardplus --reference-cache "$cache" --out "$work/$out" "$@"
}

# cache_field OUT FIELD: true or false, the boolean "FIELD" of report.json's reference cache
# object (the only object with these fields at 1x, where no centre reference is rendered).
cache_field() {
    grep -o "\"$2\": [a-z]*" "$work/$1/report.json" | head -n 1 | cut -d' ' -f2
}

metrics() { grep -E '"(rmse|psnr|max_abs)"' "$work/$1/report.json"; }

compare_into first
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(cache_field first stored)" != true ] && problem="the reference was not stored"
[ -z "$problem" ] && [ "$(ls "$cache" | wc -l)" -ne 1 ] && problem="$(ls "$cache" | wc -l) entries, expected 1"
report "the first compare renders and stores the reference" "$problem"

compare_into second
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(cache_field second reused)" != true ] && problem="not reused"
[ -z "$problem" ] && ! grep -q "reference reused from the cache" "$work/stderr" && problem="stderr does not say it was reused"
[ -z "$problem" ] && ! cmp -s "$work/first/reference.exr" "$work/second/reference.exr" && problem="the reference image differs"
[ -z "$problem" ] && [ "$(metrics first)" != "$(metrics second)" ] && problem="the metrics differ"
report "the second compare reuses it, the same bytes" "$problem"

# Corrupt the stored image: one byte in the middle of hdr.exr.
exr=$(ls "$cache"/*/hdr.exr)
size=$(stat -c %s "$exr")
printf '\xff' | dd of="$exr" bs=1 seek=$((size / 2)) conv=notrunc status=none
compare_into corrupt
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(cache_field corrupt reused)" != false ] && problem="a corrupt entry was trusted"
[ -z "$problem" ] && ! grep -q "warning: reference cache: .*corrupt" "$work/stderr" && problem="no warning naming the corrupt entry"
[ -z "$problem" ] && ! cmp -s "$work/first/reference.exr" "$work/corrupt/reference.exr" && problem="the re-rendered reference differs"
compare_into repaired
[ -z "$problem" ] && [ "$(cache_field repaired reused)" != true ] && problem="the replaced entry was not reused"
report "a corrupt entry is rendered again and replaced" "$problem"

compare_into lights --lights 5
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(cache_field lights reused)" != false ] && problem="another light count reused the entry"
report "another light count misses" "$problem"

before=$(ls "$cache" | sort)
compare_into off --lights 7 --no-reference-cache
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && [ "$(cache_field off used)" != false ] && problem="report says the cache was used"
[ -z "$problem" ] && [ "$(ls "$cache" | sort)" != "$before" ] && problem="it wrote an entry"
report "--no-reference-cache neither reads nor writes" "$problem"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
