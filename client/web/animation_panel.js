// The animation section: shown only for a model with clips (GET
// /models/{id} lists them), a clip selector, the part of the clip to play
// (from / to, in frames where the clip has a frame rate, else in seconds;
// empty: the whole clip), a time slider over that part and a play button
// that steps the time round it. Its state is the request's `animation`
// block (`range` in seconds), so the URL, the copied commands and the
// sprite sheet see it as any other parameter.
import { rangeBoxes, shownOf } from './clip_range.js';

// Steps of the play button per second of the clip's own time.
const PLAY_STEPS_PER_SECOND = 12;

export class AnimationPanel {
  // `root` holds #clip-select, #clip-range, #clip-time, #clip-time-label,
  // #clip-play and #clip-sheet; `hooks.get()` is the current `animation` (or undefined),
  // `hooks.set(animation, final)` replaces it (undefined: rest pose) and
  // `hooks.sheetOfClip(name)` asks for an animated sprite sheet of a clip,
  // `hooks.clipsChanged()` says the model's clips (this.clips) were replaced.
  constructor(root, hooks) {
    this.root = root;
    this.hooks = hooks;
    this.clips = [];
    this.modelId = null;
    this.infoCache = new Map();
    this.timer = null;
    this.select = root.querySelector('#clip-select');
    this.slider = root.querySelector('#clip-time');
    this.label = root.querySelector('#clip-time-label');
    this.play = root.querySelector('#clip-play');
    this.sheetButton = root.querySelector('#clip-sheet');
    this.rangeBox = root.querySelector('#clip-range');
    this.rangeBoxesOf = null;  // the clip the range boxes were built for
    this.rangeBoxes = null;
    this.select.addEventListener('change', () => this.chooseClip(this.select.value));
    this.slider.addEventListener('input', () => this.setTime(Number(this.slider.value), false));
    this.slider.addEventListener('change', () => this.setTime(Number(this.slider.value), true));
    this.play.addEventListener('click', () => (this.timer ? this.stop() : this.start()));
    this.sheetButton.addEventListener('click', () => {
      const current = this.hooks.get();
      const clip = this.clipNamed(current?.clip);
      if (clip) this.hooks.sheetOfClip(clip.name, current.range);
    });
  }

  // The model shown changed (or may have): fetch what it has, once per id.
  async showModel(id) {
    if (id === this.modelId) return;
    this.modelId = id;
    this.stop();
    let clips = [];
    if (id) {
      if (!this.infoCache.has(id)) {
        const res = await fetch(`/models/${id}`).catch(() => null);
        const info = res && res.ok ? await res.json().catch(() => null) : null;
        this.infoCache.set(id, info?.animation?.clips ?? []);
      }
      clips = this.infoCache.get(id);
    }
    if (id !== this.modelId) return;  // another model was chosen meanwhile
    this.clips = clips;
    this.hooks.clipsChanged?.();
    this.root.hidden = clips.length === 0;
    this.select.replaceChildren(new Option('rest pose', ''),
      ...clips.map((c) => new Option(`${c.name} (${c.duration.toFixed(2)} s)`, c.name)));
    // A clip the model does not have (a URL made for another model) goes.
    const current = this.hooks.get();
    if (current && !clips.some((c) => c.name === current.clip)) this.hooks.set(undefined, true);
    else this.sync();
  }

  // Shows the state's clip, range and time.
  sync() {
    const current = this.hooks.get();
    const clip = this.clipNamed(current?.clip);
    this.select.value = clip ? clip.name : '';
    this.slider.disabled = !clip;
    this.play.disabled = !clip;
    this.sheetButton.disabled = !clip;
    this.syncRange(clip, current?.range);
    const length = this.lengthOf(clip, current?.range);
    this.slider.max = String(clip ? length : 1);
    this.slider.step = String(clip ? Math.max(length / 200, 0.001) : 0.01);
    const time = current?.time ?? 0;
    this.slider.value = String(time);
    // Where a clip counts frames, the frame the time shows.
    const frame = clip?.frame_rate > 0 ? ` · frame ${shownOf((current?.range?.[0] ?? 0) + time, clip)}` : '';
    this.label.textContent = clip ? `${time.toFixed(3)} s${frame}` : '';
    this.play.textContent = this.timer ? 'Pause' : 'Play';
    this.play.setAttribute('aria-pressed', this.timer ? 'true' : 'false');
  }

  clipNamed(name) {
    return this.clips.find((c) => c.name === name);
  }

  // The seconds the time runs over: the range's, or the clip's.
  lengthOf(clip, range) {
    if (range) return Math.max(range[1] - range[0], 0);
    return clip ? clip.duration : 0;
  }

  // The from / to boxes: built for each clip (their unit is the clip's),
  // then given the state's range (the box being typed in keeps its text).
  syncRange(clip, range) {
    this.rangeBox.hidden = !clip;
    if (clip !== this.rangeBoxesOf) {
      this.rangeBoxesOf = clip;
      this.rangeBoxes = clip ? rangeBoxes({
        clip, range, label: 'clip range', pointer: '/animation/range',
        onRange: (next) => this.setRange(next),
      }) : null;
      this.rangeBox.replaceChildren(...(this.rangeBoxes?.nodes ?? []));
    }
    this.rangeBoxes?.show(range);
  }

  chooseClip(name) {
    this.stop();
    this.hooks.set(name ? { clip: name, time: 0 } : undefined, true);
  }

  // A new part of the clip starts at its beginning (time counts from it).
  setRange(range) {
    const current = this.hooks.get();
    if (!current) return;
    const next = { ...current, time: 0 };
    if (range) next.range = range;
    else delete next.range;
    this.hooks.set(next, true);
  }

  setTime(time, final) {
    const current = this.hooks.get();
    if (!current) return;
    this.hooks.set({ ...current, time }, final);
  }

  // Steps the time round the clip's loop (or its range's); each step asks
  // for a full render (the render loop drops steps it cannot keep up with).
  start() {
    const clip = this.clipNamed(this.hooks.get()?.clip);
    if (!clip) return;
    this.timer = setInterval(() => {
      const current = this.hooks.get();
      if (!current || !this.clipNamed(current.clip)) {
        this.stop();
        return;
      }
      const step = 1 / PLAY_STEPS_PER_SECOND;
      const length = this.lengthOf(clip, current.range);
      const next = length > 0 ? ((current.time ?? 0) + step) % length : 0;
      this.hooks.set({ ...current, time: Math.round(next * 1000) / 1000 }, true);
    }, 1000 / PLAY_STEPS_PER_SECOND);
    this.sync();
  }

  stop() {
    if (this.timer) clearInterval(this.timer);
    this.timer = null;
    this.sync();
  }
}
