// The page's state is the sparse JSON the user asked for (what a render
// request sends); what a control shows is that over the preset over the
// schema's defaults. Pure functions, no DOM.

export function clone(value) {
  return value === undefined ? undefined : JSON.parse(JSON.stringify(value));
}

export function isPlainObject(value) {
  return value !== null && typeof value === 'object' && !Array.isArray(value);
}

// Objects merge key by key; anything else (arrays included) replaces, as
// the server applies explicit fields over a preset.
export function deepMerge(base, over) {
  if (!isPlainObject(base) || !isPlainObject(over)) return clone(over);
  const out = clone(base);
  for (const [key, value] of Object.entries(over)) {
    out[key] = key in out ? deepMerge(out[key], value) : clone(value);
  }
  return out;
}

// A field's default where it holds for every request; undefined where the
// schema has none, or where it depends on other fields (x-default-when: a
// light's space is view in a sheet, model otherwise), which the daemon
// decides.
export function fixedDefault(schema) {
  return schema['x-default-when'] ? undefined : schema.default;
}

// The defaults the schema declares, filled down into objects, so that every
// control has a value to show even where a block's own default is {}.
export function schemaDefaults(schema) {
  if (schema.type === 'object' && schema.properties) {
    const out = isPlainObject(schema.default) ? clone(schema.default) : {};
    for (const [key, sub] of Object.entries(schema.properties)) {
      const value = schemaDefaults(sub);
      if (value !== undefined) out[key] = key in out ? deepMerge(value, out[key]) : value;
    }
    return out;
  }
  if (schema.type === 'array' && Array.isArray(schema.default) && isPlainObject(schema.items)
      && schema.items.type === 'object') {
    // Items of an array default ([{"type":"directional"}]) get their own defaults too.
    const itemDefaults = schemaDefaults(schema.items);
    return schema.default.map((item) => deepMerge(itemDefaults, item));
  }
  return clone(fixedDefault(schema));
}

export function pointerParts(pointer) {
  if (pointer === '' || pointer === '/') return [];
  return pointer.split('/').slice(1).map((p) => p.replace(/~1/g, '/').replace(/~0/g, '~'));
}

export function getPointer(root, pointer) {
  let node = root;
  for (const part of pointerParts(pointer)) {
    if (node === null || typeof node !== 'object' || !(part in node)) return undefined;
    node = node[part];
  }
  return node;
}

// Sets `value` at `pointer` in the sparse `params`. Where the path enters
// an array the request does not hold yet (lights, a colour, a direction),
// the array shown on screen is copied in first, because the server replaces
// arrays whole: changing light 0's intensity must not drop its direction.
export function setPointer(params, effective, pointer, value) {
  const parts = pointerParts(pointer);
  let node = params;
  for (let i = 0; i < parts.length - 1; i++) {
    const part = parts[i];
    if (node[part] === undefined || node[part] === null || typeof node[part] !== 'object') {
      const shown = getPointer(effective, '/' + parts.slice(0, i + 1).join('/'));
      node[part] = Array.isArray(shown) ? clone(shown) : {};
    }
    node = node[part];
  }
  const last = parts[parts.length - 1];
  if (value === undefined) {
    if (Array.isArray(node)) node.splice(Number(last), 1);
    else delete node[last];
  } else {
    node[last] = value;
  }
  pruneEmpty(params, true);
}

// Blocks whose presence is itself a request, even with nothing in them:
// `"sheet": {}` asks for the default sprite sheet.
const MEANS_SOMETHING_EMPTY = new Set(['sheet']);

// Empty objects left after removing overrides say nothing; drop them so the
// URL and the copied JSON stay short.
function pruneEmpty(node, top = false) {
  for (const [key, value] of Object.entries(node)) {
    if (isPlainObject(value)) {
      pruneEmpty(value);
      if (Object.keys(value).length === 0 && !(top && MEANS_SOMETHING_EMPTY.has(key))) delete node[key];
    }
  }
}

// What the controls show.
export function effectiveParams(defaults, presets, params) {
  const preset = params.preset && presets[params.preset] ? presets[params.preset].params : {};
  return deepMerge(deepMerge(defaults, preset), params);
}

// Choosing a look keeps the view (model, camera, image size, the layer
// shown, the sprite sheet) and drops the other overrides, so the preset is
// seen as it was designed.
export const VIEW_KEYS = ['model', 'camera', 'width', 'height', 'output', 'sheet'];

export function withPreset(params, preset) {
  const out = {};
  for (const key of VIEW_KEYS) if (key in params) out[key] = clone(params[key]);
  if (preset) out.preset = preset;
  return out;
}

// The whole state lives in the URL's fragment, so a link reproduces the view.
export function paramsToHash(params) {
  return Object.keys(params).length ? '#' + encodeURIComponent(JSON.stringify(params)) : '';
}

export function paramsFromHash(hash) {
  if (!hash || hash.length < 2) return {};
  try {
    const value = JSON.parse(decodeURIComponent(hash.slice(1)));
    return isPlainObject(value) ? value : {};
  } catch {
    return {};
  }
}
