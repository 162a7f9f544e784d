// Sensors (hello.sensors, readings from each RLFR): the points drawn in the 3D view,
// coloured by their illuminance on the false-colour scale in the lux view, their readings as
// labels, and a table per sensor set of the figures lighting designers check (EN 12464-1
// style): Eavg, Emin, Emax and the uniformity U0 = Emin / Eavg, all in lx. The readings
// can be downloaded as CSV (sensor,index,x,y,z,lux).
import * as THREE from 'three';

import { formatValue, rampColor, scalePosition } from './false_color.js';
import { gridIsolines, isolineLevels } from './isolines.js';
import { downloadBlob, el } from './ui.js';
import { srgbToLinear } from './colors.js';

export class Sensors {
  constructor(viewer, panel) {
    this.viewer = viewer;
    this.panel = panel;
    this.sets = [];
    this.values = new Float32Array(0);
    this.showPoints = true;
    this.planView = false; // readings and isolines drawn whatever the checkboxes say
    this.drawnIsolines = 0; // isoline segments in the last drawing
    // Readings are written only when asked: a storey's hundreds of labels would cover the view.
    this.showValues = false;
    this.object = null;
    // A year-of-daylight map shown instead of the readings (annual.js): {values (per point, NaN
    // where unknown), max (the value at the top of the ramp), format(v) for the labels}.
    this.metric = null;
  }

  // Colours and labels the points by `metric` (see the constructor) instead of the frame's
  // readings; null shows the readings again.
  setMetric(metric) {
    this.metric = metric;
    this.viewer.requestRender();
  }

  setScene(hello) {
    this.sets = [];
    let offset = 0;
    for (const s of hello.sensors || []) {
      this.sets.push({ name: s.name, normal: s.normal, nu: s.nu, nv: s.nv, points: s.points, offset });
      offset += s.points.length;
    }
    this.count = offset;
    this.values = new Float32Array(offset).fill(NaN);
    if (this.object) {
      this.viewer.overlays.remove(this.object);
      this.object.geometry.dispose();
      this.object.material.dispose();
    }
    const pos = new Float32Array(3 * offset);
    this.sets.forEach((s) => s.points.forEach((p, i) => pos.set(p, 3 * (s.offset + i))));
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    this.colors = new THREE.BufferAttribute(new Float32Array(3 * offset).fill(1), 3);
    g.setAttribute('color', this.colors);
    this.object = new THREE.Points(g, new THREE.PointsMaterial({ size: 5, sizeAttenuation: false, vertexColors: true, toneMapped: false }));
    this.object.visible = this.showPoints;
    this.viewer.addOverlay(this.object);
    this._buildPanel();
  }

  setReadings(values) {
    if (values.length !== this.count) {
      throw new Error(`frame has ${values.length} sensor readings, hello has ${this.count} sensor points`);
    }
    this.values = Float32Array.from(values);
    this._updateTable();
  }

  stats(set) {
    const v = this.values.subarray(set.offset, set.offset + set.points.length);
    let sum = 0, min = Infinity, max = -Infinity;
    for (const x of v) {
      sum += x;
      min = Math.min(min, x);
      max = Math.max(max, x);
    }
    const avg = sum / v.length;
    return { n: v.length, avg, min, max, u0: avg > 0 ? min / avg : NaN };
  }

  // Before each render: point colours follow the lux scale in the lux view, else white.
  colour(used) {
    if (!this.object) return;
    const lux = used.mode === 'false-lux';
    const c = this.colors.array;
    const m = this.metric;
    for (let i = 0; i < this.count; i++) {
      // Ramp colours are sRGB; the points material expects linear colours.
      let rgb = [1, 0.9, 0.15];
      if (m) rgb = rampColor(Math.min(Math.max(m.values[i] / m.max, 0), 1)).map((x) => srgbToLinear(x / 255));
      else if (lux) rgb = rampColor(scalePosition(used.scale, this.values[i])).map((x) => srgbToLinear(x / 255));
      c.set(rgb, 3 * i);
    }
    this.colors.needsUpdate = true;
    this.object.visible = this.showPoints;
  }

  // The plan view: readings and isolines drawn whatever the checkboxes say.
  setPlanView(on) {
    this.planView = on;
    this.viewer.requestRender();
  }

