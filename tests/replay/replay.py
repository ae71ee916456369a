#!/usr/bin/python3
"""The same requests to a running toond, their answers written down: status,
the headers that do not carry times, and a digest of every body. Two
builds' records compared line by line say whether a change that should not
change behaviour changed any answer (a refactoring's before and after).

    toond --listen 127.0.0.1:8931 --data-dir /tmp/replay-a --result-cache-mb 0 &
    tests/replay/replay.py http://127.0.0.1:8931 --shared ../shared/models -o before.jsonl
    ... the other build ...
    tests/replay/replay.py http://127.0.0.1:8932 --shared ../shared/models -o after.jsonl
    diff before.jsonl after.jsonl    # or: replay.py --compare before.jsonl after.jsonl

The models are uploaded first (their ids are content addresses, the same
for both builds); each request of requests.json then names its model by
the folder it came from ("@spot"), which is replaced by the id."""
import argparse
import hashlib
import http.client
import json
import os
import sys
import urllib.parse
import uuid

HERE = os.path.dirname(os.path.abspath(__file__))
# Headers that say how long something took or when: they differ between
# any two runs of the same build.
TIMED = {"date", "server-timing", "keep-alive", "connection"}


def connect(url):
    parts = urllib.parse.urlsplit(url)
    return http.client.HTTPConnection(parts.hostname, parts.port or 80, timeout=600)


def multipart(files):
    boundary = uuid.uuid4().hex
    body = b""
    for name, data in files:
        body += (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
                 "Content-Type: application/octet-stream\r\n\r\n").encode() + data + b"\r\n"
    body += f"--{boundary}--\r\n".encode()
    return body, f"multipart/form-data; boundary={boundary}"


def bundle_files(folder, names):
    files = []
    for name in names:
        with open(os.path.join(folder, name), "rb") as f:
            files.append((name, f.read()))
    return files


def upload(url, files):
    body, kind = multipart(files)
    conn = connect(url)
    conn.request("POST", "/models", body, {"Content-Type": kind})
    answer = conn.getresponse()
    reply = answer.read()
    if answer.status not in (200, 201):
        sys.exit(f"upload of {[n for n, _ in files]} answered {answer.status}: {reply[:300]!r}")
    return json.loads(reply)["id"]


def with_ids(value, ids):
    if isinstance(value, str) and "@" in value:
        for name, model_id in ids.items():
            value = value.replace("@" + name, model_id)
        return value
    if isinstance(value, list):
        return [with_ids(v, ids) for v in value]
    if isinstance(value, dict):
        return {k: with_ids(v, ids) for k, v in value.items()}
    return value


def answer_record(name, answer, body):
    headers = sorted((k.lower(), v) for k, v in answer.getheaders() if k.lower() not in TIMED)
    return {"name": name, "status": answer.status, "headers": headers,
            "bytes": len(body), "sha256": hashlib.sha256(body).hexdigest()}


def send(url, request, ids):
    conn = connect(url)
    path = with_ids(request.get("path", "/render"), ids)
    method = request.get("method", "POST")
    body = json.dumps(with_ids(request.get("body", {}), ids)).encode() if method == "POST" else None
    conn.request(method, path, body, {"Content-Type": "application/json"} if body else {})
    answer = conn.getresponse()
    return answer_record(request["name"], answer, answer.read())


def compare(a_path, b_path):
    with open(a_path) as a, open(b_path) as b:
        before = [json.loads(line) for line in a]
        after = [json.loads(line) for line in b]
    differ = [(x["name"], x, y) for x, y in zip(before, after) if x != y]
    for name, x, y in differ:
        print(f"{name}: differs\n  before {json.dumps(x)}\n  after  {json.dumps(y)}")
    if len(before) != len(after):
        print(f"{len(before)} answers before, {len(after)} after")
    print(f"replay: {len(before)} answers compared, {len(differ)} differ")
    return 1 if differ or len(before) != len(after) else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("url", nargs="?")
    parser.add_argument("--shared", default=os.path.join(HERE, "..", "..", "..", "shared", "models"))
    parser.add_argument("--requests", default=os.path.join(HERE, "requests.json"))
    parser.add_argument("-o", "--output", default="-")
    parser.add_argument("--compare", nargs=2, metavar=("BEFORE", "AFTER"))
    args = parser.parse_args()
    if args.compare:
        return compare(*args.compare)
    if not args.url:
        parser.error("a daemon URL, or --compare BEFORE AFTER")
    with open(args.requests) as f:
        plan = json.load(f)
    repo = os.path.join(HERE, "..", "..")
    ids = {}
    for name, model in plan["models"].items():
        root = os.path.join(args.shared, "..") if model["folder"].startswith("models/") else repo
        ids[name] = upload(args.url, bundle_files(os.path.join(root, model["folder"]), model["files"]))
    out = sys.stdout if args.output == "-" else open(args.output, "w")
    for request in plan["requests"]:
        out.write(json.dumps(send(args.url, request, ids), sort_keys=True) + "\n")
    if out is not sys.stdout:
        out.close()
    print(f"replay: {len(plan['requests'])} requests", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
