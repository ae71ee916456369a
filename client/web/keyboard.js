// The reference viewers' keys. Keys typed into a text or number box, or a
// select, are the user's and never trigger a shortcut.

// Viewer modes 1–5, in the order the reference viewers numbered them.
export const MODE_PRESETS = ['lines_only', 'toon_contours', 'bw_comic', 'highlight_color', 'highlight_toon'];

// Light moves: key → [axis, sign].
const LIGHT_KEYS = { j: [0, -1], l: [0, 1], u: [1, -1], o: [1, 1], i: [2, -1], k: [2, 1] };

function typingInto(target) {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable || target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement) return true;
  if (target instanceof HTMLInputElement) {
    return !['range', 'checkbox', 'color', 'button', 'file', 'radio'].includes(target.type);
  }
  return false;
}

// actions: preset(name), zoom(factor), strafe(dx), moveLight(axis, sign),
// resetView(), togglePanel(), toggleHelp().
export function installKeyboard(actions) {
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || typingInto(e.target)) return;
    const key = e.key;
    let handled = true;
    if (key >= '1' && key <= '5') actions.preset(MODE_PRESETS[Number(key) - 1]);
    else if (key === 'w') actions.zoom(1.15);
    else if (key === 's') actions.zoom(1 / 1.15);
    else if (key === 'a') actions.strafe(-1);
    else if (key === 'd') actions.strafe(1);
    else if (key in LIGHT_KEYS) actions.moveLight(...LIGHT_KEYS[key]);
    else if (key === 'r') actions.resetView();
    else if (key === 'g') actions.togglePanel();
    else if (key === '?') actions.toggleHelp();
    else handled = false;
    if (handled) e.preventDefault();
  });
}
