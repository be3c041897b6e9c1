#!/usr/bin/env python3
"""The table of tests/bench/shadow_raster.sh: per pipeline and --shadow-raster, the frame's median
GPU time (ms), the shadow work's (the sum of the shadow passes: the faces' cull, and the hardware's
shadow_maps or the compute rasterizer's clear, raster, big and copy), each of those passes, and the
rasterizer's counters, from each run's render.json."""
import sys

from cull_table import table  # the same rows: frame, passes, counters

PASSES = ["shadow_cull", "shadow_raster_clear", "shadow_raster", "shadow_raster_big", "shadow_maps"]
COUNTERS = ["shadow_triangles_submitted", "shadow_raster_triangles", "shadow_raster_triangles_listed",
            "shadow_raster_triangles_overflow", "shadow_raster_list_capacity",
            "shadow_raster_depth_atomics"]


def main(out):
    print(table(out, PASSES, COUNTERS, lambda k: k.replace("shadow_", "").replace("triangles", "tri"),
                total="shadows"))


if __name__ == "__main__":
    main(sys.argv[1])
