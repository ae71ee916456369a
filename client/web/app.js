// The slider studio: controls from GET /schema, live renders from POST
// /render, uploads to POST /models, the whole state in the URL's fragment.
import { ControlPanel } from './controls.js';
import { curlCommand, paramsJson, toonCommand } from './commands.js';
import { installKeyboard } from './keyboard.js';
import {
  clone, effectiveParams, getPointer, paramsFromHash, paramsToHash, schemaDefaults, setPointer, withPreset,
} from './params.js';
import { ApiError, LostServer, RenderLoop, answerFailure } from './render_loop.js';
import { AnimationPanel } from './animation_panel.js';
import { MaterialList } from './material_list.js';
import { SheetPreview } from './sheet_preview.js';
import { MODEL_FILE, bundlePaths, filesFromDrop, filesFromInput, uploadBundle } from './upload.js';

const $ = (id) => document.getElementById(id);

// Quick renders while something moves: the longer side at most this many
// pixels, one sample, so llvmpipe answers within a frame or two.
const QUICK_SIDE = 256;
// Orbit speed in degrees per dragged pixel.
const YAW_PER_PX = 0.5;
const PITCH_PER_PX = 0.4;
// A strafe step, in the model's bounding radii at zoom 1.
const STRAFE_STEP = 0.1;
// A light step: a fraction of a directional light's direction, or of a point
// light's distance from the origin (at least one model unit).
const LIGHT_STEP = 0.1;

const studio = {
  schema: null,
  presets: {},
  defaults: {},
  params: paramsFromHash(location.hash),
  panel: null,
  sheetPanel: null,
  animation: null,
  materials: null,
  loop: null,
  sheet: null,
  sheetUrl: null,
  atlasUrl: null,
  renders: 0,
  errors: 0,
  imageUrl: null,
  downloadUrl: null,
  retryTimer: null,
};

function effective() {
  return effectiveParams(studio.defaults, studio.presets, studio.params);
}

async function getJson(url) {
  let res;
  try {
    res = await fetch(url);
  } catch (e) {
    throw new LostServer(e.message);
  }
  const body = await res.json().catch(() => null);
  if (!res.ok) throw new ApiError(res.status, body);
  return body;
}

// ---- state → screen -------------------------------------------------------

function sync() {
  const shown = effective();
  studio.panel.render(shown);
  $('preset-select').value = studio.params.preset ?? '';
  ensureModelOption(studio.params.model);
  $('model-select').value = studio.params.model ?? '';
  const hash = paramsToHash(studio.params);
  history.replaceState(null, '', hash || location.pathname);
  const view = $('view');
  view.style.aspectRatio = `${shown.width} / ${shown.height}`;
  view.style.maxWidth = `${shown.width}px`;
  for (const radio of document.querySelectorAll('#layers input')) radio.checked = radio.value === shown.output;
  syncSheet(shown);
  if (studio.materials) {
    studio.materials.sync();
    studio.materials.showModel(studio.params.model ?? null);
  }
  if (studio.animation) {
    studio.animation.sync();
    studio.animation.showModel(studio.params.model ?? null);
  }
}

function change(pointer, value, final) {
  setPointer(studio.params, effective(), pointer, value);
  sync();
  studio.loop.request(final ? 'full' : 'quick');
}

function bodyFor(kind) {
  const body = clone(studio.params);
  // The live loop renders one image; the sheet section asks for the sheet.
  delete body.sheet;
  // The svg block means something to output svg alone (the SVG button's).
  if (body.output !== 'svg') delete body.svg;
  if (kind === 'quick') {
    const shown = effective();
    const scale = Math.min(1, QUICK_SIDE / Math.max(shown.width, shown.height));
    body.width = Math.max(16, Math.round(shown.width * scale));
    body.height = Math.max(16, Math.round(shown.height * scale));
    body.msaa = 1;
    body.supersample = 1;
  }
  return body;
}

