// toond's sheet files read by readers toond did not write: a walk sheet of
// Blender's walking character (4 directions × 6 frames of Walk, 96²,
// dimetric, tests/exported/blender) asked for as ?atlas=aseprite is opened
// by the npm package ase-parser (a reader of Aseprite's published format,
// pinned in package.json), and as ?atlas=godot by a reader of Godot's
// text-resource grammar (godot_resource.mjs); both are checked against the
// atlas (?atlas=json) and the sheet's PNG as Chromium decodes it, packed
// (sheet.pack) and not, and drawn as two layers (sheet.layers).
//   node sheet_files.test.mjs --toond PATH --exported DIR
// Exit 0: every check passed; 1: a check failed.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import Aseprite from 'ase-parser';
import { parseGodotResource } from './godot_resource.mjs';
import { argument, checker, decodePngInPage, launchChromium, loadChromium, openPage, startDaemon } from './harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const chromium = await loadChromium(here);
const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);
const toondBinary = argument('--toond');
const exported = argument('--exported');
const { check, failed } = checker();

async function post(url, body) {
  const res = await fetch(url, { method: 'POST', body: JSON.stringify(body), headers: { 'Content-Type': 'application/json' } });
  if (!res.ok) throw new Error(`${url} answered ${res.status}: ${await res.text()}`);
  return Buffer.from(await res.arrayBuffer());
}

async function upload(url, file) {
  const form = new FormData();
  form.append('file', new Blob([readFileSync(file)]), path.basename(file));
  const res = await fetch(`${url}/models`, { method: 'POST', body: form });
  if (!res.ok) throw new Error(`upload failed: ${res.status} ${await res.text()}`);
  return res.json();
}

// Every answer of one sheet request: its PNG decoded by Chromium, its atlas,
// its .aseprite file and its Godot resource.
async function sheetFiles(url, page, request) {
  // One at a time: each may draw the whole sheet, and the daemon's queue
  // holds a few sheets' frames at most.
  const png = await post(`${url}/render`, request);
  const json = await post(`${url}/render?atlas=json`, request);
  const aseprite = await post(`${url}/render?atlas=aseprite`, request);
  const godot = await post(`${url}/render?atlas=godot`, request);
  const decoded = await page.evaluate(decodePngInPage, png.toString('base64'));
  return { image: { ...decoded, rgba: Buffer.from(decoded.rgba, 'base64') }, atlas: JSON.parse(json), aseprite,
    godot: godot.toString('utf8') };
}

// The tile an atlas frame stands for, w × h RGBA: its pixels put at
// spriteSourceSize in a transparent sourceSize canvas.
function tileOf(image, frame) {
  const { w, h } = frame.sourceSize;
  const tile = Buffer.alloc(w * h * 4);
  for (let y = 0; y < frame.frame.h; y++) {
    const from = ((frame.frame.y + y) * image.width + frame.frame.x) * 4;
    image.rgba.copy(tile, ((frame.spriteSourceSize.y + y) * w + frame.spriteSourceSize.x) * 4, from, from + frame.frame.w * 4);
  }
  return tile;
}

// The largest difference of any channel between two RGBA buffers, fully
// transparent pixels counting as (0, 0, 0, 0) whatever their colour.
function largestDifference(a, b) {
  let largest = a.length === b.length ? 0 : Infinity;
  for (let i = 0; i < a.length && i < b.length; i += 4) {
    for (let k = 0; k < 4; k++) {
      const va = a[i + 3] === 0 ? 0 : a[i + k];
      const vb = b[i + 3] === 0 ? 0 : b[i + k];
      largest = Math.max(largest, Math.abs(va - vb));
    }
  }
  return largest;
}

