// The comparison must see a wrong pose: toond's poses of a real case are
// perturbed on purpose (a vertex moved past the tolerance, a vertex moved
// within it, every pose taken a third of a frame late, a rest vertex
// moved away from its twin) and each verdict checked. A comparer that
// passed everything would fail here.
import { compareFull, kTolerance, loadCase, poseBoth, toondPoses } from './suite.mjs';

function copyOf(both) {
  return { ...both, toond: structuredClone(both.toond) };
}

// Moves vertex v of pose k (or of the rest positions, k = 'rest') by
// `amount` along x.
function moved(both, k, v, amount) {
  const copy = copyOf(both);
  const points = k === 'rest' ? copy.toond.rest : copy.toond.poses[k].positions;
  points[3 * v] += amount;
  return copy;
}

export async function selfTest(options) {
  const theCase = loadCase('bending_arm.glb');
  const both = await poseBoth(options, theCase);
  const honest = compareFull(theCase, both);
  const size = honest.size;
  // The peak of the bend, frame 7 (7/24 s, a key): where a wrong pose shows most.
  const peak = both.times.findIndex((t) => Math.abs(t - 7 / 24) < 1e-6);
  if (peak < 0) throw new Error('self-test: frame 7 is not among the times sampled');
  const frame = 1 / 24;
  const late = {
    ...both,
    toond: toondPoses(options, theCase, 'Bend', both.times.map((t) => t + frame / 3)),
  };
  const checks = [
    ['the honest poses hold', honest, true],
    ['one vertex 1.5x the tolerance off at the peak fails', compareFull(theCase, moved(both, peak, 100, 1.5 * kTolerance * size)), false],
    ['one vertex 0.5x the tolerance off holds', compareFull(theCase, moved(both, peak, 100, 0.5 * kTolerance * size)), true],
    ['every pose a third of a frame late fails', compareFull(theCase, late), false],
    ['a rest vertex away from its twin fails', compareFull(theCase, moved(both, 'rest', 100, 20 * kTolerance * size)), false],
  ];
  let right = true;
  for (const [what, result, shouldHold] of checks) {
    const ok = result.holds === shouldHold;
    right &&= ok;
    console.log(`self-test: ${what}: ${result.holds ? 'holds' : 'fails'} (${result.outliers} outliers, ` +
      `${result.unmatched} unmatched)${ok ? '' : '  WRONG VERDICT'}`);
  }
  // The one vertex moved is the one outlier.
  const one = checks[1][1].outliers === 1;
  console.log(`self-test: the vertex moved past the tolerance is the only outlier: ${one}`);
  return right && one;
}
