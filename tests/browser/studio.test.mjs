// The slider studio in a real browser: Debian's chromium, driven by
// playwright-core, against a real toond on 127.0.0.1 (port 0, temp data dir).
//   node studio.test.mjs --toond PATH --models DIR --artifacts DIR
// Exit 0: every check passed; 1: a check failed; 77 (CTest SKIP_RETURN_CODE):
// everything that ran passed but the spot upload was skipped because the
// shared models are absent. Screenshots go to --artifacts.
import { existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { argument, launchChromium, openPage, startDaemon } from './harness.mjs';
import { dragSlider, imageStats, rendersShown, waitForFullRender } from './page_actions.mjs';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const { chromium } = await import(path.join(here, 'node_modules/playwright-core/index.mjs')).catch(() => {
  console.error('playwright-core is not installed: run tests/browser/install.sh');
  process.exit(1);
});

const SKIP = 77;
// Every wait is bounded; the ASan build's daemon is several times slower.
const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);

const toondBinary = argument('--toond');
const modelsDir = argument('--models');
const artifacts = argument('--artifacts');
mkdirSync(artifacts, { recursive: true });

let failures = 0;
const skipped = [];
function check(condition, what, detail = '') {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}${detail ? ` (${detail})` : ''}`);
  if (!condition) failures += 1;
}

// ---- the daemon -------------------------------------------------------------

function startToond(listen, dataDir) {
  return startDaemon(toondBinary, listen, dataDir, STEP_TIMEOUT_MS);
}

function stopDaemon(daemon) {
  return new Promise((resolve) => {
    if (daemon.child.exitCode !== null || daemon.child.signalCode !== null) { resolve(); return; }
    daemon.child.once('exit', () => resolve());
    daemon.child.kill('SIGKILL');
  });
}

// ---- page helpers -------------------------------------------------------------

async function shot(page, name) {
  const file = path.join(artifacts, name);
  await page.screenshot({ path: file });
  console.log(`     screenshot ${file}`);
}

// Every numeric leaf of the schema as the JSON pointer of the control that
// edits it: a number's own pointer, a vector's components, a colour's array
// (plus its alpha). Arrays of objects are looked at through item 0.
// `objects` (multi-model scenes) and `sheet` (sprite sheets) are not edited
// on this page; `animation` is, by the animation section, which only a
// model with clips shows (animation.test.mjs).
function numericLeaves(schema, pointer = '', out = []) {
  if (schema.type === 'object' && schema.properties) {
    for (const [key, sub] of Object.entries(schema.properties)) {
      if (pointer === '' && ['objects', 'sheet', 'animation'].includes(key)) continue;
      numericLeaves(sub, `${pointer}/${key}`, out);
    }
  } else if (schema.type === 'array' && schema.items?.type === 'object') {
    numericLeaves(schema.items, `${pointer}/0`, out);
  } else if (schema.type === 'array' && ['number', 'integer'].includes(schema.items?.type)) {
    if (schema['x-control'] === 'color') {
      out.push({ pointer, kind: 'color' });
      if (schema.maxItems > 3) out.push({ pointer: `${pointer}/3`, kind: 'number', schema: schema.items });
    } else {
      for (let i = 0; i < schema.maxItems; i++) out.push({ pointer: `${pointer}/${i}`, kind: 'number', schema: schema.items });
    }
  } else if (schema.type === 'number' || schema.type === 'integer') {
    out.push({ pointer, kind: Array.isArray(schema.enum) ? 'select' : 'number', schema });
  }
  return out;
}

// ---- the checks -----------------------------------------------------------------

async function checkControls(page, base) {
  const schema = await (await fetch(`${base}/schema`)).json();
  await page.evaluate(() => { for (const d of document.querySelectorAll('#panel details')) d.open = true; });
  // Ramp stops exist only once added; add one so item 0 has controls.
  for (const button of await page.locator('button[data-add]').all()) {
    if (await button.isEnabled() && (await button.getAttribute('data-add')) === '/shading/ramp') await button.click();
  }
  const leaves = numericLeaves(schema);
  const missing = [];
  const wrongRange = [];
  for (const leaf of leaves) {
    const selector = leaf.kind === 'color' ? 'input[type=color]' : leaf.kind === 'select' ? 'select' : 'input[type=number]';
    const control = page.locator(`[data-path="${leaf.pointer}"] ${selector}, input[data-path="${leaf.pointer}"]`).first();
    if (await control.count() === 0) { missing.push(leaf.pointer); continue; }
    if (leaf.kind === 'number') {
      const min = await control.getAttribute('min');
      const max = await control.getAttribute('max');
      if ((leaf.schema.minimum !== undefined && Number(min) !== leaf.schema.minimum)
          || (leaf.schema.maximum !== undefined && Number(max) !== leaf.schema.maximum)) {
        wrongRange.push(`${leaf.pointer} ${min}..${max}`);
      }
    }
  }
  check(missing.length === 0, `a control for each of the schema's ${leaves.length} numeric leaves`,
    missing.length ? `missing: ${missing.join(', ')}` : '');
  check(wrongRange.length === 0, 'number boxes carry the schema\'s minimum and maximum', wrongRange.join(', '));
  const sliders = await page.locator('#panel input[type=range]').count();
  const labelled = await page.evaluate(() => [...document.querySelectorAll('#panel input, #panel select')]
    .filter((e) => !(e.labels?.length || e.getAttribute('aria-label'))).map((e) => e.id || e.outerHTML.slice(0, 60)));
  check(sliders >= 30, 'sliders for the ranged numbers', `${sliders} sliders`);
  check(labelled.length === 0, 'every control has a label', labelled.join(', '));
}

