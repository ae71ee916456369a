#!/usr/bin/python3
"""Where a render's time goes: the median of each Server-Timing phase for a
few sizes and sampling settings, against a running toond (start it with
--result-cache-mb 0; a different yaw per request keeps any cache out).

    bench/phase_times.py http://127.0.0.1:8080 [--model ID] [--repeats 8]

On a GPU the drawing passes report the device's time (dur) and the render
thread's recording time (printed as NAME_cpu)."""
import argparse
import http.client
import json
import statistics
import urllib.parse

POINTS = [(512, {}), (512, {"msaa": 1}), (512, {"msaa": 1, "supersample": 2}), (512, {"supersample": 2}),
          (512, {"msaa": 1, "supersample": 3}), (1024, {}), (2048, {})]


def phases(conn, body):
    conn.request("POST", "/render", json.dumps(body), {"Content-Type": "application/json"})
    res = conn.getresponse()
    res.read()
    if res.status != 200:
        raise SystemExit(f"/render answered {res.status}")
    out = {}
    for part in (res.getheader("Server-Timing") or "").split(","):
        name, *fields = part.strip().split(";")
        for field in fields:
            if field.startswith("dur="):
                out[name] = float(field[4:])
            elif field.startswith("cpu="):
                out[name + "_cpu"] = float(field[4:])
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--model", help="a stored model's id (default: the demo model)")
    parser.add_argument("--repeats", type=int, default=8)
    args = parser.parse_args()
    url = urllib.parse.urlparse(args.url)
    conn = http.client.HTTPConnection(url.hostname, url.port or 80)
    for size, extra in POINTS:
        body = dict(width=size, height=size, **extra)
        if args.model:
            body["model"] = args.model
        runs = []
        for i in range(args.repeats + 2):  # the first two warm up
            body["camera"] = {"yaw": 30 + i * 0.01}
            runs.append(phases(conn, body))
        runs = runs[2:]
        names = [k for k in runs[0] if k != "queue"]
        medians = " ".join(f"{k}={statistics.median(r.get(k, 0.0) for r in runs):.2f}" for k in names)
        print(f"{size}² {json.dumps(extra)}: {medians}")


if __name__ == "__main__":
    main()
