// Small DOM helpers shared by the panels: element construction, labelled rows, a slider
// paired with a number box, and the one-line notices of the status bar.

// el('input', {type: 'range', title: '…', dataset: {testid: 'x'}}, [children])
export function el(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null) continue;
    if (k === 'dataset') Object.assign(e.dataset, v);
    else if (k === 'style' && typeof v === 'object') Object.assign(e.style, v);
    else if (k === 'text') e.textContent = v;
    else if (k === 'html') e.innerHTML = v;
    else if (k.startsWith('on') && typeof v === 'function') e.addEventListener(k.slice(2), v);
    else if (k in e && typeof v !== 'string') e[k] = v;
    else e.setAttribute(k, v);
  }
  for (const c of [].concat(children)) {
    if (c === null || c === undefined || c === false) continue;
    e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  }
  return e;
}

// <label class="row"><span>text</span> control… </label>
export function row(label, controls, title) {
  return el('label', { class: 'row', title }, [el('span', { class: 'row-label', text: label }), ...[].concat(controls)]);
}

// A value that the user changes by `input` and `change` events alike (tests and keyboard
// users may fire either): handler(value) runs on every `input`, and on a `change` unless
// that change only ends an `input` of the same value. Values the program sets fire neither,
// so re-picking a value after a Reset or a remote state always reaches the handler.
export function onValue(input, handler, read = (e) => e.value) {
  let lastInput;
  input.addEventListener('input', () => {
    lastInput = read(input);
    handler(lastInput);
  });
  input.addEventListener('change', () => {
    const v = read(input);
    const sameAsInput = v === lastInput;
    lastInput = undefined;
    if (!sameAsInput) handler(v);
  });
}

// Sets a control's value unless the user is using it right now.
export function setIfIdle(input, value, prop = 'value') {
  if (document.activeElement === input && input._dragging) return;
  if (input[prop] !== value) input[prop] = value;
}

// A range slider with a number box beside it, both in the units shown: `factor` × the value
// (a dimmer of 0.5 shown as 50 %), min, max, step and numberMin/numberMax in those units. The
// number box may go beyond the slider's range (a dimmer above 100 %) within numberMin..
// numberMax. `log`: the slider moves on a logarithmic scale (colour temperature), its position
// ln(shown). set(value) and onChange(value) take the value itself.
export function sliderNumber({ min, max, step, value, numberMin, numberMax, title, testid, id, unit, log = false, factor = 1, onChange }) {
  const toSlider = (shown) => (log ? Math.log(shown) : shown);
  const fromSlider = (position) => (log ? Math.round(Math.exp(position) / step) * step : position);
  const slider = el('input', {
    type: 'range',
    min: toSlider(min),
    max: toSlider(max),
    step: log ? 'any' : step,
    title,
    id,
    dataset: testid ? { testid } : undefined,
  });
  const lowest = numberMin ?? min, highest = numberMax ?? max;
  const number = el('input', {
    type: 'number',
    min: lowest,
    max: highest,
    step,
    title,
    class: 'num',
    dataset: testid ? { testid: `${testid}-value` } : undefined,
  });
  slider.addEventListener('pointerdown', () => (slider._dragging = true));
  slider.addEventListener('pointerup', () => (slider._dragging = false));
  const place = (shown) => setIfIdle(slider, String(toSlider(Math.min(Math.max(shown, min), max))));
  const set = (v) => {
    place(v * factor);
    if (document.activeElement !== number) number.value = String(round(v * factor, step));
  };
  set(value);
  const fromSliderEvent = () => {
    const shown = fromSlider(Number(slider.value));
    number.value = String(round(shown, step));
    onChange(shown / factor);
  };
  slider.addEventListener('input', fromSliderEvent);
  slider.addEventListener('change', fromSliderEvent);
  const fromNumber = () => {
    const v = Number(number.value);
    if (number.value === '' || !Number.isFinite(v)) return;
    const clamped = Math.min(Math.max(v, lowest), highest);
    place(clamped);
    onChange(clamped / factor);
  };
  number.addEventListener('change', fromNumber);
  number.addEventListener('keydown', (e) => e.key === 'Enter' && fromNumber());
  const wrap = el('span', { class: 'slider-number' }, [slider, number, unit ? el('span', { class: 'unit', text: unit }) : null]);
  return { element: wrap, slider, number, set };
}

function round(v, step) {
  const digits = Math.max(0, -Math.floor(Math.log10(Number(step) || 1)));
  return Number(v.toFixed(Math.min(6, digits + 1)));
}

// Number input; onChange(number) on Enter/blur when it is a valid number.
export function numberInput({ value, min, max, step = 'any', title, unit, id, testid, onChange, width }) {
  const input = el('input', { type: 'number', min, max, step, title, id, class: 'num', dataset: testid ? { testid } : undefined });
  if (width) input.style.width = width;
  if (value !== undefined && value !== null) input.value = String(value);
  input.addEventListener('change', () => {
    const v = Number(input.value);
    if (input.value === '' || !Number.isFinite(v)) return;
    if ((min !== undefined && v < min) || (max !== undefined && v > max)) {
      input.classList.add('invalid');
      return;
    }
    input.classList.remove('invalid');
    onChange(v);
  });
  if (!unit) return input;
  const wrap = el('span', { class: 'with-unit' }, [input, el('span', { class: 'unit', text: unit })]);
  wrap.input = input;
  return wrap;
}

export function select(options, { value, title, id, testid, onChange } = {}) {
  const s = el(
    'select',
    { title, id, dataset: testid ? { testid } : undefined },
    options.map(([v, label]) => el('option', { value: v, text: label })),
  );
  if (value !== undefined) s.value = value;
  if (onChange) onValue(s, onChange);
  return s;
}

// Transient notices in the status bar (errors stay longer).
let noticeTimer = null;
export function notice(text, kind = 'info', ms = kind === 'error' ? 8000 : 4000) {
  const n = document.getElementById('notice');
  if (!n) return;
  n.textContent = text;
  n.className = kind;
  n.title = text;
  clearTimeout(noticeTimer);
  noticeTimer = setTimeout(() => {
    n.textContent = '';
    n.className = '';
  }, ms);
}

export function fmt3(v) {
  return v.map((x) => Number(x).toFixed(2)).join(', ');
}

// Offers `blob` to the user as a download named `filename` (screenshots, states, CSV).
export function downloadBlob(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 2000);
}
