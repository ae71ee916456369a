// The control for a list of the model's clips (the schema's
// x-control "clips": sheet.animation): a row per clip with a choice of the
// model's clips, its frame count (or frames per second, when the request
// gives fps), the part of the clip it plays (from / to, in frames where the
// clip has a frame rate, else seconds; empty: the whole clip), whether it
// plays once (loop false: its last pose drawn) and a remove button, then an
// add button. One clip is sent as one entry, several as a list, none as
// nothing. Hidden while the model has no clips.
import { rangeBoxes } from './clip_range.js';

// Each entry of the value as a list (the wire takes an entry or a list).
function entriesOf(value) {
  if (Array.isArray(value)) return value;
  return value && typeof value === 'object' ? [value] : [];
}

function valueOf(entries) {
  if (entries.length === 0) return undefined;
  return entries.length === 1 ? entries[0] : entries;
}

// The frame count's bounds in the schema's entry (the object form).
function entrySchemaOf(schema) {
  return (schema.oneOf ?? []).find((s) => s.type === 'object') ?? { properties: {} };
}

// `make(tag, attrs, ...children)` builds an element (controls.js's el);
// `field(pointer, schema, ...children)` wraps a row with its error slot;
// `send(pointer, value, final)` changes the request; `clips()` lists the
// model's clips ({name, duration, frame_rate}). Returns the element appended to `parent`
// and an updater for the panel's list.
export function buildClipList(parent, name, schema, pointer, { make, send, clips }) {
  const entrySchema = entrySchemaOf(schema);
  const framesSchema = entrySchema.properties?.frames ?? {};
  const maxItems = (schema.oneOf ?? []).find((s) => s.type === 'array')?.maxItems ?? 1;
  const box = make('fieldset', { class: 'sub clips', 'data-path': pointer, title: schema.description },
    make('legend', { text: String(name).replace(/_/g, ' ') }));
  const rows = make('div', { class: 'clip-rows' });
  const add = make('button', { type: 'button', class: 'add', text: 'Add clip', 'data-add': pointer });
  box.append(rows, add, make('p', { class: 'field-error', role: 'alert' }));
  parent.append(box);

  let entries = [];
  let shown = null;  // what the rows were built from
  const commit = (next) => send(pointer, valueOf(next), true);

  add.addEventListener('click', () => {
    const names = clips().map((c) => c.name);
    const unused = names.find((n) => !entries.some((e) => e.clip === n)) ?? names[0];
    if (unused !== undefined) commit([...entries, { clip: unused, frames: 8 }]);
  });

  const buildRow = (entry, i) => {
    const at = `${pointer}${entries.length > 1 ? '/' + i : ''}`;
    const select = make('select', { 'aria-label': `clip ${i + 1}`, 'data-path': `${at}/clip` });
    const names = clips().map((c) => c.name);
    // A clip given by index or by a name the model lacks still shows.
    const current = typeof entry.clip === 'number' ? names[entry.clip] ?? String(entry.clip) : entry.clip;
    for (const clip of clips()) select.append(new Option(`${clip.name} (${clip.duration.toFixed(2)} s)`, clip.name));
    if (current !== undefined && !names.includes(current)) select.append(new Option(current, current));
    select.value = current ?? '';
    select.addEventListener('change', () => {
      commit(entries.map((e, k) => (k === i ? { ...e, clip: select.value } : e)));
    });
    const byFps = entry.fps !== undefined;
    const count = make('input', {
      type: 'number', min: byFps ? 0.1 : framesSchema.minimum, max: byFps ? 120 : framesSchema.maximum,
      step: byFps ? 'any' : 1, 'aria-label': `${byFps ? 'fps' : 'frames'} of clip ${i + 1}`,
      'data-path': `${at}/${byFps ? 'fps' : 'frames'}`,
    });
    count.value = String(byFps ? entry.fps : entry.frames ?? 8);
    count.addEventListener('change', () => {
      const number = Number(count.value);
      if (count.value.trim() === '' || !Number.isFinite(number)) return;
      const key = byFps ? 'fps' : 'frames';
      commit(entries.map((e, k) => (k === i ? { ...e, [key]: number } : e)));
    });
    const clip = clips().find((c) => c.name === current);
    const range = rangeBoxes({
      clip, range: entry.range, label: `range of clip ${i + 1}`, pointer: `${at}/range`,
      onRange: (next) => commit(entries.map((e, k) => {
        if (k !== i) return e;
        const { range: _, ...rest } = e;
        return next ? { ...rest, range: next } : rest;
      })),
    });
    const once = make('input', { type: 'checkbox', class: 'once', 'aria-label': `clip ${i + 1} plays once`,
      'data-path': `${at}/loop` });
    once.checked = entry.loop === false;
    once.addEventListener('change', () => commit(entries.map((e, k) => {
      if (k !== i) return e;
      const { loop: _, ...rest } = e;
      return once.checked ? { ...rest, loop: false } : rest;
    })));
    const onceLabel = make('label', { class: 'once', title: 'A one-shot (an attack, a death): frames reach its last pose, and its tags play once' },
      once, 'once');
    const remove = make('button', { type: 'button', class: 'remove', text: `Remove clip ${i + 1}` });
    remove.addEventListener('click', () => commit(entries.filter((_, k) => k !== i)));
    return make('div', { class: 'clip-row', 'data-path': at }, select,
      make('label', { text: byFps ? 'fps' : 'frames' }), count, ...range.nodes, onceLabel, remove);
  };

  const update = (effective) => {
    let value = effective;
    for (const key of pointer.split('/').slice(1)) value = value?.[key];
    entries = entriesOf(value);
    const names = clips().map((c) => c.name);
    box.hidden = names.length === 0;
    add.disabled = names.length === 0 || entries.length >= maxItems;
    const key = JSON.stringify([entries, names]);
    // Rows are rebuilt only when what they show changed; the control that
    // had the focus gets it back where it still exists.
    if (key === shown) return;
    shown = key;
    const focused = rows.contains(document.activeElement) ? document.activeElement.dataset.path : null;
    rows.replaceChildren(...entries.map(buildRow));
    if (focused) [...rows.querySelectorAll('[data-path]')].find((n) => n.dataset.path === focused)?.focus();
  };
  return { node: box, update };
}
