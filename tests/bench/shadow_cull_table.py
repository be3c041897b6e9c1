#!/usr/bin/env python3
"""The table of tests/bench/shadow_cull.sh: per pipeline, --shadow-cache and --cull-geometry, the
frame's and the shadow passes' median GPU times (ms), the kept atlas's one-time render and the
shadow faces' cull counters, from each run's render.json."""
import json
import pathlib
import sys

PASSES = ["shadow_cull", "shadow_maps", "volume_shadowed_lights", "light_passes", "blended"]
COUNTERS = ["shadow_maps_render_ms", "shadow_face_draws", "shadow_meshlets", "shadow_meshlets_submitted",
            "shadow_meshlets_culled_frustum", "shadow_meshlets_culled_range",
            "shadow_triangles_submitted", "shadow_triangles"]
SHORT = {"shadow_maps_render_ms": "kept_render_ms", "shadow_face_draws": "face_draws"}


def main(out):
    for d in sorted(pathlib.Path(out).iterdir()):
        f = d / "render.json"
        if not f.exists():
            continue
        j = json.load(open(f))
        run = j["run"]
        t = {x["pass"]: x["median_ms"] for x in run["timings"]}
        c = run["counters"]
        frame = t.get("frame", sum(t.values()))
        passes = " ".join(f"{p} {t[p]:.3f}" for p in PASSES if p in t)
        counts = " ".join(f"{SHORT.get(k, k.replace('shadow_', '').replace('meshlets', 'm').replace('triangles', 'tri'))}"
                          f"={c[k]:.4g}" for k in COUNTERS if k in c)
        print(f"{d.name:38} frame {frame:9.3f} | {passes} | {counts} [{j['device']['name']}]")


if __name__ == "__main__":
    main(sys.argv[1])
