#!/usr/bin/python3
"""What reading a file through the assimp helper costs: the helper alone
(process start, assimp, glTF written) on a one-triangle OFF and on Blender's
walker as FBX and COLLADA, then whole uploads of the same character as glTF,
FBX, COLLADA and OBJ through the daemon (medians; each upload asks a
smoothing angle of its own, so every one is a fresh import, not the store's
copy).

    bench/format_import.py http://127.0.0.1:8080 [--helper build/server/app/toond-assimp-convert] [--rounds 30]
"""
import argparse
import os
import statistics
import subprocess
import sys
import time
import urllib.request
import uuid

HERE = os.path.dirname(os.path.abspath(__file__))
BLENDER = os.path.join(HERE, "..", "tests", "exported", "blender")
TRIANGLE_OFF = b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"


def helper_ms(helper, form, data, rounds):
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        subprocess.run([helper, "--format", form, "--memory-mb", "1024", "--cpu-seconds", "10"],
                       input=data, capture_output=True, check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def multipart(files):
    boundary = uuid.uuid4().hex
    body = b""
    for name in files:
        with open(os.path.join(BLENDER, name), "rb") as f:
            content = f.read()
        body += (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
                 "Content-Type: application/octet-stream\r\n\r\n").encode() + content + b"\r\n"
    return boundary, body + f"--{boundary}--\r\n".encode()


def upload_ms(url, files, rounds, counter):
    boundary, body = multipart(files)
    times = []
    for _ in range(rounds):
        counter[0] += 1
        request = urllib.request.Request(f"{url}/models?smooth_angle={20 + counter[0] * 0.001:.3f}", data=body,
                                         headers={"Content-Type": f"multipart/form-data; boundary={boundary}"})
        start = time.perf_counter()
        with urllib.request.urlopen(request) as answer:
            answer.read()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("url")
    parser.add_argument("--helper", default=os.path.join(HERE, "..", "build", "server", "app", "toond-assimp-convert"))
    parser.add_argument("--rounds", type=int, default=30)
    args = parser.parse_args()
    print("helper alone (median of %d runs):" % args.rounds)
    print("  1-triangle OFF       %6.1f ms  (start-up)" % helper_ms(args.helper, "off", TRIANGLE_OFF, args.rounds))
    for name, form in (("walker.fbx", "fbx"), ("walker.dae", "dae")):
        with open(os.path.join(BLENDER, name), "rb") as f:
            data = f.read()
        print("  %-20s %6.1f ms  (%d KB)" % (name, helper_ms(args.helper, form, data, args.rounds), len(data) // 1024))
    print("whole upload through the daemon (median of %d):" % args.rounds)
    counter = [0]
    for files in (["walker.glb"], ["walker.fbx"], ["walker.dae"], ["walker_rest.obj", "walker_rest.mtl"]):
        print("  %-20s %6.1f ms" % (files[0], upload_ms(args.url.rstrip("/"), files, args.rounds, counter)))


if __name__ == "__main__":
    sys.exit(main())
