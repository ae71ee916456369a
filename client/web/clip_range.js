// A clip's range as the page shows it: in frames where the clip has a
// frame rate (B3D, FBX, COLLADA and the other formats that key by frame;
// the model's description lists `frame_rate`), in seconds where it has none
// (glTF). The request always carries seconds on the file's time base,
// `range: [start, end]`; frame f is at f / frame_rate seconds.

// 'frames' or 's': the unit a clip's range is shown and typed in.
export function rangeUnit(clip) {
  return clip?.frame_rate > 0 ? 'frames' : 's';
}

// Seconds as shown: frames (to a thousandth, so a range typed in whole
// frames reads back as typed), or seconds to a thousandth.
export function shownOf(seconds, clip) {
  const value = clip?.frame_rate > 0 ? seconds * clip.frame_rate : seconds;
  return String(Math.round(value * 1000) / 1000);
}

// A shown value (frames or seconds) in seconds; NaN when it is not a number.
export function secondsOf(text, clip) {
  const value = String(text).trim() === '' ? NaN : Number(text);
  return clip?.frame_rate > 0 ? value / clip.frame_rate : value;
}

// The range two boxes give: undefined when both are empty (the whole clip);
// an empty box is that end of the clip. Not checked against the clip: the
// daemon names a range it cannot play (422 at its field).
export function rangeOf(fromText, toText, clip) {
  const from = String(fromText).trim();
  const to = String(toText).trim();
  if (from === '' && to === '') return undefined;
  const start = from === '' ? 0 : secondsOf(from, clip);
  const end = to === '' ? clip?.duration ?? NaN : secondsOf(to, clip);
  return Number.isFinite(start) && Number.isFinite(end) ? [start, end] : null;
}

function element(tag, attrs) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (key === 'text') node.textContent = value;
    else node.setAttribute(key, String(value));
  }
  return node;
}

// Two number boxes, "from" and "to", and the unit they count in, for the
// range `range` (seconds, or undefined) of `clip`. `onRange(range)` gets
// the new range (undefined: the whole clip) when a box is changed to a
// number or emptied; `show(range)` puts a range in the boxes, leaving the
// one being typed in alone. `label` names the boxes for assistive
// technology; `pointer` is the range's JSON pointer.
export function rangeBoxes({ clip, range, label, pointer, onRange }) {
  const unit = rangeUnit(clip);
  const box = (end, index) => element('input', {
    type: 'number', min: 0, step: unit === 'frames' ? 1 : 'any', class: `range-${end}`,
    placeholder: end === 'from' ? '0' : (clip ? shownOf(clip.duration, clip) : ''),
    'aria-label': `${label} ${end} (${unit})`, 'data-path': `${pointer}/${index}`,
  });
  const from = box('from', 0);
  const to = box('to', 1);
  // Boxes that already say `shown` (an empty "to" says the clip's end) are
  // left as they are: the range they just sent comes back to them.
  const show = (shown) => {
    const said = rangeOf(from.value, to.value, clip);
    const same = said === undefined || shown === undefined ? said === shown
      : said !== null && Math.abs(said[0] - shown[0]) < 1e-9 && Math.abs(said[1] - shown[1]) < 1e-9;
    if (same) return;
    [from, to].forEach((input, index) => {
      if (input !== document.activeElement) input.value = shown ? shownOf(shown[index], clip) : '';
    });
  };
  show(range);
  const changed = () => {
    const next = rangeOf(from.value, to.value, clip);
    if (next !== null) onRange(next);
  };
  from.addEventListener('change', changed);
  to.addEventListener('change', changed);
  const nodes = [element('span', { text: 'from' }), from, element('span', { text: 'to' }), to,
    element('span', { class: 'range-unit', text: unit })];
  return { nodes, show };
}
