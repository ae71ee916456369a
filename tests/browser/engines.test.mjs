// toond's sprite sheets in the game engines themselves: the npm packages of
// Phaser and PixiJS (versions pinned in package.json) load a real toond
// sheet and its atlas (Blender's walking character, 4 directions × 6 frames
// of its Walk clip) in Debian's chromium, as a game would, from one JSON:
//   Phaser: this.load.aseprite(key, png, json), this.anims.createFromAseprite(key);
//   PixiJS: new Spritesheet(texture, atlas).parse().
// The atlas is also checked against the JSON Aseprite itself writes
// (aseprite_format.mjs). A turntable sheet (two pitches) goes through both
// engines too, and a one-shot (the walk with loop: false, whose tags say
// Aseprite's "repeat": "1"): Phaser plays it once and stops on its last
// frame; PixiJS reads no tags at all, so a game gives its AnimatedSprite
// loop = false from the tag itself. The walk packed (sheet.pack: trimmed
// frames, spriteSourceSize, sourceSize) plays the same 4 animations of 6
// frames in both engines, and each frame is drawn on the same pixels as its
// grid tile.
//   node engines.test.mjs --toond PATH --exported DIR --artifacts DIR
// Exit 0: every check passed; 1: a check failed.
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { asepriteProblems } from './aseprite_format.mjs';
import { argument, checker, launchChromium, loadChromium, openPage, startDaemon } from './harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const chromium = await loadChromium(here);

const STEP_TIMEOUT_MS = Number(process.env.TOOND_BROWSER_STEP_TIMEOUT_MS || 45000);
const ORIGIN = 'http://engines.toond.test';

const toondBinary = argument('--toond');
const exported = argument('--exported');
const artifacts = argument('--artifacts');
mkdirSync(artifacts, { recursive: true });

const { check, failed } = checker();
const checkOne = check;

const versionOf = (name) => JSON.parse(readFileSync(path.join(here, 'node_modules', name, 'package.json'), 'utf8')).version;

async function upload(url, file) {
  const form = new FormData();
  form.append('file', new Blob([readFileSync(file)]), path.basename(file));
  const res = await fetch(`${url}/models`, { method: 'POST', body: form });
  if (!res.ok) throw new Error(`upload failed: ${res.status} ${await res.text()}`);
  return res.json();
}

async function post(url, body) {
  const res = await fetch(url, { method: 'POST', body: JSON.stringify(body), headers: { 'Content-Type': 'application/json' } });
  if (!res.ok) throw new Error(`${url} answered ${res.status}: ${await res.text()}`);
  return Buffer.from(await res.arrayBuffer());
}

// The sheet's PNG and, asked for apart with ?atlas=json, its atlas: what a
// user saves as sheet.png and sheet.json.
async function sheetOf(url, request) {
  const [png, json] = await Promise.all([post(`${url}/render`, request), post(`${url}/render?atlas=json`, request)]);
  return { png, json, atlas: JSON.parse(json.toString('utf8')) };
}

