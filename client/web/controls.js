// Builds the control panel from the render-parameter schema (GET /schema):
// a group per block, a slider and number box per number, a colour picker per
// colour, a toggle per boolean, a select per enum. Nothing here names a
// parameter, so a parameter added to proto/ appears with no page change.
// A control whose field the render would ignore (the schema's
// x-applies-when) is hidden until it matters again.
import { applies } from './applies.js';
import { buildClipList } from './clip_list_field.js';
import { fixedDefault, getPointer, isPlainObject } from './params.js';

// Chosen elsewhere on the page: the model list, the preset menu, scenes
// (curl or the CLI only), the layer switcher, the sprite-sheet section and
// the model's material list.
const HANDLED_ELSEWHERE = new Set(['model', 'preset', 'objects', 'output', 'sheet', 'animation', 'materials']);
// Top-level scalars that belong with a block rather than with the output.
const GROUP_OF_SCALAR = { ambient: 'lights', light_combine: 'lights' };
// Ranges this wide (model units up to 1e12) make a useless slider; such a
// number gets a number box only unless the schema gives an x-slider range.
const WIDEST_SLIDER_SPAN = 1e4;
const AXIS_NAMES = ['x', 'y', 'z', 'w'];
// GET /schema comes with its keys sorted by name, so the order of the
// groups is the page's: the reference viewers' order, then any new block,
// then the output settings.
const GROUP_ORDER = ['camera', 'lights', 'shading', 'specular', 'rim', 'halftone', 'outline', 'contour', 'shadows',
  'floor', 'textures'];

// The fields a block's other fields depend on (x-applies-when names them:
// `enabled`, a light's `type`, the shading `mode`), when they are a toggle
// or a choice.
function switchesOf(schema) {
  const named = new Set();
  for (const sub of Object.values(schema.properties)) {
    for (const key of Object.keys(sub['x-applies-when'] ?? {})) {
      const target = schema.properties[key];
      if (target && (target.type === 'boolean' || Array.isArray(target.enum))) named.add(key);
    }
  }
  return named;
}

// Within a block `enabled` comes first, then the other switches, so what
// they show or hide follows them; the rest by name.
function orderedProperties(schema) {
  const switches = switchesOf(schema);
  const rank = (name) => (name === 'enabled' ? 0 : switches.has(name) ? 1 : 2);
  return Object.entries(schema.properties).sort(([a], [b]) => rank(a) - rank(b) || (a < b ? -1 : 1));
}

function labelText(name) {
  return String(name).replace(/_/g, ' ');
}

function fieldId(pointer) {
  return 'f' + pointer.replace(/[^A-Za-z0-9]+/g, '-');
}

// A step that gives about 200 slider positions over the range: 1, 2 or 5
// times a power of ten.
function niceStep(span) {
  const raw = span / 200;
  const power = 10 ** Math.floor(Math.log10(raw));
  for (const m of [1, 2, 5]) if (raw <= m * power) return m * power;
  return 10 * power;
}

function sliderRange(schema) {
  const hint = isPlainObject(schema['x-slider']) ? schema['x-slider'] : {};
  const min = hint.min ?? schema.minimum;
  const max = hint.max ?? schema.maximum;
  if (min === undefined || max === undefined) return null;
  if (hint.min === undefined && hint.max === undefined && max - min > WIDEST_SLIDER_SPAN) return null;
  const step = hint.step ?? schema.multipleOf ?? (schema.type === 'integer' ? 1 : niceStep(max - min));
  return { min, max, step };
}

function isColor(schema) {
  return schema['x-control'] === 'color';
}

function enumOf(schema) {
  if (Array.isArray(schema.enum)) return schema.enum;
  return null;
}

// outline.method: a name, or a list of names from the same set; sheet.layers:
// a list of names alone.
function multiEnumOf(schema) {
  if (schema.type === 'array' && Array.isArray(schema.items?.enum)) return schema.items.enum;
  if (!Array.isArray(schema.oneOf) || schema.oneOf.length !== 2) return null;
  const single = schema.oneOf.find((s) => Array.isArray(s.enum));
  const list = schema.oneOf.find((s) => s.type === 'array' && s.items && Array.isArray(s.items.enum));
  return single && list ? single.enum : null;
}

