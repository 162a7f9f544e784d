// A day from weather data, in the Site panel: the designer loads an EnergyPlus weather file
// (.epw; or the project's, the one chosen in the annual panel), picks a day, and scrubs its
// hours. The server reads the file and answers `weather_day` (docs/studio-protocol.md) with
// each hour's Perez sky — the one `relight annual` lights the windows with for that record —
// and the slider puts the hour's sky on every window and on the scene's environment as an
// ordinary lighting state, so every frame, sensor and number is the server's for that hour.
import { el, notice, row } from './ui.js';

const dayOf = (date) => date.slice(5); // "YYYY-MM-DD" → "MM-DD"

export class WeatherDay {
  // send(message) → seq or null; projectWeather() → the File chosen elsewhere (the annual
  // panel's), or null; fileChosen() when a file is chosen here.
  constructor(container, store, send, { projectWeather, fileChosen }) {
    this.container = container;
    this.store = store;
    this.send = send;
    this.projectWeather = projectWeather;
    this.fileChosen = fileChosen;
    this.seq = null;
    this.day = null; // the last weather_day reply
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    this.day = null;
    this.seq = null;
    this.file = el('input', {
      type: 'file',
      accept: '.epw',
      title: "An EnergyPlus weather file (.epw); without one, the annual panel's",
      dataset: { testid: 'weather-file' },
    });
    this.file.addEventListener('change', () => {
      this.load();
      this.fileChosen();
    });
    this.date = el('input', { type: 'date', value: '2026-06-21', title: 'The day of the weather file to scrub (its year is ignored)', dataset: { testid: 'weather-date' } });
    this.date.addEventListener('change', () => this.load());
    this.loadButton = el('button', { type: 'button', class: 'small', text: 'Load', title: 'Read the day from the weather file', dataset: { testid: 'weather-load' } });
    this.loadButton.addEventListener('click', () => this.load());
    this.hour = el('input', { type: 'range', min: 0, max: 23, step: 1, value: 12, disabled: true, title: 'The hour of the day (local standard time, the middle of the weather record)', dataset: { testid: 'weather-hour' } });
    this.hour.addEventListener('input', () => this.show());
    this.readout = el('p', { class: 'hint', dataset: { testid: 'weather-readout' } });
    const lit = (hello.portals || []).length > 0 || !!hello.environment;
    this.container.append(
      el('h4', { text: 'A day from weather data' }),
      row('Weather', this.file),
      row('Day', [this.date, this.loadButton]),
      row('Hour', this.hour),
      this.readout,
    );
    this.readout.textContent = lit
      ? "Load a weather file (or run the annual panel's) and scrub the day's hours: each is that hour's Perez sky on every window."
      : 'This scene has no windows (portals) and no environment.';
    this.loadButton.disabled = !lit;
  }

  // The weather file chosen here, or null.
  weatherFile() {
    return this.file?.files?.[0] ?? null;
  }

  // Asks the server for the chosen day of the chosen (or the project's) weather file.
  async load() {
    const f = this.weatherFile() ?? this.projectWeather();
    if (!f) {
      notice('Choose a weather file (.epw) here or in the annual panel', 'error');
      return;
    }
    const seq = this.send({ type: 'weather_day', weather: await f.text(), date: dayOf(this.date.value) });
    if (seq === null) {
      notice('Not connected to the server', 'error');
      return;
    }
    this.seq = seq;
    this.readout.textContent = `Reading ${f.name}…`;
  }

  // weather_day from the server.
  onDay(msg) {
    if (msg.seq !== this.seq) return;
    this.seq = null;
    this.day = msg;
    this.hour.max = String(msg.hours.length - 1);
    this.hour.value = String(Math.min(Number(this.hour.value), msg.hours.length - 1));
    this.hour.disabled = false;
    this.show();
  }

  // An error reply: ours if it answers the request in flight. Returns whether it was.
  onError(msg) {
    if (msg.seq == null || msg.seq !== this.seq) return false;
    this.seq = null;
    this.readout.textContent = msg.message;
    return true;
  }

  // Puts the hour on the slider into the state: its sky on every window and the environment.
  show() {
    if (!this.day) return;
    const h = this.day.hours[Number(this.hour.value)];
    const w = this.day.weather;
    // One undo step per scrub (a drag across the hours is one gesture).
    this.store.edit((doc) => {
      for (const p of this.hello.portals || []) this.store.portal(p.name).environment = structuredClone(h.environment);
      if (this.hello.environment) doc.environment = structuredClone(h.environment);
    }, 'weather-hour');
    const sun = h.sun_altitude_deg > 0 ? `sun ${h.sun_altitude_deg.toFixed(1)}° high` : 'sun below the horizon';
    this.readout.textContent = `${w.city}, ${this.day.date} ${h.time}: direct normal ${h.direct_normal_irradiance} W/m², diffuse horizontal ${h.diffuse_horizontal_irradiance} W/m², ${sun}`;
  }
}
