// PNGs from toond decoded by Chromium's own decoder, every pixel compared
// bit for bit: frames rendered by a real toond (their raw pixels taken from
// libpng's decode, tests/png_decoders/write_png_samples.cpp) and the encoder
// samples of every layout (palette, palette + tRNS, RGB, RGBA, strips).
//   node png_decode.test.mjs --toond PATH --samples-writer PATH --work DIR
// Exit 0: every image decodes exactly; 1: one does not, or the run failed.
//
// Pixels are read back through WebGL from an ImageBitmap made without
// premultiplied alpha or colour conversion: a 2D canvas stores premultiplied
// colour and would round translucent pixels on the way back.
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { argument, decodePngInPage, startDaemon } from './harness.mjs';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const { chromium } = await import(path.join(here, 'node_modules/playwright-core/index.mjs')).catch(() => {
  console.error('playwright-core is not installed: run tests/browser/install.sh');
  process.exit(1);
});

const toondBinary = argument('--toond');
const samplesWriter = argument('--samples-writer');
const work = argument('--work');
const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);

let failures = 0;
function check(condition, what, detail = '') {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}${detail ? ` (${detail})` : ''}`);
  if (!condition) failures += 1;
}

function startDaemonIn(dataDir) {
  return startDaemon(toondBinary, '127.0.0.1:0', dataDir, STEP_TIMEOUT_MS);
}

// Default parameters but the size and background: opaque frames at the two
// sizes the encode budget names, and one on a transparent background.
const FRAMES = {
  'demo-512': { width: 512, height: 512 },
  'demo-1024': { width: 1024, height: 1024 },
  'demo-512-transparent': { width: 512, height: 512, background: [0.9, 0.9, 0.95, 0] },
  'demo-256-no-msaa': { width: 256, height: 256, msaa: 1 },
};

async function renderFrames(url, dir) {
  const paths = [];
  for (const [name, params] of Object.entries(FRAMES)) {
    const res = await fetch(`${url}/render`, { method: 'POST', body: JSON.stringify(params), headers: { 'Content-Type': 'application/json' } });
    if (res.status !== 200) throw new Error(`render ${name}: ${res.status} ${await res.text()}`);
    const file = path.join(dir, `${name}.png`);
    writeFileSync(file, Buffer.from(await res.arrayBuffer()));
    paths.push(file);
  }
  return paths;
}

async function compare(page, name, pngFile, rawFile, width, height, colourType) {
  const decoded = await page.evaluate(decodePngInPage, readFileSync(pngFile).toString('base64'));
  const raw = readFileSync(rawFile);
  const got = Buffer.from(decoded.rgba, 'base64');
  let detail = `${width}x${height}, colour type ${colourType}`;
  let same = decoded.width === width && decoded.height === height && got.equals(raw);
  if (!same && got.length === raw.length) {
    let i = 0;
    while (got[i] === raw[i]) i += 1;
    const p = Math.floor(i / 4);
    detail += `; pixel (${p % width}, ${Math.floor(p / width)}) is ${[...got.subarray(p * 4, p * 4 + 4)]}, was ${[...raw.subarray(p * 4, p * 4 + 4)]}`;
  } else if (!same) {
    detail += `; decoded ${decoded.width}x${decoded.height}`;
  }
  check(same, `Chromium decodes ${name} exactly`, detail);
}

rmSync(work, { recursive: true, force: true });
const framesDir = path.join(work, 'frames');
const samplesDir = path.join(work, 'samples');
const dataDir = path.join(work, 'data');
for (const dir of [framesDir, samplesDir, dataDir]) mkdirSync(dir, { recursive: true });

let daemon = null;
let browser = null;
try {
  daemon = await startDaemonIn(dataDir);
  const frames = await renderFrames(daemon.url, framesDir);
  const writer = spawnSync(samplesWriter, [samplesDir, ...frames], { stdio: 'inherit' });
  check(writer.status === 0, 'the encoder wrote every sample in the colour type expected of it');

  browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    // WebGL on the CPU: no GPU in CI.
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-first-run'],
  });
  const page = await browser.newPage();
  const samples = readFileSync(path.join(samplesDir, 'samples.txt'), 'utf8').trim().split('\n');
  const types = new Set();
  for (const line of samples) {
    const [name, width, height, colourType] = line.split(' ');
    types.add(colourType);
    await compare(page, name, path.join(samplesDir, `${name}.png`), path.join(samplesDir, `${name}.rgba`),
      Number(width), Number(height), colourType);
    // The frame exactly as the server sent it, against libpng's decode of it.
    if (name.startsWith('frame-')) {
      await compare(page, `the server's ${name.slice(6)}.png`, path.join(framesDir, `${name.slice(6)}.png`),
        path.join(samplesDir, `${name}.rgba`), Number(width), Number(height), 'as served');
    }
  }
  check(['2', '3', '6'].every((t) => types.has(t)), 'palette, RGB and RGBA images were all checked', [...types].join(', '));
} catch (e) {
  check(false, 'the PNG decode test ran to the end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) daemon.child.kill('SIGKILL');
}
console.log(`png decode test: ${failures} failed`);
process.exit(failures > 0 ? 1 : 0);