function showImage({ blob, kind, ms, timing, passes }) {
  const view = $('view');
  const url = URL.createObjectURL(blob);
  if (studio.imageUrl && studio.imageUrl !== studio.downloadUrl) URL.revokeObjectURL(studio.imageUrl);
  studio.imageUrl = url;
  view.src = url;
  studio.renders += 1;
  view.dataset.renders = String(studio.renders);
  view.dataset.kind = kind;
  // For scripts (and the browser test): is this the answer to the latest state?
  view.dataset.settled = studio.loop.next ? 'no' : 'yes';
  if (kind === 'full') {
    if (studio.downloadUrl) URL.revokeObjectURL(studio.downloadUrl);
    studio.downloadUrl = url;
    const link = $('download');
    link.href = url;
    link.download = `toond-${effective().output ?? 'color'}.png`;
    link.removeAttribute('aria-disabled');
    if (studio.params.sheet && !studio.loop.next) studio.sheet.schedule();
  }
  // The server's own `total` (GPU-timed passes may overlap the thread's
  // time, so they need not add up to it); older daemons: the sum.
  const total = timing.find((t) => t.name === 'total');
  const server = total ? total.ms
    : timing.filter((t) => t.name !== 'queue').reduce((sum, t) => sum + t.ms, 0);
  const detail = timing.filter((t) => t.name !== 'total').map((t) => `${t.name} ${t.ms.toFixed(1)}`).join(', ');
  $('timing').textContent = `${kind === 'quick' ? 'preview' : 'full quality'} · ${Math.round(ms)} ms round trip, `
    + `${server.toFixed(1)} ms on the server (${detail}) · passes: ${passes || '—'}`;
  studio.panel.clearErrors();
  $('render-error').textContent = '';
}

// A failed answer shown in `slot` and at the control it names on `panel`;
// a lost or busy server waits instead. Whether it was shown.
function reportError(error, panel, slot) {
  if (error instanceof LostServer) {
    lostServer(error.retryAfter);
    return false;
  }
  panel.clearErrors();
  const where = error.path ? ` at ${error.path}` : '';
  $(slot).textContent = `${error.status} ${error.code ?? ''}${where}: ${error.message}`;
  if (error.path) panel.showError(error.path, error.message);
  return true;
}

function showRenderError(error) {
  if (!reportError(error, studio.panel, 'render-error')) return;
  studio.errors += 1;
  $('view').dataset.errors = String(studio.errors);
}

// ---- a lost server --------------------------------------------------------

function lostServer(retryAfterSeconds) {
  const banner = $('banner');
  if (studio.retryTimer) return;
  let wait = Math.max(1, retryAfterSeconds || 1);
  const attempt = async () => {
    try {
      await getJson('/healthz');
      banner.hidden = true;
      studio.retryTimer = null;
      document.body.classList.remove('offline');
      await refreshModels();
      studio.loop.request('full');
    } catch {
      wait = Math.min(wait * 2, 8);
      banner.textContent = `Lost the toond server — retrying in ${wait} s…`;
      studio.retryTimer = setTimeout(attempt, wait * 1000);
    }
  };
  banner.textContent = `Lost the toond server — retrying in ${wait} s…`;
  banner.hidden = false;
  document.body.classList.add('offline');
  studio.retryTimer = setTimeout(attempt, wait * 1000);
}

// ---- models and upload ------------------------------------------------------

function modelLabel(model) {
  const obj = (model.files ?? []).find((f) => MODEL_FILE.test(f)) ?? 'model';
  return `${obj} · ${model.triangles} triangles · ${model.id.slice(0, 8)}`;
}

function ensureModelOption(id) {
  if (!id) return;
  const select = $('model-select');
  if (![...select.options].some((o) => o.value === id)) {
    select.append(new Option(id.slice(0, 12), id));
  }
}

async function refreshModels() {
  const { models } = await getJson('/models');
  const select = $('model-select');
  select.replaceChildren(new Option('demo model', ''));
  for (const model of models) select.append(new Option(modelLabel(model), model.id));
  ensureModelOption(studio.params.model);
  select.value = studio.params.model ?? '';
}

async function upload(files) {
  const status = $('upload-status');
  const progress = $('upload-progress');
  status.classList.remove('error');
  let bundle;
  try {
    bundle = bundlePaths(files);
  } catch (e) {
    status.textContent = e.message;
    status.classList.add('error');
    return;
  }
  progress.hidden = false;
  progress.value = 0;
  status.textContent = `uploading ${bundle.length} files…`;
  try {
    const info = await uploadBundle(bundle, (fraction) => { progress.value = fraction; });
    const warnings = info.warnings?.length ? ` · warnings: ${info.warnings.join('; ')}` : '';
    status.textContent = `${modelLabel(info)}, ${info.textures} textures${warnings}`;
    await refreshModels();
    studio.params.model = info.id;
    sync();
    studio.loop.request('full');
  } catch (e) {
    status.textContent = e.path ? `${e.path}: ${e.message}` : e.message;
    status.classList.add('error');
  } finally {
    progress.hidden = true;
  }
}

