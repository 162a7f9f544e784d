// The Site panel: the project's one site (docs/scene-format.md "Site"), where every sun given by
// date and time alone stands: latitude, longitude, UTC offset, elevation (for skies by the sun's
// altitude) and true north (the clockwise angle from the scene's −z, which turns every sun and
// map). It shows the scene's site and edits the state's `site` (docs/lighting-state.md), a
// whole object at a time; "Scene's" goes back to the scene's. A scene without a site gets one
// here the moment a field is set.
import { el, numberInput, row } from './ui.js';

const FIELDS = [
  ['latitude', 'Latitude', { min: -90, max: 90, unit: '°' }, 'Latitude in degrees, north positive'],
  ['longitude', 'Longitude', { min: -180, max: 180, unit: '°' }, 'Longitude in degrees, east positive'],
  ['utc_offset', 'UTC offset', { min: -14, max: 14, unit: 'h' }, 'Local standard time minus UTC, hours (1 for CET)'],
  ['elevation_m', 'Elevation', { min: -500, max: 9000, unit: 'm' }, "Height above sea level: thinner air, brighter sun (skies by the sun's altitude)"],
  ['north_deg', 'North', { min: -360, max: 360, unit: '°' }, "True north, clockwise from the scene's −z seen from above: turns every sun and map"],
];

export class SitePanel {
  constructor(container, store) {
    this.container = container;
    this.store = store;
    this.inputs = {};
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    this.inputs = {};
    for (const [key, label, opts, title] of FIELDS) {
      const w = numberInput({
        ...opts,
        title,
        testid: `site-${key}`,
        onChange: (v) => this.store.edit((doc) => (doc.site = { ...this.current(), [key]: v })),
      });
      this.inputs[key] = w.input || w;
      this.container.append(row(label, w, title));
    }
    const reset = el('button', { type: 'button', class: 'small', text: "Scene's", title: "Back to the scene's site" });
    reset.addEventListener('click', () => this.store.edit((doc) => delete doc.site));
    this.hint = el('p', { class: 'hint' });
    this.container.append(row('', reset), this.hint);
    this.refresh();
  }

  // The site in force: the state's, else the scene's, else none (latitude and longitude are
  // required; a fresh site starts at 0° N, 0° E).
  current() {
    return this.store.doc.site ?? this.hello?.site ?? { latitude: 0, longitude: 0 };
  }

  refresh() {
    if (!this.hello) return;
    const site = this.store.doc.site ?? this.hello.site;
    for (const [key] of FIELDS) {
      const input = this.inputs[key];
      if (document.activeElement === input) continue;
      const v = site?.[key] ?? (key === 'latitude' || key === 'longitude' ? undefined : 0);
      input.value = v === undefined ? '' : String(v);
    }
    this.hint.textContent = site
      ? "Suns given by date and time alone stand here; every sun and map turns with north."
      : 'This scene has no site: each sun carries its own place. Set one to place them all.';
  }
}