  // After each render: the isolines of every grid set in the plan view (the readings' lux,
  // each level labelled once a set), then the readings as labels.
  drawLabels(layer) {
    if (!this.object) return;
    this.drawnIsolines = 0;
    if (this.planView && !this.metric) {
      for (const s of this.sets) {
        if (!(s.nu > 1 && s.nv > 1)) continue;
        const values = this.values.subarray(s.offset, s.offset + s.points.length);
        let lo = Infinity, hi = -Infinity;
        for (const v of values) {
          if (v < lo) lo = v;
          if (v > hi) hi = v;
        }
        for (const level of isolineLevels(lo, hi)) {
          const segments = gridIsolines(s, values, level);
          this.drawnIsolines += segments.length;
          for (const [a, b] of segments) layer.segment(a, b, '#ffffff');
          const middle = segments[Math.floor(segments.length / 2)];
          if (middle) layer.label(middle[0], `${formatValue(level)} lx`, { font: '10px system-ui, sans-serif', background: 'rgba(0,0,0,0.75)' });
        }
      }
    }
    if (!this.showValues && !this.planView) return;
    for (const s of this.sets) {
      s.points.forEach((p, i) => {
        const m = this.metric;
        const v = m ? m.values[s.offset + i] : this.values[s.offset + i];
        if (Number.isFinite(v)) layer.label(p, m ? m.format(v) : formatValue(v), { font: '10px system-ui, sans-serif', dy: -17 });
      });
    }
  }

  _buildPanel() {
    const p = this.panel;
    p.innerHTML = '';
    if (!this.sets.length) {
      p.append(el('p', { class: 'hint', text: 'This scene has no sensors.' }));
      return;
    }
    const showPoints = el('input', { type: 'checkbox', id: 'show-sensors', checked: this.showPoints, title: 'Draw the sensor points in the view' });
    showPoints.addEventListener('change', () => {
      this.showPoints = showPoints.checked;
      if (this.object) this.object.visible = this.showPoints;
      this.viewer.requestRender();
    });
    const showValues = el('input', { type: 'checkbox', id: 'show-sensor-values', checked: this.showValues, title: 'Write each sensor reading (lx) beside its point; labels that would overlap are left out' });
    showValues.addEventListener('change', () => {
      this.showValues = showValues.checked;
      this.viewer.requestRender();
    });
    p.append(
      el('div', { class: 'row' }, [
        el('label', { class: 'check' }, [showPoints, ' points']),
        el('label', { class: 'check' }, [showValues, ' readings (lx)']),
      ]),
    );
    const table = el('table', { class: 'sensor-table', id: 'sensor-table' }, [
      el('thead', {}, el('tr', {}, [
        el('th', { text: 'sensor set', title: 'Sensor set (scene order)' }),
        el('th', { text: 'n', title: 'Number of points' }),
        el('th', { text: 'Eavg lx', title: 'Mean illuminance, lx' }),
        el('th', { text: 'Emin lx', title: 'Lowest illuminance, lx' }),
        el('th', { text: 'Emax lx', title: 'Highest illuminance, lx' }),
        el('th', { text: 'U0', title: 'Uniformity U0 = Emin / Eavg' }),
      ])),
      (this.tbody = el('tbody')),
    ]);
    this.rows = this.sets.map((s) => {
      const cells = [0, 1, 2, 3, 4].map(() => el('td', { class: 'numcell' }));
      const tr = el('tr', { dataset: { sensor: s.name } }, [el('td', { text: s.name, title: `normal ${s.normal.join(', ')}${s.nu ? `, grid ${s.nu} × ${s.nv}` : ''}` }), ...cells]);
      this.tbody.append(tr);
      return cells;
    });
    const csv = el('button', { type: 'button', text: 'Download readings (CSV)', title: 'sensor,index,x,y,z,lux for every sensor point of the current frame' });
    csv.addEventListener('click', () => this.downloadCsv());
    p.append(table, el('div', { class: 'row' }, csv));
    this._updateTable();
  }

  _updateTable() {
    if (!this.rows) return;
    this.sets.forEach((s, k) => {
      const st = this.stats(s);
      const cells = this.rows[k];
      cells[0].textContent = String(st.n);
      cells[1].textContent = formatValue(st.avg);
      cells[2].textContent = formatValue(st.min);
      cells[3].textContent = formatValue(st.max);
      cells[4].textContent = Number.isFinite(st.u0) ? st.u0.toFixed(3) : '–';
    });
  }

  downloadCsv() {
    const lines = ['sensor,index,x,y,z,lux'];
    for (const s of this.sets) {
      s.points.forEach((p, i) => {
        const name = /[",\n]/.test(s.name) ? `"${s.name.replace(/"/g, '""')}"` : s.name;
        lines.push(`${name},${i},${p.join(',')},${this.values[s.offset + i]}`);
      });
    }
    downloadBlob(new Blob([lines.join('\n') + '\n'], { type: 'text/csv' }), 'sensors.csv');
  }
}