function installUpload() {
  for (const id of ['file-input', 'folder-input']) {
    $(id).addEventListener('change', (e) => {
      const files = filesFromInput(e.target.files);
      e.target.value = '';
      if (files.length) upload(files);
    });
  }
  window.addEventListener('dragover', (e) => {
    e.preventDefault();
    document.body.classList.add('dragging');
  });
  window.addEventListener('dragleave', (e) => {
    if (e.relatedTarget === null) document.body.classList.remove('dragging');
  });
  window.addEventListener('drop', async (e) => {
    e.preventDefault();
    document.body.classList.remove('dragging');
    upload(await filesFromDrop(e.dataTransfer));
  });
  $('model-select').addEventListener('change', (e) => {
    if (e.target.value) studio.params.model = e.target.value;
    else delete studio.params.model;
    sync();
    studio.loop.request('full');
  });
}

// ---- camera, lights, presets ------------------------------------------------

function cameraSchema(name) {
  return studio.schema.properties.camera.properties[name];
}

function clampTo(schema, value) {
  return Math.min(schema.maximum, Math.max(schema.minimum, value));
}

function setCamera(values, final) {
  studio.params.camera = { ...(studio.params.camera ?? {}), ...values };
  sync();
  studio.loop.request(final ? 'full' : 'quick');
}

function installOrbit() {
  const viewport = $('viewport');
  let drag = null;
  viewport.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    viewport.setPointerCapture(e.pointerId);
    const cam = effective().camera;
    drag = { x: e.clientX, y: e.clientY, yaw: cam.yaw, pitch: cam.pitch, moved: false };
  });
  viewport.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x;
    const dy = e.clientY - drag.y;
    if (!drag.moved && Math.abs(dx) + Math.abs(dy) < 2) return;
    drag.moved = true;
    // Yaw wraps into the schema's range; pitch stops at the poles.
    let yaw = drag.yaw - dx * YAW_PER_PX;
    yaw = ((((yaw + 180) % 360) + 360) % 360) - 180;
    const pitch = clampTo(cameraSchema('pitch'), drag.pitch + dy * PITCH_PER_PX);
    setCamera({ yaw: Math.round(yaw * 10) / 10, pitch: Math.round(pitch * 10) / 10 }, false);
  });
  const release = () => {
    if (drag?.moved) studio.loop.request('full');
    drag = null;
  };
  viewport.addEventListener('pointerup', release);
  viewport.addEventListener('pointercancel', release);
  let wheelTimer = null;
  viewport.addEventListener('wheel', (e) => {
    e.preventDefault();
    zoomBy(Math.exp(-e.deltaY * 0.0015), false);
    clearTimeout(wheelTimer);
    wheelTimer = setTimeout(() => studio.loop.request('full'), 250);
  }, { passive: false });
}

function zoomBy(factor, final) {
  const zoom = clampTo(cameraSchema('zoom'), effective().camera.zoom * factor);
  setCamera({ zoom: Math.round(zoom * 1000) / 1000 }, final);
}

function strafe(direction) {
  const cam = effective().camera;
  const shift = [...cam.shift];
  shift[0] = Math.round((shift[0] + (direction * STRAFE_STEP) / cam.zoom) * 1000) / 1000;
  setCamera({ shift }, true);
}

function moveLight(axis, sign) {
  const lights = effective().lights;
  if (!lights?.length) return;
  const light = lights[0];
  const key = light.type === 'point' ? 'position' : 'direction';
  const vector = [...(light[key] ?? [0, 0, 0])];
  const reach = light.type === 'point' ? Math.max(1, Math.hypot(...vector)) : 1;
  vector[axis] = Math.round((vector[axis] + sign * LIGHT_STEP * reach) * 1000) / 1000;
  change(`/lights/0/${key}`, vector, true);
}

