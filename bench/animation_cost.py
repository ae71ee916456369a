#!/usr/bin/python3
"""What posing costs: the default render of a skinned, animated character
against the same model rendered static (its rest pose), as a ratio of
medians over interleaved requests.

The character is the shared Stanford bunny given a three-joint spine up its
height (every vertex blended between the two nearest joints) and a two-second
clip that sways the joints; it is written here as a .glb and uploaded. Each
round renders the rest pose and one time of the clip (a fresh time each
round, so no answer comes from a cache), and the client's wall time counts
everything the daemon does: posing runs on the request's thread, before the
render thread.

With --sheet: an 8-direction sheet of 12 frames of the clip at 128² in one
request against the 96 single renders of the same tiles (medians of a few
rounds each): what the issue on animated sheets asks to stay under 1.

    bench/animation_cost.py http://127.0.0.1:8080 [--shared ../shared/models] [--rounds 40] [--size 512] [--sheet]
"""
import argparse
import http.client
import json
import math
import statistics
import struct
import sys
import time
import urllib.parse


def read_obj(path):
    positions, triangles = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            positions.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "f":
            corners = [int(p.split("/")[0]) - 1 for p in parts[1:]]
            for k in range(1, len(corners) - 1):
                triangles.append((corners[0], corners[k], corners[k + 1]))
    return positions, triangles


def quaternion_z(angle):
    return (0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2))


def rigged_glb(positions, triangles):
    low = min(p[1] for p in positions)
    high = max(p[1] for p in positions)
    step = (high - low) / 2
    joints_y = [low, low + step, high]
    bin_parts, views, accessors = [], [], []

    def add(data, component_type, count, kind, target=None):
        offset = sum(len(b) for b in bin_parts)
        padding = (-offset) % 4
        if padding:
            bin_parts.append(b"\0" * padding)
            offset += padding
        bin_parts.append(data)
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(data)}
        if target:
            view["target"] = target
        views.append(view)
        accessor = {"bufferView": len(views) - 1, "componentType": component_type, "count": count, "type": kind}
        if kind == "VEC3" and component_type == 5126 and count == len(positions):
            accessor["min"] = [min(p[i] for p in positions) for i in range(3)]
            accessor["max"] = [max(p[i] for p in positions) for i in range(3)]
        accessors.append(accessor)
        return len(accessors) - 1

    flat = [c for p in positions for c in p]
    position = add(struct.pack(f"<{len(flat)}f", *flat), 5126, len(positions), "VEC3", 34962)
    indices = [i for t in triangles for i in t]
    index = add(struct.pack(f"<{len(indices)}I", *indices), 5125, len(indices), "SCALAR", 34963)
    joints, weights = [], []
    for p in positions:
        t = min(max((p[1] - low) / step, 0.0), 1.999999)
        j = int(t)
        f = t - j
        joints += [j, j + 1, 0, 0]
        weights += [1 - f, f, 0, 0]
    joint = add(struct.pack(f"<{len(joints)}H", *joints), 5123, len(positions), "VEC4")
    weight = add(struct.pack(f"<{len(weights)}f", *weights), 5126, len(positions), "VEC4")
    ibms = []
    for y in joints_y:
        ibms += [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -y, 0, 1]
    ibm = add(struct.pack("<48f", *ibms), 5126, 3, "MAT4")
    keys = 30
    times = [2.0 * k / (keys - 1) for k in range(keys)]
    time_accessor = add(struct.pack(f"<{keys}f", *times), 5126, keys, "SCALAR")
    samplers, channels = [], []
    for node in (2, 3):
        values = []
        for t in times:
            values += quaternion_z(0.35 * math.sin(math.pi * t + node))
        output = add(struct.pack(f"<{len(values)}f", *values), 5126, keys, "VEC4")
        samplers.append({"input": time_accessor, "output": output})
        channels.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": "rotation"}})
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"mesh": 0, "skin": 0},
            {"name": "hips", "translation": [0, joints_y[0], 0], "children": [2]},
            {"name": "spine", "translation": [0, step, 0], "children": [3]},
            {"name": "head", "translation": [0, step, 0]},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": position, "JOINTS_0": joint, "WEIGHTS_0": weight},
                                    "indices": index}]}],
        "skins": [{"joints": [1, 2, 3], "inverseBindMatrices": ibm}],
        "animations": [{"name": "Sway", "samplers": samplers, "channels": channels}],
        "buffers": [{"byteLength": sum(len(b) for b in bin_parts)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    body = b"".join(bin_parts)
    body += b"\0" * ((-len(body)) % 4)
    text = json.dumps(gltf).encode()
    text += b" " * ((-len(text)) % 4)
    return (struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(body)) +
            struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(body), 0x004E4942) + body)


