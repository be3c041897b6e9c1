#!/usr/bin/env python3
"""The table of tests/bench/cull.sh: per view, MSAA, pipeline and --cull-geometry, the frame's and
the geometry passes' median GPU times (ms) and the cull counters, from each run's render.json."""
import json
import pathlib
import sys

GEOMETRY = ["meshlet_cull", "depth_prepass", "depth_pyramid", "meshlet_cull_late", "depth_prepass_late",
            "gbuffer", "gbuffer_late", "visibility", "visibility_late", "forward_opaque", "base_pass",
            "light_passes"]
COUNTERS = ["meshlets_submitted_early", "meshlets_submitted_late", "meshlets_culled_frustum",
            "meshlets_culled_cone", "meshlets_culled_occlusion", "triangles_submitted", "triangles"]


def main(out):
    rows = []
    for d in sorted(pathlib.Path(out).iterdir()):
        f = d / "render.json"
        if not f.exists():
            continue
        j = json.load(open(f))
        run = j["run"]
        t = {x["pass"]: x["median_ms"] for x in run["timings"]}
        c = run["counters"]
        frame = t.get("frame", sum(t.values()))
        passes = " ".join(f"{p} {t[p]:.3f}" for p in GEOMETRY if p in t)
        counts = " ".join(f"{k.replace('meshlets_', 'm_').replace('triangles', 'tri')}={c[k]:.0f}"
                          for k in COUNTERS if k in c)
        rows.append(f"{d.name:40} frame {frame:9.3f} | {passes} | {counts} [{j['device']['name']}]")
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1])
