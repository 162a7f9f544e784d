// A 2D canvas over the viewport for text labels of 3D points (sensor readings, luminaire
// names, the probed point): projects each point with the camera, skips points behind it or
// off screen, and drops labels that would overlap ones already placed, so a dense sensor
// grid stays readable. Redrawn after every render.
import * as THREE from 'three';

export class LabelLayer {
  constructor(canvas, viewer) {
    this.canvas = canvas;
    this.viewer = viewer;
    this.ctx = canvas.getContext('2d');
    this.boxes = [];
    this._v = new THREE.Vector3();
  }

  begin() {
    const dpr = window.devicePixelRatio || 1;
    const w = this.viewer.width, h = this.viewer.height;
    if (this.canvas.width !== Math.round(w * dpr) || this.canvas.height !== Math.round(h * dpr)) {
      this.canvas.width = Math.round(w * dpr);
      this.canvas.height = Math.round(h * dpr);
      this.canvas.style.width = `${w}px`;
      this.canvas.style.height = `${h}px`;
    }
    this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.ctx.clearRect(0, 0, w, h);
    this.boxes = [];
  }

  // Screen position (CSS px) of a world point, or null when behind the camera / outside.
  project(p) {
    const v = this._v.set(p[0], p[1], p[2]).project(this.viewer.camera);
    if (v.z < -1 || v.z > 1 || Math.abs(v.x) > 1.05 || Math.abs(v.y) > 1.05) return null;
    return [((v.x + 1) / 2) * this.viewer.width, ((1 - v.y) / 2) * this.viewer.height];
  }

  _free(box) {
    for (const b of this.boxes) {
      if (box[0] < b[2] && box[2] > b[0] && box[1] < b[3] && box[3] > b[1]) return false;
    }
    this.boxes.push(box);
    return true;
  }

  // A label at a world point; style: {color, background, font, dx, dy, force}. Returns
  // whether it was drawn.
  label(p, text, style = {}) {
    const s = this.project(p);
    if (!s) return false;
    const ctx = this.ctx;
    ctx.font = style.font || '11px system-ui, sans-serif';
    const w = ctx.measureText(text).width + 6, h = 15;
    const x = s[0] + (style.dx ?? -w / 2), y = s[1] + (style.dy ?? -h - 3);
    const box = [x, y, x + w, y + h];
    if (!style.force && !this._free(box)) return false;
    ctx.fillStyle = style.background || 'rgba(0,0,0,0.6)';
    ctx.fillRect(x, y, w, h);
    ctx.fillStyle = style.color || '#fff';
    ctx.textBaseline = 'middle';
    ctx.fillText(text, x + 3, y + h / 2 + 0.5);
    return true;
  }

  // A line between two world points (a piece of an isoline); nothing when either end is off
  // screen or behind the camera.
  segment(a, b, color = '#fff', width = 1.5) {
    const s = this.project(a), t = this.project(b);
    if (!s || !t) return;
    const ctx = this.ctx;
    ctx.beginPath();
    ctx.moveTo(s[0], s[1]);
    ctx.lineTo(t[0], t[1]);
    ctx.strokeStyle = color;
    ctx.lineWidth = width;
    ctx.stroke();
    ctx.lineWidth = 1;
  }

  dot(p, color = '#fff', r = 3) {
    const s = this.project(p);
    if (!s) return;
    this.ctx.beginPath();
    this.ctx.arc(s[0], s[1], r, 0, 2 * Math.PI);
    this.ctx.fillStyle = color;
    this.ctx.fill();
    this.ctx.strokeStyle = '#000';
    this.ctx.stroke();
  }
}
