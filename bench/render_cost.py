#!/usr/bin/python3
"""How well a render's predicted cost (X-Toond-Cost) tells its time, and how
other clients fare while a costly model renders.

Against a running toond started with --max-render-cost 0 --result-cache-mb 0
--render-timeout 30
(so nothing is refused and every request renders):

  prediction: uploads the shared models and costly constructs (stacked,
  nearly coincident and crossing triangles at several sizes), renders each
  at a few sizes and MSAA settings, and fits render-thread milliseconds
  (Server-Timing `total` less `png`) to the predicted Msamples through the
  origin. Prints each render, the fitted ms per Msample and the error of
  the prediction (median and worst |predicted/measured - 1|, and how many
  renders are off by more than 2x).

  crease pass (--crease-pass): the crease pass's own time, each frame with
  it less the same frame with creases never (medians of 5 interleaved
  pairs), on the windmill, the Kenney dog and 3,375 separate cubes at
  several sizes, MSAA settings and line widths, against the price's
  difference; fits the pass's three weights (samples an edge, a line's
  sample, a pixel of the one-sample coverage passes) and prints the error
  of the daemon's weights and of the fitted ones.

  contention (--contention): one client renders the issue's constructs at
  512² (fresh bytes every time) while another renders the demo model at 128²
  over and over; prints the small renders' p50/p99/max and each costly
  render's outcome and time. With --edges the costly renders are the
  shared windmill's default request at 2048² instead (hard-edged: its crease
  lines are drawn along its crease edges).

    bench/render_cost.py http://127.0.0.1:8080 [--shared ../shared/models] [--crease-pass | --contention SECONDS [--edges]]
"""
import argparse
import json
import math
import os
import random
import statistics
import sys
import threading
import time

from daemon_client import Client, timing


def vertex(x, y, z):
    return f"v {x:.17g} {y:.17g} {z:.17g}\n"


def nearly_coincident(n, salt=0.0):
    return "".join(vertex(-1, -1, 1e-6 * i + salt) + vertex(1, -1, 1e-6 * i) + vertex(-1, 1, 1e-6 * i) +
                   "f -3 -2 -1\n" for i in range(n))


def stacked(n):
    out = []
    for i in range(n):
        z, t = i / n, 0.01 * i
        c, s = math.cos(t), math.sin(t)
        corner = lambda x, y: vertex(x * c - y * s, x * s + y * c, z)
        out.append(corner(-1.5, -1.5) + corner(3, -1.5) + corner(-1.5, 3) + "f -3 -2 -1\n")
    return "".join(out)


def slivers(n):
    out = []
    for i in range(n):
        d = 2.0 * i / n - 1.0
        out.append(vertex(-1 + d, -1 - d, 0) + vertex(1 + d, 1 - d, 0) + vertex(1 + d + 1e-4, 1 - d, 0) +
                   "f -3 -2 -1\n")
    return "".join(out)


def cube_field(k):
    """k³ cubes apart, a normal per face: a hard-edged model of 12k³ crease edges."""
    faces = ((0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6))
    out = []
    for i in range(k ** 3):
        x, y, z = i % k, i // k % k, i // (k * k)
        out.extend(vertex(x + 0.75 * (c & 1), y + 0.75 * (c >> 1 & 1), z + 0.75 * (c >> 2 & 1)) for c in range(8))
        out.extend("f " + " ".join(str(8 * i + 1 + c) for c in f) + "\n" for f in faces)
    return "".join(out)


def cost_fields(headers):
    fields = {}
    for field in headers.get("X-Toond-Cost", "").split(";"):
        key, _, value = field.strip().partition("=")
        if key:
            fields[key] = float(value)
    return fields


TERMS = ("samples", "triangles", "tiles", "framebuffer", "frames", "edge_texels", "crease_edges")
# render/plan/render_cost.h: kTriangleSamples, kTileSamples, kFramebufferSamples, kFrameSamples, kEdgeTexelSamples,
# kCreaseEdgeSamples.
DAEMON_WEIGHTS = (1, 40, 320, 1, 1.3e6, 4.5, 275)


