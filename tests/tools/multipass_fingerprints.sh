#!/usr/bin/env bash
# Multipass forward's images, one line per configuration with its EXR's pixel hash: run with a
# build before a change and with one after it, on the same machine (docs: LAVAPIPE.md, bit-identical
# only on one machine), and diff the two outputs. Covers 1x and 4x at both shading rates, every
# --blended-lights, fp16, shadows, --cull-geometry frustum and full, the built-in courtyard, and
# the shared blended scenes when ../shared/scenes is present. Extra arguments go to every render
# (e.g. --light-lists cpu with a build that has it).
#   tests/tools/multipass_fingerprints.sh BUILD/triptych [ARGS...] > before.txt
set -euo pipefail
exe=${1:?usage: multipass_fingerprints.sh PATH/TO/triptych [ARGS...]}
tools=$(cd "$(dirname "$0")" && pwd)
shift
extra=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
shared=$(cd "$(dirname "$0")/../.." && pwd)/../shared/scenes
small=(builtin:courtyard-small --res 96x64 --lights 48 --light-types point:3,spot:1,directional:1)

configs=()
for msaa in "--msaa 1" "--msaa 4 --msaa-shading pixel" "--msaa 4 --msaa-shading sample"; do
    for bl in under additive one-pass; do
        configs+=("${small[*]} $msaa --blended-lights $bl")
    done
    configs+=("${small[*]} $msaa --accum fp16" "${small[*]} $msaa --shadows 3"
              "${small[*]} $msaa --cull-geometry frustum" "${small[*]} $msaa --cull-geometry full"
              "${small[*]} $msaa --shadows all --cull-geometry full")
done
configs+=("builtin:courtyard --res 256x144 --lights 128"
          "builtin:courtyard --res 256x144 --lights 128 --msaa 4")
for s in AlphaBlendModeTest SubpassGlass; do
    f=$(ls "$shared/$s"/*.gltf "$shared/$s"/glTF/*.gltf 2>/dev/null | head -1 || true)
    [[ -n $f ]] || continue
    configs+=("$f --res 160x90 --lights 64" "$f --res 160x90 --lights 64 --msaa 4")
done

i=0
for c in "${configs[@]}"; do
    out="$work/$i"
    # shellcheck disable=SC2086
    "$exe" render $c --pipeline multipass_forward --frames 1 --warmup 0 "${extra[@]}" \
        --out "$out" >"$work/log" 2>&1 || { echo "FAILED: $c"; cat "$work/log"; exit 1; }
    echo "$c  $(cd "$out" && "$tools/pixel_hashes.sh" *.exr)"
    i=$((i + 1))
done