function choosePreset(name) {
  if (name && !(name in studio.presets)) return;
  studio.params = withPreset(studio.params, name);
  sync();
  studio.loop.request('full');
}

function resetView() {
  delete studio.params.camera;
  sync();
  studio.loop.request('full');
}

function togglePanel() {
  const hidden = document.body.classList.toggle('panel-hidden');
  $('panel-toggle').setAttribute('aria-expanded', String(!hidden));
}

function toggleHelp() {
  const help = $('help');
  if (help.open) help.close();
  else help.showModal();
}

// ---- layers ---------------------------------------------------------------------

// One button per raster value of the schema's `output` (a daemon without it
// shows none); its vector drawing, svg, is a download beside them.
function installLayers() {
  const schema = studio.schema.properties.output;
  if (!Array.isArray(schema?.enum)) return;
  const box = $('layers');
  box.title = schema.description ?? '';
  for (const value of schema.enum) {
    if (value === 'svg') continue;
    const id = `layer-${value}`;
    const radio = Object.assign(document.createElement('input'), { type: 'radio', name: 'layer', id, value });
    const label = Object.assign(document.createElement('label'), { htmlFor: id, textContent: value });
    radio.addEventListener('change', () => {
      if (radio.checked) change('/output', value === schema.default ? undefined : value, true);
    });
    box.append(radio, label);
  }
  if (schema.enum.includes('svg')) installSvgDownload(box);
  box.hidden = false;
}

// ---- the lines as vectors -------------------------------------------------------

function installSvgDownload(box) {
  const button = Object.assign(document.createElement('button'), {
    type: 'button', id: 'svg-download', textContent: 'SVG',
    title: 'Download the lines of this view as an SVG drawing (output svg): a layer per kind of line, '
      + 'for a pen plotter or a vector editor',
  });
  const hidden = Object.assign(document.createElement('input'), { type: 'checkbox', id: 'svg-hidden' });
  const label = Object.assign(document.createElement('label'), {
    htmlFor: 'svg-hidden', textContent: 'hidden lines', title: 'Add the hidden parts of the lines, dashed (svg.hidden)',
  });
  button.addEventListener('click', () => downloadSvg(button, hidden.checked));
  const tools = Object.assign(document.createElement('span'), { className: 'svg-tools' });
  tools.append(button, hidden, label);
  box.append(tools);
}

// The full-quality request of the view shown, but for its output: the
// drawing comes back as a file to save.
async function downloadSvg(button, withHidden) {
  const body = bodyFor('full');
  body.output = 'svg';
  if (withHidden) body.svg = { hidden: true };
  button.disabled = true;
  try {
    let res;
    try {
      res = await fetch('/render', { method: 'POST', headers: { 'Content-Type': 'application/json' },
        body: JSON.stringify(body) });
    } catch (e) {
      throw new LostServer(e.message);
    }
    if (!res.ok) throw await answerFailure(res);
    const url = URL.createObjectURL(await res.blob());
    const link = Object.assign(document.createElement('a'), { href: url, download: 'toond-lines.svg' });
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
    button.dataset.downloads = String(Number(button.dataset.downloads || 0) + 1);
  } catch (error) {
    showRenderError(error);
  } finally {
    button.disabled = false;
  }
}

// ---- sprite sheet ---------------------------------------------------------------

function sheetOn() {
  return studio.params.sheet !== undefined;
}

function syncSheet(shown) {
  if (!studio.sheetPanel) return;
  $('sheet-toggle').checked = sheetOn();
  $('sheet-controls').hidden = !sheetOn();
  $('sheet-frame').hidden = !sheetOn() || !studio.sheetUrl;
  for (const id of ['sheet-format', 'sheet-format-label']) $(id).hidden = !sheetOn();
  if (!sheetOn()) {
    $('sheet-status').textContent = '';
    $('sheet-error').textContent = '';
    for (const id of ['sheet-download', 'atlas-download', 'file-download']) $(id).hidden = true;
  }
  studio.sheetPanel.render(shown);
}

// The sheet's files besides its PNG and atlas, asked for with the body of
// the sheet shown when their button is pressed. The Godot resource names
// the PNG by the name the sheet's download gives it, so the two saved side
// by side belong together.
const SHEET_FILES = {
  aseprite: { query: '?atlas=aseprite', name: 'toond-sheet.aseprite', label: 'Download .aseprite' },
  godot: { query: '?atlas=godot&texture=toond-sheet.png', name: 'toond-sheet.tres', label: 'Download .tres' },
};

