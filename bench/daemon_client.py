"""A toond client for the benchmark scripts: uploads, timed renders, and
the Server-Timing entries an answer carries."""
import http.client
import json
import time
import urllib.parse
import uuid


def multipart(files):
    """(name, bytes or text) pairs as one multipart/form-data body and its type."""
    boundary = uuid.uuid4().hex
    parts = []
    for name, data in files:
        if isinstance(data, str):
            data = data.encode()
        parts.append(f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"{name}\"\r\n"
                     f"Content-Type: application/octet-stream\r\n\r\n".encode() + data + b"\r\n")
    return b"".join(parts) + f"--{boundary}--\r\n".encode(), f"multipart/form-data; boundary={boundary}"


class Client:
    """One kept-alive connection to a daemon."""

    def __init__(self, url, timeout=120):
        u = urllib.parse.urlparse(url)
        self.conn = http.client.HTTPConnection(u.hostname, u.port or 80, timeout=timeout)

    def upload(self, files):
        body, ctype = multipart(files)
        self.conn.request("POST", "/models", body=body, headers={"Content-Type": ctype})
        res = self.conn.getresponse()
        data = res.read()
        if res.status not in (200, 201):
            raise SystemExit(f"upload answered {res.status}: {data[:300]!r}")
        return json.loads(data)

    def render(self, params):
        """(status, seconds, headers, body) of POST /render with `params`."""
        started = time.perf_counter()
        self.conn.request("POST", "/render", body=json.dumps(params), headers={"Content-Type": "application/json"})
        res = self.conn.getresponse()
        data = res.read()
        return res.status, time.perf_counter() - started, dict(res.getheaders()), data


def timing(headers, name):
    """The milliseconds Server-Timing gives `name`, or None."""
    for entry in headers.get("Server-Timing", "").split(","):
        fields = entry.strip().split(";")
        if fields[0] == name:
            for f in fields[1:]:
                if f.startswith("dur="):
                    return float(f[4:])
    return None
