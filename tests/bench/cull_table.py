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


def table(out, passes, counters, name, total=None):
    """One row per run folder under `out` with a render.json: the frame, the median GPU time of
    each of `passes` it has (with `total`, a label: their sum first), and each of `counters` it
    has, labelled by name(counter)."""
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
        times = " ".join(f"{p} {t[p]:.3f}" for p in passes if p in t)
        if total:
            times = f"{total} {sum(t[p] for p in passes if p in t):.3f} : {times}"
        counts = " ".join(f"{name(k)}={c[k]:.4g}" for k in counters if k in c)
        rows.append(f"{d.name:40} frame {frame:9.3f} | {times} | {counts} [{j['device']['name']}]")
    return "\n".join(rows)


def main(out):
    print(table(out, GEOMETRY, COUNTERS,
                lambda k: k.replace("meshlets_", "m_").replace("triangles", "tri")))


if __name__ == "__main__":
    main(sys.argv[1])