// A page on ORIGIN that holds both engines and one sheet per name.
async function enginePage(browser, sheets) {
  const { context, page, pageErrors } = await openPage(browser, { width: 640, height: 480 });
  const files = {
    '/': { body: '<!doctype html><meta charset="utf-8"><title>engines</title><body></body>', type: 'text/html' },
    '/phaser.min.js': { body: readFileSync(path.join(here, 'node_modules/phaser/dist/phaser.min.js')), type: 'text/javascript' },
    '/pixi.min.js': { body: readFileSync(path.join(here, 'node_modules/pixi.js/dist/pixi.min.js')), type: 'text/javascript' },
  };
  for (const [name, sheet] of Object.entries(sheets)) {
    files[`/${name}.png`] = { body: sheet.png, type: 'image/png' };
    files[`/${name}.json`] = { body: sheet.json, type: 'application/json' };
    // As saved beside each other under the atlas's own meta.image name.
    files[`/${name}/${sheet.atlas.meta.image}`] = files[`/${name}.png`];
    files[`/${name}/sheet.json`] = files[`/${name}.json`];
  }
  await context.route(`${ORIGIN}/**`, (route) => {
    const file = files[new URL(route.request().url()).pathname];
    return file ? route.fulfill({ body: file.body, contentType: file.type }) : route.fulfill({ status: 404, body: '' });
  });
  await page.goto(`${ORIGIN}/`);
  await page.addScriptTag({ url: `${ORIGIN}/phaser.min.js` });
  await page.addScriptTag({ url: `${ORIGIN}/pixi.min.js` });
  await page.evaluate(() => {
    // A Phaser game that loads sheet `key` with its Aseprite loader and
    // calls `create` as its scene's create.
    window.phaserGame = (key, create, config = {}) => {
      const parent = document.createElement('div');
      parent.id = `phaser-${key}-${document.body.children.length}`;
      document.body.append(parent);
      return new Phaser.Game({
        type: Phaser.CANVAS, width: 320, height: 240, parent, banner: false, transparent: true,
        audio: { noAudio: true }, ...config,
        scene: { preload() { this.load.aseprite(key, `${key}.png`, `${key}.json`); }, create },
      });
    };
    // PixiJS's Spritesheet of sheet `key`, and the atlas it was made from.
    window.pixiSheet = async (key) => {
      const image = new Image();
      image.src = `${key}.png`;
      await image.decode();
      const atlas = await (await fetch(`${key}.json`)).json();
      const sheet = new PIXI.Spritesheet(PIXI.Texture.from(image), atlas);
      await sheet.parse();
      return { atlas, sheet };
    };
  });
  return { page, pageErrors };
}

// Phaser as its documentation loads an Aseprite export; then a sprite plays
// the first animation. Answers what Phaser made of it.
function phaserLoads(page, name) {
  return page.evaluate(([key, stepTimeout]) => new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('Phaser did not finish')), stepTimeout);
    const game = window.phaserGame(key, function create() {
      const made = this.anims.createFromAseprite(key);
      const texture = this.textures.get(key);
      const animations = made.map((anim) => ({
        key: anim.key,
        frames: anim.frames.map((f) => f.textureFrame),
        durations: anim.frames.map((f) => f.duration),
        duration: anim.duration,
      }));
      const first = texture.get('0');
      const pivot = { custom: first.customPivot, x: first.pivotX, y: first.pivotY };
      const sprite = this.add.sprite(160, 120, key);
      const shown = [];
      let error = null;
      sprite.on('animationupdate', (anim, frame) => shown.push(frame.textureFrame));
      try {
        // A walk loops: Aseprite's tags play once unless told to repeat.
        if (made.length) sprite.play({ key: made[0].key, repeat: -1 });
      } catch (e) {
        error = String(e);
      }
      const startFrame = sprite.anims.currentFrame?.textureFrame ?? null;
      const finish = () => {
        clearTimeout(timer);
        const result = { animations, pivot, shown: [...shown], startFrame, error, repeats: made.map((a) => a.repeat),
          origin: { x: sprite.originX, y: sprite.originY }, renderer: game.renderer.type };
        game.destroy(true);
        resolve(result);
      };
      // A full loop shown, or give up after the step's time.
      const poll = setInterval(() => {
        if (shown.length >= (made[0]?.frames.length ?? 0) || error) {
          clearInterval(poll);
          finish();
        }
      }, 50);
    });
  }), [name, STEP_TIMEOUT_MS]);
}

