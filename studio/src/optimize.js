// The optimise panel (issue 20): inverse lighting design as `relight optimize` computes it, run
// by the server from the state on screen (docs/studio-protocol.md, `optimize`). Per sensor set
// the designer types targets — the mean illuminance Em between a min and a max, the uniformity
// U0 = Emin / Em at least a min, every point's E between a min and a max (blank: no target) —
// picks the objective (least power, or the best uniformity) and, when the scene has windows,
// whether their daylight counts (the luminaires top it up; else the windows are dark), and
// presses Run. The result: feasible, or infeasible and the targets that bind; per target its
// value, what was achieved and whether it is met; the power and the luminaires' dimmers. The
// state document that reproduces it becomes the studio's lighting state, as a loaded state file
// does (the panels follow, every client sees it; State → Save writes it).
import { el, notice, select } from './ui.js';

// The targets of a set, in the order `relight optimize` lists them: [key, label, unit, title].
const KINDS = [
  ['em_min', 'Em min', 'lx', 'Mean illuminance of the set at least this (lx)'],
  ['em_max', 'Em max', 'lx', 'Mean illuminance of the set at most this (lx)'],
  ['u0_min', 'U0 min', '', 'Uniformity U0 = Emin / Em of the set at least this (0…1)'],
  ['e_min', 'E min', 'lx', 'Every point of the set at least this (lx)'],
  ['e_max', 'E max', 'lx', 'Every point of the set at most this (lx)'],
];

const OBJECTIVES = [
  ['power', 'least power'],
  ['uniformity', 'best uniformity (largest U0)'],
];

// An achieved or target value: lx with one decimal, U0 with three.
const formatTarget = (key, v) => (key === 'u0_min' ? v.toFixed(3) : v.toFixed(1));

export class OptimizePanel {
  // send(message) → seq or null; applyState(doc) makes doc the client's lighting state (and
  // sends it); stateShown() → a promise that resolves once the state on screen has been sent
  // (the server optimises from the last state it received).
  constructor(panel, send, { applyState, stateShown = async () => {} }) {
    this.panel = panel;
    this.send = send;
    this.applyState = applyState;
    this.stateShown = stateShown;
    this.sets = [];
    this.hasWindows = false;
    this.seq = null; // of the run in progress
    this.starting = false; // waiting for the state shown before sending
    this.result = null;
    this._build();
  }

  setScene(hello) {
    this.sets = (hello.sensors || []).map((s) => s.name);
    this.hasWindows = (hello.portals || []).length > 0;
    this.result = null;
    this.seq = null;
    this.starting = false;
    this.targetsBox.innerHTML = '';
    this.inputs = this.sets.map((name, i) => this._setTargets(name, i));
    if (!this.sets.length) this.targetsBox.append(el('p', { class: 'hint', text: 'This scene has no sensors to set targets on.' }));
    this.daylightRow.hidden = !this.hasWindows;
    this.daylight.checked = false;
    this.statusText.textContent = '';
    this.resultBox.innerHTML = '';
    this._updateButton();
  }

  _build() {
    this.targetsBox = el('div', { class: 'optimize-targets' });
    this.objective = select(OBJECTIVES, {
      value: 'power',
      title: 'What to optimise while every target is met: the least electric power (Σ W · dimmer), or the largest uniformity U0 of the sets with targets',
      testid: 'optimize-objective',
    });
    this.daylight = el('input', {
      type: 'checkbox',
      title: "Keep the windows' daylight as the state shown has it: the luminaires top it up (daylight-linked dimming). Unticked, the design is for electric light alone and the windows are dark in the result",
      dataset: { testid: 'optimize-daylight' },
    });
    this.daylightRow = el('div', { class: 'row' }, [
      el('span', { class: 'row-label' }),
      el('label', { class: 'check' }, [this.daylight, ' keep daylight']),
    ]);
    this.runButton = el('button', {
      type: 'button',
      text: 'Run',
      title: 'Find the luminaire dimmers that meet the targets, starting from the state shown now (as relight optimize), and apply them',
      dataset: { testid: 'optimize-run' },
    });
    this.runButton.addEventListener('click', () => this.run());
    this.statusText = el('span', { class: 'hint', dataset: { testid: 'optimize-status' } });
    this.resultBox = el('div', { dataset: { testid: 'optimize-result' } });
    this.panel.append(
      el('p', { class: 'hint', text: 'Targets per sensor set (blank: none). Run finds the luminaire dimmers that meet them, as relight optimize, and applies them.' }),
      this.targetsBox,
      el('label', { class: 'row', title: this.objective.title }, [el('span', { class: 'row-label', text: 'Objective' }), this.objective]),
      this.daylightRow,
      el('div', { class: 'row' }, [this.runButton, this.statusText]),
      this.resultBox,
    );
    this.inputs = [];
    this._updateButton();
  }

