#!/usr/bin/env python3
"""Tables and the memory-against-time plot of shadow_bench.sh (docs/shadows.md).

Usage: shadow_table.py OUT N...   (OUT holds s{N}_tiled/ and s{N}_volumes/ compare runs)
Prints one markdown table per N: per pipeline the frame and shadow-pass medians, the shadow
memory, the error against both references; writes OUT/shadow_memory_time.svg.
"""
import json
import os
import sys


def timing(run, name):
    for t in run["timings"]:
        if t["pass"] == name:
            return t["median_ms"]
    return None


def counter(run, name):
    c = run.get("counters", {})
    return c.get(name) if isinstance(c, dict) else None


def rows(out, n):
    for lighting in ("tiled", "off", "volumes"):
        path = os.path.join(out, f"s{n}_{lighting}", "report.json")
        if not os.path.exists(path):
            continue
        r = json.load(open(path))
        for p in r["pipelines"]:
            if p.get("status") != "ok":
                continue
            if lighting == "volumes" and p["name"] != "deferred":
                continue
            name = p["name"] + {"volumes": " (volumes)", "off": " (maps every frame)"}.get(lighting, "")
            run = p["run"]
            shadow_ms = timing(run, "shadow_maps")
            yield r, {
                "name": name,
                "frame": timing(run, "frame"),
                "shadow_ms": shadow_ms,
                "bytes": counter(run, "shadow_map_bytes") or 0,
                "renders": counter(run, "shadow_map_renders_per_frame"),
                "once_ms": counter(run, "shadow_maps_render_ms"),
                "rays": p["error_vs_reference"]["hdr"]["rmse"],
                "maps": p.get("error_vs_shadow_map_reference", {}).get("hdr", {}).get("rmse"),
            }


def fmt(v, f="{:.3g}"):
    return "-" if v is None else f.format(v)


def table(out, n):
    points = []
    header = None
    for r, row in rows(out, n):
        if header is None:
            s = r["shadows"]
            ref = r["reference"]["run"]
            smr = r["shadow_map_reference"]
            header = (f"### {s['shadowed_lights']} shadowed lights of {len(r.get('lights', [])) or '?'}"
                      f" ({s['faces']} faces, edges {s['face_edge_texels']}, atlas "
                      f"{s['atlas']['bytes'] / 2**20:.1f} MiB), {r['device']['name']}\n\n"
                      f"reference (rays) frame {fmt(timing(ref, 'frame'))} ms; shadow-map reference "
                      f"{fmt(timing(smr['run'], 'frame')) if smr.get('rendered') else '-'} ms, "
                      f"rmse vs rays {fmt(smr.get('error_vs_reference', {}).get('hdr', {}).get('rmse'))}\n\n"
                      "| pipeline | frame ms | shadow_maps pass ms | cached maps, one render ms | map renders/frame |"
                      " shadow memory MiB | rmse vs rays | rmse vs maps |\n|---|---|---|---|---|---|---|---|")
            print(header)
        print(f"| {row['name']} | {fmt(row['frame'])} | {fmt(row['shadow_ms'])} | {fmt(row['once_ms'])} | {fmt(row['renders'])} |"
              f" {row['bytes'] / 2**20:.2f} | {fmt(row['rays'])} | {fmt(row['maps'])} |")
        points.append((row["name"], n, row["bytes"] / 2**20, row["frame"]))
    print()
    return points


def plot(points, path):
    """Shadow memory (x, log) against frame time (y, log), one marker per (pipeline, N)."""
    import math
    pts = [p for p in points if p[2] > 0 and p[3]]
    if not pts:
        return
    w, h, m = 640, 400, 60
    xs = [math.log10(p[2]) for p in pts]
    ys = [math.log10(p[3]) for p in pts]
    x0, x1 = min(xs) - 0.2, max(xs) + 0.2
    y0, y1 = min(ys) - 0.2, max(ys) + 0.2
    sx = lambda v: m + (v - x0) / (x1 - x0) * (w - 2 * m)
    sy = lambda v: h - m - (v - y0) / (y1 - y0) * (h - 2 * m)
    colours = {"forwardplus": "#1f77b4", "deferred": "#2ca02c", "deferred (volumes)": "#d62728",
               "visbuffer": "#9467bd", "multipass_forward": "#ff7f0e"}
    colours.update({k + " (maps every frame)": v for k, v in list(colours.items())})
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">',
           f'<text x="{w/2}" y="{h-15}" text-anchor="middle">shadow-map memory, MiB (log)</text>',
           f'<text x="15" y="{h/2}" transform="rotate(-90 15 {h/2})" text-anchor="middle">frame, median ms (log)</text>',
           f'<rect x="{m}" y="{m}" width="{w-2*m}" height="{h-2*m}" fill="none" stroke="#999"/>']
    for name, n, mb, ms in pts:
        x, y = sx(math.log10(mb)), sy(math.log10(ms))
        c = colours.get(name, "#333")
        svg.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4" fill="{c}"><title>{name}, {n} shadowed: '
                   f'{mb:.2f} MiB, {ms:.2f} ms</title></circle>')
        svg.append(f'<text x="{x+6:.1f}" y="{y-4:.1f}" fill="{c}">{name} {n}</text>')
    svg.append("</svg>")
    open(path, "w").write("\n".join(svg) + "\n")
    print(f"plot: {path}")


def main():
    out, counts = sys.argv[1], sys.argv[2:]
    points = []
    for n in counts:
        points += table(out, n)
    plot(points, os.path.join(out, "shadow_memory_time.svg"))


if __name__ == "__main__":
    main()
