#!/usr/bin/env python3
"""One table from visbuffer_bench.sh's runs: per run and pipeline, the frame and its three
costliest passes (median ms), memory (MB, the pipeline's ledger), and the tonemapped RMSE and
PSNR against the reference (and the centre reference under MSAA). Usage: visbuffer_table.py DIR"""
import csv
import json
import os
import sys


def passes(run):
    t = {x["pass"]: x["median_ms"] for x in run["timings"]}
    frame = t.pop("frame", float("nan"))
    top = sorted(t.items(), key=lambda kv: -kv[1])[:3]
    return frame, ", ".join(f"{k} {v:.2f}" for k, v in top), run["timings"][0]["device"]


def error(p, key):
    e = p.get(key, {}).get("tonemapped")
    return f"{e['rmse']:.2e} / {e['psnr']:.1f}" if e else "-"


def report(name, path):
    r = json.load(open(path))
    for p in r["pipelines"]:
        if p.get("status") != "ok":
            print(f"| {name} | {p['name']} | failed: {p.get('status')} | | | | |")
            continue
        frame, top, device = passes(p["run"])
        mem = p["run"]["memory"]["total_bytes"] / 1e6
        centre = next((k for k in p if "center" in k or "centre" in k), None)
        print(f"| {name} | {p['name']} | {frame:.2f} | {top} | {mem:.1f} | "
              f"{error(p, 'error_vs_reference')} | {error(p, centre) if centre else '-'} |")
    return device


def sweep(name, path):
    rows = list(csv.DictReader(open(path)))
    for row in rows:
        ms = {k: v for k, v in row.items() if k.endswith("_ms") and v}
        print(f"| {name} | {row.get('pipeline')} | {row.get('frame_ms', '?')} | "
              + ", ".join(f"{k} {v}" for k, v in sorted(ms.items())[:6])
              + f" | {row.get('memory_mb', row.get('memory_bytes', '?'))} | - | - |")


def main(root):
    print("| run | pipeline | frame ms | costliest passes (ms) | memory MB | vs reference (rmse / psnr, tonemapped) | vs centre reference |")
    print("|---|---|---|---|---|---|---|")
    device = "?"
    for name in sorted(os.listdir(root)):
        d = os.path.join(root, name)
        if os.path.isfile(os.path.join(d, "report.json")):
            device = report(name, os.path.join(d, "report.json"))
        elif os.path.isfile(os.path.join(d, "sweep.csv")):
            sweep(name, os.path.join(d, "sweep.csv"))
    print(f"\ndevice: {device}")


if __name__ == "__main__":
    main(sys.argv[1])