// PixiJS's Spritesheet on the same JSON: its textures and animations; an
// AnimatedSprite of the first animation stepped by hand, at Pixi's own pace
// and then at the atlas's durations (Pixi's frame objects: {texture, time}),
// each step half a millisecond past the frame's time.
function pixiLoads(page, name) {
  return page.evaluate(async (key) => {
    const { atlas, sheet } = await window.pixiSheet(key);
    const anchor = (t) => ({ x: t.defaultAnchor?.x, y: t.defaultAnchor?.y });
    const animations = Object.fromEntries(Object.entries(sheet.animations).map(([anim, textures]) => [anim,
      textures.map((t) => t && { label: t.label, x: t.frame.x, y: t.frame.y, w: t.frame.width, h: t.frame.height,
        anchor: anchor(t) })]));
    const textures = Object.keys(sheet.textures).length;
    const [firstName, first] = Object.entries(sheet.animations)[0] ?? [];
    if (!first?.length) return { textures, animations, seen: [], timedSeen: [], anchor: {} };
    const sprite = new PIXI.AnimatedSprite({ textures: first, autoUpdate: false });
    sprite.play();
    const seen = [sprite.currentFrame];
    for (let i = 0; i < first.length; i++) {
      sprite.update({ deltaTime: 1 / sprite.animationSpeed, deltaMS: 1000 / 60 });
      seen.push(sprite.currentFrame);
    }
    const times = (atlas.animations?.[firstName] ?? []).map((frame) => atlas.frames[frame].duration);
    const timed = new PIXI.AnimatedSprite({
      textures: first.map((texture, i) => ({ texture, time: times[i] })), autoUpdate: false });
    timed.play();
    const timedSeen = [timed.currentFrame];
    for (const ms of times) {
      timed.update({ deltaTime: ((ms + 0.5) * 60) / 1000, deltaMS: ms + 0.5 });
      timedSeen.push(timed.currentFrame);
    }
    // The usual way: Assets.load on the JSON, which finds the image by meta.image.
    const loaded = await PIXI.Assets.load(`${key}/sheet.json`);
    const viaAssets = Object.fromEntries(Object.entries(loaded.animations ?? {}).map(([n, t]) => [n, t.length]));
    return { textures, animations, seen, timedSeen, viaAssets, anchor: { x: sprite.anchor.x, y: sprite.anchor.y } };
  }, name);
}

// Every frame of sheet `key` drawn alone by Phaser (canvas) and by PixiJS
// (WebGL), without smoothing, the sprite placed so that its tile's top left
// falls on the whole pixel (100, 120) whatever its anchor; the pixels are
// kept in the page (window.drawn) for sameDrawing to compare. A packed
// frame is drawn at its trim offset inside that tile, so a packed sheet
// and its grid must draw alike.
function drawFrames(page, name) {
  return page.evaluate(([key, stepTimeout]) => new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`Phaser did not draw ${key}`)), stepTimeout);
    window.drawn = window.drawn ?? {};
    const game = window.phaserGame(key, function create() {
      const names = this.textures.get(key).getFrameNames().sort((a, b) => a - b);
      const sprite = this.add.sprite(0, 0, key, names[0]);
      const frames = [];
      const place = () => {
        sprite.setFrame(names[frames.length]);
        sprite.setPosition(100 + sprite.originX * sprite.width, 120 + sprite.originY * sprite.height);
      };
      place();
      this.game.events.on('postrender', () => {
        if (frames.length === names.length) return;
        frames.push(this.game.canvas.getContext('2d').getImageData(0, 0, 200, 160).data);
        if (frames.length < names.length) {
          place();
          return;
        }
        clearTimeout(timer);
        window.drawn[`phaser:${key}`] = frames;
        setTimeout(() => game.destroy(true), 0);
        resolve();
      });
    }, { width: 200, height: 160, antialias: false });
  }).then(async () => {
    const { sheet } = await window.pixiSheet(key);
    sheet.textureSource.scaleMode = 'nearest';
    const renderer = await PIXI.autoDetectRenderer({ width: 200, height: 160, preference: 'webgl', backgroundAlpha: 0 });
    const frames = [];
    for (const name of Object.keys(sheet.textures).sort((a, b) => a - b)) {
      const sprite = new PIXI.Sprite(sheet.textures[name]);
      const { width, height } = sprite.texture.orig;
      sprite.position.set(100 + sprite.anchor.x * width, 120 + sprite.anchor.y * height);
      const target = PIXI.RenderTexture.create({ width: 200, height: 160 });
      renderer.render({ container: sprite, target, clear: true });
      frames.push(renderer.extract.pixels(target).pixels);
      target.destroy(true);
      sprite.destroy();
    }
    window.drawn[`pixi:${key}`] = frames;
    renderer.destroy();
  }), [name, STEP_TIMEOUT_MS]);
}

