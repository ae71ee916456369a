// The page's animation section in a real browser (Debian's chromium through
// playwright-core, a real toond on 127.0.0.1:0): hidden for a model without
// clips, shown with a clip selector for Blender's rigged bar, the time
// slider and the play button posing the render through `animation`, a
// range of the clip in seconds (glTF keys by seconds) and, for Minetest's
// player (a B3D, 60 frames a second), in frames, into the render and into a
// sheet whose clip row takes a range and plays once; the player's material
// list (its image and alpha, an alpha chosen there rendered); and gone again
// (with the state's `animation`) for a model without clips.
//   node animation.test.mjs --toond PATH --exported DIR --artifacts DIR
// Exit 0: every check passed; 1: a check failed. Screenshots go to --artifacts.
import { mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { argument, checker, launchChromium, loadChromium, openPage, startDaemon } from './harness.mjs';
import { imageStats, rendersShown, waitForFullRender } from './page_actions.mjs';

const chromium = await loadChromium(path.dirname(fileURLToPath(import.meta.url)));

const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);

const toondBinary = argument('--toond');
const exported = argument('--exported');
const artifacts = argument('--artifacts');
mkdirSync(artifacts, { recursive: true });

const { check, failed } = checker();

async function uploadFiles(url, folder, names) {
  const form = new FormData();
  for (const name of names) {
    form.append('file', new Blob([readFileSync(path.join(exported, folder, name))]), name);
  }
  const res = await fetch(`${url}/models`, { method: 'POST', body: form });
  if (!res.ok) throw new Error(`upload failed: ${res.status} ${await res.text()}`);
  return (await res.json()).id;
}

const uploadRiggedBar = (url) => uploadFiles(url, 'blender', ['rigged.gltf', 'rigged.bin']);

// The body of the last single render asked for.
function lastRender(requests) {
  return requests.filter((r) => !r.url.includes('?')).at(-1)?.body;
}