function toHex(rgb) {
  const byte = (v) => Math.round(Math.min(1, Math.max(0, Number(v) || 0)) * 255).toString(16).padStart(2, '0');
  return '#' + byte(rgb[0]) + byte(rgb[1]) + byte(rgb[2]);
}

function fromHex(hex) {
  return [1, 3, 5].map((i) => Math.round((parseInt(hex.slice(i, i + 2), 16) / 255) * 1000) / 1000);
}

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === 'class') node.className = value;
    else if (key === 'text') node.textContent = value;
    else node.setAttribute(key, value === true ? '' : value);
  }
  for (const child of children) if (child) node.append(child);
  return node;
}

export class ControlPanel {
  // handlers.change(pointer, value, final): a control moved (final: released).
  // handlers.addItem(pointer, item) / handlers.removeItem(pointer).
  // options.only: build just these top-level blocks, without their group
  // boxes (the sprite-sheet section's own controls). options.clips(): the
  // shown model's clips ({name, duration}), for an x-control "clips" field.
  constructor(root, schema, handlers, options = {}) {
    this.root = root;
    this.schema = schema;
    this.handlers = handlers;
    this.only = options.only ?? null;
    this.clips = options.clips ?? (() => []);
    this.updaters = [];
    this.shape = null;
    this.openGroups = new Set(['camera', 'lights', 'outline']);
  }

  // Redraws when the number of lights or ramp stops changed, else only
  // refreshes values (so a focused control keeps its focus while dragging).
  render(effective) {
    this.effective = effective;
    const shape = this.shapeOf(this.schema, effective, '');
    if (shape !== this.shape) {
      this.shape = shape;
      this.build(effective);
    }
    for (const update of this.updaters) update(effective);
  }

  shapeOf(schema, value, pointer) {
    if (!schema || typeof schema !== 'object') return '';
    if (schema.type === 'object' && schema.properties) {
      return Object.entries(schema.properties)
        .map(([k, s]) => this.shapeOf(s, value?.[k], pointer + '/' + k)).join('');
    }
    if (schema.type === 'array' && schema.items?.type === 'object') {
      const items = Array.isArray(value) ? value : [];
      return pointer + ':' + items.length + ';' + items.map((v, i) => this.shapeOf(schema.items, v, pointer + '/' + i)).join('');
    }
    return '';
  }

  build(effective) {
    for (const details of this.root.querySelectorAll('details[data-group]')) {
      if (details.open) this.openGroups.add(details.dataset.group);
      else this.openGroups.delete(details.dataset.group);
    }
    this.updaters = [];
    this.root.replaceChildren();
    const groups = new Map();
    const groupBody = (name) => {
      if (this.only && !groups.has(name)) {
        const body = el('div', { class: 'group-body', 'data-group': name });
        groups.set(name, { details: body, body });
      }
      if (!groups.has(name)) {
        const body = el('div', { class: 'group-body' });
        const details = el('details', { 'data-group': name, open: this.openGroups.has(name) },
          el('summary', { text: labelText(name) }), body);
        groups.set(name, { details, body });
      }
      return groups.get(name).body;
    };
    const props = this.schema.properties;
    for (const [name, sub] of Object.entries(props)) {
      if (this.only ? !this.only.includes(name) : HANDLED_ELSEWHERE.has(name)) continue;
      const pointer = '/' + name;
      if (sub.type === 'object' && sub.properties) {
        const body = groupBody(name);
        if (sub.description && !this.only) body.append(el('p', { class: 'hint', text: sub.description }));
        this.buildProperties(body, sub, pointer, effective);
        this.hideUnlessApplies(groups.get(name).details, sub, pointer);
      } else {
        this.buildField(groupBody(GROUP_OF_SCALAR[name] ?? (sub.type === 'array' && sub.items?.type === 'object' ? name : 'output')),
          name, sub, pointer, effective);
      }
    }
    // Output last: it gathers the loose top-level fields.
    const rank = (g) => (g === 'output' ? Infinity : GROUP_ORDER.includes(g) ? GROUP_ORDER.indexOf(g) : GROUP_ORDER.length);
    const ordered = [...groups.keys()].sort((a, b) => rank(a) - rank(b));
    for (const name of ordered) this.root.append(groups.get(name).details);
  }

