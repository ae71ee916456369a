// The rig conformance suite's comparisons: a case of cases.json posed by
// toond (toond-pose-dump: the daemon's import and pose) and by three.js
// (three_pose.mjs, the oracle) at the same times of the same clip,
// compared vertex by vertex (compareFull), and toond's levels of detail
// held to their own errors (compareLevels). README.md here says why.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { ThreeModel } from './three_pose.mjs';
import { comparePose, diagonal, matchByRestPosition } from './vertex_match.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));

// Every vertex within this fraction of the model's size (the diagonal of
// its rest bounds) of three.js's, at every time sampled.
export const kTolerance = 1e-4;
// Rest positions closer than this fraction of the size are one vertex.
const kMatchTolerance = 1e-5;

export function loadCase(name) {
  const cases = JSON.parse(fs.readFileSync(path.join(here, 'cases.json'), 'utf8')).cases;
  const found = cases.find((c) => c.name === name);
  if (!found) throw new Error(`no case "${name}" in cases.json`);
  return found;
}

// The times compared: every key of the clip (three.js's, as float32 like
// the file's), times evenly inside each gap between neighbouring keys (at
// least two, more where the keys are few: some 48 over the clip), time 0
// and a time before the first key where the clip starts later, and two
// past its duration and one before 0, where both loop.
export function sampleTimes(clip) {
  const keys = new Set();
  for (const track of clip.tracks) for (const t of track.times) keys.add(t);
  const sorted = [...keys].filter((t) => t >= 0 && t <= clip.duration).sort((a, b) => a - b);
  const times = new Set([0, ...sorted]);
  const between = Math.max(2, Math.ceil(48 / Math.max(1, sorted.length - 1)));
  for (let k = 0; k + 1 < sorted.length; k++) {
    const gap = sorted[k + 1] - sorted[k];
    for (let j = 0; j < between; j++) times.add(sorted[k] + gap * (j + 0.5) / between);
  }
  if (sorted.length > 0 && sorted[0] > 0) times.add(0.5 * sorted[0]);
  const d = clip.duration;
  if (d > 0) {
    times.add(d + 0.37 * Math.min(d, sorted.length > 1 ? sorted[1] - sorted[0] : d));
    times.add(d + 0.5 * d);
    times.add(-0.25 * d);
  }
  return [...times].sort((a, b) => a - b);
}

// toond's poses of the case at `times` (toond's own time base).
export function toondPoses(options, theCase, clipName, times) {
  const files = theCase.files.map((f) => path.join(options.exported, f));
  const env = { ...process.env };
  if (options.converter) env.TOOND_ASSIMP_CONVERTER = options.converter;
  const run = spawnSync(options.poseDump, ['--clip', clipName, '--times', times.join(','), ...files],
    { env, maxBuffer: 1 << 30, encoding: 'utf8' });
  if (run.status !== 0) {
    throw new Error(`toond-pose-dump failed on ${theCase.name} (status ${run.status}): ${run.stderr}`);
  }
  return JSON.parse(run.stdout);
}

// three.js's positions in the file's world space as toond reads the file:
// the case's `three_to_file` (a uniform scale, for FBXLoader's
// centimetres) applied.
function toFileSpace(points, theCase) {
  const scale = theCase.three_to_file?.scale ?? 1;
  if (scale === 1) return points;
  return points.map((x) => x * scale);
}

// A case toond cannot read yet (cases.json says why): three.js must load
// and pose it, and toond must refuse it with the error recorded, so the
// day it reads the file this test fails and the case is compared instead.
export async function refusedAsKnown(options, theCase) {
  const model = await ThreeModel.load(path.join(options.exported, theCase.files[0]));
  const clipName = typeof theCase.clip === 'string' ? theCase.clip : theCase.clip.three;
  model.posedPositions(model.clip(clipName), 0);
  let refusal = '';
  try {
    toondPoses(options, theCase, '0', [0]);
  } catch (error) {
    refusal = String(error.message);
  }
  const known = refusal.includes(theCase.toond_refuses);
  console.log(`${theCase.name}: three.js reads and poses it (${model.vertexCount} vertices); toond ` +
    (known ? `refuses it as recorded: ${theCase.toond_refuses}` : `no longer refuses it as recorded (${refusal || 'it reads it'})`));
  console.log(`  not compared: ${theCase.why}`);
  return known;
}

