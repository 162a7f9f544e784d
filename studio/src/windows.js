// The Windows panel: per portal (hello.portals) the glass tint (transmittance per channel,
// 0..1), frosted glass (frost_deg 0..90, a von Mises–Fisher blur of the shell) and what
// the window sees (docs/scene-format.md "Portals"): a uniform sky (luminance, cd/m²), a
// CIE standard general sky (ISO 15469 types 1–15 or the traditional overcast; as bright as the
// sun's altitude makes it, with a turbidity, or by horizontal illuminance or zenith luminance;
// ground albedo; the sun by date and local time at the project's site (hello.site), by its own
// place (latitude, longitude, UTC offset, date and time → "YYYY-MM-DDTHH:MM") or by angles,
// and its illuminance) or an HDR map (file, rotate_deg, scale). Below, the exterior objects'
// placements (visible, translate, rotate_deg). Each change replaces the portal's
// `environment` object as a whole in the state document. A scene with a top-level environment
// (hello.environment: furniture under a sky or a captured map, lit through the visibility cuts)
// gets the same form first, editing the document's own `environment` (docs/lighting-state.md).
import { hexToLinear, linearToHex } from './colors.js';
import { el, numberInput, row, select, setIfIdle, sliderNumber } from './ui.js';

const SKY_TYPES = [
  ['overcast', 'overcast (traditional)'],
  ['1', '1 overcast, steep'],
  ['2', '2 overcast, steep, sun side'],
  ['3', '3 overcast, moderate'],
  ['4', '4 overcast, moderate, sun side'],
  ['5', '5 uniform'],
  ['6', '6 partly cloudy, sun side'],
  ['7', '7 partly cloudy, bright sun region'],
  ['8', '8 partly cloudy, solar corona'],
  ['9', '9 partly cloudy, obscured sun'],
  ['10', '10 partly cloudy, bright sun region'],
  ['11', '11 white-blue, solar corona'],
  ['12', '12 clear, low turbidity'],
  ['13', '13 clear, polluted'],
  ['14', '14 cloudless turbid, broad corona'],
  ['15', '15 white-blue turbid, broad corona'],
];

const clone = (x) => JSON.parse(JSON.stringify(x ?? null));
const MUNICH = { latitude: 48.14, longitude: 11.58, utc_offset: 1 };
const pad = (n) => String(n).padStart(2, '0');

export class WindowsPanel {
  constructor(container, store) {
    this.container = container;
    this.store = store;
    this.blocks = [];
    store.onChange(() => this.refresh());
  }

  setScene(hello) {
    this.hello = hello;
    this.container.innerHTML = '';
    this.blocks = [];
    if (hello.environment) {
      this.blocks.push(this._block({ name: 'Environment', environment: hello.environment, top: true }, 'env'));
    }
    this.blocks.push(...(hello.portals || []).map((p, i) => this._block(p, i)));
    if (!this.blocks.length) this.container.append(el('p', { class: 'hint', text: 'This scene has no windows (portals) and no environment.' }));
    if (hello.exterior?.length) this._exterior(hello.exterior);
    this.refresh();
  }

  // A sun by place and time: at the project's site (hello.site, docs/scene-format.md "Site") when
  // the scene has one, its date and time alone; otherwise with a place of its own.
  placeSun(datetime = '2026-03-21T12:00') {
    return this.hello?.site ? { datetime } : { ...MUNICH, datetime };
  }

  entry(name) {
    return this.store.doc.portals?.[name] || {};
  }

  effectiveEnv(p) {
    if (p.top) return this.store.doc.environment ?? p.environment;
    return this.entry(p.name).environment ?? p.environment;
  }

  _setEnv(p, env) {
    this.store.edit((doc) => {
      const same = JSON.stringify(env) === JSON.stringify(p.environment);
      if (p.top) {
        if (same) delete doc.environment;
        else doc.environment = env;
        return;
      }
      const e = this.store.portal(p.name);
      if (same) delete e.environment;
      else e.environment = env;
    });
  }