// How the frames `engine` drew of sheets a and b compare: frames that
// differ in any byte, and frames with nothing drawn.
function sameDrawing(page, engine, a, b) {
  return page.evaluate(([e, x, y]) => {
    const one = window.drawn[`${e}:${x}`];
    const other = window.drawn[`${e}:${y}`];
    let differing = 0;
    let empty = 0;
    one.forEach((pixels, i) => {
      if (pixels.some((v, k) => v !== other[i][k])) differing += 1;
      if (!pixels.some((v, k) => k % 4 === 3 && v !== 0)) empty += 1;
    });
    return { frames: one.length, others: other.length, differing, empty };
  }, [engine, a, b]);
}

// Phaser plays a one-shot's first tag as a game plays an attack: as
// createFromAseprite made it, with no repeat of its own given. Answers the
// frames shown, whether it completed, the frame it rests on a while after,
// and each animation's repeat as Phaser holds it.
function phaserPlaysOnce(page, name) {
  return page.evaluate(([key, stepTimeout]) => new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('Phaser did not finish the one-shot')), stepTimeout);
    const game = window.phaserGame(key, function create() {
      const made = this.anims.createFromAseprite(key);
      const sprite = this.add.sprite(160, 120, key);
      const shown = [];
      let completed = 0;
      sprite.on('animationupdate', (anim, frame) => shown.push(frame.textureFrame));
      sprite.on('animationcomplete', () => {
        completed += 1;
        // Rest a whole play more: a one-shot shows nothing further.
        setTimeout(() => {
          clearTimeout(timer);
          const result = { shown: [...shown], completed, rests: sprite.anims.currentFrame?.textureFrame ?? null,
            playing: sprite.anims.isPlaying, repeats: made.map((a) => a.repeat), first: made[0]?.frames.map((f) => f.textureFrame) };
          game.destroy(true);
          resolve(result);
        }, made[0].duration + 200);
      });
      sprite.play(made[0].key);
    });
  }), [name, STEP_TIMEOUT_MS]);
}

// PixiJS on a one-shot: its Spritesheet keeps the tag-less `animations`
// only, so an AnimatedSprite loops unless the game says otherwise; here
// stepped past its end as it comes (loop true) and with loop = false taken
// from the tag's "repeat" as a game would.
function pixiPlaysOnce(page, name) {
  return page.evaluate(async (key) => {
    const { atlas, sheet } = await window.pixiSheet(key);
    const tag = atlas.meta.frameTags[0];
    const textures = sheet.animations[tag.name];
    const play = (loop) => {
      const sprite = new PIXI.AnimatedSprite({ textures, autoUpdate: false, loop });
      let completed = 0;
      sprite.onComplete = () => { completed += 1; };
      sprite.play();
      const seen = [sprite.currentFrame];
      for (let i = 0; i < textures.length + 2; i++) {
        sprite.update({ deltaTime: 1 / sprite.animationSpeed, deltaMS: 1000 / 60 });
        seen.push(sprite.currentFrame);
      }
      return { seen, completed, playing: sprite.playing };
    };
    return { tag, frames: textures.length, asItComes: play(true), fromTag: play(tag.repeat === undefined) };
  }, name);
}