// `layers`: the file's layers bottom first, each with the sheet its cels
// must show (by default the one colour layer, the PNG of the request).
function checkAseprite(label, files, layers = [{ name: 'color', image: files.image }]) {
  const { atlas } = files;
  const ase = new Aseprite(files.aseprite, 'walk.aseprite');
  ase.parse();
  const frames = Object.values(atlas.frames);
  check(ase.numFrames === 24 && ase.width === 96 && ase.height === 96 && ase.colorDepth === 32,
    `${label}: ase-parser reads 24 frames of 96×96 at 32 bits`, `${ase.numFrames} of ${ase.width}×${ase.height}, ${ase.colorDepth} bpp`);
  check(ase.frames.map((f) => f.frameDuration).join() === frames.map((f) => f.duration).join(),
    `${label}: each frame's duration is the atlas's`, ase.frames.map((f) => f.frameDuration).join());
  const tags = atlas.meta.frameTags;
  check(ase.tags.length === 4 && ase.tags.every((t, i) => t.name === tags[i].name && t.from === tags[i].from
        && t.to === tags[i].to && t.animDirection === 'Forward' && t.repeat === 0),
  `${label}: one tag per direction, with the atlas's name, from and to, looping forward`,
  ase.tags.map((t) => `${t.name} ${t.from}-${t.to} ${t.animDirection} x${t.repeat}`).join('; '));
  const names = layers.map((l) => l.name);
  check(ase.layers.map((l) => l.name).join() === names.join(), `${label}: the layers ${names.join(', ')}, bottom first`,
    ase.layers.map((l) => l.name).join());
  let worst = 0;
  let cels = 0;
  let framesWithEveryLayer = 0;
  ase.frames.forEach((f, i) => {
    const canvases = layers.map(() => Buffer.alloc(96 * 96 * 4));
    for (const cel of f.cels) {
      cels += 1;
      const canvas = canvases[cel.layerIndex];
      for (let y = 0; y < cel.h; y++) cel.rawCelData.copy(canvas, ((cel.ypos + y) * 96 + cel.xpos) * 4, y * cel.w * 4, (y + 1) * cel.w * 4);
    }
    if (new Set(f.cels.map((c) => c.layerIndex)).size === layers.length) framesWithEveryLayer += 1;
    layers.forEach((l, k) => { worst = Math.max(worst, largestDifference(canvases[k], tileOf(l.image, frames[i]))); });
  });
  check(cels === 24 * layers.length && framesWithEveryLayer === 24 && worst <= 1,
    `${label}: every frame has a cel per layer, at its place its tile of that layer's sheet (±1)`,
    `${cels} cels, largest difference ${worst}`);
  const pivot = ase.slices.find((s) => s.name === 'pivot');
  const anchor = frames[0].anchor;
  check(pivot && pivot.keys[0].pivot.x === Math.round(anchor.x * 96) && pivot.keys[0].pivot.y === Math.round(anchor.y * 96),
    `${label}: the slice "pivot" holds the atlas's anchor in pixels`, JSON.stringify(pivot?.keys[0]));
}

const call = (value, name) => value && typeof value === 'object' && value.call === name ? value.args : null;

function checkGodot(label, files) {
  const { atlas } = files;
  let sections;
  try {
    sections = parseGodotResource(files.godot);
  } catch (e) {
    check(false, `${label}: the Godot resource follows the text-resource grammar`, e.message);
    return;
  }
  const [head, ...rest] = sections;
  const ext = rest.filter((s) => s.tag === 'ext_resource');
  const subs = rest.filter((s) => s.tag === 'sub_resource');
  const resource = rest.find((s) => s.tag === 'resource');
  check(head.tag === 'gd_resource' && head.fields.type === 'SpriteFrames' && head.fields.format === 3
        && head.fields.load_steps === ext.length + subs.length + 1 && rest.at(-1) === resource,
  `${label}: a format-3 SpriteFrames resource, its [resource] last`, JSON.stringify(head));
  check(ext.length === 1 && ext[0].fields.type === 'Texture2D' && ext[0].fields.path === atlas.meta.image,
    `${label}: the sheet's PNG is its one external texture, beside it by default`, JSON.stringify(ext[0]?.fields));
  const textures = new Map();
  for (const s of subs) textures.set(s.fields.id, s);
  const regionsOk = Object.entries(atlas.frames).every(([name, f]) => {
    const sub = textures.get(`AtlasTexture_${name}`);
    const region = call(sub?.props.region, 'Rect2');
    const margin = call(sub?.props.margin, 'Rect2');
    const wantMargin = f.trimmed ? [f.spriteSourceSize.x, f.spriteSourceSize.y, f.sourceSize.w - f.frame.w,
      f.sourceSize.h - f.frame.h].join() : undefined;
    return sub?.fields.type === 'AtlasTexture' && call(sub.props.atlas, 'ExtResource')?.[0] === ext[0].fields.id
      && region?.join() === [f.frame.x, f.frame.y, f.frame.w, f.frame.h].join() && margin?.join() === wantMargin;
  });
  check(subs.length === 24 && regionsOk, `${label}: an AtlasTexture per atlas frame, its region the frame (and a margin where trimmed)`);
  const animations = resource?.props.animations ?? [];
  const tags = atlas.meta.frameTags;
  check(animations.map((a) => a.name?.stringName).join() === tags.map((t) => t.name).join(),
    `${label}: the animations are the atlas's tags`, animations.map((a) => a.name?.stringName).join());
  const framesOk = animations.every((a, i) => {
    const names = a.frames.map((f) => call(f.texture, 'SubResource')?.[0]);
    const want = Array.from({ length: tags[i].to - tags[i].from + 1 }, (_, k) => `AtlasTexture_${tags[i].from + k}`);
    const timed = a.frames.every((f, k) => Math.abs((f.duration / a.speed) * 1000 - atlas.frames[String(tags[i].from + k)].duration) < 1e-6);
    return names.join() === want.join() && timed && a.loop === (tags[i].repeat === undefined);
  });
  check(framesOk, `${label}: each animation plays its tag's frames for their atlas durations, and loops`);
}

