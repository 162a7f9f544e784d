// The false-colour legend (#legend): the CLI's 7-colour ramp as a vertical bar with the
// scale's tick labels (src/render/false_color_scale.h rules) and the unit, lx for
// illuminance or cd/m² for luminance. Shown only in the false-colour view modes. Also draws
// the same legend onto a 2D canvas for screenshots (as `relight render` appends it).
import { RAMP, formatTick, rampCss, scalePosition, scaleTicks } from './false_color.js';

export const UNIT = { lux: 'lx', luminance: 'cd/m²' };
const TITLE = { lux: 'Illuminance', luminance: 'Luminance' };

export class Legend {
  constructor(element) {
    this.element = element;
    this.key = '';
  }

  // used: viewer.used ({mode, quantity, scale, scaleError}).
  update(used) {
    const show = used.mode === 'false-lux' || used.mode === 'false-luminance';
    this.element.style.display = show ? '' : 'none';
    if (!show) return;
    const key = JSON.stringify([used.quantity, used.scale, used.scaleError]);
    if (key === this.key) return;
    this.key = key;
    const { scale, quantity } = used;
    const ticks = scaleTicks(scale);
    const gradient = `linear-gradient(to top, ${RAMP.map((c, i) => `rgb(${c.join(',')}) ${((100 * i) / (RAMP.length - 1)).toFixed(2)}%`).join(', ')})`;
    this.element.innerHTML = '';
    const title = document.createElement('div');
    title.className = 'legend-title';
    title.innerHTML = `${TITLE[quantity]}<br><span class="legend-unit">${UNIT[quantity]}</span>`;
    title.title = `${TITLE[quantity]} in ${UNIT[quantity]}, ${scale.logarithmic ? 'logarithmic' : 'linear'} scale`;
    const body = document.createElement('div');
    body.className = 'legend-body';
    const bar = document.createElement('div');
    bar.className = 'legend-bar';
    bar.style.background = gradient;
    const labels = document.createElement('div');
    labels.className = 'legend-ticks';
    for (const t of ticks) {
      const label = document.createElement('span');
      label.className = 'legend-tick';
      label.style.bottom = `${(100 * scalePosition(scale, t)).toFixed(2)}%`;
      label.textContent = formatTick(t);
      labels.appendChild(label);
    }
    body.append(bar, labels);
    const foot = document.createElement('div');
    foot.className = 'legend-scale';
    foot.textContent = used.scaleError ? `range: ${used.scaleError}` : scale.logarithmic ? 'log scale' : 'linear scale';
    this.element.append(title, body, foot);
  }
}

// Draws the legend to the right of an image on a 2D context (x0: left edge, h: height).
export function drawLegend(ctx, x0, width, h, used) {
  const { scale, quantity } = used;
  ctx.fillStyle = '#202020';
  ctx.fillRect(x0, 0, width, h);
  const top = 40, bottom = h - 20, barX = x0 + 12, barW = 18;
  for (let y = top; y <= bottom; y++) {
    ctx.fillStyle = rampCss((bottom - y) / (bottom - top));
    ctx.fillRect(barX, y, barW, 1);
  }
  ctx.fillStyle = '#fff';
  ctx.font = '13px sans-serif';
  ctx.textBaseline = 'middle';
  ctx.fillText(UNIT[quantity], barX, 20);
  for (const t of scaleTicks(scale)) {
    const y = bottom - scalePosition(scale, t) * (bottom - top);
    ctx.fillRect(barX + barW, Math.round(y), 5, 1);
    ctx.fillText(formatTick(t), barX + barW + 8, y);
  }
}
