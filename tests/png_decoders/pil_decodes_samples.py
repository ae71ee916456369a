#!/usr/bin/env python3
"""Decodes the PNGs that encode_png wrote (toond_png_samples) with Pillow, a
decoder that shares no code with ours, and checks every pixel bit for bit
against the raw RGBA the encoder was given.

    pil_decodes_samples.py --writer toond_png_samples --dir OUT_DIR [FRAME.png ...]

Exit 0: every sample decodes exactly; 1: a sample differs, or Pillow is
missing (scripts/install-deps.sh installs python3-pil)."""
import argparse
import pathlib
import subprocess
import sys

try:
    import PIL
    from PIL import Image
except ImportError:
    print("Pillow is missing: run scripts/install-deps.sh (python3-pil)")
    sys.exit(1)

# What Pillow calls each PNG colour type encode_png writes.
MODE_OF_COLOUR_TYPE = {2: "RGB", 3: "P", 6: "RGBA"}


def first_difference(a, b):
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return i
    return min(len(a), len(b))


def check_sample(directory, name, width, height, colour_type):
    with Image.open(directory / f"{name}.png") as image:
        image.load()
        problems = []
        if image.size != (width, height):
            problems.append(f"size {image.size}, expected {(width, height)}")
        expected_mode = MODE_OF_COLOUR_TYPE.get(colour_type)
        if image.mode != expected_mode:
            problems.append(f"Pillow mode {image.mode}, expected {expected_mode} for colour type {colour_type}")
        decoded = image.convert("RGBA").tobytes()
    raw = (directory / f"{name}.rgba").read_bytes()
    if decoded != raw:
        at = first_difference(decoded, raw)
        pixel = at // 4
        problems.append(
            f"pixel ({pixel % width}, {pixel // width}) decodes to {tuple(decoded[pixel * 4:pixel * 4 + 4])}, "
            f"was {tuple(raw[pixel * 4:pixel * 4 + 4])}")
    return problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--writer", required=True)
    parser.add_argument("--dir", required=True, type=pathlib.Path)
    parser.add_argument("frames", nargs="*")
    args = parser.parse_args()

    if subprocess.run([args.writer, str(args.dir), *args.frames], check=False).returncode != 0:
        print(f"FAIL {args.writer} could not write the samples")
        return 1
    failures = 0
    for line in (args.dir / "samples.txt").read_text().splitlines():
        name, width, height, colour_type = line.split()
        problems = check_sample(args.dir, name, int(width), int(height), int(colour_type))
        print(f"{'FAIL' if problems else 'ok  '} {name} ({width}x{height}, colour type {colour_type})")
        for problem in problems:
            print(f"     {problem}")
        failures += bool(problems)
    print(f"Pillow {PIL.__version__}: {failures} sample(s) differ")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
