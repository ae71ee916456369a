// What Aseprite itself writes when it exports a sprite sheet's JSON data
// ("Export Sprite Sheet", JSON Data, Hash; on the command line `--data` with
// `--format json-hash --list-tags`), field by field with its type, and a
// check of an atlas against it. Aseprite's writer puts these fields, and no
// others, in this order:
//
//   { "frames": {
//       "<file name>": {                      one per frame; the name comes from
//                                              --filename-format, "{frame}" gives
//                                              "0", "1", … (json-array: a list with
//                                              the name in "filename" instead)
//         "frame": { "x": int, "y": int, "w": int, "h": int },   where it is in the sheet
//         "rotated": false,                    always false (Aseprite never rotates)
//         "trimmed": bool,                     true when spriteSourceSize is not the whole frame
//         "spriteSourceSize": { "x": int, "y": int, "w": int, "h": int },
//         "sourceSize": { "w": int, "h": int },
//         "duration": int                      milliseconds
//       }, … },
//     "meta": {
//       "app": string,                         the program's web address
//       "version": string,
//       "image": string,                       the sheet's file name (left out when none)
//       "format": "RGBA8888" | "I8",
//       "size": { "w": int, "h": int },
//       "scale": string,                       "1"
//       "frameTags": [                         with --list-tags
//         { "name": string, "from": int, "to": int,      inclusive frame indices
//           "direction": "forward" | "reverse" | "pingpong" | "pingpong_reverse",
//           "repeat": string (only when set), "color": "#rrggbbaa" and "data": string
//           (only with user data) }, … ],
//       "layers": [ … ],                       with --list-layers
//       "slices": [ … ]                        with --list-slices
//     } }
//
// Readers built for this file (Phaser's aseprite loader among them) look
// frames up by these names and types; keys they do not know are left
// alone, which is where toond's own (yaw, pitch, clip, anchor, …) ride.

const RECT = { x: 'int', y: 'int', w: 'int', h: 'int' };
const SIZE = { w: 'int', h: 'int' };

export const ASEPRITE_FRAME = {
  frame: RECT,
  rotated: 'boolean',
  trimmed: 'boolean',
  spriteSourceSize: RECT,
  sourceSize: SIZE,
  duration: 'int',
};

export const ASEPRITE_META = {
  app: 'string',
  version: 'string',
  image: 'string',
  format: 'string',
  size: SIZE,
  scale: 'string',
};

export const ASEPRITE_TAG = { name: 'string', from: 'int', to: 'int', direction: 'string' };
export const ASEPRITE_DIRECTIONS = ['forward', 'reverse', 'pingpong', 'pingpong_reverse'];
export const ASEPRITE_FORMATS = ['RGBA8888', 'I8'];

function typeProblems(value, shape, where) {
  if (typeof shape === 'object') {
    if (value === null || typeof value !== 'object' || Array.isArray(value)) return [`${where} is not an object`];
    return Object.entries(shape).flatMap(([key, inner]) =>
      (key in value ? typeProblems(value[key], inner, `${where}.${key}`) : [`${where} lacks ${key}`]));
  }
  if (shape === 'int') return Number.isInteger(value) ? [] : [`${where} is not an integer (${JSON.stringify(value)})`];
  return typeof value === shape ? [] : [`${where} is not a ${shape} (${JSON.stringify(value)})`];
}

// Every way `atlas` departs from what Aseprite writes, as readable lines;
// empty when an Aseprite reader takes it as one of Aseprite's own.
export function asepriteProblems(atlas) {
  const problems = [];
  if (!atlas || typeof atlas.frames !== 'object' || Array.isArray(atlas.frames)) return ['frames is not an object'];
  const names = Object.keys(atlas.frames);
  if (names.length === 0) problems.push('frames is empty');
  for (const name of names) {
    const frame = atlas.frames[name];
    problems.push(...typeProblems(frame, ASEPRITE_FRAME, `frames["${name}"]`));
    if (frame.rotated !== false) problems.push(`frames["${name}"].rotated is not false`);
    if (Number.isInteger(frame.duration) && frame.duration < 1) problems.push(`frames["${name}"].duration < 1`);
    const s = frame.spriteSourceSize;
    const whole = s && frame.sourceSize && s.x === 0 && s.y === 0
      && s.w === frame.sourceSize.w && s.h === frame.sourceSize.h;
    if (s && frame.trimmed === whole) problems.push(`frames["${name}"].trimmed does not say whether it is trimmed`);
  }
  problems.push(...typeProblems(atlas.meta, ASEPRITE_META, 'meta'));
  if (atlas.meta && !ASEPRITE_FORMATS.includes(atlas.meta.format)) problems.push(`meta.format ${atlas.meta.format}`);
  const tags = atlas.meta?.frameTags;
  if (!Array.isArray(tags)) return [...problems, 'meta.frameTags is not a list'];
  tags.forEach((tag, i) => {
    const where = `meta.frameTags[${i}]`;
    problems.push(...typeProblems(tag, ASEPRITE_TAG, where));
    if (!ASEPRITE_DIRECTIONS.includes(tag.direction)) problems.push(`${where}.direction is ${tag.direction}`);
    if (!(tag.from <= tag.to)) problems.push(`${where} runs from ${tag.from} to ${tag.to}`);
    // Frames named as `{frame}` names them: how Phaser finds a tag's frames.
    for (let f = tag.from; f <= tag.to; f++) {
      if (!(String(f) in atlas.frames)) problems.push(`${where} spans frame ${f}, but no frame is named "${f}"`);
    }
    if ('repeat' in tag && typeof tag.repeat !== 'string') problems.push(`${where}.repeat is not a string`);
  });
  return problems;
}
