// The annual panel (issue 17): a year of daylight as `relight annual` computes it, run by the
// server on the state shown now with daylight alone (docs/studio-protocol.md, `annual`). The
// designer picks an EnergyPlus weather file (.epw) and the occupied hours and presses Run; a
// progress bar follows the server's `annual_progress`; the result is a table per sensor set
// (sDA300/50%, ASE1000,250h, mean DA300, the EN 17037 daylight provision) and maps on the
// sensor points: DA300, the three UDI bands (fell short < 100 lx, useful 100–2000 lx, exceeded
// > 2000 lx) or the hours of direct sun ≥ 1000 lx (ASE), on the false-colour ramp.
import { rampCss } from './false_color.js';
import { el, notice, row } from './ui.js';

const MAPS = [
  ['', 'none (the readings)'],
  ['da300', 'DA300: share of hours ≥ 300 lx'],
  ['udi_fell_short', 'UDI fell short: < 100 lx'],
  ['udi_useful', 'UDI useful: 100–2000 lx'],
  ['udi_exceeded', 'UDI exceeded: > 2000 lx'],
  ['ase_hours', 'ASE: hours of direct sun ≥ 1000 lx'],
];

const percent = (v) => `${(100 * v).toFixed(1)}%`;

export class AnnualPanel {
  // send(message) → seq or null; sensors: the Sensors of the view (its points are coloured);
  // projectWeather() → the weather File chosen elsewhere (the Site panel's day), or null.
  constructor(panel, send, sensors, projectWeather) {
    this.panel = panel;
    this.send = send;
    this.sensors = sensors;
    this.projectWeather = projectWeather;
    this.seq = null; // of the run in progress
    this.result = null;
    this._build();
  }

  setScene(hello) {
    this.sensorSets = (hello.sensors || []).map((s) => ({ name: s.name, points: s.points.length }));
    this.hasWindows = (hello.portals || []).length > 0;
    this.result = null;
    this.seq = null;
    this.resultBox.innerHTML = '';
    this.mapSelect.value = '';
    this.sensors.setMetric(null);
    this.updateRun();
  }

  _build() {
    const p = this.panel;
    this.file = el('input', {
      type: 'file',
      accept: '.epw',
      title: 'An EnergyPlus weather file (.epw): its location, time zone and hourly irradiance',
      dataset: { testid: 'annual-weather' },
    });
    this.file.addEventListener('change', () => this.updateRun());
    this.occupied = el('input', {
      type: 'text',
      value: '08:00-18:00',
      size: 11,
      title: 'Occupied hours, local standard time: HH:MM-HH:MM',
      dataset: { testid: 'annual-occupied' },
    });
    this.runButton = el('button', {
      type: 'button',
      text: 'Run',
      title: 'Compute every occupied hour of the year with the sun up: the state shown now, daylight alone (luminaires off)',
      dataset: { testid: 'annual-run' },
    });
    this.runButton.addEventListener('click', () => this.run());
    this.progress = el('progress', { max: 1, value: 0, dataset: { testid: 'annual-progress' } });
    this.progressText = el('span', { class: 'hint', dataset: { testid: 'annual-progress-text' } });
    this.mapSelect = el('select', { title: 'Colour the sensor points by a metric of the last run', dataset: { testid: 'annual-map' } });
    for (const [value, label] of MAPS) this.mapSelect.append(el('option', { value, text: label }));
    this.mapSelect.addEventListener('change', () => this._showMap());
    this.legend = el('div', { class: 'annual-legend' });
    this.resultBox = el('div', { dataset: { testid: 'annual-result' } });
    p.append(
      row('Weather', this.file),
      row('Occupied', this.occupied, 'Occupied hours, local standard time'),
      el('div', { class: 'row' }, [this.runButton, this.progress, this.progressText]),
      this.resultBox,
      row('Map', this.mapSelect),
      this.legend,
    );
    this.updateRun();
  }

  // The weather file chosen here, else the project's (chosen in the Site panel), or null.
  weatherFile() {
    return this.file.files?.[0] ?? null;
  }

  updateRun() {
    this.runButton.disabled = this.seq !== null || !(this.weatherFile() ?? this.projectWeather()) || this.hasWindows === false;
  }

