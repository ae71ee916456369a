#!/usr/bin/env python3
"""How much of toond's throughput PNG encoding costs: renders/s and p50/p99
with 1 and 4 clients at the default zlib level and with encoding all but
switched off (png_compression 0: stored), interleaved, each client one
kept-alive connection, a different yaw per request (no cache hit).

    bench/encode_share.py http://127.0.0.1:8080 MODEL_ID [--seconds 6] [--rounds 2]

Start toond with --result-cache-mb 0."""
import argparse
import http.client
import json
import threading
import time
import urllib.parse


def load(host, port, model, clients, seconds, extra):
    stop = time.time() + seconds
    latencies, ok = [], [0]
    lock = threading.Lock()

    def client(k):
        conn = http.client.HTTPConnection(host, port)
        i = 0
        while time.time() < stop:
            i += 1
            body = dict(model=model, width=512, height=512, camera=dict(yaw=30 + k * 1e-3 + i * 1e-5), **extra)
            started = time.time()
            conn.request("POST", "/render", json.dumps(body))
            answer = conn.getresponse()
            answer.read()
            with lock:
                latencies.append((time.time() - started) * 1000)
                ok[0] += answer.status == 200

    threads = [threading.Thread(target=client, args=(k,)) for k in range(clients)]
    began = time.time()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    latencies.sort()
    return ok[0] / (time.time() - began), latencies[len(latencies) // 2], latencies[int(len(latencies) * 0.99)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("url")
    parser.add_argument("model")
    parser.add_argument("--seconds", type=float, default=6)
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    where = urllib.parse.urlparse(args.url)
    for _ in range(args.rounds):
        for label, extra in (("png level 3", {}), ("png level 0", {"png_compression": 0})):
            for clients in (1, 4):
                rate, p50, p99 = load(where.hostname, where.port, args.model, clients, args.seconds, extra)
                print(f"{label}, {clients} clients: {rate:.1f} renders/s, p50 {p50:.1f} ms, p99 {p99:.1f} ms",
                      flush=True)


if __name__ == "__main__":
    main()
