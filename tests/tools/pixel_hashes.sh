#!/usr/bin/env bash
# The first 16 hex digits of the SHA-1 of each image's pixels (oiiotool --hash), one per file,
# on one line: what the fingerprint tools compare. Pixels, not file bytes, so that how the
# writer compresses (the EXR zip level, the PNG encoder) does not change a fingerprint.
#   tests/tools/pixel_hashes.sh FILE...
set -euo pipefail
for f in "$@"; do
    [[ -e $f ]] || continue
    hash=$(oiiotool --hash "$f" | awk '/SHA-1:/ {print $2}')
    [[ -n $hash ]] || { echo "pixel_hashes.sh: no hash for $f" >&2; exit 1; }
    printf '%s ' "${hash:0:16}"
done