  buildProperties(parent, schema, pointer, effective) {
    for (const [name, sub] of orderedProperties(schema)) {
      this.buildField(parent, name, sub, pointer + '/' + name, effective);
    }
  }

  // Shows `node` only while the schema's conditions for `pointer` hold.
  hideUnlessApplies(node, schema, pointer) {
    const conditions = schema['x-applies-when'];
    if (!conditions) return;
    this.updaters.push((effective) => {
      const on = applies(conditions, pointer, effective);
      node.hidden = !on;
      node.dataset.applies = on ? 'yes' : 'no';
    });
  }

  // Every builder below appends exactly one element: the one hidden when
  // the field does not apply.
  buildField(parent, name, schema, pointer, effective) {
    this.buildControl(parent, name, schema, pointer, effective);
    this.hideUnlessApplies(parent.lastElementChild, schema, pointer);
  }

  buildControl(parent, name, schema, pointer, effective) {
    const multi = multiEnumOf(schema);
    const values = enumOf(schema);
    if (schema['x-control'] === 'clips') {
      const { update } = buildClipList(parent, name, schema, pointer,
        { make: el, send: (...args) => this.handlers.change(...args), clips: this.clips });
      this.updaters.push(update);
    } else if (schema.type === 'object' && schema.properties) {
      const box = el('fieldset', { class: 'sub', 'data-path': pointer }, el('legend', { text: labelText(name) }));
      this.buildProperties(box, schema, pointer, effective);
      parent.append(box);
    } else if (schema.type === 'array' && schema.items?.type === 'object') {
      this.buildItems(parent, name, schema, pointer, effective);
    } else if (schema.type === 'array' && isColor(schema)) {
      this.colorField(parent, name, schema, pointer);
    } else if (schema.type === 'array' && ['number', 'integer'].includes(schema.items?.type)
               && schema.maxItems && schema.maxItems <= 4) {
      const box = el('fieldset', { class: 'sub vector', 'data-path': pointer }, el('legend', { text: labelText(name) }));
      // A vector with no value yet (a point light's position, which has no
      // default) starts as zeros around the component typed, so the request
      // holds a whole vector rather than one number.
      const send = (at, value, final) => {
        if (Array.isArray(getPointer(this.effective, pointer)) || value === undefined) {
          this.handlers.change(at, value, final);
        } else {
          const vector = new Array(schema.minItems ?? schema.maxItems).fill(0);
          vector[Number(at.slice(at.lastIndexOf('/') + 1))] = value;
          this.handlers.change(pointer, vector, final);
        }
      };
      for (let i = 0; i < schema.maxItems; i++) {
        this.numberField(box, AXIS_NAMES[i], { ...schema.items, 'x-slider': schema['x-slider'] }, pointer + '/' + i,
          labelText(name) + ' ' + AXIS_NAMES[i], send);
      }
      parent.append(box);
    } else if (schema.type === 'number' || schema.type === 'integer') {
      if (values) this.selectField(parent, name, schema, pointer, values);
      else this.numberField(parent, name, schema, pointer, labelText(name));
    } else if (schema.type === 'boolean') {
      this.toggleField(parent, name, schema, pointer);
    } else if (values) {
      this.selectField(parent, name, schema, pointer, values);
    } else if (multi) {
      this.multiField(parent, name, schema, pointer, multi);
    } else {
      this.jsonField(parent, name, schema, pointer);
    }
  }

  field(pointer, schema, ...children) {
    const box = el('div', { class: 'field', 'data-path': pointer, title: schema.description }, ...children,
      el('p', { class: 'field-error', role: 'alert' }));
    return box;
  }

