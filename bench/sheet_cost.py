#!/usr/bin/python3
"""What a sprite sheet costs against the same frames asked for one by one.

Against a running toond (start it with --result-cache-mb 0, so every
request renders): each round posts one sheet of FRAMES frames, then the
FRAMES single renders of the same views under the same framing, over one
kept-alive connection, and reports the medians and their ratio.

    bench/sheet_cost.py http://127.0.0.1:8080 [--frames 8] [--size 256] [--rounds 15] [--model ID]
                        [--sheet '{"pixel_art": {"scale": 4}}']

--sheet adds fields to the sheet block (pixel_art, animate, ...); the
single renders stay the plain full-size ones, the yardstick for every
kind of sheet.
"""
import argparse
import http.client
import json
import statistics
import time
import urllib.parse


def post(conn, path, body):
    started = time.perf_counter()
    conn.request("POST", path, body=json.dumps(body), headers={"Content-Type": "application/json"})
    res = conn.getresponse()
    data = res.read()
    elapsed = time.perf_counter() - started
    if res.status != 200:
        raise SystemExit(f"{path} answered {res.status}: {data[:300]!r}")
    return elapsed, data


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--model", help="a stored model's id (default: the demo model)")
    parser.add_argument("--sheet", default="{}", help="JSON object of more sheet fields, e.g. {\"animate\": true}")
    args = parser.parse_args()

    url = urllib.parse.urlparse(args.url)
    conn = http.client.HTTPConnection(url.hostname, url.port or 80)
    base = {"width": args.size, "height": args.size}
    if args.model:
        base["model"] = args.model
    sheet = dict(base, sheet=dict(json.loads(args.sheet), frames=args.frames))
    _, atlas_bytes = post(conn, "/render?atlas=json", sheet)
    atlas = json.loads(atlas_bytes)
    singles = [
        dict(base, camera={"yaw": f["yaw"], "pitch": f["pitch"], "distance": atlas["meta"]["camera"]["distance"]})
        for f in atlas["frames"].values()
    ]

    post(conn, "/render", sheet)  # warm: programs built, model on the GPU
    sheet_s, singles_s = [], []
    for _ in range(args.rounds):
        sheet_s.append(post(conn, "/render", sheet)[0])
        singles_s.append(sum(post(conn, "/render", p)[0] for p in singles))
    sheet_ms = statistics.median(sheet_s) * 1e3
    singles_ms = statistics.median(singles_s) * 1e3
    print(json.dumps({
        "frames": args.frames,
        "size": args.size,
        "sheet": json.loads(args.sheet),
        "rounds": args.rounds,
        "sheet_ms": round(sheet_ms, 2),
        "singles_ms": round(singles_ms, 2),
        "ratio": round(sheet_ms / singles_ms, 3),
    }))


if __name__ == "__main__":
    main()