def solve(matrix, vector):
    """Gaussian elimination with partial pivoting (one row per term)."""
    n = len(vector)
    m = [row[:] + [v] for row, v in zip(matrix, vector)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(m[r][col]))
        m[col], m[pivot] = m[pivot], m[col]
        for r in range(n):
            if r != col and m[col][col]:
                f = m[r][col] / m[col][col]
                m[r] = [a - f * b for a, b in zip(m[r], m[col])]
    return [m[i][n] / m[i][i] if m[i][i] else 0.0 for i in range(n)]


def fit_weights(rows):
    """ms per unit of each term, minimising the squared relative error."""
    a = [[sum(r[i] * r[j] / ms ** 2 for r, ms in rows) for j in range(len(TERMS))] for i in range(len(TERMS))]
    b = [sum(r[i] * ms / ms ** 2 for r, ms in rows) for i in range(len(TERMS))]
    return solve(a, b)


def report(rows, predict, title):
    errors = [predict(r) / ms - 1 for r, ms in rows]
    absolute = sorted(abs(e) for e in errors)
    print(f"{title}: |predicted/measured - 1| median {statistics.median(absolute):.2f}, "
          f"p90 {absolute[int(0.9 * (len(absolute) - 1))]:.2f}, worst {absolute[-1]:.2f}; "
          f"off by more than 2x: {sum(1 for e in errors if e > 1 or e < -0.5)} of {len(errors)}")


def shared_bundles(folder):
    bundles = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.isdir(path) or name == "edge-cases":
            continue
        files = []
        for root, _, names in os.walk(path):
            for f in names:
                if os.path.splitext(f)[1].lower() in (".obj", ".mtl", ".png", ".jpg"):
                    full = os.path.join(root, f)
                    with open(full, "rb") as fh:
                        files.append((os.path.relpath(full, path), fh.read()))
        bundles[name] = files
    return bundles


def prediction(url, shared):
    client = Client(url)
    models = {name: client.upload(files)["id"] for name, files in shared_bundles(shared).items()}
    for n in (500, 2000):
        models[f"nearly_coincident_{n}"] = client.upload([("m.obj", nearly_coincident(n))])["id"]
    for n in (200, 800):
        models[f"stacked_{n}"] = client.upload([("m.obj", stacked(n))])["id"]
    for n in (20000, 80000):
        models[f"slivers_{n}"] = client.upload([("m.obj", slivers(n))])["id"]
    for k in (8, 15):
        models[f"cube_field_{k}"] = client.upload([("m.obj", cube_field(k))])["id"]
    client.render({"width": 64, "height": 64})  # programs built
    requests = []
    for name, model in models.items():
        for size, msaa in ((256, 1), (512, 4), (1024, 4)):
            requests.append((name, {"model": model, "width": size, "height": size, "msaa": msaa}))
    # The screen-space edge pass, whose cost grows with the line's width
    # (silhouettes and creases, the edges method), and crease lines along
    # the crease edges beside the hull (the windmill is hard-edged), at two
    # widths and up to 2048².
    for name in ("stanford-bunny", "windmill"):
        for size, msaa in ((512, 4), (2048, 1)):
            for width in (2, 8):
                outline = {"width": width, "method": "edges" if name == "stanford-bunny" else "hull"}
                requests.append((f"{name} edges w{width}", {"model": models[name], "width": size, "height": size,
                                                            "msaa": msaa, "outline": outline}))
    rows = []
    for name, params in requests:
        size, msaa = params["width"], params["msaa"]
        client.render(params)  # model on the GPU
        runs = []
        fields = {}
        for _ in range(3):
            status, _, headers, body = client.render(params)
            if status != 200:
                # A render stopped at its deadline is left out: its time is the deadline's.
                print(f"{name} {size}² msaa {msaa}: {status} {body[:200]!r}")
                runs = []
                break
            runs.append(timing(headers, "total") - (timing(headers, "png") or 0))
            fields = cost_fields(headers)
        if runs:
            rows.append((name, size, msaa, fields, statistics.median(runs)))
    data = [([f.get(t, 0.0) for t in TERMS], ms) for *_, f, ms in rows]
    # The daemon's figure, scaled by its best single factor (ms per Msample).
    slope = sum(f["cost"] * ms / ms ** 2 for *_, f, ms in rows) / sum(f["cost"] ** 2 / ms ** 2 for *_, f, ms in rows)
    weights = fit_weights(data)
    print(f"{'model':28} {'size':>5} {'msaa':>4} {'Msamples':>10} {'ms':>9} {'predicted ms':>12} {'ratio':>6}")
    for name, size, msaa, f, ms in rows:
        guess = slope * f["cost"]
        print(f"{name:28} {size:5} {msaa:4} {f['cost']:10.1f} {ms:9.1f} {guess:12.1f} {guess / ms:6.2f}")
    print(f"\n{len(rows)} renders; the daemon's figure at {slope:.4f} ms per Msample ({1000 / slope:.0f} Msamples/s)")
    report(data, lambda r: slope * sum(r[i] * w for i, w in enumerate(DAEMON_WEIGHTS)) / 1e6, "daemon's weights")
    report(data, lambda r: sum(x * w for x, w in zip(r, weights)), "weights fitted here")
    print("fitted weights, in surface samples: " +
          ", ".join(f"{t} {w / weights[0]:.4g}" for t, w in zip(TERMS, weights)) +
          f" (a surface sample {weights[0] * 1e6:.3f} ms per million)")

