#!/usr/bin/env python3
"""The camera-path benchmark's tables from a compare report.json (docs/camera_paths.md):
per pipeline the frame-time percentiles, view update, error and replans, then the views where
the ranking of the pipelines by frame time flips. Usage: path_table.py REPORT.json"""
import json
import sys


def fmt(v, digits=3):
    return "-" if v is None else f"{v:.{digits}g}"


def main(path):
    r = json.load(open(path))
    p = r["path"]
    print(f"{p['views']} views of {p['source']}, lights {p['light_motion']}, "
          f"{r['settings']['width']}x{r['settings']['height']}, {r['device']['name']}; "
          f"reference rendered {p['reference']['renders']}x, reused {p['reference']['reused']}x")
    print("| pipeline | frame ms median | p95 | p99 | max | view update ms median | max "
          "| rmse median | max | replans |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for s in p["pipelines"]:
        f, u, e = (s["summary"][k] or {} for k in ("frame_ms", "view_update_ms", "rmse_hdr"))
        print(f"| {s['name']} | {fmt(f.get('median'))} | {fmt(f.get('p95'))} | "
              f"{fmt(f.get('p99'))} | {fmt(f.get('max'))} | {fmt(u.get('median'))} | "
              f"{fmt(u.get('max'))} | {fmt(e.get('median'))} | {fmt(e.get('max'))} | "
              f"{s['replans']} |" + (f" FAILED: {s['error']}" if s["error"] else ""))
    print(f"\nranking flips (a pipeline ahead by more than {100 * p['rank_margin']:.0f} %): "
          f"{len(p['rank_flips'])}")
    for flip in p["rank_flips"]:
        print(f"  view {flip['view']}: {' < '.join(flip['before'])}  ->  {' < '.join(flip['after'])}")
    print(f"worst view (largest error): {p['worst_view']}")


if __name__ == "__main__":
    main(sys.argv[1])
