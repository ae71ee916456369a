#!/usr/bin/python3
"""Draws docs/images/layers.png: the demo model in each `output` of one
request, side by side, from a running toond.

    /usr/bin/python3 docs/images/make_layers.py http://127.0.0.1:8080 [OUT.png]

Debian's interpreter, for Pillow (python3-pil). The PNGs are shown as a
viewer would need them shown: the transparent ones over a checkerboard, the
16-bit depth scaled to 8 bits (nearest black, background white), and the id
layer's indices through a fixed colour per index (its own palette is grey).
"""
import io
import json
import sys
import urllib.request

from PIL import Image, ImageDraw

OUTPUTS = ["color", "lines", "depth", "normal", "id"]
SIZE = 192
LABEL = 18
ID_COLOURS = [(0, 0, 0, 0), (230, 120, 40, 255), (60, 130, 220, 255), (90, 180, 90, 255), (200, 60, 160, 255)]


def render(url, output):
    body = json.dumps({"width": SIZE, "height": SIZE, "background": [0, 0, 0, 0], "output": output}).encode()
    request = urllib.request.Request(url.rstrip("/") + "/render", data=body, method="POST")
    with urllib.request.urlopen(request) as answer:
        return Image.open(io.BytesIO(answer.read()))


def checkerboard():
    board = Image.new("RGBA", (SIZE, SIZE), (255, 255, 255, 255))
    draw = ImageDraw.Draw(board)
    for y in range(0, SIZE, 12):
        for x in range(0, SIZE, 12):
            if (x // 12 + y // 12) % 2:
                draw.rectangle([x, y, x + 11, y + 11], fill=(225, 225, 225, 255))
    return board


def viewable(output, image):
    if output == "depth":
        grey = image.point(lambda v: v / 257).convert("L")
        return grey.convert("RGBA")
    if output == "id":
        indices = image.convert("L") if image.mode != "P" else image
        rgba = Image.new("RGBA", image.size)
        rgba.putdata([ID_COLOURS[i % len(ID_COLOURS)] for i in indices.getdata()])
        return rgba
    return image.convert("RGBA")


def main():
    url = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else "docs/images/layers.png"
    strip = Image.new("RGBA", (SIZE * len(OUTPUTS), SIZE + LABEL), (255, 255, 255, 255))
    draw = ImageDraw.Draw(strip)
    for i, output in enumerate(OUTPUTS):
        panel = checkerboard()
        panel.alpha_composite(viewable(output, render(url, output)))
        strip.paste(panel, (i * SIZE, 0))
        draw.text((i * SIZE + 6, SIZE + 3), output, fill=(0, 0, 0, 255))
    strip.convert("RGB").save(out, optimize=True)


if __name__ == "__main__":
    main()
