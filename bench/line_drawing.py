#!/usr/bin/python3
"""Vector line drawings (output svg) against the PNG lines layer of the same
request, per shared model and CGAL's fandisk: time, strokes and file size.

Against a running toond started with --result-cache-mb 0 --max-render-cost 0
(every request is drawn, none refused):

  for each model and view, the SVG and the PNG (output lines) of the same
  request, interleaved, REPEAT times each after one warm-up of each (the
  first SVG of a model works out its edges once; the first PNG uploads it
  to the GPU); prints the medians of the round trip and of the daemon's own
  time (Server-Timing total), their ratio SVG/PNG, the strokes (paths),
  the SVG's and the PNG's sizes, the candidate edges and triangle tests
  (X-Toond-Lines) and the predicted cost (X-Toond-Cost).

  --fit: also fits the line drawing's price weights (render/plan/render_cost.h:
  kLineTriangleSamples, kLineEdgeSamples) to the SVG's own time (Server-Timing
  `lines`), in the ms a Msample of llvmpipe's renders takes (--ms-per-msample,
  bench/render_cost.py fits it), and prints the prediction's error.

    bench/line_drawing.py http://127.0.0.1:8080 [--shared ../shared/models] [--repeat 7] [--size 512] [--fit]
"""
import argparse
import json
import os
import statistics
import sys

from daemon_client import Client, timing

HERE = os.path.dirname(os.path.abspath(__file__))
VIEWS = [{"yaw": 30, "pitch": 15}, {"yaw": -120, "pitch": 30}]


def rendered(client, params):
    """(seconds, headers, body) of a render that must succeed."""
    status, seconds, headers, body = client.render(params)
    if status != 200:
        raise SystemExit(f"render {json.dumps(params)} answered {status}: {body[:300]!r}")
    return seconds, headers, body


def header_fields(headers, name):
    fields = {}
    for field in headers.get(name, "").split(";"):
        key, _, value = field.strip().partition("=")
        if value:
            fields[key] = float(value)
    return fields


def bundles(shared):
    out = {}
    if shared and os.path.isdir(shared):
        for name in sorted(os.listdir(shared)):
            path = os.path.join(shared, name)
            if not os.path.isdir(path) or name == "edge-cases":
                continue
            files = []
            for root, _, names in os.walk(path):
                for f in names:
                    if os.path.splitext(f)[1].lower() in (".obj", ".mtl", ".png", ".jpg"):
                        full = os.path.join(root, f)
                        with open(full, "rb") as fh:
                            files.append((os.path.relpath(full, path), fh.read()))
            out[name] = files
    with open(os.path.join(HERE, "..", "tests", "exported", "cgal", "fandisk.off"), "rb") as fh:
        out["fandisk (CGAL)"] = [("fandisk.off", fh.read())]
    return out


def measure(client, model, view, size, repeat):
    """Interleaved SVG and PNG of one request: medians and the last answers."""
    base = {"model": model, "camera": view, "width": size, "height": size}
    svg_req, png_req = dict(base, output="svg"), dict(base, output="lines")
    rendered(client, svg_req)  # warm-up: the model's edges, its GPU copy
    rendered(client, png_req)
    rows = {"svg": [], "png": []}
    for _ in range(repeat):
        for kind, req in (("svg", svg_req), ("png", png_req)):
            wall, headers, body = rendered(client, req)
            rows[kind].append((wall * 1000, timing(headers, "total"), timing(headers, "lines"), headers, body))
    return rows


def median(rows, index):
    return statistics.median(r[index] for r in rows)


def report(name, view, rows):
    svg, png = rows["svg"], rows["png"]
    headers, body = svg[-1][3], svg[-1][4]
    lines = header_fields(headers, "X-Toond-Lines")
    cost = header_fields(headers, "X-Toond-Cost")
    png_size = len(png[-1][4])
    ratio_wall = median(svg, 0) / median(png, 0)
    ratio_server = median(svg, 1) / median(png, 1)
    print(f"{name:22s} yaw {view['yaw']:5d}: svg {median(svg, 0):7.1f} ms ({median(svg, 1):7.1f} on the daemon), "
          f"png {median(png, 0):7.1f} ms ({median(png, 1):7.1f}); ratio {ratio_wall:4.2f} ({ratio_server:4.2f}); "
          f"{int(lines.get('paths', 0)):5d} paths, svg {len(body) / 1024:7.1f} KiB, png {png_size / 1024:6.1f} KiB; "
          f"{int(lines.get('candidates', 0))} edges, {int(lines.get('occluder_tests', 0))} tests; "
          f"price {cost.get('cost', 0):.2f} Msamples")
    sys.stdout.flush()
    return {"lines_ms": median(svg, 2), "cost": cost, "ratio": ratio_wall}


def fit(samples, ms_per_msample):
    # Least squares through the origin: lines_ms / ms_per_msample * 1e6 = a·triangles + b·edges.
    sxx = syy = sxy = sx = sy = 0.0
    for s in samples:
        x, y, t = s["cost"].get("line_triangles", 0), s["cost"].get("line_edges", 0), s["lines_ms"]
        target = t / ms_per_msample * 1e6
        sxx += x * x
        syy += y * y
        sxy += x * y
        sx += x * target
        sy += y * target
    det = sxx * syy - sxy * sxy
    a = (sx * syy - sy * sxy) / det
    b = (sy * sxx - sx * sxy) / det
    print(f"fitted: {a:.1f} samples a triangle, {b:.1f} an edge (at {ms_per_msample} ms a Msample)")
    for s in samples:
        predicted = (a * s["cost"].get("line_triangles", 0) + b * s["cost"].get("line_edges", 0)) / 1e6 * ms_per_msample
        print(f"  measured {s['lines_ms']:7.1f} ms, fitted {predicted:7.1f} ms, daemon's price "
              f"{s['cost'].get('cost', 0) * ms_per_msample:7.1f} ms")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("url")
    parser.add_argument("--shared", default=os.path.join(HERE, "..", "..", "shared", "models"))
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--only", default="", help="comma-separated model names")
    parser.add_argument("--fit", action="store_true")
    parser.add_argument("--ms-per-msample", type=float, default=1.4)
    args = parser.parse_args()
    client = Client(args.url, timeout=300)
    samples, ratios = [], []
    for name, files in bundles(args.shared).items():
        if args.only and name not in args.only.split(","):
            continue
        model = client.upload(files)
        print(f"{name}: {model['triangles']} triangles")
        for view in VIEWS:
            s = report(name, view, measure(client, model["id"], view, args.size, args.repeat))
            samples.append(s)
            ratios.append(s["ratio"])
    print(f"SVG/PNG round-trip ratio over {len(ratios)} views: median {statistics.median(ratios):.2f}, "
          f"max {max(ratios):.2f}, over 2: {sum(r > 2 for r in ratios)}")
    if args.fit:
        fit(samples, args.ms_per_msample)


if __name__ == "__main__":
    main()
