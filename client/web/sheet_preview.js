// The sprite-sheet preview. A sheet costs one render per frame, so it never
// rides the live slider loop: it is asked for once the state has rested for
// a moment (and the single image is up to date), one request at a time, and
// only when its body changed since the last sheet shown.
import { LostServer, answerFailure } from './render_loop.js';

// Long enough that a slider nudged twice in a row costs one sheet, short
// enough to feel like it follows.
export const SHEET_REST_MS = 600;

async function post(url, body, as) {
  let res;
  try {
    res = await fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body });
  } catch (e) {
    throw new LostServer(e.message);
  }
  if (!res.ok) throw await answerFailure(res);
  return as === 'json' ? res.json() : res.blob();
}

export class SheetPreview {
  // bodyFor() → the sheet request's JSON body, or null when no sheet is wanted.
  // onSheet({blob, atlas, ms}), onError(error), onBusy(busy).
  constructor({ bodyFor, onSheet, onError, onBusy, restMs = SHEET_REST_MS }) {
    this.bodyFor = bodyFor;
    this.onSheet = onSheet;
    this.onError = onError;
    this.onBusy = onBusy ?? (() => {});
    this.restMs = restMs;
    this.timer = null;
    this.running = false;
    this.again = false;
    this.shownBody = null;
  }

  schedule(delay = this.restMs) {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.run(), delay);
  }

  cancel() {
    clearTimeout(this.timer);
    this.timer = null;
    this.shownBody = null;
  }

  async run() {
    this.timer = null;
    if (this.running) {
      this.again = true;
      return;
    }
    const params = this.bodyFor();
    if (!params) return;
    const body = JSON.stringify(params);
    if (body === this.shownBody) return;
    this.running = true;
    this.onBusy(true);
    const started = performance.now();
    try {
      // The atlas alone is cheap (no render; a packed sheet's is drawn,
      // since its trims are the pixels'), and asking for it with the very
      // same body keeps its tiles and the image in step.
      const [blob, atlas] = await Promise.all([post('/render', body), post('/render?atlas=json', body, 'json')]);
      // Dropped if the sheet was switched off or changed meanwhile.
      const now = this.bodyFor();
      if (now && JSON.stringify(now) === body) {
        this.shownBody = body;
        this.onSheet({ blob, atlas, ms: performance.now() - started });
      }
    } catch (e) {
      this.onError(e);
    } finally {
      this.running = false;
      this.onBusy(false);
    }
    if (this.again) {
      this.again = false;
      this.run();
    }
  }
}
