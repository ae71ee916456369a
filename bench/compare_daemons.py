#!/usr/bin/python3
"""Two running toond builds side by side: the same requests go to each in
turn (the order swapped every round, so neither always runs on a warmer
box), and the medians of the Server-Timing phases and of the answer's size
are printed per daemon. For a change's before and after on a noisy machine,
where only a same-minute ratio means anything.

Start both with --result-cache-mb 0 (each request has its own yaw anyway):

    old/build/server/app/toond --listen 127.0.0.1:8931 --data-dir /tmp/a --result-cache-mb 0 &
    build/server/app/toond     --listen 127.0.0.1:8932 --data-dir /tmp/b --result-cache-mb 0 &
    bench/compare_daemons.py http://127.0.0.1:8931 http://127.0.0.1:8932 \\
        --models ../shared/models --folders stanford-bunny spot --sizes 512 1024 --rounds 30

Each model is rendered with the default request at every size, and at the
first size also as its geometry floor (flat white, every effect and line
off)."""
import argparse
import http.client
import json
import os
import statistics
import urllib.parse
import uuid

FLOOR = {"shading": {"mode": "flat", "base": "white"}, "outline": {"enabled": False},
         "contour": {"enabled": False}, "specular": {"enabled": False}, "rim": {"enabled": False},
         "shadows": {"enabled": False}}
PHASES = ("png", "total")  # more with --phases


def connect(url):
    parts = urllib.parse.urlsplit(url)
    return http.client.HTTPConnection(parts.hostname, parts.port or 80, timeout=300)


def upload(url, folder):
    boundary = uuid.uuid4().hex
    body = b""
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as f:
            data = f.read()
        body += (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
                 "Content-Type: application/octet-stream\r\n\r\n").encode() + data + b"\r\n"
    body += f"--{boundary}--\r\n".encode()
    conn = connect(url)
    conn.request("POST", "/models", body, {"Content-Type": f"multipart/form-data; boundary={boundary}"})
    answer = conn.getresponse()
    reply = answer.read()
    if answer.status not in (200, 201):
        raise SystemExit(f"{url}: upload of {folder} answered {answer.status}: {reply[:200]!r}")
    return json.loads(reply)["id"]


def render(conn, body):
    conn.request("POST", "/render", json.dumps(body), {"Content-Type": "application/json"})
    answer = conn.getresponse()
    data = answer.read()
    if answer.status != 200:
        raise SystemExit(f"render answered {answer.status}: {data[:200]!r}")
    timing = {"bytes": len(data)}
    for part in (answer.getheader("Server-Timing") or "").split(","):
        name, *fields = part.strip().split(";")
        for field in fields:
            if field.startswith("dur="):
                timing[name] = float(field[4:])
    return timing


def alternate(conns, bodies, rounds, phases):
    """Medians per daemon of `rounds` renders each, the two taking turns;
    two warm-up rounds are left out."""
    results = [[] for _ in conns]
    for i in range(rounds + 2):
        order = (0, 1) if i % 2 == 0 else (1, 0)
        for k in order:
            timing = render(conns[k], dict(bodies[k], camera={"yaw": 30 + i * 1e-3}))
            if i >= 2:
                results[k].append(timing)
    return [{key: statistics.median(t.get(key, 0.0) for t in runs) for key in phases + ("bytes",)}
            for runs in results]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("urls", nargs=2)
    parser.add_argument("--models", default="../shared/models")
    parser.add_argument("--folders", nargs="+", default=["stanford-bunny", "spot"])
    parser.add_argument("--sizes", nargs="+", type=int, default=[512, 1024])
    parser.add_argument("--rounds", type=int, default=30)
    parser.add_argument("--phases", nargs="+", default=list(PHASES),
                        help="Server-Timing phases to print (main, hull, readback, png, total, ...)")
    args = parser.parse_args()
    phases = tuple(args.phases)
    conns = [connect(url) for url in args.urls]
    for folder in args.folders:
        ids = [upload(url, os.path.join(args.models, folder)) for url in args.urls]
        for size in args.sizes:
            requests = [("default", {})] + ([("floor", FLOOR)] if size == args.sizes[0] else [])
            for name, extra in requests:
                bodies = [dict(model=model, width=size, height=size, **extra) for model in ids]
                # Each daemon has its own model id; the rest of the request is the same.
                medians = alternate(conns, bodies, args.rounds, phases)
                line = f"{folder:16s} {size:5d} {name:8s}"
                for url, m in zip(args.urls, medians):
                    line += f" | {url}: " + " ".join(f"{key} {m[key]:.2f}" for key in phases) + f" bytes {m['bytes']:.0f}"
                print(line, flush=True)


if __name__ == "__main__":
    main()
