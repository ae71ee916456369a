#!/usr/bin/env python3
"""Writes the IQM seeds of the bundle_import fuzz target (corpus/bundle_import/):
a one-triangle IQM with a joint and a clip of two frames, and the same with
a second IQM holding the clip alone beside it, in the target's file format
(records separated by a "--file--" line, each a name line and the bytes).

    python3 tests/fuzz/make_iqm_seeds.py
"""
import os
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "bundle_import")


def iqm(mesh=True, joints=True, clip=True):
    text = b"\0tri\0skin.png\0root\0wave\0"
    text += b"\0" * (-len(text) % 4)
    parts = []  # (field index pair to fill, bytes)
    body = bytearray()
    offsets = {}

    def place(name, data):
        while (124 + len(body)) % 4:
            body.append(0)
        offsets[name] = 124 + len(body)
        body.extend(data)

    place("text", text)
    if mesh:
        positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 0, 1)
        texcoords = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
        blend_index = bytes([0, 0, 0, 0] * 3)
        blend_weight = bytes([255, 0, 0, 0] * 3)
        place("positions", positions)
        place("texcoords", texcoords)
        place("bindex", blend_index)
        place("bweight", blend_weight)
        arrays = struct.pack("<5I", 0, 0, 7, 3, offsets["positions"]) + struct.pack("<5I", 1, 0, 7, 2, offsets["texcoords"])
        if joints:
            arrays += struct.pack("<5I", 4, 0, 1, 4, offsets["bindex"]) + struct.pack("<5I", 5, 0, 1, 4, offsets["bweight"])
        place("arrays", arrays)
        place("triangles", struct.pack("<3I", 0, 1, 2))
        place("meshes", struct.pack("<6I", 1, 5, 0, 3, 0, 1))
    if joints:
        place("joints", struct.pack("<Ii10f", 14, -1, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1))
    if clip:
        place("poses", struct.pack("<iI20f", -1, 0x7, *([0, 0, 0, 0, 0, 0, 1, 1, 1, 1] + [0.001, 0.001, 0.001] + [0] * 7)))
        place("anims", struct.pack("<3IfI", 19, 0, 2, 24.0, 1))
        place("frames", struct.pack("<6H", 0, 0, 0, 500, 0, 0))
    n_arrays = (4 if joints else 2) if mesh else 0
    fields = [
        2, 124 + len(body), 0,
        len(text), offsets["text"],
        1 if mesh else 0, offsets.get("meshes", 0),
        n_arrays, 3 if mesh else 0, offsets.get("arrays", 0),
        1 if mesh else 0, offsets.get("triangles", 0), 0,
        1 if joints else 0, offsets.get("joints", 0),
        1 if clip else 0, offsets.get("poses", 0),
        1 if clip else 0, offsets.get("anims", 0),
        2 if clip else 0, 3 if clip else 0, offsets.get("frames", 0), 0,
        0, 0, 0, 0,
    ]
    return b"INTERQUAKEMODEL\0" + struct.pack("<27I", *fields) + bytes(body)


def record(name, data):
    return name.encode() + b"\n" + data


def main():
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, "iqm_skinned_clip"), "wb") as out:
        out.write(record("tri.iqm", iqm()))
    with open(os.path.join(HERE, "iqm_clip_beside"), "wb") as out:
        out.write(record("tri.iqm", iqm(clip=False)) + b"\n--file--\n" + record("wave.iqm", iqm(mesh=False)))


if __name__ == "__main__":
    main()