function checkOneShot(phaser, pixi, atlas, phaserWalk) {
  const tags = atlas.meta.frameTags;
  check(tags.length === 2 && tags.every((t) => t.repeat === '1'), 'the one-shot\'s tags say "repeat": "1"',
    JSON.stringify(tags.map((t) => t.repeat)));
  const names = phaser.first ?? [];
  check(phaser.completed === 1 && phaser.shown.join() === names.slice(1).join() && phaser.rests === names.at(-1)
        && !phaser.playing,
  'Phaser: the one-shot plays its frames once and rests on the last',
  `shown ${phaser.shown.join(', ')}; completed ${phaser.completed}; rests on ${phaser.rests}; tag ${names.join(', ')}`);
  check(phaser.repeats.every((r) => r === 0) && phaserWalk.repeats.length > 0 && phaserWalk.repeats.every((r) => r === 0),
    'Phaser: createFromAseprite ignores "repeat": every tag is made to play once (repeat 0), the walk\'s looping tags too',
    `one-shot ${phaser.repeats.join(', ')}; walk ${phaserWalk.repeats.join(', ')}`);
  const last = pixi.frames - 1;
  check(pixi.asItComes.seen.includes(0, 1) && pixi.asItComes.completed === 0,
    'PixiJS: the Spritesheet ignores "repeat": as it comes, the AnimatedSprite loops round',
    pixi.asItComes.seen.join());
  check(pixi.fromTag.completed === 1 && pixi.fromTag.seen.at(-1) === last && !pixi.fromTag.playing
        && pixi.fromTag.seen.join() === [...Array.from({ length: pixi.frames }, (_, k) => k), last, last, last].join(),
  'PixiJS: with loop = false from the tag, the AnimatedSprite plays once and stops on the last frame',
  pixi.fromTag.seen.join());
}

const sum = (values) => values.reduce((a, b) => a + b, 0);
const close = (a, b) => Math.abs(a - b) < 1e-9;

function checkAtlas(label, atlas) {
  const problems = asepriteProblems(atlas);
  check(problems.length === 0, `${label}: the atlas has every field Aseprite writes, with Aseprite's types`,
    problems.slice(0, 5).join('; '));
}

function checkPhaserWalk(phaser, atlas, clipMs, label = '') {
  const check = (condition, what, detail) => checkOne(condition, `${label}${what}`, detail);
  const tags = atlas.meta.frameTags;
  check(phaser.animations.length === 4 && phaser.animations.every((a) => a.frames.length === 6),
    'Phaser: createFromAseprite gives 4 animations of 6 frames',
    phaser.animations.map((a) => `${a.key}: ${a.frames.length}`).join(', '));
  check(phaser.animations.every((a, i) => a.key === tags[i].name
        && a.frames.join() === Array.from({ length: 6 }, (_, k) => String(tags[i].from + k)).join()),
  'Phaser: each animation is its tag, its frames in the tag\'s order',
  phaser.animations.map((a) => `${a.key} [${a.frames}]`).join('; '));
  check(phaser.animations.every((a) => a.durations.every((d) => Math.abs(d - clipMs / 6) <= 1)
        && Math.abs(sum(a.durations) - clipMs) <= 6 && a.duration === sum(a.durations)),
  `Phaser: frame durations within 1 ms of a sixth of the clip's ${clipMs} ms, adding up to it`,
  phaser.animations.map((a) => `${a.key} [${a.durations}] = ${a.duration}`).join('; '));
  check(phaser.error === null, 'Phaser: the sprite plays', phaser.error ?? '');
  const firstTag = phaser.animations[0]?.frames ?? [];
  check(phaser.shown.length >= firstTag.length && phaser.shown.every((f, i) => f === firstTag[(i + 1) % firstTag.length]),
    'Phaser: the playing sprite advances through the frames in order and loops',
    `from ${phaser.startFrame}: ${phaser.shown.join(', ')}`);
  const anchor = atlas.frames['0']?.anchor ?? {};
  check(phaser.pivot.custom && close(phaser.pivot.x, anchor.x) && close(phaser.pivot.y, anchor.y)
        && close(phaser.origin.x, anchor.x) && close(phaser.origin.y, anchor.y),
  'Phaser: the frame\'s pivot and the sprite\'s origin are the atlas\'s anchor',
  `${JSON.stringify(phaser.pivot)}, origin ${JSON.stringify(phaser.origin)}, anchor ${JSON.stringify(anchor)}`);
}