  _block(p, i) {
    const b = { p, i };
    const summary = p.top
      ? 'The environment that lights the scene from infinity wherever its geometry does not block it (through the visibility cuts)'
      : `Window "${p.name}": ${p.diameter?.toFixed?.(2) ?? '?'} m across, facing (${(p.outward || []).map((x) => x.toFixed(2)).join(', ')})`;
    const details = el('details', { class: 'portal', open: true, dataset: p.top ? { environment: 'top' } : { portal: p.name } }, [
      el('summary', { title: summary }, p.name),
    ]);
    if (p.top) {
      this._envRows(b, details, 'The sky or map around the scene');
      return b;
    }
    // Tint.
    b.tint = el('input', { type: 'color', dataset: { testid: `tint-${i}` }, title: 'Glass tint: transmittance per channel (white = clear glass)' });
    b.tint.addEventListener('input', () => this.store.edit(() => (this.store.portal(p.name).tint = hexToLinear(b.tint.value).map((x) => Number(x.toFixed(4))))));
    const clear = el('button', { type: 'button', class: 'small', text: "Scene's tint", title: "Back to the scene's tint" });
    clear.addEventListener('click', () => this.store.edit((doc) => delete doc.portals?.[p.name]?.tint));
    details.append(row('Tint', [b.tint, clear], 'Window colour: multiplies the light through the window'));
    // Frost.
    b.frost = sliderNumber({
      min: 0,
      max: 90,
      step: 0.5,
      value: p.frost_deg || 0,
      unit: '°',
      testid: `frost-${i}`,
      title: 'Frosted glass: angular blur σ of the view out, 0 (clear) to 90°; the light through the window is preserved',
      onChange: (v) => this.store.edit(() => (this.store.portal(p.name).frost_deg = v)),
    });
    details.append(row('Frost', b.frost.element, 'Frosted glass blur width'));
    this._envRows(b, details, 'Environment seen through the window');
    return b;
  }

  // The environment's type, its reset and its form.
  _envRows(b, details, title) {
    const p = b.p;
    b.envType = select(
      [
        ['uniform', 'uniform sky'],
        ['cie_sky', 'CIE sky (and sun)'],
        ['perez', 'Perez sky (weather)'],
        ['map', 'HDR map'],
      ],
      { title: p.top ? 'What surrounds the scene' : 'What the window sees', testid: `env-type-${b.i}`, onChange: (t) => this._switchType(b, t) },
    );
    const reset = el('button', { type: 'button', class: 'small', text: "Scene's", title: "Back to the scene's environment" });
    reset.addEventListener('click', () =>
      this.store.edit((doc) => (p.top ? delete doc.environment : delete doc.portals?.[p.name]?.environment)),
    );
    details.append(row(p.top ? 'Around' : 'Outside', [b.envType, reset], title));
    b.envForm = el('div', { class: 'env-form' });
    details.append(b.envForm);
    this.container.append(details);
  }

  _switchType(b, type) {
    const cur = this.effectiveEnv(b.p);
    b.pendingMap = false;
    if (cur?.type === type) return this.refresh();
    if (b.p.environment?.type === type) return this._setEnv(b.p, clone(b.p.environment));
    if (type === 'uniform') return this._setEnv(b.p, { type, luminance: 1000 });
    if (type === 'cie_sky') return this._setEnv(b.p, { type, sky_type: 'overcast', horizontal_illuminance: 10000 });
    if (type === 'perez') {
      return this._setEnv(b.p, {
        type, direct_normal_irradiance: 600, diffuse_horizontal_irradiance: 120,
        sun: this.placeSun(),
      });
    }
    // A map needs a file first.
    b.pendingMap = true;
    this._form(b, { type: 'map', file: '', rotate_deg: 0, scale: 1 });
  }