// The download buttons the format select asks for, once a sheet is shown.
function syncSheetFormat() {
  const format = $('sheet-format').value;
  const shown = Boolean(studio.sheetUrl) && sheetOn();
  $('sheet-download').hidden = !shown || format === 'aseprite';
  $('atlas-download').hidden = !shown || format !== 'png';
  const file = $('file-download');
  file.hidden = !shown || format === 'png';
  file.textContent = SHEET_FILES[format]?.label ?? '';
}

async function downloadSheetFile() {
  const file = SHEET_FILES[$('sheet-format').value];
  const body = studio.sheet.shownBody;
  if (!file || !body) return;
  $('file-download').disabled = true;
  try {
    const res = await fetch(`/render${file.query}`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body });
    if (!res.ok) throw await answerFailure(res);
    const link = document.createElement('a');
    link.href = URL.createObjectURL(await res.blob());
    link.download = file.name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 60000);
  } catch (e) {
    showSheetError(e);
  } finally {
    $('file-download').disabled = false;
  }
}

function replaceUrl(key, url) {
  if (studio[key]) URL.revokeObjectURL(studio[key]);
  studio[key] = url;
  return url;
}

// The atlas's frames as boxes over the sheet, in percent of its size so
// they follow the image however wide it is shown.
function showTiles(atlas) {
  const size = atlas.meta?.size ?? { w: 1, h: 1 };
  const layer = $('sheet-tiles');
  layer.replaceChildren();
  const frames = Object.entries(atlas.frames ?? {});
  for (const [name, f] of frames) {
    const tile = document.createElement('div');
    tile.className = 'tile';
    tile.dataset.frame = name;
    Object.assign(tile.style, {
      left: `${(f.frame.x / size.w) * 100}%`, top: `${(f.frame.y / size.h) * 100}%`,
      width: `${(f.frame.w / size.w) * 100}%`, height: `${(f.frame.h / size.h) * 100}%`,
    });
    const label = `frame ${name} · yaw ${+f.yaw.toFixed(2)}° · pitch ${+f.pitch.toFixed(2)}°`;
    tile.title = label;
    const tag = document.createElement('span');
    tag.textContent = label;
    tile.append(tag);
    layer.append(tile);
  }
  return frames.length;
}

function showSheet({ blob, atlas, ms }) {
  const view = $('sheet-view');
  view.src = replaceUrl('sheetUrl', URL.createObjectURL(blob));
  const count = showTiles(atlas);
  const size = atlas.meta?.size;
  view.dataset.frames = String(count);
  view.dataset.sheets = String(Number(view.dataset.sheets || 0) + 1);
  $('sheet-frame').hidden = false;
  studio.sheetPanel.clearErrors();
  $('sheet-error').textContent = '';
  $('sheet-status').textContent = `${count} frames · ${size?.w}×${size?.h} px · ${Math.round(ms)} ms`;
  $('sheet-download').href = studio.sheetUrl;
  $('atlas-download').href = replaceUrl('atlasUrl', URL.createObjectURL(new Blob([JSON.stringify(atlas, null, 2)],
    { type: 'application/json' })));
  syncSheetFormat();
}

// The sheet's request: the page's state, except that an animated sheet
// takes its clips from sheet.animation and not from the pose shown above.
function sheetBody() {
  const body = clone(studio.params);
  if (body.sheet?.animation) delete body.animation;
  return body;
}

// The animation section's "Sheet of this clip": the sheet on, each of its
// directions a row of the clip's frames (over the part of it shown).
function sheetOfClip(clip, range) {
  const animation = range ? { clip, frames: 8, range } : { clip, frames: 8 };
  studio.params.sheet = { ...(studio.params.sheet ?? {}), animation };
  sync();
  studio.sheet.schedule(0);
}

function showSheetError(error) {
  reportError(error, studio.sheetPanel, 'sheet-error');
}