function fixed(x, digits = 3) {
  return Number(x).toExponential(digits);
}

export async function poseBoth(options, theCase) {
  const model = await ThreeModel.load(path.join(options.exported, theCase.files[0]));
  const clipNames = typeof theCase.clip === 'string' ? { three: theCase.clip, toond: theCase.clip } : theCase.clip;
  const clip = model.clip(clipNames.three);
  const times = sampleTimes(clip);
  // toond's time = three.js's + offset (a format whose two readers start
  // the clip at different times; none of the cases needs one so far).
  const offset = theCase.time_offset ?? 0;
  const toond = toondPoses(options, theCase, clipNames.toond, times.map((t) => t + offset));
  return { model, clip, times, toond };
}

export function compareFull(theCase, { model, clip, times, toond }) {
  const threeRest = toFileSpace(model.restPositions(), theCase);
  const size = diagonal(threeRest);
  const match = matchByRestPosition(Float64Array.from(toond.rest), threeRest, kMatchTolerance * size);
  const threshold = kTolerance * size;
  let worst = { largest: 0, time: 0, vertex: -1 };
  let outliers = 0;
  let timesWithOutliers = 0;
  times.forEach((time, k) => {
    const threePosed = toFileSpace(model.posedPositions(clip, time), theCase);
    const result = comparePose(match, Float64Array.from(toond.poses[k].positions), threePosed, threshold);
    if (result.largest > worst.largest) worst = { largest: result.largest, time, vertex: result.worstVertex };
    outliers += result.outliers;
    if (result.outliers > 0) timesWithOutliers++;
  });
  const unmatched = match.unmatchedToond.length + match.unmatchedThree.length;
  console.log(`${theCase.name}: clip "${clip.name}" (toond "${toond.clip.name}", ${fixed(toond.clip.duration, 6)} s; ` +
    `three.js ${fixed(clip.duration, 6)} s), ${times.length} times from ${fixed(times[0])} to ${fixed(times.at(-1))} s`);
  console.log(`  vertices: toond ${toond.vertices}, three.js ${model.vertexCount}; unmatched at rest: ` +
    `${match.unmatchedToond.length} toond, ${match.unmatchedThree.length} three.js; size ${fixed(size)}, ` +
    `tolerance ${fixed(threshold)}`);
  console.log(`  max error ${fixed(worst.largest)} (${fixed(worst.largest / size)} of the size) at t=${worst.time} ` +
    `vertex ${worst.vertex}; outliers ${outliers} vertex-times over ${timesWithOutliers} of ${times.length} times`);
  for (const warning of toond.warnings) console.log(`  toond warning: ${warning}`);
  return { holds: outliers === 0 && unmatched === 0, outliers, unmatched, largest: worst.largest, size };
}

// Each level of detail, in each pose: the farthest a full-detail vertex is
// from the level's posed triangles, against the level's own error times
// the pose's largest joint stretch (toond-pose-dump measures both).
export function compareLevels(theCase, { times, toond }) {
  const levels = toond.levels ?? [];
  console.log(`${theCase.name}: ${levels.length} levels of detail (${levels.map((l) => l.triangles).join(', ')} ` +
    `of ${toond.triangles} triangles), ${times.length} times`);
  let holds = true;
  for (const level of levels) {
    let worst = { ratio: 0, farthest: 0, bound: 0, time: 0 };
    let beyond = 0;
    let timesBeyond = 0;
    toond.poses.forEach((pose, k) => {
      const l = pose.levels[level.level - 1];
      const ratio = l.bound > 0 ? l.farthest / l.bound : (l.farthest > 0 ? Infinity : 0);
      if (ratio > worst.ratio || worst.ratio === 0 && l.farthest > worst.farthest) {
        worst = { ratio, farthest: l.farthest, bound: l.bound, time: times[k] };
      }
      beyond += l.vertices_beyond;
      if (l.vertices_beyond > 0) timesBeyond++;
    });
    const ok = beyond === 0;
    holds &&= ok;
    console.log(`  level ${level.level} (${level.triangles} triangles, error ${fixed(level.error)}): farthest ` +
      `${fixed(worst.farthest)} against ${fixed(worst.bound)} at t=${worst.time}; ${beyond} vertex-times beyond, ` +
      `at ${timesBeyond} of ${times.length} times${ok ? '' : '  FAILS'}`);
  }
  return holds;
}

