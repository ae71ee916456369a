// The page's output tools in a real browser (Debian's chromium through
// playwright-core, a real toond on 127.0.0.1:0): controls shown only where
// the schema's x-applies-when says they matter, the layer switcher
// (`output`), the SVG download beside it, and the sprite-sheet preview with
// its atlas.
//   node layers.test.mjs --toond PATH --artifacts DIR
// Exit 0: every check passed; 1: a check failed. Screenshots go to --artifacts.
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import Aseprite from 'ase-parser';
import { argument, launchChromium, openPage, startDaemon } from './harness.mjs';
import { dragSlider, imageStats, rendersShown, waitForFullRender } from './page_actions.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const { chromium } = await import(path.join(here, 'node_modules/playwright-core/index.mjs')).catch(() => {
  console.error('playwright-core is not installed: run tests/browser/install.sh');
  process.exit(1);
});

const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);

const toondBinary = argument('--toond');
const artifacts = argument('--artifacts');
mkdirSync(artifacts, { recursive: true });

let failures = 0;
function check(condition, what, detail = '') {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}${detail ? ` (${detail})` : ''}`);
  if (!condition) failures += 1;
}

async function shot(page, name) {
  const file = path.join(artifacts, name);
  await page.screenshot({ path: file, fullPage: true });
  console.log(`     screenshot ${file}`);
}

async function waitForRenderError(page, after) {
  await page.waitForFunction((n) => Number(document.getElementById('view').dataset.errors || 0) > n, after,
    { timeout: STEP_TIMEOUT_MS });
}

// The body of the last single render asked for (not an atlas).
function lastRender(requests) {
  return requests.filter((r) => !r.url.includes('?')).at(-1)?.body;
}

// Shown: neither the control nor anything above it is hidden.
function shown(page, pointer) {
  return page.locator(`[data-path="${pointer}"]`).first().isVisible();
}

// ---- the checks -----------------------------------------------------------------

async function checkLightType(page, requests) {
  check(await shown(page, '/lights/0/direction') && !(await shown(page, '/lights/0/position'))
        && !(await shown(page, '/lights/0/radius')),
  'a directional light shows its direction, not a position or radius');
  const errors = Number((await page.getAttribute('#view', 'data-errors')) || 0);
  await page.selectOption('#f-lights-0-type', 'point');
  check(await shown(page, '/lights/0/position') && await shown(page, '/lights/0/radius')
        && !(await shown(page, '/lights/0/direction')),
  'switching to a point light shows position and radius and hides direction');
  // A point light needs a position: the server's 400 lands on the box now shown.
  await waitForRenderError(page, errors);
  const light = page.locator('fieldset[data-path="/lights/0"]');
  check(await light.evaluate((f) => f.classList.contains('invalid'))
        && /position/.test(await light.locator('.field-error').first().textContent()),
  'the missing position is named at the light');
  await shot(page, '11-point-light.png');
  const before = await rendersShown(page);
  for (const [i, v] of [2, 3, 4].entries()) {
    const box = page.locator(`[data-path="/lights/0/position/${i}"] input[type=number]`);
    await box.fill(String(v));
    await box.press('Enter');
  }
  // Each Enter may send a render: one with only x and y typed ([2,3,0]) is
  // valid too, and on a slow daemon it can finish and settle the view before
  // the last one is sent. Wait for the request with all three, then for it
  // to settle.
  const typedDeadline = Date.now() + STEP_TIMEOUT_MS;
  while (JSON.stringify(lastRender(requests)?.lights?.[0]?.position) !== '[2,3,4]' && Date.now() < typedDeadline) {
    await page.waitForTimeout(50);
  }
  await page.waitForFunction((n) => {
    const view = document.getElementById('view');
    return Number(view.dataset.renders) > n && view.dataset.settled === 'yes'
      && document.getElementById('render-error').textContent === '';
  }, before, { timeout: STEP_TIMEOUT_MS });
  const typed = lastRender(requests);
  check(JSON.stringify(typed?.lights?.[0]?.position) === '[2,3,4]' && typed?.lights?.[0]?.type === 'point',
    'the typed position is sent as a whole vector and renders', JSON.stringify(typed?.lights));
  const rendered = await rendersShown(page);
  await page.selectOption('#f-lights-0-type', 'directional');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(!(await shown(page, '/lights/0/position')) && await shown(page, '/lights/0/direction'),
    'back to directional hides the position again');
}

// The light's space, a select made from the schema's enum: absent (the
// default: model for this single image) until chosen; view is sent. And
// the field of view shows for an orthographic camera only once a distance
// sizes the view through it.
async function checkLightSpaceAndFov(page, requests) {
  const options = await page.locator('#f-lights-0-space option').evaluateAll((os) => os.map((o) => o.value));
  check(options.join() === ',model,view' && await page.inputValue('#f-lights-0-space') === '',
    'the light has a space select: unset, model or view', options.join());
  let rendered = await rendersShown(page);
  await page.selectOption('#f-lights-0-space', 'view');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(lastRender(requests)?.lights?.[0]?.space === 'view', 'choosing view sends lights[0].space',
    JSON.stringify(lastRender(requests)?.lights));
  rendered = await rendersShown(page);
  await page.selectOption('#f-camera-projection', 'orthographic');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(!(await shown(page, '/camera/fov')), 'orthographic and fitted: the field of view is hidden');
  rendered = await rendersShown(page);
  const distance = page.locator('[data-path="/camera/distance"] input[type=number]');
  await distance.fill('6');
  await distance.press('Enter');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(await shown(page, '/camera/fov') && lastRender(requests)?.camera?.distance === 6,
    'orthographic at a distance: the field of view, which sizes the view, shows');
}

async function checkGroupSwitches(page) {
  check(!(await shown(page, '/rim/power')) && !(await shown(page, '/rim/color')),
    'rim is off by default: its power and colour are hidden');
  await page.check('#f-rim-enabled');
  check(await shown(page, '/rim/power') && await shown(page, '/rim/mask'), 'switching rim on shows its controls');
  await page.uncheck('#f-rim-enabled');
  check(!(await shown(page, '/rim/power')), 'switching rim off hides them again');
  check(await shown(page, '/outline/width'), 'outline is on by default: its width is shown');
  await page.uncheck('#f-outline-enabled');
  check(!(await shown(page, '/outline/width')) && !(await shown(page, '/outline/method'))
        && await shown(page, '/outline/enabled'), 'switching the outline off hides all but its switch');
  await page.check('#f-outline-enabled');
  check(!(await shown(page, '/outline/darken')), 'the darkening of material-coloured lines hides with a fixed colour');
  await page.selectOption('#f-outline-color-mode', 'material');
  check(await shown(page, '/outline/darken') && !(await shown(page, '/outline/color')),
    'material-coloured lines show darken, not the fixed colour');
  await page.selectOption('#f-outline-color-mode', 'fixed');
  check(!(await shown(page, '/floor/size')), 'floor sub-controls hidden while the floor is off');
  check(!(await shown(page, '/shadows/map_size')) && await shown(page, '/shadows/enabled'),
    'shadow sub-controls hidden while shadows are off');

  check(await shown(page, '/shading/steps') && await shown(page, '/shading/two_tone'), 'cel mode shows the bands');
  await page.selectOption('#f-shading-mode', 'phong');
  check(!(await shown(page, '/shading/steps')) && !(await shown(page, '/shading/rounding'))
        && !(await shown(page, '/shading/band_aa')) && !(await shown(page, '/shading/two_tone'))
        && !(await shown(page, '/shading/ramp')),
  'phong hides the cel-only controls');
  check(await page.locator('details[data-group=specular]').isVisible(), 'phong keeps the specular group');
  await page.selectOption('#f-shading-mode', 'flat');
  check(!(await page.locator('details[data-group=specular]').isVisible())
        && !(await page.locator('details[data-group=rim]').isVisible()),
  'flat (unlit) hides the lighting effects');
  check(!(await shown(page, '/ambient')) && !(await shown(page, '/lights/0/direction')),
    'flat (unlit) hides the ambient term and the lights');
  await shot(page, '12-flat-mode-controls.png');
  const rendered = await rendersShown(page);
  await page.selectOption('#f-shading-mode', 'cel');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(await shown(page, '/shading/steps'), 'cel again shows the bands');
  check(await shown(page, '/ambient') && await shown(page, '/lights/0/direction'), 'and the lights');
}

async function checkLayers(page, requests) {
  const buttons = await page.locator('#layers input[type=radio]').evaluateAll((r) => r.map((e) => e.value));
  check(JSON.stringify(buttons) === JSON.stringify(['color', 'lines', 'depth', 'normal', 'id']),
    'a layer button per value of the schema\'s output', buttons.join(' '));
  check(await page.isChecked('#layer-color'), 'colour is the layer shown first');
  const colour = await imageStats(page, '#view');
  const background = await page.locator('#view').evaluate((v) => getComputedStyle(v).backgroundImage);
  check(/conic-gradient/.test(background), 'the image lies on a checkerboard', background.slice(0, 40));

  requests.length = 0;
  let rendered = await rendersShown(page);
  await page.click('label[for=layer-lines]');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  const last = lastRender(requests);
  check(last?.output === 'lines', 'the lines button renders with output "lines"', JSON.stringify(last));
  check(decodeURIComponent(page.url()).includes('"output":"lines"'), 'the URL keeps the layer');
  check(await page.getAttribute('#download', 'download') === 'toond-lines.png', 'the download is named for the layer');
  const lines = await imageStats(page, '#view');
  check(lines.hash !== colour.hash, 'the lines layer is another image than the colour one');
  check(lines.transparent > lines.width * lines.height * 0.5, 'the lines layer is mostly transparent',
    `${lines.transparent} of ${lines.width * lines.height} pixels`);
  await shot(page, '13-lines-layer.png');

  for (const layer of ['depth', 'normal', 'id']) {
    rendered = await rendersShown(page);
    await page.click(`label[for=layer-${layer}]`);
    await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
    check(lastRender(requests)?.output === layer, `the ${layer} button renders with output "${layer}"`);
  }
  rendered = await rendersShown(page);
  await page.click('label[for=layer-color]');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  const back = lastRender(requests);
  check(back && !('output' in back), 'colour again leaves output to its default', JSON.stringify(back));
  check((await imageStats(page, '#view')).hash === colour.hash, 'and shows the colour image again');
}

// The format select and the pack switch: .aseprite and Godot downloads
// asked for with the body of the sheet shown, under names that go together;
// pack sends sheet.pack and the atlas that comes back is packed.
async function checkSheetFiles(page, requests) {
  check(await page.locator('#sheet-format').isVisible() && await page.inputValue('#sheet-format') === 'png'
        && await page.locator('#atlas-download').isVisible() && await page.locator('#file-download').isHidden(),
  'a format select, PNG + JSON at first: the sheet and atlas downloads');
  const lastSheet = [...requests].reverse().find((r) => r.body.sheet && !r.url.includes('?'));
  const download = async (format) => {
    await page.selectOption('#sheet-format', format);
    requests.length = 0;
    const [file] = await Promise.all([page.waitForEvent('download', { timeout: STEP_TIMEOUT_MS }), page.click('#file-download')]);
    const bytes = readFileSync(await file.path());
    const asked = requests.find((r) => r.url.includes(`atlas=${format}`));
    return { name: file.suggestedFilename(), bytes, asked };
  };
  const ase = await download('aseprite');
  check(ase.name === 'toond-sheet.aseprite' && ase.bytes.readUInt16LE(4) === 0xA5E0 && ase.bytes.readUInt16LE(6) === 6
        && await page.locator('#atlas-download').isHidden(),
  '.aseprite: one file of the 6 frames, asked for with ?atlas=aseprite', `${ase.name}, ${ase.bytes.length} bytes`);
  // sheet.layers: a checkbox per layer among the sheet's controls; with
  // colour and lines checked the sheet is asked for as both layers and the
  // .aseprite file holds a layer each.
  const layerBoxes = await page.locator('[data-path="/sheet/layers"] input[type=checkbox]')
    .evaluateAll((boxes) => boxes.map((b) => b.value));
  check(layerBoxes.join() === 'color,lines', 'a checkbox per layer the schema\'s sheet.layers lists', layerBoxes.join());
  for (const layer of ['color', 'lines']) {
    const before = Number(await page.getAttribute('#sheet-view', 'data-sheets'));
    await page.check(`[data-path="/sheet/layers"] input[value=${layer}]`);
    await page.waitForFunction((n) => Number(document.getElementById('sheet-view').dataset.sheets) > n
      && !document.getElementById('sheet').classList.contains('busy'), before, { timeout: STEP_TIMEOUT_MS });
  }
  const layered = await download('aseprite');
  const layeredFile = new Aseprite(layered.bytes, 'layers.aseprite');
  layeredFile.parse();
  check(layered.asked?.body.sheet?.layers?.join() === 'color,lines'
        && layeredFile.layers.map((l) => l.name).join() === 'color,lines',
  'colour and lines checked: the .aseprite file holds both layers', layeredFile.layers.map((l) => l.name).join());
  for (const layer of ['lines', 'color']) {
    const before = Number(await page.getAttribute('#sheet-view', 'data-sheets'));
    await page.uncheck(`[data-path="/sheet/layers"] input[value=${layer}]`);
    await page.waitForFunction((n) => Number(document.getElementById('sheet-view').dataset.sheets) > n
      && !document.getElementById('sheet').classList.contains('busy'), before, { timeout: STEP_TIMEOUT_MS });
  }
  const unlayered = [...requests].reverse().find((r) => r.body.sheet);
  check(unlayered && !('layers' in unlayered.body.sheet), 'none checked leaves sheet.layers out',
    JSON.stringify(unlayered?.body.sheet));
  const tres = await download('godot');
  check(tres.name === 'toond-sheet.tres' && tres.bytes.toString().includes('path="toond-sheet.png"')
        && await page.getAttribute('#sheet-download', 'download') === 'toond-sheet.png'
        && await page.locator('#sheet-download').isVisible(),
  'Godot: a .tres naming the PNG the sheet download saves beside it', tres.name);
  check(lastSheet && [ase, tres].every((d) => d.asked && JSON.stringify(d.asked.body) === JSON.stringify(lastSheet.body)),
    'both are asked for with the body of the sheet shown');
  await page.selectOption('#sheet-format', 'png');
  check(await shown(page, '/sheet/pack') && !(await shown(page, '/sheet/power_of_two')),
    'a pack switch in the sheet\'s controls, power_of_two hidden while it is off');
  const sheets = Number(await page.getAttribute('#sheet-view', 'data-sheets'));
  requests.length = 0;
  await page.check('[data-path="/sheet/pack"] input[type=checkbox]');
  await page.waitForFunction((n) => Number(document.getElementById('sheet-view').dataset.sheets) > n
    && !document.getElementById('sheet').classList.contains('busy'), sheets, { timeout: STEP_TIMEOUT_MS });
  const packed = requests.filter((r) => r.body.sheet?.pack === true);
  const tiles = await page.locator('#sheet-tiles .tile').count();
  check(packed.length === 1 && !packed[0].url.includes('?') && await shown(page, '/sheet/power_of_two') && tiles === 6
        && /6 frames/.test(await page.textContent('#sheet-status')),
  'pack sends sheet.pack; the atlas is read from the packed PNG (no second draw) and outlines its 6 frames',
  `${packed.map((r) => r.url).join(', ')}; ${tiles} tiles`);
  // Back to the grid, and the sheet of it shown before the next check.
  const packedSheets = Number(await page.getAttribute('#sheet-view', 'data-sheets'));
  await page.uncheck('[data-path="/sheet/pack"] input[type=checkbox]');
  await page.waitForFunction((n) => Number(document.getElementById('sheet-view').dataset.sheets) > n
    && !document.getElementById('sheet').classList.contains('busy'), packedSheets, { timeout: STEP_TIMEOUT_MS });
}

// The drawing as Chromium reads it: its layers' ids (DOMParser), its
// size and how many pixels its strokes ink, drawn from an <img> into a canvas.
async function readSvgInPage(page, text) {
  return page.evaluate(async (svg) => {
    const doc = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const ids = [...doc.documentElement.children].filter((e) => e.localName === 'g').map((g) => g.id);
    const strokes = doc.querySelectorAll('g#silhouette path').length;
    const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
    const img = new Image();
    img.src = url;
    await img.decode();
    const canvas = Object.assign(document.createElement('canvas'), { width: img.naturalWidth, height: img.naturalHeight });
    const ctx = canvas.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const { data } = ctx.getImageData(0, 0, canvas.width, canvas.height);
    let ink = 0;
    for (let i = 3; i < data.length; i += 4) ink += data[i] > 127 ? 1 : 0;
    URL.revokeObjectURL(url);
    return { ids, strokes, width: img.naturalWidth, height: img.naturalHeight, ink,
      parseError: doc.querySelector('parsererror') !== null };
  }, text);
}

async function downloadSvg(page, name) {
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: STEP_TIMEOUT_MS }),
    page.click('#svg-download')]);
  const file = path.join(artifacts, name);
  await download.saveAs(file);
  return { file, suggested: download.suggestedFilename(), text: readFileSync(file, 'utf8') };
}

// The SVG button beside the layers: the view's lines downloaded as an SVG
// drawing, which Chromium opens with its layers and draws with ink.
async function checkSvg(page, requests) {
  check(await page.isVisible('#svg-download'), 'an SVG button beside the layer buttons');
  requests.length = 0;
  const plain = await downloadSvg(page, 'toond-lines.svg');
  check(plain.suggested === 'toond-lines.svg', 'the drawing downloads as toond-lines.svg', plain.suggested);
  const asked = lastRender(requests);
  check(asked?.output === 'svg' && !('svg' in asked), 'it asks for output "svg"', JSON.stringify(asked));
  const read = await readSvgInPage(page, plain.text);
  check(!read.parseError, 'Chromium parses the drawing as SVG');
  check(JSON.stringify(read.ids) === JSON.stringify(['silhouette', 'creases', 'intersections', 'boundary']),
    'with a layer per kind of line', read.ids.join(' '));
  check(read.strokes > 0, 'the silhouette layer has strokes', String(read.strokes));
  check(read.width === 192 && read.height === 192, 'an <img> of it is the view\'s size', `${read.width}×${read.height}`);
  check(read.ink > 100 && read.ink < 0.25 * read.width * read.height, 'and Chromium draws its lines',
    `${read.ink} inked pixels`);
  await page.check('#svg-hidden');
  const withHidden = await downloadSvg(page, 'toond-lines-hidden.svg');
  check(lastRender(requests)?.svg?.hidden === true, 'the hidden-lines box asks for svg.hidden');
  const again = await readSvgInPage(page, withHidden.text);
  check(again.ids[0] === 'hidden', 'and the drawing gets a hidden layer first', again.ids.join(' '));
}

async function checkSheet(page, requests) {
  check(await page.locator('#sheet-toggle').isVisible() && !(await shown(page, '/sheet/frames')),
    'a sprite-sheet switch, its controls hidden while off');
  requests.length = 0;
  await page.check('#sheet-toggle');
  check(await shown(page, '/sheet/frames') && await shown(page, '/sheet/columns'),
    'switching the sheet on shows its controls from the schema');
  check(!(await shown(page, '/sheet/frame_ms')), 'the animation\'s frame time hides while animate is off');
  // A refused sheet marks the control it names; the next sheet clears it.
  const frames = page.locator('[data-path="/sheet/frames"] input[type=number]');
  await frames.fill('0');
  await frames.press('Enter');
  await page.waitForFunction(() => document.getElementById('sheet-error').textContent !== '', null,
    { timeout: STEP_TIMEOUT_MS });
  check(/\/sheet\/frames/.test(await page.textContent('#sheet-error'))
        && await page.locator('#sheet-controls .invalid').count() > 0,
  'a refused sheet names the field and marks it', await page.textContent('#sheet-error'));
  for (const [field, value] of [['frames', 6], ['columns', 3]]) {
    const box = page.locator(`[data-path="/sheet/${field}"] input[type=number]`);
    await box.fill(String(value));
    await box.press('Enter');
  }
  await page.waitForFunction(() => document.getElementById('sheet-view').dataset.frames === '6'
    && !document.getElementById('sheet').classList.contains('busy'), null, { timeout: STEP_TIMEOUT_MS });
  check(await page.locator('#sheet-controls .invalid').count() === 0 && await page.textContent('#sheet-error') === '',
    'the sheet that then arrives clears the mark');
  const tiles = await page.locator('#sheet-tiles .tile').count();
  check(tiles === 6, 'the sheet preview outlines as many tiles as frames', `${tiles} tiles`);
  const sheetBodies = requests.filter((r) => r.body.sheet);
  const atlas = sheetBodies.filter((r) => r.url.endsWith('?atlas=json'));
  const last = atlas[atlas.length - 1];
  check(last && last.body.sheet.frames === 6 && last.body.sheet.columns === 3,
    'the atlas is asked for with ?atlas=json and the sheet', JSON.stringify(last?.body.sheet));
  check(sheetBodies.some((r) => !r.url.includes('?') && JSON.stringify(r.body) === JSON.stringify(last?.body)),
    'the sheet image is asked for with the same body');
  const sheet = await imageStats(page, '#sheet-view');
  const single = await imageStats(page, '#view');
  check(sheet.width === 3 * single.width && sheet.height === 2 * single.height,
    'the sheet is 3 tiles across and 2 down', `${sheet.width}×${sheet.height}, tile ${single.width}×${single.height}`);
  check(/6 frames/.test(await page.textContent('#sheet-status')), 'the frame count is shown',
    await page.textContent('#sheet-status'));
  // Tile 4 of 3 columns × 2 rows: the middle of the lower row.
  const tile = page.locator('#sheet-tiles .tile').nth(4);
  const box = await tile.boundingBox();
  const view = await page.locator('#sheet-view').boundingBox();
  const near = (a, b) => Math.abs(a - b) <= 2;
  check(box && view && near(box.x - view.x, view.width / 3) && near(box.y - view.y, view.height / 2)
        && near(box.width, view.width / 3) && near(box.height, view.height / 2),
  'the atlas places tile 4 in the middle of the lower row', JSON.stringify({ box, view }));
  await tile.hover();
  const label = tile.locator('span');
  check(await label.isVisible() && /frame 4 · yaw/.test(await label.textContent()),
    'hovering a tile outlines it and names its frame and yaw', await label.textContent());
  await shot(page, '14-sprite-sheet.png');
  await checkSheetFiles(page, requests);

  // Dragging a slider with the sheet on: the live loop's quick renders go
  // on alone, and the sheet follows once, when the drag has ended. The
  // drag holds halfway until a quick render is shown, so on a busy machine
  // the whole drag cannot fit inside the first quick render's round trip.
  const sheets = Number(await page.getAttribute('#sheet-view', 'data-sheets'));
  const rendered = await rendersShown(page);
  requests.length = 0;
  await dragSlider(page, '/outline/width', 6, () => page.waitForFunction((n) => {
    const v = document.getElementById('view');
    return Number(v.dataset.renders || 0) > n && v.dataset.kind === 'quick';
  }, rendered, { timeout: STEP_TIMEOUT_MS }));
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  await page.waitForFunction((n) => Number(document.getElementById('sheet-view').dataset.sheets) > n
    && !document.getElementById('sheet').classList.contains('busy'), sheets, { timeout: STEP_TIMEOUT_MS });
  const quick = requests.filter((r) => !r.body.sheet && r.body.msaa === 1).length;
  const sheetRenders = requests.filter((r) => r.body.sheet && !r.url.includes('?')).length;
  check(quick >= 2 && sheetRenders === 1, 'a drag renders quick single images and one sheet at its end',
    `${quick} quick renders, ${sheetRenders} sheet renders`);
  const released = Number(await page.inputValue('[data-path="/outline/width"] input[type=number]'));
  check(requests.filter((r) => r.body.sheet).every((r) => r.body.outline?.width === released),
    'the sheet shows the released value', `slider at ${released}`);
  check(decodeURIComponent(page.url()).includes('"sheet":{'), 'the URL keeps the sheet');
  await page.uncheck('#sheet-toggle');
  check(await page.locator('#sheet-frame').isHidden() && !decodeURIComponent(page.url()).includes('"sheet"'),
    'switching the sheet off hides it and drops it from the state');
}

// ---- main -------------------------------------------------------------------------

const dataDir = mkdtempSync(path.join(tmpdir(), 'toond-layers-'));
let daemon = null;
let browser = null;
const started = Date.now();
try {
  daemon = await startDaemon(toondBinary, '127.0.0.1:0', dataDir, STEP_TIMEOUT_MS);
  console.log(`toond at ${daemon.url}`);
  browser = await launchChromium(chromium);
  const { page, pageErrors } = await openPage(browser, { width: 1280, height: 900 });
  const requests = [];
  page.on('request', (r) => {
    if (!/\/render(\?|$)/.test(r.url())) return;
    try { requests.push({ url: r.url(), body: JSON.parse(r.postData() || '{}') }); } catch { /* not JSON */ }
  });
  // Small tiles keep the sheet quick on llvmpipe. Each part starts from a
  // fresh page, so one that fails does not hide what the others find.
  const start = encodeURIComponent(JSON.stringify({ width: 192, height: 192 }));
  for (const [name, part] of [['light type', (p) => checkLightType(p, requests)],
    ['light space and fov', (p) => checkLightSpaceAndFov(p, requests)], ['group switches', checkGroupSwitches],
    ['layers', (p) => checkLayers(p, requests)], ['svg download', (p) => checkSvg(p, requests)],
    ['sprite sheet', (p) => checkSheet(p, requests)]]) {
    try {
      await page.goto('about:blank');
      await page.goto(`${daemon.url}/#${start}`);
      await waitForFullRender(page, 0, STEP_TIMEOUT_MS);
      // Closed groups would hide every control alike.
      await page.evaluate(() => { for (const d of document.querySelectorAll('#panel details')) d.open = true; });
      await part(page);
    } catch (e) {
      check(false, `the ${name} checks ran to the end`, e.stack || String(e));
    }
  }
  check(pageErrors.length === 0, 'no uncaught errors in the page', pageErrors.join(' | '));
} catch (e) {
  check(false, 'the browser test ran to the end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) {
    daemon.child.kill('SIGKILL');
  }
  rmSync(dataDir, { recursive: true, force: true });
}

console.log(`layers test: ${failures} failed, ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in ${artifacts}`);
if (failures > 0) process.exit(1);
process.exit(0);
