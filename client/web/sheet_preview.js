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

// The JSON of a PNG's tEXt chunk `toond:atlas` (the sheet's atlas rides
// there): chunks are length, type, data, CRC after the 8-byte signature.
export function atlasInPng(buffer) {
  const view = new DataView(buffer);
  const bytes = new Uint8Array(buffer);
  const key = new TextEncoder().encode('toond:atlas\0');
  for (let at = 8; at + 12 <= bytes.length;) {
    const length = view.getUint32(at);
    const type = String.fromCharCode(...bytes.subarray(at + 4, at + 8));
    const data = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'tEXt' && key.every((b, i) => data[i] === b)) {
      return JSON.parse(new TextDecoder().decode(data.subarray(key.length)));
    }
    if (type === 'IEND') break;
    at += 12 + length;
  }
  throw new Error('the sheet came without its atlas (no tEXt chunk toond:atlas)');
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
      // The atlas alone is cheap (no render), and asking for it with the
      // very same body keeps its tiles and the image in step. A packed
      // sheet's atlas needs the pixels (its trims), so it is read from the
      // PNG's own tEXt chunk rather than drawn a second time.
      const [blob, atlas] = params.sheet?.pack
        ? await post('/render', body).then(async (b) => [b, atlasInPng(await b.arrayBuffer())])
        : await Promise.all([post('/render', body), post('/render?atlas=json', body, 'json')]);
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
