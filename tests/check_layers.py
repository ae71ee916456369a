#!/usr/bin/env python3
"""The rooms of server/ and the way their includes point.

Each room is a folder; ROOMS lists them lowest first. A file may include
headers of its own room and of any room below it; an include of a room
above it runs back up, and fails the check with the file, the line and
both rooms. A folder of server/ that no room holds fails too, so a new room
is given its place here. Includes that name no room (the proto library's
request_error.h, the files the build embeds) are not checked.

    tests/check_layers.py [REPO]
"""
import os
import re
import sys

# Lowest first. A file belongs to the longest of these its path starts with.
ROOMS = [
    "server/parallel",        # one job's work over the cores
    "server/text",            # the one text trim every reader uses
    "server/helper_process",  # what the helper programs share
    "server/glb",             # the .glb container writer
    "server/image",           # PNG, sRGB, palettes, WebP
    "server/bundle_paths",    # how the files of an upload name each other
    "server/draco_decode",    # the Draco helper and its answer's wire format
    "server/assimp_convert",  # the assimp helper program
    "server/scene/mesh",      # a model as imported: meshes, rigs, creases, levels of detail
    "server/scene/animation", # clips sampled, poses, what moves alike
    "server/scene/import",    # bundles and the importers of every format
    "server/scene/store",     # the model store, its bound, the models kept in memory
    "server/gpu",             # EGL and the RAII GL objects
    "server/render/plan",     # parameters, a frame's plan and price, camera, levels, sheets' layout
    "server/render/cull",     # what is left out before drawing: facing runs, the hull cull
    "server/render/frame",    # a frame's GPU side: models, blocks, resources, pacing
    "server/render/passes",   # one file per pass, and the object loop they share
    "server/render/run",      # the renderer running a plan, the render threads, the fair queue
    "server/render/atlas",    # a sheet's atlas (Aseprite JSON)
    "server/render/vector",   # line drawings as vectors: exact visibility, strokes, SVG
    "server/pipeline",        # a request's way from parameters to the answer's bytes
    "server/http",            # parse, call the pipeline, answer
    "server/app",             # toond's main and its flags
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def room_of(path):
    best = None
    for room in ROOMS:
        if path == room or path.startswith(room + "/"):
            if best is None or len(room) > len(best):
                best = room
    return best


def main():
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    rank = {room: i for i, room in enumerate(ROOMS)}
    problems = []
    files = 0
    for folder, _, names in os.walk(os.path.join(repo, "server")):
        for name in sorted(names):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.relpath(os.path.join(folder, name), repo).replace(os.sep, "/")
            room = room_of(path)
            if room is None:
                problems.append(f"{path}: in no room; give its folder a place in ROOMS ({__file__})")
                continue
            files += 1
            with open(os.path.join(repo, path), encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    target = room_of("server/" + match.group(1))
                    if target is not None and rank[target] > rank[room]:
                        problems.append(f"{path}:{number}: includes {match.group(1)}, of {target}, "
                                        f"above its own room {room}")
    for problem in problems:
        print(problem)
    print(f"check_layers: {files} files in {len(ROOMS)} rooms; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
