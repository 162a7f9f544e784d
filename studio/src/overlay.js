// What the marker overlays (luminaires, emitters) share: freeing a group's objects when a
// scene is (re)loaded, and the scene's size that their markers scale with.
export function clearGroup(group) {
  group.traverse((o) => {
    o.geometry?.dispose();
    o.material?.dispose?.();
  });
  group.clear();
}

// The diagonal of the scene's bounding box (m), 8 when the hello gives none.
export function sceneDiagonal(hello) {
  const b = hello.bounds;
  return b ? Math.hypot(...b.max.map((v, i) => v - b.min[i])) : 8;
}