async function uploadSpot(page) {
  const spot = path.join(modelsDir, 'spot');
  if (!existsSync(path.join(spot, 'spot.obj'))) {
    skipped.push(`spot upload: ${spot} is absent`);
    console.log(`SKIP spot upload: ${spot} is absent; the demo model stands in`);
    return false;
  }
  const before = await rendersShown(page);
  await page.setInputFiles('#folder-input', spot);
  await page.waitForFunction(() => document.getElementById('model-select').value !== '', null, { timeout: STEP_TIMEOUT_MS });
  await waitForFullRender(page, before, STEP_TIMEOUT_MS);
  const status = await page.textContent('#upload-status');
  check(/spot\.obj · 5856 triangles/.test(status) && /1 textures/.test(status), 'spot uploaded through the folder input', status);
  const options = await page.locator('#model-select option').allTextContents();
  check(options.some((o) => o.startsWith('spot.obj')), 'the model list offers spot', options.join(' | '));
  await shot(page, '02-spot-uploaded.png');
  return true;
}

async function checkOutlineSlider(page, requests) {
  const before = await imageStats(page);
  const shown = await rendersShown(page);
  requests.length = 0;
  await dragSlider(page, '/outline/width', 8);
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  const after = await imageStats(page);
  const width = Number(await page.inputValue('[data-path="/outline/width"] input[type=number]'));
  check(width >= 7 && width <= 9, 'dragging the outline-width slider sets the width', `width ${width}`);
  // A ring about 6 px wider around the silhouette: thousands more dark pixels.
  check(after.dark - before.dark > 1500, 'a wider outline darkens the image',
    `dark pixels ${before.dark} → ${after.dark}`);
  // The full render leaves width to the default (512); quick ones ask for less.
  const quick = requests.filter((r) => r.width !== undefined && r.width < 512).length;
  const last = requests[requests.length - 1];
  check(quick >= 1 && last !== undefined && (last.width ?? 512) === 512, 'quick low-resolution renders while dragging, then one full render',
    `${quick} quick of ${requests.length}, last ${last?.width ?? 'default 512'} px`);
  check(requests.maxInFlight === 1, 'at most one render request in flight', `max ${requests.maxInFlight}`);
  await shot(page, '03-outline-width-8.png');
}

async function checkInlineError(page) {
  const errorsBefore = Number((await page.getAttribute('#view', 'data-errors')) || 0);
  const box = page.locator('[data-path="/outline/width"] input[type=number]');
  await box.fill('1000');
  await box.press('Enter');
  await page.waitForFunction((n) => Number(document.getElementById('view').dataset.errors || 0) > n, errorsBefore,
    { timeout: STEP_TIMEOUT_MS });
  const field = page.locator('.field[data-path="/outline/width"]');
  const invalid = await field.evaluate((f) => f.classList.contains('invalid'));
  const message = await field.locator('.field-error').textContent();
  check(invalid && /outline\/width/.test(message) && /64/.test(message),
    'an out-of-range width is marked at its control with the server\'s message', message);
  check((await box.getAttribute('aria-invalid')) === 'true', 'the control at fault is aria-invalid');
  await shot(page, '04-inline-error.png');
  const shown = await rendersShown(page);
  await box.fill('4');
  await box.press('Enter');
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(await field.evaluate((f) => !f.classList.contains('invalid')), 'a good value clears the error');
}