// sheet.layers: the .aseprite file holds the colour without its lines and
// the lines, each cel its tile of that layer's sheet asked for on its own;
// packed, the colour and the lines sheets share one atlas and each frame of
// either is its grid tile.
async function checkLayers(url, page, request) {
  const decode = async (png) => {
    const decoded = await page.evaluate(decodePngInPage, png.toString('base64'));
    return { ...decoded, rgba: Buffer.from(decoded.rgba, 'base64') };
  };
  const bare = await decode(await post(`${url}/render`, { ...request, outline: { enabled: false }, contour: { enabled: false } }));
  const lines = await decode(await post(`${url}/render`, { ...request, output: 'lines' }));
  const layered = { ...request, sheet: { ...request.sheet, layers: ['color', 'lines'] } };
  const atlas = JSON.parse(await post(`${url}/render?atlas=json`, layered));
  const aseprite = await post(`${url}/render?atlas=aseprite`, layered);
  checkAseprite('two layers', { atlas, aseprite }, [{ name: 'color', image: bare }, { name: 'lines', image: lines }]);
  const packed = { ...layered, sheet: { ...layered.sheet, pack: true } };
  const packedAtlas = JSON.parse(await post(`${url}/render?atlas=json`, packed));
  const packedColour = await decode(await post(`${url}/render`, packed));
  const packedLines = await decode(await post(`${url}/render`, { ...packed, output: 'lines' }));
  let worst = 0;
  for (const [name, frame] of Object.entries(packedAtlas.frames)) {
    worst = Math.max(worst, largestDifference(tileOf(packedColour, frame), tileOf(bare, atlas.frames[name])),
      largestDifference(tileOf(packedLines, frame), tileOf(lines, atlas.frames[name])));
  }
  const linesAtlas = JSON.parse(await post(`${url}/render?atlas=json`, { ...packed, output: 'lines' }));
  const sameSize = packedColour.width === packedLines.width && packedColour.height === packedLines.height
    && JSON.stringify(linesAtlas) === JSON.stringify(packedAtlas);
  check(sameSize && worst === 0, 'packed with both layers, the colour and the lines sheets share one atlas and '
    + 'each frame of either is its tile of that layer\'s grid sheet', `${packedColour.width}×${packedColour.height}, `
    + `largest difference ${worst}`);
}

const dataDir = mkdtempSync(path.join(tmpdir(), 'toond-sheet-files-'));
let daemon = null;
let browser = null;
try {
  const version = JSON.parse(readFileSync(path.join(here, 'node_modules/ase-parser/package.json'), 'utf8')).version;
  console.log(`ase-parser ${version}`);
  daemon = await startDaemon(toondBinary, '127.0.0.1:0', dataDir, STEP_TIMEOUT_MS);
  const walker = await upload(daemon.url, path.join(exported, 'blender', 'walker.glb'));
  browser = await launchChromium(chromium);
  const { page } = await openPage(browser, { width: 64, height: 64 });
  await page.goto('about:blank');
  const request = { model: walker.id, width: 96, height: 96, background: [0, 0, 0, 0], camera: { preset: 'dimetric' },
    sheet: { frames: 4, yaw_start: 0, animation: { clip: 'Walk', frames: 6 } } };
  const grid = await sheetFiles(daemon.url, page, request);
  const packed = await sheetFiles(daemon.url, page, { ...request, sheet: { ...request.sheet, pack: true } });
  checkAseprite('grid', grid);
  checkAseprite('packed', packed);
  check(packed.aseprite.equals(grid.aseprite), 'the .aseprite file is the same packed or not (its cels are trimmed either way)');
  checkGodot('grid', grid);
  checkGodot('packed', packed);
  const share = (packed.image.width * packed.image.height) / (grid.image.width * grid.image.height);
  check(share <= 0.6, 'the packed PNG takes at most 60 % of the grid\'s area',
    `${packed.image.width}×${packed.image.height} of ${grid.image.width}×${grid.image.height}: ${share.toFixed(3)}`);
  await checkLayers(daemon.url, page, request);
} catch (e) {
  check(false, 'the sheet-files test ran to its end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) daemon.child.kill('SIGTERM');
  rmSync(dataDir, { recursive: true, force: true });
}
console.log(`${failed() ? 'FAILED' : 'passed'}: ${failed()} failing check(s)`);
process.exit(failed() ? 1 : 0);