def upload(conn, name, data):
    boundary = "toondbench"
    body = (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
            f"Content-Type: application/octet-stream\r\n\r\n").encode() + data + f"\r\n--{boundary}--\r\n".encode()
    conn.request("POST", "/models", body, {"Content-Type": f"multipart/form-data; boundary={boundary}"})
    answer = conn.getresponse()
    text = answer.read()
    if answer.status not in (200, 201):
        sys.exit(f"upload failed: {answer.status} {text[:300]}")
    return json.loads(text)


def render_ms(conn, params):
    start = time.perf_counter()
    conn.request("POST", "/render", json.dumps(params), {"Content-Type": "application/json"})
    answer = conn.getresponse()
    answer.read()
    if answer.status != 200:
        sys.exit(f"render failed: {answer.status}")
    return (time.perf_counter() - start) * 1e3


def sheet_against_singles(conn, model, rounds):
    size, directions, frames = 128, 8, 12
    sheet = {"model": model, "width": size, "height": size,
             "sheet": {"frames": directions, "animation": {"clip": "Sway", "frames": frames}}}
    render_ms(conn, sheet)  # frames the clip once
    sheet_times, single_times = [], []
    for r in range(rounds):
        sheet["png_compression"] = 1 + r % 2  # a fresh request each round (no cached answer)
        sheet_times.append(render_ms(conn, sheet))
        total = 0.0
        for d in range(directions):
            for k in range(frames):
                total += render_ms(conn, {"model": model, "width": size, "height": size, "png_compression": 1 + r % 2,
                                          "camera": {"yaw": 360.0 * d / directions},
                                          "animation": {"clip": "Sway", "time": 2.0 * k / frames}})
        single_times.append(total)
    s, t = statistics.median(sheet_times), statistics.median(single_times)
    print(f"{directions} directions x {frames} frames at {size}², {rounds} rounds: sheet median {s:.0f} ms, "
          f"the {directions * frames} singles {t:.0f} ms, ratio {s / t:.3f}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("server")
    parser.add_argument("--shared", default="../shared/models")
    parser.add_argument("--rounds", type=int, default=40)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--sheet", action="store_true")
    args = parser.parse_args()
    url = urllib.parse.urlparse(args.server)
    conn = http.client.HTTPConnection(url.hostname, url.port or 80, timeout=120)
    positions, triangles = read_obj(f"{args.shared}/stanford-bunny/stanford-bunny.obj")
    info = upload(conn, "rigged-bunny.glb", rigged_glb(positions, triangles))
    print(f"rigged bunny: {len(positions)} positions, {info['triangles']} triangles, "
          f"clips {[c['name'] for c in info['animation']['clips']]}")
    if args.sheet:
        return sheet_against_singles(conn, info["id"], max(1, args.rounds // 10))
    base = {"model": info["id"], "width": args.size, "height": args.size}
    # The first posed request frames the clip (once per model and clip): timed apart.
    first = render_ms(conn, dict(base, animation={"clip": "Sway", "time": 0.0}))
    print(f"first posed render (frames the clip): {first:.1f} ms")
    static, posed = [], []
    for r in range(args.rounds):
        # The rest pose renders from the result cache after the first time
        # unless the daemon runs with --result-cache-mb 0: vary a no-op field.
        static.append(render_ms(conn, dict(base, png_compression=1 + r % 2)))
        posed.append(render_ms(conn, dict(base, png_compression=1 + r % 2,
                                          animation={"clip": "Sway", "time": 0.013 * (r + 1)})))
    s, p = statistics.median(static), statistics.median(posed)
    print(f"{args.size}², {args.rounds} interleaved rounds: static median {s:.1f} ms, posed median {p:.1f} ms, "
          f"ratio {p / s:.3f}")


if __name__ == "__main__":
    main()