  // The inputs of sensor set i: {key: <input>} for every kind of target.
  _setTargets(name, i) {
    const inputs = {};
    for (const [key, label, unit, title] of KINDS) {
      inputs[key] = el('input', {
        type: 'number',
        class: 'num',
        min: 0,
        max: key === 'u0_min' ? 1 : undefined,
        step: 'any',
        placeholder: 'none',
        title: `${title}; blank: no target`,
        dataset: { testid: `optimize-${key}-${i}` },
      });
      inputs[key].addEventListener('input', () => this._updateButton());
      inputs[key].addEventListener('change', () => this._updateButton());
      inputs[key].label = label;
      inputs[key].unit = unit;
    }
    const pair = (label, title, a, b, unit) =>
      el('div', { class: 'row', title }, [
        el('span', { class: 'row-label', text: label }),
        a,
        ...(b ? [el('span', { text: 'to' }), b] : [el('span', { class: 'hint', text: 'at least' })]),
        unit ? el('span', { class: 'unit', text: unit }) : null,
      ]);
    this.targetsBox.append(
      el('div', { class: 'optimize-set', dataset: { set: name } }, [
        el('div', { class: 'optimize-set-name', text: name }),
        pair('Em', 'Mean illuminance of the set: at least / at most (lx)', inputs.em_min, inputs.em_max, 'lx'),
        pair('U0', 'Uniformity Emin / Em of the set: at least', inputs.u0_min, null, ''),
        pair('E (points)', 'Every point of the set: at least / at most (lx)', inputs.e_min, inputs.e_max, 'lx'),
      ]),
    );
    return inputs;
  }

  // The TARGETS.json object of the inputs (docs/studio-protocol.md, `optimize`), and how many
  // targets it has.
  targets() {
    const sensors = {};
    let count = 0;
    this.sets.forEach((name, i) => {
      for (const [key] of KINDS) {
        const input = this.inputs[i][key];
        const text = input.value.trim();
        if (text === '') continue;
        const v = Number(text);
        if (!Number.isFinite(v)) continue;
        (sensors[name] ??= {})[key] = v;
        count++;
      }
    });
    return { targets: { sensors, objective: this.objective.value }, count };
  }

  _updateButton() {
    const busy = this.seq !== null || this.starting;
    this.runButton.disabled = busy || this.targets().count === 0;
  }

  async run() {
    const { targets, count } = this.targets();
    if (!count || this.seq !== null || this.starting) return;
    this.starting = true;
    this._updateButton();
    this.statusText.textContent = 'running…';
    const sets = this.sets;
    await this.stateShown();
    if (this.sets !== sets) return; // a new hello (reconnected) meanwhile: setScene reset the panel
    this.starting = false;
    const daylight = this.hasWindows && this.daylight.checked;
    const seq = this.send({ type: 'optimize', targets, daylight });
    if (seq === null) {
      this.statusText.textContent = '';
      notice('Not connected to the server', 'error');
      this._updateButton();
      return;
    }
    this.seq = seq;
    this.daylightRun = daylight;
    this._updateButton();
  }

