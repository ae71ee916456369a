#!/usr/bin/env python3
"""Writes the glTF twins of the game files under tests/exported/: each game
model converted by the assimp command-line tool (assimp-utils, not toond's
own helper) and then given the material its game draws it with, so a test
can hold toond's default render of the game file against the twin's.

    python3 tests/exported/make_game_twins.py [ASSIMP]

Minetest (Irrlicht): the skin as base colour, alphaMode MASK at 0.5, no
highlight (roughness 1, no specular extension), NEAREST magnification.
OpenArena (Quake 3): the skin as base colour, opaque, LINEAR filtering.
3d_armor's character: the three images the mod sets (character.png,
3d_armor_trans.png twice) on its three materials, as Minetest draws them.
The images are referenced by file name (not embedded): a test uploads each
twin with them beside it (3d_armor's character.png is minetest/character.png).
"""
import json
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
NEAREST, LINEAR, LINEAR_MIPMAP_LINEAR = 9728, 9729, 9987

MINETEST = {"alphaMode": "MASK", "alphaCutoff": 0.5, "magFilter": NEAREST}
QUAKE = {"alphaMode": "OPAQUE", "magFilter": LINEAR}

# (game file, twin, one image per material in material order, how it is drawn)
TWINS = [
    ("minetest/character.b3d", "minetest/character_twin.glb", ["character.png"], MINETEST),
    ("minetest/door_a.b3d", "minetest/door_a_twin.glb", ["doors_door_wood.png"], MINETEST),
    ("homedecor/homedecor_desk_fan.b3d", "homedecor/homedecor_desk_fan_twin.glb", ["homedecor_desk_fan_uv.png"],
     MINETEST),
    ("3d_armor/3d_armor_character.b3d", "3d_armor/3d_armor_character_twin.glb",
     ["character.png", "3d_armor_trans.png", "3d_armor_trans.png"], MINETEST),
    ("openarena/armor_red.md3", "openarena/armor_red_twin.glb", ["redarmor.tga"], QUAKE),
]


def read_glb(path):
    data = open(path, "rb").read()
    magic, _, _ = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF", path
    at, doc, binary = 12, None, b""
    while at < len(data):
        length, kind = struct.unpack_from("<I4s", data, at)
        chunk = data[at + 8:at + 8 + length]
        if kind == b"JSON":
            doc = json.loads(chunk)
        elif kind == b"BIN\0":
            binary = chunk
        at += 8 + length
    return doc, binary


def write_glb(path, doc, binary):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    if binary:
        chunks += struct.pack("<I4s", len(binary), b"BIN\0") + binary
    with open(path, "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


def as_game_draws(doc, images, look):
    """Every material: its image as base colour, the look's alpha and filter,
    fully rough and without the specular-glossiness extension assimp adds."""
    doc["images"] = [{"uri": image} for image in images]
    doc["samplers"] = [{"magFilter": look["magFilter"], "minFilter": LINEAR_MIPMAP_LINEAR}]
    doc["textures"] = [{"source": i, "sampler": 0} for i in range(len(images))]
    for i, material in enumerate(doc["materials"]):
        material.pop("extensions", None)
        material["pbrMetallicRoughness"] = {
            "baseColorTexture": {"index": min(i, len(images) - 1)},
            "baseColorFactor": [1, 1, 1, 1],
            "metallicFactor": 0.0,
            "roughnessFactor": 1.0,
        }
        material["alphaMode"] = look["alphaMode"]
        if "alphaCutoff" in look:
            material["alphaCutoff"] = look["alphaCutoff"]
    used = [e for e in doc.get("extensionsUsed", []) if e != "KHR_materials_pbrSpecularGlossiness"]
    doc["extensionsUsed"] = used
    if not used:
        del doc["extensionsUsed"]
    doc.pop("extensionsRequired", None)
    doc["asset"]["generator"] = "assimp, then tests/exported/make_game_twins.py"
    return doc


def main():
    assimp = sys.argv[1] if len(sys.argv) > 1 else "assimp"
    with tempfile.TemporaryDirectory() as scratch:
        for source, twin, images, look in TWINS:
            converted = os.path.join(scratch, os.path.basename(source) + ".glb")
            subprocess.run([assimp, "export", os.path.join(HERE, source), converted, "-fglb2"], check=True,
                           stdout=subprocess.DEVNULL)
            doc, binary = read_glb(converted)
            write_glb(os.path.join(HERE, twin), as_game_draws(doc, images, look), binary)
            print(twin)


if __name__ == "__main__":
    main()
