// What the page tests share: their command line, the toond under test and
// the headless chromium that drives the page.
import { spawn } from 'node:child_process';
import path from 'node:path';
import { createInterface } from 'node:readline';

// Starts toond and waits for its "listening on <url>" line; resolves to
// { child, url }.
export function startDaemon(toondBinary, listen, dataDir, timeoutMs) {
  const child = spawn(toondBinary, ['--listen', listen, '--data-dir', dataDir], { stdio: ['ignore', 'pipe', 'pipe'] });
  child.stderr.on('data', (d) => process.stderr.write(`[toond] ${d}`));
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('toond did not print its listening line')), timeoutMs);
    child.on('exit', (code) => reject(new Error(`toond exited early with ${code}`)));
    createInterface({ input: child.stdout }).on('line', (line) => {
      const m = /listening on (http:\/\/\S+)/.exec(line);
      if (m) {
        clearTimeout(timer);
        resolve({ child, url: m[1] });
      }
    });
  });
}

// Debian's chromium, headless, with the background services that would
// make requests of their own switched off.
export function launchChromium(chromium) {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update',
      '--disable-default-apps', '--disable-sync', '--no-first-run'],
  });
}

// A fresh page of `viewport` in its own context (returned too), and the list its uncaught
// errors go to (a test ends by checking it is empty).
export async function openPage(browser, viewport) {
  const context = await browser.newContext({ viewport });
  const page = await context.newPage();
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));
  return { context, page, pageErrors };
}

// The value after `name` on the command line; throws when it is missing.
export function argument(name) {
  const i = process.argv.indexOf(name);
  if (i < 0 || i + 1 >= process.argv.length) throw new Error(`missing ${name}`);
  return process.argv[i + 1];
}

// playwright-core's chromium from the tests' own node_modules; exits 1 with
// the way to install it when it is missing.
export async function loadChromium(testFolder) {
  const { chromium } = await import(path.join(testFolder, 'node_modules/playwright-core/index.mjs')).catch(() => {
    console.error('playwright-core is not installed: run tests/browser/install.sh');
    process.exit(1);
  });
  return chromium;
}

// A test's checks: each prints ok or FAIL with what it checked; `failed()`
// counts the FAILs.
export function checker() {
  let failures = 0;
  return {
    check(condition, what, detail = '') {
      console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}${detail ? ` (${detail})` : ''}`);
      if (!condition) failures += 1;
    },
    failed: () => failures,
  };
}

// Runs in a page (page.evaluate): the PNG's pixels as Chromium decodes
// them, RGBA rows top to bottom, base64. Read back through WebGL from an
// ImageBitmap made without premultiplied alpha or colour conversion: a 2D
// canvas stores premultiplied colour and would round translucent pixels.
export async function decodePngInPage(pngBase64) {
  const bytes = Uint8Array.from(atob(pngBase64), (c) => c.charCodeAt(0));
  const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }),
    { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
  const { width, height } = bitmap;
  const gl = new OffscreenCanvas(width, height).getContext('webgl2', { premultipliedAlpha: false });
  if (!gl) throw new Error('no WebGL2 context');
  gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
  gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
  gl.bindTexture(gl.TEXTURE_2D, gl.createTexture());
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, bitmap);
  gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, gl.getParameter(gl.TEXTURE_BINDING_2D), 0);
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let binary = '';
  for (let i = 0; i < pixels.length; i += 0x8000) binary += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
  return { width, height, rgba: btoa(binary) };
}
