#!/usr/bin/python3
"""Draws docs/images/creases_before_after.png: the shared windmill's default
frame at 512² from two running toond builds side by side, whole and a part
of it enlarged three times: before (crease lines found by the screen-space
edge pass, a build of commit 6b47f8c) and after (drawn along the crease
edges, issue 47).

    /usr/bin/python3 docs/images/make_creases.py URL_BEFORE URL_AFTER [MODELS_DIR] [OUT.png]

Debian's interpreter, for Pillow (python3-pil). Both daemons get the same
upload (the same model id) and the same request.
"""
import io
import json
import os
import sys
import urllib.request
import uuid

from PIL import Image, ImageDraw

SIZE = 512
CROP = (160, 230, 340, 410)  # the door, a window and the gallery's posts
ZOOM = 2
LABEL = 20


def upload(url, folder):
    boundary = uuid.uuid4().hex
    parts = []
    for name in sorted(os.listdir(folder)):
        if os.path.splitext(name)[1].lower() not in (".obj", ".mtl", ".jpg", ".png"):
            continue
        with open(os.path.join(folder, name), "rb") as f:
            parts.append(f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
                         f"Content-Type: application/octet-stream\r\n\r\n".encode() + f.read() + b"\r\n")
    body = b"".join(parts) + f"--{boundary}--\r\n".encode()
    request = urllib.request.Request(url.rstrip("/") + "/models", data=body, method="POST",
                                     headers={"Content-Type": f"multipart/form-data; boundary={boundary}"})
    with urllib.request.urlopen(request) as answer:
        return json.loads(answer.read())["id"]


def render(url, model):
    body = json.dumps({"model": model, "width": SIZE, "height": SIZE}).encode()
    request = urllib.request.Request(url.rstrip("/") + "/render", data=body, method="POST",
                                     headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(request) as answer:
        return Image.open(io.BytesIO(answer.read())).convert("RGBA"), answer.headers.get("X-Toond-Passes", "")


def main():
    before_url, after_url = sys.argv[1], sys.argv[2]
    models = sys.argv[3] if len(sys.argv) > 3 else os.path.join(os.path.dirname(__file__), "..", "..", "..",
                                                                 "shared", "models")
    out = sys.argv[4] if len(sys.argv) > 4 else "docs/images/creases_before_after.png"
    folder = os.path.join(models, "windmill")
    crop_w, crop_h = (CROP[2] - CROP[0]) * ZOOM, (CROP[3] - CROP[1]) * ZOOM
    column = max(SIZE, crop_w)
    sheet = Image.new("RGBA", (2 * column, LABEL + SIZE + crop_h), (255, 255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    for i, url in enumerate((before_url, after_url)):
        image, passes = render(url, upload(url, folder))
        x = i * column
        draw.text((x + 6, 4), ("before: " if i == 0 else "after: ") + passes, fill=(0, 0, 0, 255))
        sheet.paste(image, (x, LABEL))
        draw.rectangle([x + CROP[0], LABEL + CROP[1], x + CROP[2], LABEL + CROP[3]], outline=(220, 40, 40, 255))
        part = image.crop(CROP).resize((crop_w, crop_h), Image.NEAREST)
        sheet.paste(part, (x + (column - crop_w) // 2, LABEL + SIZE))
    sheet.convert("RGB").save(out, optimize=True)


if __name__ == "__main__":
    sys.exit(main())
