#!/usr/bin/env python3
"""Paired, interleaved timing of triptych builds (or of one build under environment settings).

The figure of issue 43 item 5 (docs/efficiency.md, "The material floor on lavapipe"):
Forward+'s forward_opaque and frame at 0 and 256 lights, courtyard 1280x720. Each round runs
every variant once, in an order rotated per round; the ratios to the first variant are taken
within a round (the load of a shared machine moves between rounds) and their median printed,
beside each variant's medians and its process CPU seconds (user + sys: less disturbed by other
work than wall time, but it includes start-up and pipeline creation).

  tests/bench/material_floor.py --rounds 5 --lights 0 before=/tmp/triptych.main after=build/triptych
  tests/bench/material_floor.py --lights 256 a=build/triptych b=build/triptych:VAR=1,OTHER=2
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile


def parse_variant(text):
    label, sep, rest = text.partition("=")
    if not sep or not rest:
        sys.exit(f"material_floor.py: variant '{text}' is not LABEL=BINARY[:ENV=VALUE,...]")
    binary, _, envs = rest.partition(":")
    env = dict(e.split("=", 1) for e in envs.split(",") if e)
    return label, binary, env


def run_once(binary, env, args, out):
    cmd = [binary, "render", args.scene, "--pipeline", args.pipeline, "--res", args.res,
           "--lights", str(args.lights), "--seed", str(args.seed), "--frames", str(args.frames),
           "--warmup", "1", "--calibration", "none", "--msaa", str(args.msaa), "--out", out]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, env={**os.environ, **env}, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "render.json")) as f:
        timings = {t["pass"]: t["median_ms"] for t in json.load(f)["run"]["timings"]}
    return timings[args.pass_name], timings["frame"], cpu


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("variants", nargs="+", help="LABEL=BINARY[:ENV=VALUE,...]; the first is the base")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--lights", type=int, default=0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--frames", type=int, default=5)
    p.add_argument("--res", default="1280x720")
    p.add_argument("--msaa", type=int, default=1)
    p.add_argument("--scene", default="builtin:courtyard")
    p.add_argument("--pipeline", default="forwardplus")
    p.add_argument("--pass", dest="pass_name", default="forward_opaque")
    args = p.parse_args()
    variants = [parse_variant(v) for v in args.variants]
    results = {label: [] for label, _, _ in variants}
    work = tempfile.mkdtemp(prefix="material_floor_")
    for r in range(args.rounds):
        k = r % len(variants)
        for label, binary, env in variants[k:] + variants[:k]:
            results[label].append(run_once(binary, env, args, os.path.join(work, label)))
        print(f"round {r + 1}: " + "  ".join(
            f"{label} {results[label][-1][0]:.0f}/{results[label][-1][1]:.0f} ms" for label, _, _ in variants),
            flush=True)
    base = variants[0][0]
    print(f"{args.pipeline} {args.scene} {args.res}, {args.lights} lights, {args.rounds} rounds of "
          f"{args.frames} frames; {args.pass_name} and frame: median ms; ratio: median over the rounds "
          f"of the variant's / {base}'s in the same round")
    for label, _, _ in variants:
        rows, ref = results[label], results[base]
        med = lambda i: statistics.median(x[i] for x in rows)
        ratio = lambda i: statistics.median(a[i] / b[i] for a, b in zip(rows, ref))
        print(f"{label:12s} {args.pass_name} {med(0):8.1f} (min {min(x[0] for x in rows):7.1f})  "
              f"frame {med(1):8.1f} (min {min(x[1] for x in rows):7.1f})  cpu {med(2):6.2f} s  "
              f"ratio {args.pass_name} {ratio(0):.3f} frame {ratio(1):.3f} cpu {ratio(2):.3f}")


if __name__ == "__main__":
    main()