  // Builds the environment form for env (rebuilt when the type or the sun mode changes).
  _form(b, env) {
    const key = JSON.stringify([env.type, sunMode(env), brightnessMode(env), siteSun(env), b.pendingMap]);
    b.env = clone(env);
    if (b.formKey === key) return this._fill(b);
    b.formKey = key;
    const f = b.envForm;
    f.innerHTML = '';
    b.fields = {};
    const commit = () => {
      if (b.env.type === 'map' && !b.env.file) return;
      b.pendingMap = false;
      this._setEnv(b.p, clone(b.env));
    };
    const num = (k, label, opts, title, obj = () => b.env) => {
      const w = numberInput({ ...opts, title, onChange: (v) => ((obj()[k] = v), commit()) });
      b.fields[k] = w.input || w;
      f.append(row(label, w, title));
    };
    if (env.type === 'uniform') {
      num('luminance', 'Luminance', { min: 0, unit: 'cd/m²' }, 'Luminance of the whole sky and ground seen through the window, cd/m²');
      const c = el('input', { type: 'color', title: 'Colour of the uniform sky (chromaticity)' });
      c.addEventListener('input', () => ((b.env.color = hexToLinear(c.value).map((x) => Number(x.toFixed(4)))), commit()));
      b.fields.color = c;
      f.append(row('Colour', c, 'Sky colour'));
    } else if (env.type === 'cie_sky') {
      const sky = select(SKY_TYPES, {
        title: 'CIE standard general sky (ISO 15469 / CIE S 011) type, or the traditional CIE overcast sky',
        testid: `sky-type-${b.i}`,
        onChange: (v) => {
          b.env.sky_type = v === 'overcast' ? v : Number(v);
          // Skies that are not uniform in azimuth depend on where the sun is: give one.
          if (!b.env.sun && !['overcast', '1', '3', '5'].includes(v)) {
            b.env.sun = this.placeSun();
            if (b.env.horizontal_illuminance !== undefined || b.env.zenith_luminance !== undefined) {
              b.env.sun_illuminance ??= Number(v) >= 11 ? 70000 : Number(v) >= 6 ? 30000 : 0;
            }
          }
          commit();
        },
      });
      b.fields.sky_type = sky;
      f.append(row('Sky type', sky, 'Sky luminance distribution'));
      const by = select(
        [
          ['s', "by the sun's altitude"],
          ['h', 'horizontal illuminance'],
          ['z', 'zenith luminance'],
        ],
        {
          title: "The sky's brightness: by the sun's altitude (the sky and sun of a day at the site: dark at night), or fixed as its horizontal illuminance (lx, without the sun) or its zenith luminance (cd/m²)",
          value: brightnessMode(env),
          testid: `sky-brightness-${b.i}`,
          onChange: (v) => {
            const val = b.env.horizontal_illuminance ?? b.env.zenith_luminance;
            delete b.env.horizontal_illuminance;
            delete b.env.zenith_luminance;
            if (v === 'z') b.env.zenith_luminance = val ?? 3000;
            else if (v === 'h') b.env.horizontal_illuminance = val ?? 10000;
            else {
              b.env.sun ??= this.placeSun(); // the altitude needs a sun
              delete b.env.sun_illuminance; // the model's
            }
            commit();
          },
        },
      );
      f.append(row('Brightness', by));
      if (env.zenith_luminance !== undefined) num('zenith_luminance', 'Zenith', { min: 0, unit: 'cd/m²' }, 'Luminance of the sky at the zenith, cd/m²');
      else if (env.horizontal_illuminance !== undefined) num('horizontal_illuminance', 'Sky', { min: 0, unit: 'lx' }, 'Diffuse horizontal illuminance of the sky (without the sun), lx; 10000 lx is a bright overcast day');
      else num('linke_turbidity', 'Turbidity', { min: 1, max: 10, step: 0.1 }, 'Linke turbidity of the atmosphere (1 very clean … 10 hazy; 3 typical): how much the air dims the sun');
      num('ground_albedo', 'Albedo', { min: 0, max: 1, step: 0.01 }, 'Reflectance of the ground below the horizon (Lambertian), 0..1; default 0.2');
      this._sunForm(b, env, f, num, commit, true);
      if (sunMode(env) !== 'none') num('sun_illuminance', 'Sun disc', { min: 0, unit: 'lx' }, "Illuminance of the sun normal to its direction, lx (0 = no sun disc; clear sky ≈ 70000–100000; empty with a sky by the sun's altitude: the model's)");
    } else if (env.type === 'perez') {
      num('direct_normal_irradiance', 'Direct', { min: 0, max: 1500, unit: 'W/m²' }, 'Direct normal irradiance of the weather record, W/m² (clear sky ≈ 600–900)');
      num('diffuse_horizontal_irradiance', 'Diffuse', { min: 0, max: 1500, unit: 'W/m²' }, 'Diffuse horizontal irradiance of the weather record, W/m² (overcast ≈ 50–300)');
      num('dew_point_c', 'Dew point', { min: -90, max: 60, unit: '°C' }, 'Surface dew point, °C: the atmosphere\'s water, which sets the luminous efficacy (empty: 2 cm of precipitable water)');
      num('ground_albedo', 'Albedo', { min: 0, max: 1, step: 0.01 }, 'Reflectance of the ground below the horizon (Lambertian), 0..1; default 0.2');
      this._sunForm(b, env, f, num, commit, false);
    } else if (env.type === 'map') {
      const file = el('input', {
        type: 'text',
        placeholder: 'sky.exr, sky.hdr or a capture',
        title: 'Equirectangular HDR map (.exr or .hdr) in cd/m², such as a room captured with `relight capture` (docs/capture.md); relative paths resolve against the folder of the .rlt. Press Enter to apply.',
        dataset: { testid: `env-file-${b.i}` },
      });
      const apply = () => {
        b.env.file = file.value.trim();
        commit();
      };
      file.addEventListener('change', apply);
      file.addEventListener('keydown', (e) => e.key === 'Enter' && apply());
      b.fields.file = file;
      f.append(row('File', file, 'HDR map file'));
      num('rotate_deg', 'Rotation', { step: 1, unit: '°' }, 'Turns the map clockwise seen from above, degrees');
      num('scale', 'Scale', { min: 0, step: 'any' }, 'Multiplier on the map values (cd/m²)');
    }
    this._fill(b);
  }