  // An error reply: the run failed if it was ours (bad targets, or a run already going). The
  // message goes into the panel. Returns whether it was ours.
  onError(msg) {
    if (msg.seq == null || msg.seq !== this.seq) return false;
    this.seq = null;
    this.statusText.textContent = 'failed';
    this.resultBox.innerHTML = '';
    this.resultBox.append(el('p', { class: 'optimize-verdict bad', text: msg.message, dataset: { testid: 'optimize-error' } }));
    this._updateButton();
    return true;
  }

  // optimized from the server: the summary `relight optimize` prints and the state document
  // that reproduces it, which becomes the lighting state (infeasible: the closest it came).
  onResult(msg) {
    if (msg.seq !== this.seq) return;
    this.seq = null;
    this.result = msg;
    const r = msg.result;
    this.statusText.textContent = 'done';
    this._updateButton();
    const box = this.resultBox;
    box.innerHTML = '';
    const verdict = r.feasible
      ? `feasible${r.binding.length ? ` — at the bound: ${r.binding.join(', ')}` : ''}`
      : `infeasible — binding: ${r.binding.join(', ')}`;
    box.append(el('p', { class: `optimize-verdict ${r.feasible ? 'ok' : 'bad'}`, text: verdict, dataset: { testid: 'optimize-verdict' } }));
    box.append(el('table', { class: 'sensor-table', dataset: { testid: 'optimize-table' } }, [
      el('thead', {}, el('tr', {}, [
        el('th', { text: 'target' }),
        el('th', { text: 'value', title: 'The target (lx, or U0)' }),
        el('th', { text: 'achieved', title: 'What the result gives, read from the scene relit with its state as relight probe reads it' }),
        el('th', { text: 'met', title: 'Met within 1e-6 (relative); * at its bound (binding)' }),
      ])),
      el('tbody', {}, r.targets.map((t) => el('tr', { dataset: { target: `${t.set}: ${t.target}` } }, [
        el('td', { text: `${t.set}: ${KINDS.find(([k]) => k === t.target)?.[1] ?? t.target}` }),
        el('td', { class: 'numcell', text: formatTarget(t.target, t.value) }),
        el('td', { class: 'numcell', text: formatTarget(t.target, t.achieved) }),
        el('td', { class: t.met ? 'numcell ok' : 'numcell bad', text: `${t.met ? 'yes' : 'no'}${t.binding ? ' *' : ''}` }),
      ]))),
    ]));
    const watts = r.watts_from_data ? '' : ' (luminaires without wattage data count as the mean of the others, or 1 W each)';
    box.append(
      el('p', { class: 'hint', dataset: { testid: 'optimize-summary' } }, [
        el('span', { text: `power ${r.power_w.toFixed(2)} W${watts}`, dataset: { testid: 'optimize-power' } }),
        ` · ${r.objective_name === 'uniformity' ? `U0 ${r.objective.toFixed(3)}` : `objective ${r.objective.toFixed(2)} W`}`,
        ` · ${r.iterations} simplex iterations${r.aim_trials ? `, ${r.aim_trials} aims tried` : ''}`,
        ' · ',
        el('span', { text: `${r.seconds.toFixed(3)} s`, dataset: { testid: 'optimize-seconds' } }),
      ]),
    );
    const names = Object.keys(r.luminaires);
    if (names.length) {
      box.append(el('table', { class: 'sensor-table', dataset: { testid: 'optimize-luminaires' } }, [
        el('thead', {}, el('tr', {}, [el('th', { text: 'luminaire' }), el('th', { text: 'dimmer' })])),
        el('tbody', {}, names.map((name) => el('tr', { dataset: { luminaire: name } }, [
          el('td', { text: name }),
          el('td', { class: 'numcell', text: r.luminaires[name].dimmer.toFixed(3) }),
        ]))),
      ]));
    }
    box.append(el('p', { class: 'hint', text: `${r.feasible ? 'This' : 'The closest'} state is now the lighting state${this.hasWindows && !this.daylightRun ? ' (windows dark: electric light alone)' : ''}; State → Save writes it.` }));
    this.applyState(msg.state);
  }
}