async function checkOrbit(page) {
  const yaw = async () => Number(await page.inputValue('[data-path="/camera/yaw"] input[type=number]'));
  const before = { yaw: await yaw(), image: await imageStats(page) };
  const shown = await rendersShown(page);
  const box = await page.locator('#viewport').boundingBox();
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(cx + i * 12, cy + i * 3);
  await page.mouse.up();
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  const after = { yaw: await yaw(), image: await imageStats(page) };
  // 120 px right at 0.5°/px turns the camera 60° toward -X.
  check(Math.abs(after.yaw - (before.yaw - 60)) < 1.5, 'dragging the image orbits the camera',
    `yaw ${before.yaw} → ${after.yaw}`);
  check(after.image.hash !== before.image.hash, 'the orbited image differs');
  await shot(page, '05-orbited.png');
}

async function checkReloadFromUrl(context, page) {
  const url = page.url();
  const original = await imageStats(page);
  check(url.includes('#') && decodeURIComponent(url).includes('"yaw"'), 'the URL holds the state', url.slice(0, 120));
  const fresh = await context.newPage();
  await fresh.goto(url);
  await waitForFullRender(fresh, 0);
  const again = await imageStats(fresh);
  check(again.hash === original.hash && again.width === original.width,
    'a reload from the URL renders the same image', `${original.hash} vs ${again.hash}`);
  await fresh.close();
}

async function checkKeyboard(page) {
  let shown = await rendersShown(page);
  await page.locator('#viewport').focus();
  await page.keyboard.press('3');
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(await page.inputValue('#preset-select') === 'bw_comic', 'key 3 picks the B&W comic mode');
  await shot(page, '06-key-3-bw-comic.png');
  const zoom = async () => Number(await page.inputValue('[data-path="/camera/zoom"] input[type=number]'));
  const z0 = await zoom();
  shown = await rendersShown(page);
  await page.keyboard.press('w');
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(await zoom() > z0, 'w zooms in', `${z0} → ${await zoom()}`);
  const light = async () => Number(await page.inputValue('[data-path="/lights/0/direction/0"] input[type=number]'));
  const x0 = await light();
  shown = await rendersShown(page);
  await page.keyboard.press('l');
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(Math.abs(await light() - (x0 + 0.1)) < 1e-6, 'l moves the light along +x', `${x0} → ${await light()}`);
  await page.keyboard.press('?');
  check(await page.evaluate(() => document.getElementById('help').open), '? opens the key list');
  await shot(page, '07-help.png');
  await page.keyboard.press('Escape');
  await page.keyboard.press('g');
  check(await page.locator('#panel').isHidden(), 'g hides the control panel');
  await page.keyboard.press('g');
  shown = await rendersShown(page);
  await page.keyboard.press('r');
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(!decodeURIComponent(page.url()).includes('"camera"'), 'r resets the view');
}