  // The sun's rows of an environment form (a Perez sky always has a sun: no 'none').
  _sunForm(b, env, f, num, commit, allowNone) {
    const mode = select(
      [
        ...(allowNone ? [['none', 'no sun']] : []),
        ['place', 'by place and local time'],
        ['angles', 'by azimuth and altitude'],
      ],
      {
        title: 'Where the sun is. North is −z and east +x; azimuths from north, clockwise toward east. CIE sky types other than 1, 3, 5 and overcast need a sun position.',
        value: sunMode(env),
        testid: `sun-mode-${b.i}`,
        onChange: (m) => {
          if (m === 'none') {
            delete b.env.sun;
            delete b.env.sun_illuminance; // a sun disc needs a sun position
          }
          if (m === 'place') b.env.sun = this.placeSun();
          if (m === 'angles') b.env.sun = { azimuth_deg: 180, altitude_deg: 35 };
          if (allowNone && m !== 'none' && b.env.sun_illuminance === undefined && brightnessMode(b.env) !== 's') b.env.sun_illuminance = 70000;
          commit();
        },
      },
    );
    f.append(row('Sun', mode, 'Sun position'));
    const sun = () => b.env.sun;
    if (sunMode(env) === 'place') {
      if (siteSun(env)) {
        f.append(row('Place', el('span', { class: 'hint', text: "the project's site (Site panel)" }), 'A sun by date and time alone stands at the site'));
      } else {
        num('latitude', 'Latitude', { min: -90, max: 90, unit: '°' }, 'Latitude in degrees, north positive', sun);
        num('longitude', 'Longitude', { min: -180, max: 180, unit: '°' }, 'Longitude in degrees, east positive', sun);
        num('utc_offset', 'UTC offset', { min: -14, max: 14, unit: 'h' }, 'Local time minus UTC, hours (e.g. 1 for CET, 2 for CEST)', sun);
      }
      const date = el('input', { type: 'date', title: 'Local date', dataset: { testid: `sun-date-${b.i}` } });
      const time = el('input', { type: 'time', title: 'Local time (HH:MM)', dataset: { testid: `sun-time-${b.i}` } });
      const scrub = el('input', { type: 'range', min: 0, max: 1439, step: 5, title: 'Time of day: drag to move the sun through the day', class: 'time-slider', dataset: { testid: `sun-time-slider-${b.i}` } });
      const setDT = () => {
        if (!date.value || !time.value) return;
        b.env.sun.datetime = `${date.value}T${time.value.slice(0, 5)}`;
        commit();
      };
      date.addEventListener('change', setDT);
      time.addEventListener('change', setDT);
      scrub.addEventListener('input', () => {
        const m = Number(scrub.value);
        time.value = `${pad(Math.floor(m / 60))}:${pad(m % 60)}`;
        setDT();
      });
      b.fields.date = date;
      b.fields.time = time;
      b.fields.scrub = scrub;
      f.append(row('Date', date, 'Local date'), row('Time', [time, scrub], 'Local time'));
    } else if (sunMode(env) === 'angles') {
      num('azimuth_deg', 'Azimuth', { min: -360, max: 360, unit: '°' }, 'Sun azimuth from north, clockwise toward east (180 = south)', sun);
      num('altitude_deg', 'Altitude', { min: -90, max: 90, unit: '°' }, 'Sun altitude above the horizon', sun);
    }
  }