function checkPixiWalk(pixi, atlas, label = '') {
  const check = (condition, what, detail) => checkOne(condition, `${label}${what}`, detail);
  const names = Object.keys(pixi.animations);
  check(names.length === 4 && names.every((n) => pixi.animations[n].length === 6 && pixi.animations[n].every(Boolean)),
    'PixiJS: the Spritesheet has 4 animations of 6 textures',
    names.map((n) => `${n}: ${pixi.animations[n].length}`).join(', '));
  check(names.join() === atlas.meta.frameTags.map((t) => t.name).join(),
    'PixiJS: one animation per direction, named as the tags', names.join(', '));
  const placed = names.length > 0 && names.every((n) => pixi.animations[n].every((t) => {
    const f = atlas.frames[t.label];
    return f && t.x === f.frame.x && t.y === f.frame.y && t.w === f.frame.w && t.h === f.frame.h
      && close(t.anchor.x, f.anchor.x) && close(t.anchor.y, f.anchor.y);
  }));
  check(placed, 'PixiJS: every texture cuts its tile and carries its anchor');
  check(JSON.stringify(pixi.viaAssets) === JSON.stringify(Object.fromEntries(names.map((n) => [n, 6]))),
    'PixiJS: Assets.load on the JSON finds the PNG by meta.image and gives the same animations',
    JSON.stringify(pixi.viaAssets));
  check(pixi.seen.join() === '0,1,2,3,4,5,0', 'PixiJS: an AnimatedSprite of a direction steps through its frames',
    pixi.seen.join());
  check(pixi.timedSeen.join() === '0,1,2,3,4,5,0',
    'PixiJS: given the atlas\'s durations, it shows each frame for its time', pixi.timedSeen.join());
  const anchor = atlas.frames['0']?.anchor ?? {};
  check(close(pixi.anchor.x, anchor.x) && close(pixi.anchor.y, anchor.y), 'PixiJS: the sprite stands on the anchor',
    JSON.stringify(pixi.anchor));
}

// A packed walk sheet plays as its grid does, and every frame is drawn on
// the very pixels its grid tile is drawn on, in both engines.
async function checkPacked(page, packed, clipMs) {
  checkPhaserWalk(await phaserLoads(page, 'packed'), packed.atlas, clipMs, 'packed: ');
  checkPixiWalk(await pixiLoads(page, 'packed'), packed.atlas, 'packed: ');
  check(Object.values(packed.atlas.frames).every((f) => f.trimmed), 'packed: every frame is trimmed');
  await drawFrames(page, 'walk');
  await drawFrames(page, 'packed');
  for (const engine of ['phaser', 'pixi']) {
    const drawn = await sameDrawing(page, engine, 'walk', 'packed');
    check(drawn.frames === 24 && drawn.others === 24 && drawn.differing === 0 && drawn.empty === 0,
      `${engine}: each packed frame is drawn where its grid tile is, pixel for pixel`, JSON.stringify(drawn));
  }
}