// Several files dropped on the page (what a file manager's multi-select
// drop gives): the OBJ and its MTL go up as one bundle, a note beside them
// stays behind, and the new model is the one shown.
async function checkDropUpload(page) {
  const before = await rendersShown(page);
  await page.evaluate(() => {
    const v = [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]];
    const faces = [[1, 4, 3, 2], [5, 6, 7, 8], [1, 2, 6, 5], [2, 3, 7, 6], [3, 4, 8, 7], [4, 1, 5, 8]];
    const obj = 'mtllib box.mtl\nusemtl teal\n' + v.map((p) => `v ${p.join(' ')}`).join('\n') + '\n'
      + faces.map((f) => `f ${f.join(' ')}`).join('\n') + '\n';
    const dt = new DataTransfer();
    dt.items.add(new File([obj], 'box.obj'));
    dt.items.add(new File(['newmtl teal\nKd 0.1 0.6 0.6\n'], 'box.mtl'));
    dt.items.add(new File(['not part of the model'], 'notes.txt'));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await page.waitForFunction(() => /box\.obj/.test(document.getElementById('upload-status').textContent), null,
    { timeout: STEP_TIMEOUT_MS });
  await waitForFullRender(page, before, STEP_TIMEOUT_MS);
  const status = await page.textContent('#upload-status');
  check(/box\.obj · 12 triangles/.test(status), 'a multi-file drop uploads the OBJ with its MTL', status);
  const selected = await page.evaluate(() => document.getElementById('model-select').selectedOptions[0]?.textContent);
  check(/^box\.obj/.test(selected ?? ''), 'the dropped model is the one shown', selected);
  const info = await page.evaluate(async () => {
    const id = document.getElementById('model-select').value;
    return (await fetch(`/models/${id}`)).json();
  });
  check(JSON.stringify(info.files) === JSON.stringify(['box.mtl', 'box.obj']), 'the note was left out of the bundle',
    JSON.stringify(info.files));
  await shot(page, '09-dropped-box.png');
}

async function checkNarrow(context, url) {
  const phone = await context.newPage();
  await phone.setViewportSize({ width: 390, height: 844 });
  await phone.goto(url);
  await waitForFullRender(phone, 0);
  const overflow = await phone.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  check(overflow <= 0, 'no sideways scrolling at phone width', `${overflow} px too wide`);
  const imageWidth = (await phone.locator('#view').boundingBox()).width;
  check(imageWidth > 300 && imageWidth <= 390, 'the image fills a phone-width window', `${imageWidth} px`);
  await shot(phone, '08-phone-width.png');
  await phone.close();
}

async function checkLostServer(page, daemon, dataDir) {
  const port = new URL(daemon.url).port;
  await stopDaemon(daemon);
  await page.keyboard.press('s');
  await page.waitForSelector('#banner:not([hidden])', { timeout: STEP_TIMEOUT_MS });
  check(/Lost the toond server/.test(await page.textContent('#banner')), 'a lost server shows a banner');
  await shot(page, '09-lost-server.png');
  // Back on the same port: the page retries, hides the banner and renders.
  const shown = await rendersShown(page);
  const revived = await startToond(`127.0.0.1:${port}`, dataDir);
  await page.waitForSelector('#banner', { state: 'hidden', timeout: STEP_TIMEOUT_MS });
  await waitForFullRender(page, shown, STEP_TIMEOUT_MS);
  check(true, 'the page reconnects when the server is back');
  return revived;
}

// ---- main -------------------------------------------------------------------------

const dataDir = mkdtempSync(path.join(tmpdir(), 'toond-browser-'));
let daemon = null;
let browser = null;
const started = Date.now();
try {
  daemon = await startToond('127.0.0.1:0', dataDir);
  console.log(`toond at ${daemon.url}`);
  browser = await launchChromium(chromium);
  const { context, page, pageErrors } = await openPage(browser, { width: 1280, height: 800 });
  const requests = [];
  requests.maxInFlight = 0;
  let inFlight = 0;
  page.on('request', (r) => {
    if (!r.url().endsWith('/render')) return;
    inFlight += 1;
    requests.maxInFlight = Math.max(requests.maxInFlight, inFlight);
    try { requests.push(JSON.parse(r.postData() || '{}')); } catch { /* not JSON */ }
  });
  const settle = (r) => { if (r.url().endsWith('/render')) inFlight -= 1; };
  page.on('requestfinished', settle);
  page.on('requestfailed', settle);

  await page.goto(daemon.url + '/');
  await waitForFullRender(page, 0, STEP_TIMEOUT_MS);
  check(await page.inputValue('#model-select') === '', 'the demo model is shown on first load');
  check(/passes: \S/.test(await page.textContent('#timing')), 'render time and passes are shown',
    await page.textContent('#timing'));
  await shot(page, '01-demo.png');

  await checkControls(page, daemon.url);
  await page.goto(daemon.url + '/');  // drop the ramp stop the control check added
  await waitForFullRender(page, 0, STEP_TIMEOUT_MS);
  for (const type of ['javascript', 'css']) {
    const res = await fetch(`${daemon.url}/${type === 'css' ? 'style.css' : 'app.js'}`);
    check(res.headers.get('content-type').startsWith(`text/${type}`), `page files are served as text/${type}`);
  }

  await uploadSpot(page);
  await checkOutlineSlider(page, requests);
  await checkInlineError(page);
  await checkOrbit(page);
  await checkReloadFromUrl(context, page);
  await checkKeyboard(page);
  await checkNarrow(context, page.url());
  await checkDropUpload(page);
  daemon = await checkLostServer(page, daemon, dataDir);
  check(pageErrors.length === 0, 'no uncaught errors in the page', pageErrors.join(' | '));
} catch (e) {
  check(false, 'the browser test ran to the end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) await stopDaemon(daemon);
  rmSync(dataDir, { recursive: true, force: true });
}

console.log(`browser test: ${failures} failed, ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in ${artifacts}`);
if (failures > 0) process.exit(1);
if (skipped.length > 0) {
  console.log(`skipped: ${skipped.join('; ')}`);
  process.exit(SKIP);
}
process.exit(0);
