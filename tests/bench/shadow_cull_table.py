#!/usr/bin/env python3
"""The table of tests/bench/shadow_cull.sh: per pipeline, --shadow-cache and --cull-geometry, the
frame's and the shadow passes' median GPU times (ms), the kept atlas's one-time render and the
shadow faces' cull counters, from each run's render.json."""
import sys

from cull_table import table  # the same rows: frame, passes, counters

PASSES = ["shadow_cull", "shadow_maps", "volume_shadowed_lights", "light_passes", "blended"]
COUNTERS = ["shadow_maps_render_ms", "shadow_face_draws", "shadow_meshlets", "shadow_meshlets_submitted",
            "shadow_meshlets_culled_frustum", "shadow_meshlets_culled_range",
            "shadow_triangles_submitted", "shadow_triangles"]
SHORT = {"shadow_maps_render_ms": "kept_render_ms", "shadow_face_draws": "face_draws"}


def main(out):
    print(table(out, PASSES, COUNTERS,
                lambda k: SHORT.get(k, k.replace("shadow_", "").replace("meshlets", "m")
                                    .replace("triangles", "tri"))))


if __name__ == "__main__":
    main(sys.argv[1])