  // Puts the values of b.env into the form's fields (those not being edited).
  _fill(b) {
    const env = b.env;
    const put = (k, v) => {
      const input = b.fields[k];
      if (input && document.activeElement !== input && v !== undefined) input.value = String(v);
    };
    if (env.type === 'uniform') {
      put('luminance', env.luminance);
      put('color', linearToHex(env.color || [1, 1, 1], true));
    } else if (env.type === 'cie_sky') {
      put('sky_type', String(env.sky_type ?? 'overcast'));
      put('horizontal_illuminance', env.horizontal_illuminance);
      put('zenith_luminance', env.zenith_luminance);
      put('ground_albedo', env.ground_albedo ?? 0.2);
      put('linke_turbidity', env.linke_turbidity ?? 3);
      put('sun_illuminance', env.sun_illuminance ?? (brightnessMode(env) === 's' ? '' : 0));
    } else if (env.type === 'perez') {
      put('direct_normal_irradiance', env.direct_normal_irradiance);
      put('diffuse_horizontal_irradiance', env.diffuse_horizontal_irradiance);
      put('dew_point_c', env.dew_point_c);
      put('ground_albedo', env.ground_albedo ?? 0.2);
    }
    if (env.type === 'cie_sky' || env.type === 'perez') {
      const s = env.sun || {};
      put('latitude', s.latitude);
      put('longitude', s.longitude);
      put('utc_offset', s.utc_offset ?? 0);
      put('azimuth_deg', s.azimuth_deg);
      put('altitude_deg', s.altitude_deg);
      if (s.datetime) {
        const [d, t = '12:00'] = s.datetime.split('T');
        put('date', d);
        put('time', t.slice(0, 5));
        const [hh, mm] = t.split(':').map(Number);
        if (b.fields.scrub && !b.fields.scrub._dragging) put('scrub', String(hh * 60 + mm));
      }
    }
    if (env.type === 'map') {
      put('file', env.file);
      put('rotate_deg', env.rotate_deg ?? 0);
      put('scale', env.scale ?? 1);
    }
  }

  _exterior(names) {
    const box = el('details', { class: 'portal', open: true }, [el('summary', { title: 'Exterior objects the windows see (placements for every window)' }, 'Exterior objects')]);
    this.exteriorRows = names.map((name) => {
      const vis = el('input', { type: 'checkbox', checked: true, title: `Show "${name}"` });
      const cur = () => this.store.doc.exterior?.[name] || {};
      const edit = (fn) =>
        this.store.edit((doc) => {
          doc.exterior ??= {};
          const e = (doc.exterior[name] ??= {});
          fn(e);
          if (!Object.keys(e).length) delete doc.exterior[name];
        });
      vis.addEventListener('change', () => edit((e) => (vis.checked ? delete e.visible : (e.visible = false))));
      const t = [0, 1, 2].map((k) =>
        numberInput({
          value: 0,
          step: 0.1,
          width: '4.2em',
          title: `Move by ${'xyz'[k]}, m (from where the scene put it)`,
          onChange: (v) => edit((e) => {
            e.translate = [0, 1, 2].map((j) => (j === k ? v : cur().translate?.[j] ?? 0));
          }),
        }),
      );
      const rot = numberInput({ value: 0, step: 5, unit: '°', title: 'Turn about the vertical axis through its bounding box centre, counter-clockwise seen from above', onChange: (v) => edit((e) => (e.rotate_deg = v)) });
      box.append(el('div', { class: 'row' }, [el('label', { class: 'check' }, [vis, ` ${name}`])]), row('Move (m)', t), row('Rotate', rot));
      return { name, vis, t, rot };
    });
    this.container.append(box);
  }

  refresh() {
    if (!this.hello) return;
    for (const b of this.blocks) {
      if (!b.p.top) {
        const e = this.entry(b.p.name);
        const tint = e.tint ?? b.p.tint ?? [1, 1, 1];
        if (document.activeElement !== b.tint) b.tint.value = linearToHex(tint);
        b.frost.set(e.frost_deg ?? b.p.frost_deg ?? 0);
      }
      const env = this.effectiveEnv(b.p);
      if (b.pendingMap && env.type !== 'map') {
        setIfIdle(b.envType, 'map');
        continue;
      }
      b.pendingMap = false;
      setIfIdle(b.envType, env.type);
      this._form(b, env);
    }
    for (const r of this.exteriorRows || []) {
      const e = this.store.doc.exterior?.[r.name] || {};
      r.vis.checked = e.visible !== false;
      r.t.forEach((w, k) => document.activeElement !== w && (w.value = String(e.translate?.[k] ?? 0)));
      if (document.activeElement !== r.rot.input) r.rot.input.value = String(e.rotate_deg ?? 0);
    }
  }
}

// How a CIE sky's brightness is given: 's' by the sun's altitude (neither key), 'h', 'z'.
function brightnessMode(env) {
  if (env.zenith_luminance !== undefined) return 'z';
  return env.horizontal_illuminance !== undefined ? 'h' : 's';
}

// A sun by date and time alone: at the project's site.
function siteSun(env) {
  return !!env.sun && env.sun.datetime !== undefined && env.sun.latitude === undefined;
}

function sunMode(env) {
  if (!env.sun) return 'none';
  return env.sun.datetime !== undefined || env.sun.latitude !== undefined ? 'place' : 'angles';
}
