// toond against three.js in one run, on the same machine: the Stanford bunny
// at 512², 3 bands, outline, without AA and with MSAA 4 / antialias:true.
// toond: warm request-to-PNG over HTTP on 127.0.0.1 (toond_bench versus).
// three.js: MeshToonMaterial + OutlineEffect in headless Chromium, render →
// canvas.toBlob PNG per frame, with SwiftShader and with ANGLE on Mesa
// llvmpipe (--use-gl=angle --use-angle=gl-egl). Writes compare.json and
// compare.md to --out and prints the table.
//
//   node bench/threejs/compare.mjs [--bench build/bench/toond_bench]
//        [--out bench/results] [--frames 20] [--models ../shared/models] [--quick] [--reuse-toond]
import { spawnSync } from 'node:child_process';
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, mkdirSync, existsSync, statSync } from 'node:fs';
import { dirname, join, resolve, extname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
const repo = resolve(here, '..', '..');
const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const quick = args.includes('--quick');
const bench = resolve(opt('--bench', join(repo, 'build', 'bench', 'toond_bench')));
const out = resolve(opt('--out', join(repo, 'bench', 'results')));
const frames = Number(opt('--frames', quick ? 8 : 20));
const models = resolve(opt('--models', join(repo, '..', 'shared', 'models')));
const chromiumPath = opt('--chromium', '/usr/bin/chromium');
mkdirSync(out, { recursive: true });

// 1. toond, through its own driver (starts a daemon of its own).
// --reuse-toond: take versus.json from an earlier run instead.
if (!args.includes('--reuse-toond')) {
  console.error(`compare: toond via ${bench}`);
  const toondRun = spawnSync(bench, ['versus', '--out', out, '--models', models, '--repeats',
    String(Math.ceil(frames / 4)), ...(quick ? ['--quick'] : [])], { stdio: ['ignore', 'inherit', 'inherit'] });
  if (toondRun.status !== 0) throw new Error(`toond_bench versus failed (${toondRun.status})`);
}
const toond = JSON.parse(readFileSync(join(out, 'versus.json'), 'utf8'));

// 2. three.js: a static server for the page, three and the model.
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.obj': 'text/plain' };
const server = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  const file = path.startsWith('/models/') ? join(models, path.slice('/models/'.length)) : join(here, path);
  if (!file.startsWith(here) && !file.startsWith(models)) { res.writeHead(403).end(); return; }
  if (!existsSync(file) || !statSync(file).isFile()) { res.writeHead(404).end(); return; }
  res.writeHead(200, { 'Content-Type': types[extname(file)] || 'application/octet-stream' });
  res.end(readFileSync(file));
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const base = `http://127.0.0.1:${server.address().port}`;

const backends = [
  { name: 'SwiftShader', args: ['--enable-unsafe-swiftshader'] },
  { name: 'ANGLE on Mesa llvmpipe', args: ['--use-gl=angle', '--use-angle=gl-egl', '--ignore-gpu-blocklist'] },
];
const three = [];
for (const backend of backends) {
  for (const aa of [false, true]) {
    const browser = await chromium.launch({ executablePath: chromiumPath, headless: true,
      args: ['--no-sandbox', '--headless=new', ...backend.args] });
    try {
      const page = await browser.newPage({ viewport: { width: 600, height: 600 } });
      page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
      await page.goto(`${base}/index.html?aa=${aa ? 1 : 0}&size=512&model=/models/stanford-bunny/stanford-bunny.obj`);
      await page.waitForFunction(() => window.benchReady === true, null, { timeout: 120000 });
      const r = await page.evaluate((n) => window.runBench(n), frames);
      writeFileSync(join(out, `threejs-${backend.name.split(' ')[0].toLowerCase()}-${aa ? 'aa' : 'noaa'}.png`),
        Buffer.from(r.png.split(',')[1], 'base64'));
      delete r.png;
      three.push({ backend: backend.name, ...r });
      console.error(`  three.js ${backend.name} ${aa ? 'antialias' : 'no AA'}: ${r.median_ms.toFixed(2)} ms ` +
        `(${r.renderer}, ${r.samples} samples, ${r.triangles} triangles)`);
    } finally {
      await browser.close();
    }
  }
}
server.close();

// 3. Ratios at equal output settings: no AA ↔ msaa 1, antialias ↔ msaa 4.
const rows = [];
for (const c of toond.configs) {
  for (const t of three.filter((x) => x.antialias === (c.msaa > 1))) {
    rows.push({
      toond: `lod ${c.lod}, msaa ${c.msaa}`, three: `${t.backend}, ${t.antialias ? 'antialias' : 'no AA'}`,
      toond_ms: c.wall_ms, toond_server_ms: c.server_ms, floor_ms: c.floor.total_ms, three_ms: t.median_ms,
      ratio: c.wall_ms / t.median_ms, target: c.lod === 'auto' ? 0.25 : 0.5,
      lod_drawn: c.lod_drawn, pct_off_vs_full: c.pct_pixels_off_vs_full ?? null,
    });
  }
}
const result = { toond, three, rows, frames };
writeFileSync(join(out, 'compare.json'), JSON.stringify(result, null, 1));
const f = (x, d = 2) => (x === null || x === undefined ? '–' : Number(x).toFixed(d));
let md = '| toond (request-to-PNG) | three.js (frame-to-PNG) | toond ms | server ms (floor) | three.js ms | ratio | target | auto vs full, % px off |\n';
md += '|---|---|---:|---:|---:|---:|---:|---:|\n';
for (const r of rows) {
  md += `| ${r.toond} | ${r.three} | ${f(r.toond_ms)} | ${f(r.toond_server_ms)} (${f(r.floor_ms)}) | ${f(r.three_ms)} | ` +
    `${f(r.ratio, 3)} ${r.ratio <= r.target ? '✓' : '✗'} | ≤ ${r.target} | ${f(r.pct_off_vs_full, 3)} |\n`;
}
if (toond.load) {
  md += '\n| clients | requests/s | p50 ms | p99 ms | failed |\n|---:|---:|---:|---:|---:|\n';
  for (const l of toond.load) md += `| ${l.clients} | ${f(l.requests_per_s, 1)} | ${f(l.p50_ms, 1)} | ${f(l.p99_ms, 1)} | ${l.failures} |\n`;
}
writeFileSync(join(out, 'compare.md'), md);
console.log(md);
