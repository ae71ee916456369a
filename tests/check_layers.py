#!/usr/bin/env python3
"""What each room of the code may include.

A room is a folder of C++ sources: the libraries the daemon, its helpers
and the CLI share (common/), the wire schema's reader (proto/cpp), the
daemon's rooms (server/), the CLI (client/cli) and the benchmarks (bench).
ROOMS says, for each, the other rooms whose headers its files may include;
an include of any other room fails with the file, the line and both rooms.
So does a folder of C++ sources that no room holds (a new room is given
its place here), and a table whose rooms include each other round a cycle.
UNREACHABLE says which rooms a room's files may not reach even through
the headers of rooms they may include: the include chain that gets there
fails with the file.

The table's floors (a room stands one floor above the highest room it may
include) are drawn in docs/architecture.md between DIAGRAM_BEGIN and
DIAGRAM_END; a drawing that is not the table's is a problem too, and
`--diagram` prints the one to paste there.

An include is looked up as the compiler does: beside the file, then under
each include root (INCLUDE_ROOTS). Includes found nowhere (the files the
build generates, system headers) are not checked.

    tests/check_layers.py [REPO]
    tests/check_layers.py --diagram
"""
import os
import re
import sys

INCLUDE_ROOTS = ["common", "server", "proto/cpp", "tests"]

# Room → (what it holds, the rooms its files may include besides its own).
ROOMS = {
    "common/text": ("the one text trim every reader uses", []),
    "common/parallel": ("one job's work over the cores", []),
    "common/image": ("PNG, sRGB, palettes, WebP", ["common/parallel"]),
    "common/glb": ("the .glb container writer", []),
    "common/bundle_paths": ("how the files of an upload name each other", ["common/text"]),
    "common/obj_text": ("how OBJ and MTL text is read: tinyobj's rewrites, what an MTL says of a material",
                        ["common/bundle_paths", "common/text"]),
    "proto/cpp": ("the wire schema, its presets and the errors it raises", []),
    "server/helpers/process": ("what the helper programs share: their limits, their stdio", []),
    "server/helpers/launch": ("how the daemon runs a helper program", []),
    "server/helpers/draco_decode": ("the Draco helper and its answer's wire format", ["server/helpers/process"]),
    "server/helpers/assimp_convert": ("the assimp helper program", ["server/helpers/process", "common/glb"]),
    "server/scene/mesh": ("a model as imported: meshes, rigs, creases, levels of detail", ["common/parallel"]),
    "server/scene/animation": ("clips sampled, poses, what moves alike", ["common/parallel", "server/scene/mesh"]),
    "server/scene/reading": ("what every format's reader shares: the bundle, limits, errors, mesh building, images",
                             ["common/bundle_paths", "common/image", "common/text", "server/scene/mesh"]),
    "server/scene/gltf": ("glTF 2.0 and GLB", ["common/bundle_paths", "server/helpers/draco_decode",
                                               "server/helpers/launch", "server/scene/animation",
                                               "server/scene/mesh", "server/scene/reading"]),
    "server/scene/import": ("the other formats, and the importer chosen for an upload",
                            ["common/bundle_paths", "common/glb", "common/image", "common/obj_text", "common/text",
                             "server/helpers/launch",
                             "server/scene/animation", "server/scene/gltf", "server/scene/mesh",
                             "server/scene/reading"]),
    "server/scene/store": ("the model store, its bound, the models kept in memory",
                           ["common/bundle_paths", "server/scene/import", "server/scene/mesh", "server/scene/reading"]),
    "server/sheet_files": ("a sheet's files besides its PNG: trimmed and packed tiles, .aseprite, Godot",
                           ["common/image"]),
    "server/gpu": ("EGL and the RAII GL objects", ["common/image", "common/text"]),
    "server/render/plan": ("parameters, a frame's plan and price, camera, levels, sheets' layout",
                           ["server/scene/animation", "server/scene/mesh"]),
    "server/render/cull": ("what is left out before drawing: facing runs, the hull cull",
                           ["server/render/plan", "server/scene/mesh"]),
    "server/render/frame": ("a frame's GPU side: models, blocks, resources, pacing",
                            ["common/image", "server/gpu", "server/render/cull", "server/render/plan",
                             "server/scene/animation", "server/scene/mesh"]),
    "server/render/passes": ("one file per pass, and the object loop they share",
                             ["server/gpu", "server/render/cull", "server/render/frame", "server/render/plan"]),
    "server/render/run": ("the renderer running a plan, the render threads, the fair queue",
                          ["common/image", "server/gpu", "server/render/cull", "server/render/frame",
                           "server/render/passes", "server/render/plan", "server/scene/animation",
                           "server/scene/mesh"]),
    "server/render/atlas": ("a sheet's atlas (Aseprite JSON)", ["server/render/plan"]),
    "server/render/vector": ("line drawings as vectors: exact visibility, strokes, SVG",
                             ["common/image", "common/parallel", "server/render/frame", "server/render/plan",
                              "server/scene/animation", "server/scene/mesh"]),
    # server/gpu for the GPU's failures alone, which the entry says as its own (render_failure.h).
    "server/pipeline": ("a request's way from parameters to the answer's bytes, entered by render_entry.h",
                        ["common/image", "proto/cpp", "server/gpu", "server/render/atlas", "server/render/frame",
                         "server/render/vector", "server/sheet_files",
                         "server/render/plan", "server/render/run", "server/scene/animation",
                         "server/scene/mesh", "server/scene/store"]),
    # The store and an upload's files for the model routes; render requests
    # through the pipeline's entry alone.
    "server/http": ("parse, call the pipeline's entry, answer",
                    ["common/text", "proto/cpp", "server/pipeline", "server/scene/reading", "server/scene/store"]),
    "server/app": ("toond's main and its flags",
                   ["common/text", "server/gpu", "server/http", "server/pipeline", "server/render/run",
                    "server/scene/store"]),
    "client/cli": ("the toon command-line client",
                   ["common/bundle_paths", "common/glb", "common/image", "common/obj_text", "common/text",
                    "proto/cpp"]),
    "bench": ("the benchmarks, run by hand",
              ["common/image", "server/gpu", "server/scene/gltf", "server/scene/import", "server/scene/mesh",
               "server/scene/reading", "server/scene/store", "tests/support"]),
    # Not fenced itself: the test harness the benchmarks share.
    "tests/support": ("the tests' daemon harness and generated models", None),
}
FENCED_TOPS = ["common", "proto", "server", "client", "bench"]

