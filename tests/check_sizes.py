#!/usr/bin/env python3
"""Sizes the code keeps to, measured as a newcomer would measure them.

- Functions: universal-ctags's idea of each C++ function's first and last
  line. The longest in server/ and common/ may be LIMITS' lines long, in
  client/ fewer: a function longer than that does more than one thing.
- Uniforms set by name under server/render: a uniform a pass sets by its
  name (`program.set("u_…", …)`) is a string the shader and the renderer
  must agree on unchecked; per-frame values belong in uniform blocks
  (server/render/frame/uniform_blocks.h), whose layout is checked. At most
  MAX_NAMED_UNIFORMS such calls.

    tests/check_sizes.py [REPO]      (exit status 1 and every excess printed)
"""
import os
import re
import subprocess
import sys

LIMITS = {"server": 100, "common": 100, "client": 80}
MAX_NAMED_UNIFORMS = 12
NAMED_UNIFORM = re.compile(r'\.set\(\s*"(u_\w+)"')


def function_lengths(repo, tree):
    """(lines, path, name) of every function ctags finds under `tree`."""
    try:
        run = subprocess.run(["ctags", "-R", "--languages=C++", "--kinds-C++=f", "--fields=+ne", "-f", "-", tree],
                             cwd=repo, capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit(f"check_sizes: universal-ctags did not run ({e}); scripts/install-deps.sh installs it")
    found = []
    for line in run.stdout.splitlines():
        fields = line.split("\t")
        extra = dict(f.split(":", 1) for f in fields[3:] if ":" in f)
        if "line" in extra and "end" in extra:
            found.append((int(extra["end"]) - int(extra["line"]) + 1, fields[1], fields[0]))
    return found


def named_uniforms(repo):
    calls = []
    for folder, _, files in os.walk(os.path.join(repo, "server", "render")):
        for name in sorted(files):
            if not name.endswith((".cpp", ".h")):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                for number, text in enumerate(f, 1):
                    for match in NAMED_UNIFORM.finditer(text):
                        calls.append(f"{os.path.relpath(path, repo)}:{number}: {match.group(1)}")
    return calls


def main():
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    problems = []
    for tree, limit in LIMITS.items():
        lengths = sorted(function_lengths(repo, tree), reverse=True)
        for lines, path, name in lengths:
            if lines > limit:
                problems.append(f"{path}: {name} is {lines} lines, more than {limit} in {tree}/")
        if lengths:
            print(f"check_sizes: longest function in {tree}/: {lengths[0][2]} ({lengths[0][1]}), "
                  f"{lengths[0][0]} lines (limit {limit})")
    uniforms = named_uniforms(repo)
    print(f"check_sizes: {len(uniforms)} uniforms set by name under server/render (limit {MAX_NAMED_UNIFORMS})")
    if len(uniforms) > MAX_NAMED_UNIFORMS:
        problems.append(f"{len(uniforms)} uniforms set by name under server/render, more than {MAX_NAMED_UNIFORMS}: "
                        "move per-frame values into a uniform block")
        problems.extend("  " + u for u in uniforms)
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