# render/plan/render_cost.h: kCreaseEdgeSamples, a line's sample (counted as a surface's), 2 × kLineCoveragePassSamples.
DAEMON_CREASE_WEIGHTS = (275, 1, 3.2)


def crease_pass_rows(url, shared):
    """(edges, line samples, coverage-pass pixels, ms) of the crease pass, one row a setting."""
    client = Client(url)
    bundles = shared_bundles(shared)
    models = {name: client.upload(bundles[name])["id"] for name in ("windmill", "kenney-cube-pet-dog")}
    models["cube_field_15"] = client.upload([("m.obj", cube_field(15))])["id"]
    rows = []
    for name, model in models.items():
        for size, msaa in ((256, 1), (512, 4), (1024, 1), (1024, 4), (2048, 1)):
            for width in (2, 8):
                times = {"auto": [], "never": []}
                fields = {}
                for repeat in range(6):  # the first pair puts the model on the GPU
                    for creases in ("auto", "never"):
                        status, _, headers, body = client.render({
                            "model": model, "width": size, "height": size, "msaa": msaa,
                            "outline": {"width": width, "creases": creases}})
                        if status != 200:
                            raise SystemExit(f"{name} {size}² msaa {msaa}: {status} {body[:200]!r}")
                        fields[creases] = cost_fields(headers)
                        if repeat:
                            times[creases].append(timing(headers, "total") - (timing(headers, "png") or 0))
                ms = statistics.median(times["auto"]) - statistics.median(times["never"])
                with_lines, without = fields["auto"], fields["never"]
                # The lines' samples as the daemon counts them, before its share.
                line_samples = (with_lines["samples"] - without["samples"]) / DAEMON_CREASE_WEIGHTS[1]
                passes = 2 * size * size if msaa == 1 else 0
                rows.append((with_lines.get("crease_edges", 0.0), line_samples, passes, ms))
                print(f"{name:20} {size:5}² msaa {msaa} width {width}: crease pass {ms:6.1f} ms, "
                      f"{with_lines.get('crease_edges', 0):.0f} edges, {line_samples / 1e6:.2f} M line samples", flush=True)
    return rows