# Room → rooms its files may not reach, include after include, through any
# header: the HTTP layer knows no EGL or GL, not even by way of the
# pipeline's headers (the entry keeps the render threads behind it).
UNREACHABLE = {
    "server/http": ["server/gpu"],
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')

ARCHITECTURE = "docs/architecture.md"
DIAGRAM_BEGIN = "<!-- rooms: drawn by tests/check_layers.py --diagram -->"
DIAGRAM_END = "<!-- rooms: end -->"


def room_of(path):
    best = None
    for room in ROOMS:
        if path == room or path.startswith(room + "/"):
            if best is None or len(room) > len(best):
                best = room
    return best


def resolve(repo, path, include):
    """The repository path `include` in file `path` names, or None."""
    for base in [os.path.dirname(path)] + INCLUDE_ROOTS:
        candidate = os.path.normpath(os.path.join(base, include)).replace(os.sep, "/")
        if os.path.isfile(os.path.join(repo, candidate)):
            return candidate
    return None


def sources(repo):
    for top in FENCED_TOPS:
        for folder, names, files in os.walk(os.path.join(repo, top)):
            names[:] = [n for n in names if n != "node_modules"]
            for name in sorted(files):
                if name.endswith((".h", ".cpp")):
                    yield os.path.relpath(os.path.join(folder, name), repo).replace(os.sep, "/")


def cycle_in_table():
    """A cycle of rooms that may include each other, or None."""
    state = {}

    def visit(room, trail):
        state[room] = "open"
        for other in ROOMS[room][1] or []:
            if state.get(other) == "open":
                return trail + [room, other]
            if other not in state:
                found = visit(other, trail + [room])
                if found:
                    return found
        state[room] = "done"
        return None

    for room in ROOMS:
        if room not in state:
            found = visit(room, [])
            if found:
                return found
    return None


def includes_of(repo, path, known):
    """The repository files `path` includes, looked up once."""
    if path not in known:
        found = []
        with open(os.path.join(repo, path), encoding="utf-8") as f:
            for line in f:
                match = INCLUDE.match(line)
                target = resolve(repo, path, match.group(1)) if match else None
                if target:
                    found.append(target)
        known[path] = found
    return known[path]


def unreachable_chain(repo, path, forbidden, known):
    """The include chain from `path` to a file of a `forbidden` room, or None."""
    came_from = {path: None}
    queue = [path]
    while queue:
        current = queue.pop(0)
        if room_of(current) in forbidden:
            chain = []
            while current:
                chain.append(current)
                current = came_from[current]
            return list(reversed(chain))
        for target in includes_of(repo, current, known):
            if target not in came_from:
                came_from[target] = current
                queue.append(target)
    return None


def reach_problems(repo):
    problems = []
    known = {}
    for path in sources(repo):
        forbidden = UNREACHABLE.get(room_of(path))
        chain = unreachable_chain(repo, path, forbidden, known) if forbidden else None
        if chain:
            problems.append(f"{path}: reaches {chain[-1]}, of {room_of(chain[-1])}, which {room_of(path)} may not "
                            f"reach: " + " -> ".join(chain))
    return problems


def floors():
    """Each fenced room's floor: one above the highest room it may include."""
    floor = {}

    def of(room):
        if room not in floor:
            floor[room] = 1 + max((of(other) for other in ROOMS[room][1] if ROOMS[other][1] is not None), default=-1)
        return floor[room]

    for room, (_, allowed) in ROOMS.items():
        if allowed is not None:
            of(room)
    return floor


def diagram():
    """The table's floors, top down, as docs/architecture.md draws them."""
    floor = floors()
    lines = ["```", "floor  rooms (each may include rooms below it, as tests/check_layers.py allows)"]
    for level in range(max(floor.values()), -1, -1):
        rooms = sorted(room for room, f in floor.items() if f == level)
        line = f"{level:>5}  "
        for room in rooms:
            if len(line) + len(room) > 100 and line.strip():
                lines.append(line.rstrip())
                line = " " * 7
            line += room + "  "
        lines.append(line.rstrip())
    lines.append("```")
    return "\n".join(lines)


def diagram_problem(repo):
    """What is wrong with the architecture page's drawing of the table, or None."""
    path = os.path.join(repo, ARCHITECTURE)
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8") as f:
        text = f.read()
    begin, end = text.find(DIAGRAM_BEGIN), text.find(DIAGRAM_END)
    if begin < 0 or end < begin:
        return f"{ARCHITECTURE}: no drawing of the rooms between '{DIAGRAM_BEGIN}' and '{DIAGRAM_END}'"
    drawn = text[begin + len(DIAGRAM_BEGIN):end].strip()
    if drawn != diagram():
        return f"{ARCHITECTURE}: its drawing of the rooms is not the table's; paste what `tests/check_layers.py --diagram` prints"
    return None


def problems_of(repo):
    problems = []
    cycle = cycle_in_table()
    if cycle:
        problems.append("the table's rooms include each other round a cycle: " + " -> ".join(cycle))
    elif diagram_problem(repo):
        problems.append(diagram_problem(repo))
    files = 0
    for path in sources(repo):
        room = room_of(path)
        if room is None or ROOMS[room][1] is None:
            problems.append(f"{path}: in no room; give its folder a place in ROOMS ({__file__})")
            continue
        files += 1
        allowed = set(ROOMS[room][1]) | {room}
        with open(os.path.join(repo, path), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target_path = resolve(repo, path, match.group(1))
                target = room_of(target_path) if target_path else None
                if target is not None and target not in allowed:
                    problems.append(f"{path}:{number}: includes {match.group(1)}, of {target}, "
                                    f"which {room} may not include")
    return files, problems + reach_problems(repo)


def main():
    if sys.argv[1:] == ["--diagram"]:
        print(diagram())
        return 0
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    files, problems = problems_of(repo)
    for problem in problems:
        print(problem)
    print(f"check_layers: {files} files in {len(ROOMS)} rooms; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
