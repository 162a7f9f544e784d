// Isolines of illuminance over a sensor grid (the plan view, docs/studio.md "Plan view"):
// levels on the 1-2-5 series that give 4 to 10 lines over a set's range, and the lines of a
// level by marching squares over the grid's cells, crossings interpolated linearly along the
// cell edges between the points' values. A grid set's points run u fastest (point i + nu·j),
// as the scene format makes them.

// Levels strictly inside (lo, hi): the 1-2-5 step that gives 4 to 10 of them, or the fewest above.
export function isolineLevels(lo, hi) {
  if (!(hi > lo) || !Number.isFinite(lo) || !Number.isFinite(hi)) return [];
  const decade = 10 ** Math.floor(Math.log10(hi - lo));
  let chosen = [];
  for (const step of [5, 2, 1, 0.5, 0.2, 0.1].map((f) => f * decade)) {
    const levels = [];
    for (let v = Math.ceil(lo / step) * step; v < hi; v += step) if (v > lo) levels.push(Number(v.toPrecision(12)));
    chosen = levels;
    if (levels.length >= 4) break;
  }
  return chosen.length > 10 ? chosen.filter((_, k) => k % Math.ceil(chosen.length / 10) === 0) : chosen;
}

// The segments [[a, b], ...] (world points) of `level` over a grid set {nu, nv, points} with
// `values` (per point, NaN where unknown: its cells are skipped).
export function gridIsolines(set, values, level) {
  const { nu, nv, points } = set;
  const segments = [];
  const at = (i, j) => i + nu * j;
  const cross = (ka, kb) => {
    const a = values[ka], b = values[kb];
    if ((a - level) * (b - level) >= 0 || a === b) return null;
    const t = (level - a) / (b - a);
    const p = points[ka], q = points[kb];
    return [0, 1, 2].map((c) => p[c] + t * (q[c] - p[c]));
  };
  for (let j = 0; j + 1 < nv; ++j) {
    for (let i = 0; i + 1 < nu; ++i) {
      const corners = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
      if (corners.some((k) => !Number.isFinite(values[k]))) continue;
      // The edges in order round the cell; two crossings make a segment, four (a saddle) two,
      // paired by the cell's mean as the middle's value.
      const hits = [0, 1, 2, 3].map((e) => cross(corners[e], corners[(e + 1) % 4])).map((p, e) => (p ? { p, e } : null)).filter(Boolean);
      if (hits.length === 2) segments.push([hits[0].p, hits[1].p]);
      if (hits.length === 4) {
        const mean = corners.reduce((s, k) => s + values[k], 0) / 4;
        const firstAbove = values[corners[0]] > level;
        // The middle on corner 0's side joins corner 0's edges' crossings across the cell.
        if ((mean > level) === firstAbove) segments.push([hits[0].p, hits[1].p], [hits[2].p, hits[3].p]);
        else segments.push([hits[3].p, hits[0].p], [hits[1].p, hits[2].p]);
      }
    }
  }
  return segments;
}
