// Which three.js vertex each toond vertex is, and how far apart they are
// in a pose.
//
// The two do not share a vertex order or count: toond welds equal
// positions and splits vertices at hard edges as its import needs, and
// three.js's loaders keep the file's vertices (FBXLoader and ColladaLoader
// one per triangle corner). So a vertex is known by where it is at rest:
// each toond vertex's candidates are the three.js vertices within a tiny
// tolerance of its rest position (both in the file's world space, three's
// through the case's unit and axis conversion). Several candidates are
// copies of one point of the surface (split at a seam or per corner);
// they are skinned alike, so in a pose the vertex is compared with the
// candidate nearest to it (the tie-break). A toond vertex without any
// candidate, or a three.js vertex that is no toond vertex's candidate, is
// geometry one side has and the other lacks, and fails the case.

// Points (x y z after each other) bucketed in a grid of `cell`-sized
// cubes, to find those near a point.
class PointGrid {
  constructor(points, cell) {
    this.points = points;
    this.cell = cell;
    this.buckets = new Map();
    for (let i = 0; i < points.length / 3; i++) {
      const key = this.#key(this.#cellOf(points, i));
      const bucket = this.buckets.get(key);
      if (bucket) bucket.push(i);
      else this.buckets.set(key, [i]);
    }
  }

  #cellOf(points, i) {
    return [0, 1, 2].map((axis) => Math.floor(points[3 * i + axis] / this.cell));
  }

  #key([x, y, z]) {
    return `${x},${y},${z}`;
  }

  // Indices of the points within `radius` (at most one cell) of point i of
  // `points`.
  near(points, i, radius) {
    const [cx, cy, cz] = this.#cellOf(points, i);
    const found = [];
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (let dz = -1; dz <= 1; dz++) {
          for (const j of this.buckets.get(this.#key([cx + dx, cy + dy, cz + dz])) ?? []) {
            if (distance(points, i, this.points, j) <= radius) found.push(j);
          }
        }
      }
    }
    return found;
  }
}

export function distance(a, i, b, j) {
  const dx = a[3 * i] - b[3 * j];
  const dy = a[3 * i + 1] - b[3 * j + 1];
  const dz = a[3 * i + 2] - b[3 * j + 2];
  return Math.sqrt(dx * dx + dy * dy + dz * dz);
}

// The diagonal of the box around the points.
export function diagonal(points) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < points.length; i += 3) {
    for (let axis = 0; axis < 3; axis++) {
      lo[axis] = Math.min(lo[axis], points[i + axis]);
      hi[axis] = Math.max(hi[axis], points[i + axis]);
    }
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// candidates[v]: the three.js vertices at toond vertex v's rest position;
// unmatchedToond / unmatchedThree: the vertices of either side the other
// has nothing at.
export function matchByRestPosition(toondRest, threeRest, tolerance) {
  const grid = new PointGrid(threeRest, tolerance);
  const covered = new Uint8Array(threeRest.length / 3);
  const candidates = [];
  const unmatchedToond = [];
  for (let v = 0; v < toondRest.length / 3; v++) {
    const near = grid.near(toondRest, v, tolerance);
    candidates.push(near);
    if (near.length === 0) unmatchedToond.push(v);
    for (const j of near) covered[j] = 1;
  }
  const unmatchedThree = [];
  for (let j = 0; j < covered.length; j++) if (!covered[j]) unmatchedThree.push(j);
  return { candidates, unmatchedToond, unmatchedThree };
}

// One pose compared: each toond vertex's distance to its nearest
// candidate; `outliers` counts the vertices farther than `threshold`.
export function comparePose(match, toondPosed, threePosed, threshold) {
  let largest = 0;
  let worstVertex = -1;
  let outliers = 0;
  match.candidates.forEach((near, v) => {
    if (near.length === 0) return;
    let error = Infinity;
    for (const j of near) error = Math.min(error, distance(toondPosed, v, threePosed, j));
    if (error > largest) {
      largest = error;
      worstVertex = v;
    }
    if (!(error <= threshold)) outliers++;
  });
  return { largest, worstVertex, outliers };
}
