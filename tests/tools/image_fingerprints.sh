#!/usr/bin/env bash
# Prints one line per configuration: the configuration and the pixels' hash of the EXR it
# renders (and of its debug images). Run before and after a change that must not move a pixel
# (a refactoring), then diff the two outputs: every pipeline and the reference on the built-in
# scene, 1x and 4x at both shading rates, tiled and clustered, every light-list layout and
# culling mode.
#   tests/tools/image_fingerprints.sh BUILD/triptych > before.txt
# ONLY=REGEX (an extended regular expression) keeps the configurations it matches, e.g.
#   ONLY='forwardplus.*clustered|light-bin gpu' tests/tools/image_fingerprints.sh BUILD/triptych
# The hashes are of the pixels (tests/tools/pixel_hashes.sh): how the writer compresses them
# does not change a fingerprint.
set -euo pipefail
exe=${1:?usage: image_fingerprints.sh PATH/TO/triptych}
tools=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=builtin:courtyard-small
common=(--res 96x64 --frames 1 --warmup 0 --lights 48 --light-types point:3,spot:1,directional:1)

configs=()
for msaa in "--msaa 1" "--msaa 4 --msaa-shading pixel" "--msaa 4 --msaa-shading sample"; do
    configs+=("--pipeline reference $msaa"
              "--pipeline reference $msaa --reference-position depth --reference-precision fp32")
    [[ $msaa == "--msaa 1" ]] || configs+=("--pipeline reference $msaa --reference-msaa center")
    for assign in tiled clustered; do
        for cull in "--light-cull binned --light-bin cpu" "--light-cull binned --light-bin gpu" "--light-cull all"; do
            base="$msaa --light-assign $assign $cull"
            for lists in compact fixed linked; do
                [[ $assign == clustered && $lists != compact ]] && continue
                configs+=("--pipeline forwardplus $base --light-lists $lists")
            done
            configs+=("--pipeline forwardplus $base --tile 8 --light-spheres inline --cull-by invocation")
            [[ $assign == clustered ]] && configs+=("--pipeline forwardplus $base --light-loop subgroup --slices 8")
            configs+=("--pipeline deferred $base" "--pipeline deferred $base --gbuffer wide --hdr fp16 --tile 32")
            configs+=("--pipeline visbuffer $base" "--pipeline visbuffer $base --hdr fp16 --tile 32")
            configs+=("--pipeline visbuffer $base --vis-blended forward")
        done
    done
    configs+=("--pipeline deferred $msaa --deferred-lighting volumes")
    for bl in under additive one-pass; do
        configs+=("--pipeline multipass_forward $msaa --blended-lights $bl")
    done
    configs+=("--pipeline multipass_forward $msaa --accum fp16")
    # Shadow maps through every pipeline, and the reference with the same maps.
    for p in forwardplus deferred visbuffer multipass_forward reference; do
        configs+=("--pipeline $p $msaa --shadows 3")
    done
    configs+=("--pipeline deferred $msaa --deferred-lighting volumes --shadows 3")
    # The compute rasterizer: every triangle in compute, and the small ones (also culled).
    for vr in compute hybrid "hybrid --cull-geometry frustum"; do
        configs+=("--pipeline visbuffer $msaa --vis-raster $vr")
    done
done
# The debug images (heat maps, depth bounds, G-buffer channels) of the tiled pipelines.
for p in forwardplus deferred visbuffer; do
    configs+=("--pipeline $p --msaa 4 --msaa-shading pixel --debug")
done

i=0
for c in "${configs[@]}"; do
    [[ -n ${ONLY:-} ]] && ! grep -Eq -- "$ONLY" <<<"$c" && continue
    out="$work/$i"
    # shellcheck disable=SC2086
    "$exe" render "$scene" "${common[@]}" $c --out "$out" >"$work/log" 2>&1 || { echo "FAILED: $c"; cat "$work/log"; exit 1; }
    echo "$c  $(cd "$out" && shopt -s nullglob && "$tools/pixel_hashes.sh" *.exr *debug*.png)"
    i=$((i + 1))
done
