#!/usr/bin/python3
"""What an upload costs through the daemon as the store fills, with and
without a bound (issue 55): starts TOOND twice, each on a fresh data
directory, unbounded and with --max-store-mb, and POSTs the same UPLOADS
distinct small OBJ files (~2 KB, one triangle and a comment) to both in
turn (so that a busy moment of the machine, or of its disk, falls on both
alike), each over one kept-alive connection; then prints the median and
90th percentile of the last LAST request times of each, the models kept,
and the ratio bounded / unbounded.

    bench/store_uploads.py [--toond build/server/app/toond] [--uploads 3000]
                           [--last 300] [--max-store-mb 2] [--data DIR]

--toond may name another build's binary (an older one, to compare)."""
import argparse
import http.client
import json
import os
import shutil
import statistics
import subprocess
import tempfile
import time

BOUNDARY = "toond-store-bench"


def obj(n):
    """A one-triangle OBJ padded to about 2 KB; n makes it another model."""
    head = f"# model {n}\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# "
    return head + "x" * (2048 - len(head)) + "\n"


def multipart(text):
    return (f"--{BOUNDARY}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"m.obj\"\r\n"
            f"Content-Type: text/plain\r\n\r\n{text}\r\n--{BOUNDARY}--\r\n").encode()


def start(toond, data, extra):
    proc = subprocess.Popen([toond, "--listen", "127.0.0.1:0", "--data-dir", data] + extra,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    for line in proc.stdout:
        if line.startswith("listening on "):
            return proc, line.split("listening on ", 1)[1].strip()
    raise SystemExit(f"{toond} did not start")


class Daemon:
    def __init__(self, toond, data, extra):
        self.proc, url = start(toond, data, extra)
        host, port = url.replace("http://", "").split(":")
        self.conn = http.client.HTTPConnection(host, int(port))
        self.times = []

    def upload(self, n):
        headers = {"Content-Type": f"multipart/form-data; boundary={BOUNDARY}"}
        body = multipart(obj(n))
        started = time.perf_counter()
        self.conn.request("POST", "/models", body, headers)
        res = self.conn.getresponse()
        answer = res.read()
        self.times.append(1000 * (time.perf_counter() - started))
        if res.status != 201:
            raise SystemExit(f"upload {n} answered {res.status}: {answer[:200]}")

    def store(self):
        self.conn.request("GET", "/healthz")
        return json.loads(self.conn.getresponse().read())["store"]

    def stop(self):
        self.proc.terminate()
        self.proc.wait()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--toond", default="build/server/app/toond")
    parser.add_argument("--uploads", type=int, default=3000)
    parser.add_argument("--last", type=int, default=300)
    parser.add_argument("--max-store-mb", default="2")
    parser.add_argument("--data", help="where the data directories go (default: a temporary folder)")
    args = parser.parse_args()
    root = tempfile.mkdtemp(prefix="toond-store-uploads-", dir=args.data)
    daemons = {}
    try:
        for name, extra in (("unbounded", []), (f"--max-store-mb {args.max_store_mb}",
                                                ["--max-store-mb", args.max_store_mb])):
            data = os.path.join(root, name.replace(" ", "_").strip("-"))
            daemons[name] = Daemon(args.toond, data, extra)
        for n in range(args.uploads):
            for daemon in daemons.values():
                daemon.upload(n)
        medians = []
        for name, daemon in daemons.items():
            last = daemon.times[-args.last:]
            medians.append(statistics.median(last))
            p90 = statistics.quantiles(last, n=10)[-1]
            store = daemon.store()
            print(f"{name:>20}: median {medians[-1]:.2f} ms, p90 {p90:.2f} ms of the last {args.last} "
                  f"of {args.uploads} uploads; {store['models']} models kept, {store['bytes']} bytes")
        print(f"bounded / unbounded: {medians[1] / medians[0]:.2f}")
    finally:
        for daemon in daemons.values():
            daemon.stop()
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
