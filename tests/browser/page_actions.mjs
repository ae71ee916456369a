// What the page tests do to the page and read off it.

// Drags the thumb of the slider at JSON pointer `pointer` from its value to
// `to`, in eight mouse moves (the page renders while it is dragged).
// `midway`, when given, is awaited with the button still held halfway
// along, so a test can wait there for what a drag in progress must do.
export async function dragSlider(page, pointer, to, midway = null) {
  const slider = page.locator(`[data-path="${pointer}"] input[type=range]`);
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  const [min, max, value] = await slider.evaluate((s) => [Number(s.min), Number(s.max), Number(s.value)]);
  // The thumb's centre runs from half a thumb inside either end; 8 px covers Chromium's.
  const xOf = (v) => box.x + 8 + ((v - min) / (max - min)) * (box.width - 16);
  const y = box.y + box.height / 2;
  await page.mouse.move(xOf(value), y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) {
    await page.mouse.move(xOf(value + ((to - value) * i) / 8), y);
    if (i === 4 && midway) await midway();
  }
  await page.mouse.up();
}

// The image an <img> shows (`selector`, default the render), decoded by
// the browser without premultiplying: its size, its dark pixels (every
// channel below 48), its translucent ones, and a hash of its RGBA.
export function imageStats(page, selector = '#view') {
  return page.evaluate(async (sel) => {
    const blob = await (await fetch(document.querySelector(sel).src)).blob();
    const bitmap = await createImageBitmap(blob, { premultiplyAlpha: 'none' });
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const g = canvas.getContext('2d');
    g.drawImage(bitmap, 0, 0);
    const d = g.getImageData(0, 0, bitmap.width, bitmap.height).data;
    let dark = 0;
    let transparent = 0;
    let hash = 2166136261;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] + d[i + 1] + d[i + 2] < 3 * 48) dark += 1;
      if (d[i + 3] < 255) transparent += 1;
      hash = Math.imul(hash ^ (d[i] | (d[i + 1] << 8) | (d[i + 2] << 16) | (d[i + 3] << 24)), 16777619) >>> 0;
    }
    return { width: bitmap.width, height: bitmap.height, dark, transparent, hash };
  }, selector);
}

// How many images the page has shown (its #view counts them).
export async function rendersShown(page) {
  return Number((await page.getAttribute('#view', 'data-renders')) || 0);
}

// Waits until the page shows a full-quality render newer than the
// `after`-th, with nothing pending behind it.
export async function waitForFullRender(page, after, timeoutMs) {
  await page.waitForFunction((n) => {
    const v = document.getElementById('view');
    return Number(v.dataset.renders || 0) > n && v.dataset.kind === 'full' && v.dataset.settled === 'yes';
  }, after, { timeout: timeoutMs });
}