const dataDir = mkdtempSync(path.join(tmpdir(), 'toond-animation-'));
let daemon = null;
let browser = null;
const started = Date.now();
try {
  daemon = await startDaemon(toondBinary, '127.0.0.1:0', dataDir, STEP_TIMEOUT_MS);
  const id = await uploadRiggedBar(daemon.url);
  const player = await uploadFiles(daemon.url, 'minetest', ['character.b3d', 'character.png']);
  browser = await launchChromium(chromium);
  const { page, pageErrors } = await openPage(browser, { width: 1280, height: 900 });
  const requests = [];
  page.on('request', (r) => {
    if (!/\/render(\?|$)/.test(r.url())) return;
    try { requests.push({ url: r.url(), body: JSON.parse(r.postData() || '{}') }); } catch { /* not JSON */ }
  });
  const start = encodeURIComponent(JSON.stringify({ width: 160, height: 160 }));
  await page.goto(`${daemon.url}/#${start}`);
  await waitForFullRender(page, 0, STEP_TIMEOUT_MS);
  check(await page.locator('#animation').isHidden(), 'the demo model (no clips) shows no animation section');

  let rendered = await rendersShown(page);
  await page.waitForFunction((model) => [...document.querySelectorAll('#model-select option')]
    .some((o) => o.value === model), id, { timeout: STEP_TIMEOUT_MS });
  await page.selectOption('#model-select', id);
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  await page.locator('#animation').waitFor({ state: 'visible', timeout: STEP_TIMEOUT_MS });
  const options = await page.locator('#clip-select option').allTextContents();
  check(options.length === 3 && /Bend \(1\.00 s\)/.test(options[1]) && /Twist \(0\.50 s\)/.test(options[2]),
    'a model with clips shows them, with their durations', options.join(', '));
  const rest = await imageStats(page, '#view');

  rendered = await rendersShown(page);
  await page.selectOption('#clip-select', 'Bend');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(JSON.stringify(lastRender(requests)?.animation) === JSON.stringify({ clip: 'Bend', time: 0 }),
    'choosing a clip renders it at time 0', JSON.stringify(lastRender(requests)?.animation));

  rendered = await rendersShown(page);
  await page.locator('#clip-time').fill('0.5');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  const half = lastRender(requests)?.animation;
  check(half?.clip === 'Bend' && half?.time === 0.5, 'the time slider poses the render', JSON.stringify(half));
  const posed = await imageStats(page, '#view');
  check(posed.hash !== rest.hash, 'the posed image differs from the rest pose');
  check(/0\.500 s/.test(await page.textContent('#clip-time-label')), 'the time is shown');
  check(decodeURIComponent(page.url()).includes('"animation":{"clip":"Bend","time":0.5}'), 'the URL keeps the pose');
  await page.screenshot({ path: path.join(artifacts, '21-animation-bend.png'), fullPage: true });

  // An animated sheet of the clip: its own clips, not the pose above.
  requests.length = 0;
  await page.click('#clip-sheet');
  await page.waitForFunction(() => document.getElementById('sheet-view').dataset.frames === '64'
    && !document.getElementById('sheet').classList.contains('busy'), null, { timeout: STEP_TIMEOUT_MS });
  const sheetBody = requests.filter((r) => r.body.sheet).at(-1)?.body;
  check(sheetBody && JSON.stringify(sheetBody.sheet.animation) === JSON.stringify({ clip: 'Bend', frames: 8 })
        && !('animation' in sheetBody),
  'the sheet button asks for a sheet of the clip alone', JSON.stringify(sheetBody));
  check(/64 frames/.test(await page.textContent('#sheet-status')), 'eight directions of eight frames',
    await page.textContent('#sheet-status'));
  await page.screenshot({ path: path.join(artifacts, '22-animation-sheet.png'), fullPage: true });

  // The sheet's clips are controls, not a JSON box: a clip choice and a
  // frame count per clip, clips added and removed.
  const clipsBox = page.locator('#sheet-controls fieldset.clips');
  check(await clipsBox.isVisible(), 'the sheet shows its clips as a list');
  check(await page.locator('#sheet-controls [data-path="/sheet/animation"] input.json').count() === 0
        && await clipsBox.getAttribute('data-path') === '/sheet/animation', 'sheet.animation is not a JSON box');
  const frameCount = (row = 0) => clipsBox.locator('input[data-path$="/frames"]').nth(row);
  check(await clipsBox.locator('select').inputValue() === 'Bend' && await frameCount().inputValue() === '8',
    'the clip row shows the clip and its frames');
  // Waits for a sheet newer than the one shown when the step began.
  const sheetsShown = () => page.evaluate(() => Number(document.getElementById('sheet-view').dataset.sheets || 0));
  const sheetShown = async (frames, before) => page.waitForFunction(([n, seen]) => {
    const view = document.getElementById('sheet-view');
    return Number(view.dataset.sheets) > seen && view.dataset.frames === String(n)
      && !document.getElementById('sheet').classList.contains('busy');
  }, [frames, before], { timeout: STEP_TIMEOUT_MS });
  const lastSheet = () => requests.filter((r) => r.body.sheet).at(-1)?.body.sheet.animation;
  let before = await sheetsShown();
  await frameCount().fill('4');
  await frameCount().press('Tab');
  await sheetShown(32, before);
  check(JSON.stringify(lastSheet()) === JSON.stringify({ clip: 'Bend', frames: 4 }), 'the frame count asks for 4 frames',
    JSON.stringify(lastSheet()));
  before = await sheetsShown();
  await clipsBox.locator('button.add').click();
  await sheetShown(32 + 64, before);
  check(JSON.stringify(lastSheet()) === JSON.stringify([{ clip: 'Bend', frames: 4 }, { clip: 'Twist', frames: 8 }]),
    'adding a clip asks for both, the new one a clip not yet in the sheet', JSON.stringify(lastSheet()));
  before = await sheetsShown();
  await clipsBox.locator('select').nth(1).selectOption('Bend');
  await sheetShown(32 + 64, before);
  check(JSON.stringify(lastSheet()) === JSON.stringify([{ clip: 'Bend', frames: 4 }, { clip: 'Bend', frames: 8 }]),
    'a clip row chooses its clip', JSON.stringify(lastSheet()));
  await page.screenshot({ path: path.join(artifacts, '23-animation-sheet-clips.png'), fullPage: true });
  before = await sheetsShown();
  await clipsBox.locator('button.remove').first().click();
  await sheetShown(64, before);
  check(JSON.stringify(lastSheet()) === JSON.stringify({ clip: 'Bend', frames: 8 }), 'removing a clip leaves the other',
    JSON.stringify(lastSheet()));
  await page.uncheck('#sheet-toggle');

  requests.length = 0;
  await page.click('#clip-play');
  check(await page.textContent('#clip-play') === 'Pause', 'play turns into pause');
  await page.waitForFunction(() => Number(document.getElementById('view').dataset.renders) > 0, null,
    { timeout: STEP_TIMEOUT_MS });
  // Playing goes on until three steps were asked for, however slow the
  // machine's renders are, and fails only at the step timeout.
  const timesAsked = () => [...new Set(requests.map((r) => r.body.animation?.time).filter((t) => t !== undefined))];
  const playDeadline = Date.now() + STEP_TIMEOUT_MS;
  while (timesAsked().length < 3 && Date.now() < playDeadline) await page.waitForTimeout(100);
  await page.click('#clip-play');
  const times = timesAsked();
  check(times.length >= 3, 'playing steps the time and renders each step it can', times.join(', '));

  // A part of the clip, in seconds: glTF keys by seconds.
  const rangeBox = page.locator('#clip-range');
  check(await rangeBox.isVisible() && (await rangeBox.locator('.range-unit').textContent()) === 's',
    'the clip\'s range is typed in seconds for a glTF clip');
  // Types a range into the bar's boxes and waits for a render that asks
  // for what `asked(range)` accepts, shown.
  const typeRange = async (from, to, asked) => {
    const before = await rendersShown(page);
    await rangeBox.locator('input.range-from').fill(from);
    await rangeBox.locator('input.range-to').fill(to);
    await rangeBox.locator('input.range-to').press('Tab');
    const deadline = Date.now() + STEP_TIMEOUT_MS;
    while (!asked(lastRender(requests)?.animation?.range) && Date.now() < deadline) await page.waitForTimeout(50);
    await waitForFullRender(page, before, STEP_TIMEOUT_MS);
  };
  await typeRange('0.25', '0.75', (range) => JSON.stringify(range) === '[0.25,0.75]');
  const ranged = lastRender(requests)?.animation;
  check(JSON.stringify(ranged?.range) === '[0.25,0.75]' && ranged?.time === 0,
    'the range goes into the render, its time from the range\'s start', JSON.stringify(ranged));
  check(await page.locator('#clip-time').getAttribute('max') === '0.5', 'the time slider runs over the range',
    await page.locator('#clip-time').getAttribute('max'));
  await typeRange('', '', (range) => range === undefined);
  check(!decodeURIComponent(page.url()).includes('"range"') && lastRender(requests)?.animation?.clip === 'Bend',
    'emptied, the range is the whole clip again', JSON.stringify(lastRender(requests)?.animation));

  // Minetest's player: its B3D counts frames, 60 a second; its walk is
  // frames 168-187 of its one timeline.
  rendered = await rendersShown(page);
  await page.selectOption('#model-select', player);
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  // Its material list: the skin the upload gave it and its alpha as
  // Minetest draws it; a choice there is the request's `materials`.
  await page.locator('#materials').waitFor({ state: 'visible', timeout: STEP_TIMEOUT_MS });
  const row = (await page.locator('#material-table tr').nth(1).allTextContents()).join(' ');
  check(/Character/.test(row) && /character\.png/.test(row) && /mask 0\.5 \(file\)/.test(row),
    'the material list shows the material, its image and its alpha', row);
  rendered = await rendersShown(page);
  await page.selectOption('#material-table select', 'opaque');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(lastRender(requests)?.materials?.Character?.alpha === 'opaque', 'choosing an alpha renders with it',
    JSON.stringify(lastRender(requests)?.materials));
  rendered = await rendersShown(page);
  await page.selectOption('#material-table select', '');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check(lastRender(requests)?.materials === undefined, 'the file\'s alpha again drops the override',
    JSON.stringify(lastRender(requests)?.materials));
  rendered = await rendersShown(page);
  await page.selectOption('#clip-select', 'anim');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  check((await rangeBox.locator('.range-unit').textContent()) === 'frames',
    'a clip with a frame rate takes its range in frames');
  const atWalk = (range) => Math.abs((range?.[0] ?? 0) - 168 / 60) < 1e-9 && Math.abs((range?.[1] ?? 0) - 187 / 60) < 1e-9;
  await typeRange('168', '187', atWalk);
  const walk = lastRender(requests)?.animation?.range ?? [];
  check(atWalk(walk),
    'frames 168 to 187 go out as seconds at the clip\'s 60 frames a second', JSON.stringify(walk));
  check(/frame 168\b/.test(await page.textContent('#clip-time-label')), 'the label names the frame shown',
    await page.textContent('#clip-time-label'));
  await page.screenshot({ path: path.join(artifacts, '24-animation-range.png'), fullPage: true });

  // The sheet of that part: the clip row shows the range in frames and
  // plays it once when asked.
  requests.length = 0;
  await page.click('#clip-sheet');
  await page.waitForFunction(() => document.getElementById('sheet-view').dataset.frames === '64'
    && !document.getElementById('sheet').classList.contains('busy'), null, { timeout: STEP_TIMEOUT_MS });
  check(JSON.stringify(lastSheet()?.range) === JSON.stringify(walk), 'the sheet of the clip plays its range',
    JSON.stringify(lastSheet()));
  check(await clipsBox.locator('input.range-from').inputValue() === '168'
        && await clipsBox.locator('input.range-to').inputValue() === '187',
  'the sheet\'s clip row shows the range in frames');
  before = await sheetsShown();
  await clipsBox.locator('input.once').check();
  await sheetShown(64, before);
  check(lastSheet()?.loop === false, 'the clip row plays the clip once', JSON.stringify(lastSheet()));
  await page.screenshot({ path: path.join(artifacts, '25-animation-sheet-once.png'), fullPage: true });
  await page.uncheck('#sheet-toggle');

  rendered = await rendersShown(page);
  await page.selectOption('#model-select', '');
  await waitForFullRender(page, rendered, STEP_TIMEOUT_MS);
  await page.waitForFunction(() => document.getElementById('animation').hidden, null, { timeout: STEP_TIMEOUT_MS });
  await page.waitForFunction(() => !decodeURIComponent(location.hash).includes('animation'), null,
    { timeout: STEP_TIMEOUT_MS });
  check(true, 'back on the demo model the section hides and the state drops `animation`');
  check(pageErrors.length === 0, 'no uncaught errors in the page', pageErrors.join(' | '));
} catch (e) {
  check(false, 'the browser test ran to the end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) daemon.child.kill('SIGKILL');
  rmSync(dataDir, { recursive: true, force: true });
}

console.log(`animation test: ${failed()} failed, ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in ${artifacts}`);
process.exit(failed() > 0 ? 1 : 0);