  async run() {
    const f = this.weatherFile() ?? this.projectWeather();
    if (!f) return;
    const weather = await f.text();
    const seq = this.send({ type: 'annual', weather, occupied: this.occupied.value.trim() });
    if (seq === null) {
      notice('Not connected to the server', 'error');
      return;
    }
    this.seq = seq;
    this.progress.removeAttribute('value'); // indeterminate while the server prepares
    this.progressText.textContent = 'preparing…';
    this.updateRun();
  }

  // annual_progress from the server.
  onProgress(msg) {
    if (msg.seq !== this.seq) return;
    if (msg.stage === 'hours' && msg.total > 0) {
      this.progress.max = msg.total;
      this.progress.value = msg.done;
      this.progressText.textContent = `${msg.done} / ${msg.total} hours`;
    }
  }

  // An error reply: the run failed if it was ours. Returns whether it was.
  onError(msg) {
    if (msg.seq == null || msg.seq !== this.seq) return false;
    this.seq = null;
    this.progress.value = 0;
    this.progressText.textContent = 'failed';
    this.updateRun();
    return true;
  }

  // annual from the server: the result.
  onResult(msg) {
    if (msg.seq !== this.seq) return;
    this.seq = null;
    this.result = msg;
    this.progress.max = 1;
    this.progress.value = 1;
    this.progressText.textContent = `${msg.hours} hours in ${msg.seconds.toFixed(1)} s`;
    this.updateRun();
    const w = msg.weather;
    const box = this.resultBox;
    box.innerHTML = '';
    box.append(
      el('p', {
        class: 'hint',
        text: `${w.city} (${w.latitude.toFixed(2)}°, ${w.longitude.toFixed(2)}°, UTC${w.time_zone >= 0 ? '+' : ''}${w.time_zone} h): ${msg.hours} of ${msg.occupied_hours} occupied hours (${msg.occupied}) with the sun up; daylight alone.`,
      }),
    );
    const table = el('table', { class: 'sensor-table', dataset: { testid: 'annual-table' } }, [
      el('thead', {}, el('tr', {}, [
        el('th', { text: 'sensor set' }),
        el('th', { text: 'sDA300', title: 'Share of points with DA300 ≥ 50%' }),
        el('th', { text: 'ASE', title: 'ASE1000,250h: share of points with more than 250 occupied hours of direct sun ≥ 1000 lx' }),
        el('th', { text: 'mean DA', title: 'Mean DA300 over the points' }),
        el('th', { text: 'EN 17037', title: 'Daylight provision level reached (EN 17037)' }),
      ])),
      el('tbody', {}, msg.sets.map((s) => el('tr', { dataset: { set: s.name } }, [
        el('td', { text: s.name }),
        el('td', { class: 'numcell', text: percent(s.sda300) }),
        el('td', { class: 'numcell', text: percent(s.ase) }),
        el('td', { class: 'numcell', text: percent(s.mean_da300) }),
        el('td', { text: s.en17037 }),
      ]))),
    ]);
    box.append(table);
    if (!this.mapSelect.value) this.mapSelect.value = 'da300';
    this._showMap();
  }

  _showMap() {
    const key = this.mapSelect.value;
    this.legend.innerHTML = '';
    if (!key || !this.result) {
      this.sensors.setMetric(null);
      return;
    }
    const values = new Float32Array(this.sensors.count).fill(NaN);
    let offset = 0;
    for (const s of this.result.sets) {
      s[key].forEach((v, i) => (values[offset + i] = v));
      offset += s.points;
    }
    const hours = key === 'ase_hours';
    const max = hours ? Math.max(250, ...values.filter(Number.isFinite)) : 1;
    const format = hours ? (v) => `${v} h` : (v) => `${Math.round(100 * v)}%`;
    this.sensors.setMetric({ values, max, format });
    const stops = [0, 0.25, 0.5, 0.75, 1];
    this.legend.append(
      el('div', { class: 'annual-ramp', style: { background: `linear-gradient(to right, ${stops.map((t) => rampCss(t)).join(', ')})` } }),
      el('div', { class: 'annual-ticks' }, stops.map((t) => el('span', { text: format(hours ? Math.round(t * max) : t) }))),
    );
  }
}