  numberField(parent, name, schema, pointer, accessibleName, send = this.handlers.change) {
    const id = fieldId(pointer);
    const range = sliderRange(schema);
    const number = el('input', {
      type: 'number', id, step: 'any', min: schema.minimum, max: schema.maximum, inputmode: 'decimal',
    });
    const slider = range && el('input', {
      type: 'range', min: range.min, max: range.max, step: range.step, 'aria-label': accessibleName,
    });
    if (slider) {
      slider.addEventListener('input', () => {
        number.value = slider.value;
        send(pointer, Number(slider.value), false);
      });
      slider.addEventListener('change', () => send(pointer, Number(slider.value), true));
    }
    number.addEventListener('change', () => {
      const text = number.value.trim();
      // An empty box gives the parameter back to the preset or default.
      send(pointer, text === '' ? undefined : Number(text), true);
    });
    const label = el('label', { for: id, text: name });
    if (accessibleName !== name) label.setAttribute('aria-label', accessibleName);
    parent.append(this.field(pointer, schema, label, slider, number));
    this.updaters.push((effective) => {
      const value = getPointer(effective, pointer);
      const text = value === undefined ? '' : String(value);
      if (document.activeElement !== number || number.value === '') number.value = text;
      if (slider && value !== undefined && document.activeElement !== slider) slider.value = String(value);
    });
  }

  colorField(parent, name, schema, pointer) {
    const id = fieldId(pointer);
    const picker = el('input', { type: 'color', id });
    const current = (effective) => {
      const v = getPointer(effective, pointer);
      return Array.isArray(v) ? v : [0, 0, 0];
    };
    let last = null;
    const send = (final) => {
      const rgb = fromHex(picker.value);
      const value = last && last.length > 3 ? [...rgb, ...last.slice(3)] : rgb;
      this.handlers.change(pointer, value, final);
    };
    picker.addEventListener('input', () => send(false));
    picker.addEventListener('change', () => send(true));
    const children = [el('label', { for: id, text: name }), picker];
    let alpha = null;
    if ((schema.maxItems ?? 3) > 3) {
      // [r,g,b,a]: the picker has no alpha, so a number box carries it.
      alpha = el('input', { type: 'number', min: 0, max: 1, step: 'any', 'aria-label': labelText(name) + ' alpha',
        class: 'alpha', 'data-path': pointer + '/3' });
      alpha.addEventListener('change', () => {
        this.handlers.change(pointer, [...fromHex(picker.value), Number(alpha.value)], true);
      });
      children.push(alpha);
    }
    parent.append(this.field(pointer, schema, ...children));
    this.updaters.push((effective) => {
      last = current(effective);
      picker.value = toHex(last);
      if (alpha) alpha.value = last.length > 3 ? String(last[3]) : '1';
    });
  }

  toggleField(parent, name, schema, pointer) {
    const id = fieldId(pointer);
    const box = el('input', { type: 'checkbox', id });
    box.addEventListener('change', () => this.handlers.change(pointer, box.checked, true));
    parent.append(this.field(pointer, schema, box, el('label', { for: id, text: name })));
    this.updaters.push((effective) => { box.checked = Boolean(getPointer(effective, pointer)); });
  }

  selectField(parent, name, schema, pointer, values) {
    const id = fieldId(pointer);
    const select = el('select', { id });
    const numeric = schema.type === 'number' || schema.type === 'integer';
    if (fixedDefault(schema) === undefined) select.append(el('option', { value: '', text: '—' }));
    for (const v of values) select.append(el('option', { value: String(v), text: String(v) }));
    select.addEventListener('change', () => {
      const raw = select.value;
      this.handlers.change(pointer, raw === '' ? undefined : numeric ? Number(raw) : raw, true);
    });
    parent.append(this.field(pointer, schema, el('label', { for: id, text: name }), select));
    this.updaters.push((effective) => {
      const v = getPointer(effective, pointer);
      select.value = v === undefined ? '' : String(v);
    });
  }

  multiField(parent, name, schema, pointer, values) {
    const box = el('fieldset', { class: 'field multi', 'data-path': pointer, title: schema.description },
      el('legend', { text: labelText(name) }));
    const checks = values.map((v) => {
      const id = fieldId(pointer + '/' + v);
      const check = el('input', { type: 'checkbox', id, value: v });
      box.append(el('span', {}, check, el('label', { for: id, text: v })));
      return check;
    });
    box.append(el('p', { class: 'field-error', role: 'alert' }));
    const listOnly = schema.type === 'array';
    const send = () => {
      const chosen = checks.filter((c) => c.checked).map((c) => c.value);
      // A field that takes a name gets one name as a name, several as a list
      // and none left to the server to refuse; a list alone with none
      // checked goes back to absent.
      if (!listOnly) this.handlers.change(pointer, chosen.length === 1 ? chosen[0] : chosen, true);
      else this.handlers.change(pointer, chosen.length ? chosen : undefined, true);
    };
    for (const check of checks) check.addEventListener('change', send);
    parent.append(box);
    this.updaters.push((effective) => {
      const v = getPointer(effective, pointer);
      const list = Array.isArray(v) ? v : [v];
      for (const check of checks) check.checked = list.includes(check.value);
    });
  }