function checkTurntable(phaser, pixi, atlas) {
  const want = ['turn_p10', 'turn_p40'];
  check(phaser.animations.map((a) => `${a.key}:${a.frames.length}`).join() === want.map((n) => `${n}:8`).join()
        && phaser.error === null && phaser.shown.length >= 3,
  'Phaser: a turntable of 8 frames at 2 pitches plays as 2 animations of 8',
  phaser.animations.map((a) => `${a.key}: ${a.frames.length}`).join(', '));
  check(Object.keys(pixi.animations).join() === want.join()
        && Object.values(pixi.animations).every((t) => t.length === 8 && t.every(Boolean)),
  'PixiJS: the turntable gives 2 animations of 8 textures', Object.keys(pixi.animations).join(', '));
  check(Object.values(atlas.frames).every((f) => f.duration === 80), 'the turntable\'s frames show for frame_ms');
}

const dataDir = mkdtempSync(path.join(tmpdir(), 'toond-engines-'));
let daemon = null;
let browser = null;
const started = Date.now();
try {
  console.log(`phaser ${versionOf('phaser')}, pixi.js ${versionOf('pixi.js')}`);
  daemon = await startDaemon(toondBinary, '127.0.0.1:0', dataDir, STEP_TIMEOUT_MS);
  const walker = await upload(daemon.url, path.join(exported, 'blender', 'walker.glb'));
  const clipMs = 1000 * walker.animation.clips.find((c) => c.name === 'Walk').duration;
  const base = { model: walker.id, width: 64, height: 64, background: [0, 0, 0, 0], camera: { preset: 'dimetric' } };
  const walk = await sheetOf(daemon.url, { ...base, sheet: { frames: 4, yaw_start: 0, animation: { clip: 'Walk', frames: 6 } } });
  const turn = await sheetOf(daemon.url, { ...base, sheet: { frames: 8, pitches: [10, 40], frame_ms: 80 } });
  const packed = await sheetOf(daemon.url,
    { ...base, sheet: { frames: 4, yaw_start: 0, animation: { clip: 'Walk', frames: 6 }, pack: true } });
  const once = await sheetOf(daemon.url,
    { ...base, sheet: { frames: 2, yaw_start: 0, animation: { clip: 'Walk', frames: 5, loop: false } } });
  writeFileSync(path.join(artifacts, 'engines-walk.png'), walk.png);
  writeFileSync(path.join(artifacts, 'engines-walk.json'), walk.json);
  checkAtlas('walk', walk.atlas);
  checkAtlas('turntable', turn.atlas);
  checkAtlas('one-shot', once.atlas);
  checkAtlas('packed walk', packed.atlas);

  browser = await launchChromium(chromium);
  const { page, pageErrors } = await enginePage(browser, { walk, turn, once, packed });
  check(await page.evaluate(() => Phaser.VERSION) === versionOf('phaser') && await page.evaluate(() => PIXI.VERSION) === versionOf('pixi.js'),
    'the page runs the installed Phaser and PixiJS', await page.evaluate(() => `${Phaser.VERSION}, ${PIXI.VERSION}`));
  const phaserWalk = await phaserLoads(page, 'walk');
  checkPhaserWalk(phaserWalk, walk.atlas, clipMs);
  checkPixiWalk(await pixiLoads(page, 'walk'), walk.atlas);
  await checkPacked(page, packed, clipMs);
  checkTurntable(await phaserLoads(page, 'turn'), await pixiLoads(page, 'turn'), turn.atlas);
  checkOneShot(await phaserPlaysOnce(page, 'once'), await pixiPlaysOnce(page, 'once'), once.atlas, phaserWalk);
  check(pageErrors.length === 0, 'no uncaught errors in the page', pageErrors.join('; '));
} catch (e) {
  check(false, 'the engine test ran to its end', e.stack || String(e));
} finally {
  if (browser) await browser.close();
  if (daemon) daemon.child.kill('SIGTERM');
  rmSync(dataDir, { recursive: true, force: true });
}
console.log(`${failed() ? 'FAILED' : 'passed'}: ${failed()} failing check(s), ${((Date.now() - started) / 1000).toFixed(1)} s`);
process.exit(failed() ? 1 : 0);