def crease_pass(url, shared):
    rows = crease_pass_rows(url, shared)
    slope = 1.15e-6  # ms per sample: the whole price's fit (docs/performance.md)

    def errors(weights):
        return sorted(abs(sum(w * x for w, x in zip(weights, r[:3])) / r[3] - 1) for r in rows if r[3] > 0)

    # Least squares on the relative error, three terms.
    a = [[sum(r[i] * r[j] / r[3] ** 2 for r in rows if r[3] > 0) for j in range(3)] for i in range(3)]
    b = [sum(r[i] / r[3] for r in rows if r[3] > 0) for i in range(3)]
    fitted = solve(a, b)
    for title, weights in (("daemon's weights", [w * slope for w in DAEMON_CREASE_WEIGHTS]), ("fitted", fitted)):
        e = errors(weights)
        print(f"{title}: |predicted/measured - 1| median {statistics.median(e):.2f}, "
              f"p90 {e[int(0.9 * (len(e) - 1))]:.2f}, worst {e[-1]:.2f}")
    print(f"fitted at {slope * 1e6:.2f} ms per Msample: {fitted[0] / slope:.0f} samples an edge, "
          f"{fitted[1] / slope:.2f} a line sample, {fitted[2] / slope / 2:.2f} a pixel of each coverage pass")


def contention(url, seconds, shared, edges):
    setup = Client(url)
    setup.render({"width": 128, "height": 128})
    windmill = setup.upload(shared_bundles(shared)["windmill"])["id"] if edges else None
    stop = time.monotonic() + seconds
    heavy_results = []

    def heavy():
        client = Client(url)
        kinds = [("nearly_coincident", lambda salt: nearly_coincident(60000, salt)),
                 ("stacked", lambda salt: stacked(20000) + f"# {salt}\n"),
                 ("slivers", lambda salt: slivers(200000) + f"# {salt}\n")]
        i = 0
        while time.monotonic() < stop:
            if windmill:
                status, elapsed, _, body = client.render({"model": windmill, "width": 2048, "height": 2048,
                                                          "camera": {"yaw": i}})
                code = json.loads(body)["error"]["code"] if status != 200 else "image"
                heavy_results.append(("windmill 2048²", 0.0, status, code, elapsed))
                i += 1
                continue
            name, make = kinds[i % len(kinds)]
            salt = random.random() * 1e-9
            started = time.perf_counter()
            model = client.upload([("m.obj", make(salt))])["id"]
            upload_s = time.perf_counter() - started
            status, elapsed, _, body = client.render({"model": model, "width": 512, "height": 512})
            code = json.loads(body)["error"]["code"] if status != 200 else "image"
            heavy_results.append((name, upload_s, status, code, elapsed))
            i += 1

    thread = threading.Thread(target=heavy)
    thread.start()
    time.sleep(0.5)
    light = Client(url)
    latencies = []
    while time.monotonic() < stop or thread.is_alive():
        status, elapsed, _, body = light.render({"width": 128, "height": 128, "camera": {"yaw": random.random() * 360}})
        if status != 200:
            print(f"small render answered {status}: {body[:200]!r}")
        latencies.append(elapsed)
    thread.join()
    latencies.sort()
    p = lambda q: latencies[min(len(latencies) - 1, int(q * len(latencies)))]
    print(f"small 128² demo renders while costly ones ran: {len(latencies)}, p50 {p(0.5) * 1000:.0f} ms, "
          f"p99 {p(0.99) * 1000:.0f} ms, max {latencies[-1] * 1000:.0f} ms")
    for name, upload_s, status, code, elapsed in heavy_results:
        print(f"  costly {name:18} upload {upload_s:5.2f} s, render answered {status} {code:15} in {elapsed:5.2f} s")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--shared", default=os.path.join(os.path.dirname(__file__), "..", "..", "shared", "models"))
    parser.add_argument("--contention", type=float, help="seconds of the contention run (instead of the fit)")
    parser.add_argument("--edges", action="store_true", help="contention beside the windmill at 2048² instead")
    parser.add_argument("--crease-pass", action="store_true", help="fit the crease pass's weights to its own time")
    args = parser.parse_args()
    if args.crease_pass:
        crease_pass(args.url, args.shared)
    elif args.contention:
        contention(args.url, args.contention, args.shared, args.edges)
    else:
        prediction(args.url, args.shared)


if __name__ == "__main__":
    sys.exit(main())