  // Anything the page has no widget for is edited as JSON, so it is still reachable.
  jsonField(parent, name, schema, pointer) {
    const id = fieldId(pointer);
    const input = el('input', { type: 'text', id, class: 'json', spellcheck: 'false' });
    input.addEventListener('change', () => {
      const text = input.value.trim();
      if (text === '') { this.handlers.change(pointer, undefined, true); return; }
      let value;
      try { value = JSON.parse(text); } catch { value = schema.type === 'string' ? text : undefined; }
      if (value === undefined) { this.showError(pointer, 'not JSON'); return; }
      this.handlers.change(pointer, value, true);
    });
    parent.append(this.field(pointer, schema, el('label', { for: id, text: name }), input));
    this.updaters.push((effective) => {
      if (document.activeElement === input) return;
      const v = getPointer(effective, pointer);
      input.value = v === undefined ? '' : typeof v === 'string' && schema.type === 'string' ? v : JSON.stringify(v);
    });
  }

  buildItems(parent, name, schema, pointer, effective) {
    const items = getPointer(effective, pointer);
    const list = Array.isArray(items) ? items : [];
    const box = el('div', { class: 'items', 'data-path': pointer });
    list.forEach((_, i) => {
      const itemPointer = pointer + '/' + i;
      const set = el('fieldset', { class: 'sub item', 'data-path': itemPointer },
        el('legend', { text: `${labelText(name)} ${i}` }));
      this.buildProperties(set, schema.items, itemPointer, effective);
      const remove = el('button', { type: 'button', class: 'remove', text: `Remove ${labelText(name)} ${i}` });
      remove.addEventListener('click', () => this.handlers.removeItem(itemPointer));
      set.append(remove);
      box.append(set);
    });
    const room = schema.maxItems === undefined || list.length < schema.maxItems;
    const add = el('button', { type: 'button', class: 'add', text: `Add ${labelText(name)}`, disabled: !room,
      'data-add': pointer });
    add.addEventListener('click', () => this.handlers.addItem(pointer, newItem(schema.items)));
    box.append(add);
    parent.append(box);
  }

  // Marks the control a 4xx answer's JSON pointer names (or the nearest
  // control above it) and shows the message beside it. False if none matches.
  showError(pointer, message) {
    let path = pointer;
    while (path) {
      const field = [...this.root.querySelectorAll('[data-path]')].find((f) => f.dataset.path === path);
      // A hidden control cannot show the message; the nearest shown one above it does.
      if (field && !field.closest('[hidden]')) {
        const box = field.closest('.field, fieldset') ?? field;
        box.classList.add('invalid');
        for (const input of box.querySelectorAll('input, select')) input.setAttribute('aria-invalid', 'true');
        const slot = box.querySelector(':scope > .field-error') ?? box.querySelector('.field-error');
        if (slot) slot.textContent = message;
        const details = box.closest('details');
        if (details) details.open = true;
        box.scrollIntoView({ block: 'nearest' });
        return true;
      }
      path = path.slice(0, path.lastIndexOf('/'));
    }
    return false;
  }

  clearErrors() {
    for (const box of this.root.querySelectorAll('.invalid')) {
      box.classList.remove('invalid');
      for (const input of box.querySelectorAll('[aria-invalid]')) input.removeAttribute('aria-invalid');
      for (const slot of box.querySelectorAll('.field-error')) slot.textContent = '';
    }
  }
}

// A new list entry: each property's default, required ones without a
// default at the middle of their range (a ramp stop's `at`).
function newItem(schema) {
  const item = {};
  for (const [key, sub] of Object.entries(schema.properties ?? {})) {
    if (fixedDefault(sub) !== undefined) item[key] = fixedDefault(sub);
    else if ((schema.required ?? []).includes(key) && sub.minimum !== undefined && sub.maximum !== undefined) {
      item[key] = (sub.minimum + sub.maximum) / 2;
    }
  }
  return item;
}
