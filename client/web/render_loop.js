// Keeps at most one render request in flight. Asking again while one runs
// only replaces what runs next (the latest state wins); an answer that is no
// longer what the page shows is dropped. Quick renders (while something is
// dragged) are small and cheap; the full one follows on release.

// Server-Timing: "queue;dur=0.1, shadow;dur=1.2, main;dur=8.0, png;dur=3.1".
export function parseServerTiming(header) {
  const passes = [];
  for (const entry of (header || '').split(',')) {
    const [name, ...attrs] = entry.trim().split(';');
    if (!name) continue;
    const dur = attrs.map((a) => a.trim()).find((a) => a.startsWith('dur='));
    passes.push({ name, ms: dur ? Number(dur.slice(4)) : 0 });
  }
  return passes;
}

export class ApiError extends Error {
  constructor(status, body) {
    const e = body?.error ?? {};
    super(e.message || `HTTP ${status}`);
    this.status = status;
    this.code = e.code;
    this.path = e.path;
  }
}

// A network failure or a daemon that is gone (as opposed to a refused request).
export class LostServer extends Error {}

// The error a failed answer stands for: a busy daemon (503) is a lost
// server to wait for (Retry-After), anything else an ApiError with the
// daemon's JSON error.
export async function answerFailure(res) {
  if (res.status === 503) {
    const busy = new LostServer('the daemon is busy (503)');
    busy.retryAfter = Number(res.headers.get('Retry-After')) || 1;
    return busy;
  }
  return new ApiError(res.status, await res.json().catch(() => null));
}

export class RenderLoop {
  // bodyFor(kind) → the JSON body for 'quick' or 'full' from the current state.
  // onImage({blob, kind, ms, timing, passes}), onError(error), onIdle().
  constructor({ bodyFor, onImage, onError }) {
    this.bodyFor = bodyFor;
    this.onImage = onImage;
    this.onError = onError;
    this.inFlight = null;
    this.next = null;
    this.issued = 0;
    this.shown = 0;
    this.lastFullBody = null;
  }

  request(kind) {
    this.next = { kind, body: JSON.stringify(this.bodyFor(kind)) };
    this.pump();
  }

  get busy() {
    return this.inFlight !== null;
  }

  async pump() {
    if (this.inFlight || !this.next) return;
    const job = this.next;
    this.next = null;
    job.seq = ++this.issued;
    this.inFlight = job;
    const started = performance.now();
    let result = null;
    let failure = null;
    try {
      const res = await fetch('/render', {
        method: 'POST', headers: { 'Content-Type': 'application/json' }, body: job.body,
      });
      if (!res.ok) {
        failure = await answerFailure(res);
      } else {
        const timing = parseServerTiming(res.headers.get('Server-Timing'));
        result = {
          blob: await res.blob(), kind: job.kind, body: job.body,
          ms: performance.now() - started, timing,
          passes: res.headers.get('X-Toond-Passes') || '',
        };
      }
    } catch (e) {
      failure = new LostServer(e.message);
    }
    this.inFlight = null;
    // A newer state waits: a full-quality answer for an older state is stale;
    // a quick one is still the closest picture of what is being dragged.
    const stale = this.next !== null && job.kind === 'full';
    if (failure) {
      if (!stale) this.onError(failure, job);
    } else if (!stale && job.seq > this.shown) {
      this.shown = job.seq;
      if (job.kind === 'full') this.lastFullBody = job.body;
      this.onImage(result);
    }
    this.pump();
  }
}