function installSheet() {
  if (!studio.schema.properties.sheet?.properties) return;
  studio.sheetPanel = new ControlPanel($('sheet-controls'), studio.schema, {
    change,
    addItem: () => {},
    removeItem: () => {},
  }, { only: ['sheet'], clips: () => studio.animation?.clips ?? [] });
  studio.sheet = new SheetPreview({
    bodyFor: () => (sheetOn() ? sheetBody() : null),
    onSheet: showSheet,
    onError: showSheetError,
    onBusy: (busy) => { $('sheet').classList.toggle('busy', busy); },
  });
  $('sheet-toggle').addEventListener('change', (e) => {
    if (e.target.checked) studio.params.sheet = {};
    else {
      delete studio.params.sheet;
      studio.sheet.cancel();
    }
    sync();
    // The single image is already current: the sheet need not wait for it.
    if (sheetOn()) studio.sheet.schedule(0);
  });
  $('sheet-format').addEventListener('change', syncSheetFormat);
  $('file-download').addEventListener('click', downloadSheetFile);
  $('sheet').hidden = false;
}

// ---- output -------------------------------------------------------------------

function installOutput() {
  for (const button of document.querySelectorAll('[data-copy]')) {
    button.addEventListener('click', async () => {
      const kind = button.dataset.copy;
      const params = studio.params;
      const text = kind === 'json' ? paramsJson(params)
        : kind === 'curl' ? curlCommand(location.origin, params) : toonCommand(location.origin, params);
      const box = $('copy-text');
      box.hidden = false;
      box.value = text;
      try {
        await navigator.clipboard.writeText(text);
        button.dataset.copied = 'yes';
      } catch {
        // No clipboard permission: the text is shown, selected, for Ctrl+C.
        box.select();
      }
    });
  }
  $('download').addEventListener('click', (e) => {
    if (!studio.downloadUrl) e.preventDefault();
  });
}

// ---- start ----------------------------------------------------------------------

async function loadContract() {
  const [schema, presets] = await Promise.all([getJson('/schema'), getJson('/presets')]);
  studio.schema = schema;
  studio.presets = presets;
  studio.defaults = schemaDefaults(schema);
  const select = $('preset-select');
  for (const [name, preset] of Object.entries(presets)) {
    const option = new Option(name.replace(/_/g, ' '), name);
    option.title = preset.description ?? '';
    select.append(option);
  }
  select.addEventListener('change', () => choosePreset(select.value));
}

async function start() {
  try {
    await loadContract();
  } catch (e) {
    $('panel-status').textContent = `Could not load the schema: ${e.message}`;
    lostServerThenReload();
    return;
  }
  studio.panel = new ControlPanel($('panel'), studio.schema, {
    change,
    addItem: (pointer, item) => {
      const list = [...(getPointer(effective(), pointer) ?? []), item];
      change(pointer, list, true);
    },
    removeItem: (pointer) => change(pointer, undefined, true),
  });
  studio.loop = new RenderLoop({ bodyFor, onImage: showImage, onError: showRenderError });
  installLayers();
  installSheet();
  studio.animation = new AnimationPanel($('animation'), {
    get: () => studio.params.animation,
    set: (animation, final) => change('/animation', animation, final),
    sheetOfClip,
    clipsChanged: () => syncSheet(effective()),
  });
  studio.materials = new MaterialList($('materials'), {
    get: (name) => studio.params.materials?.[name],
    setAlpha: (name, alpha) => {
      const escaped = name.replaceAll('~', '~0').replaceAll('/', '~1');
      change(`/materials/${escaped}/alpha`, alpha, true);
    },
  });
  installUpload();
  installOrbit();
  installOutput();
  installKeyboard({ preset: choosePreset, zoom: (f) => zoomBy(f, true), strafe, moveLight, resetView, togglePanel, toggleHelp });
  $('panel-toggle').addEventListener('click', togglePanel);
  $('help-button').addEventListener('click', toggleHelp);
  window.addEventListener('hashchange', () => {
    studio.params = paramsFromHash(location.hash);
    sync();
    studio.loop.request('full');
  });
  sync();
  studio.loop.request('full');
  refreshModels().catch(() => {});
}

// Before the page has its schema there is nothing to retry but the start.
function lostServerThenReload() {
  const banner = $('banner');
  banner.textContent = 'Lost the toond server — retrying…';
  banner.hidden = false;
  setTimeout(() => location.reload(), 3000);
}

start();
