// The top-down view of a run on a canvas: the mission's SVG drawing (world metres, y up) as the
// background, the robots (LED colour, heading), optional trails and range-and-bearing links.
const TRAIL = 60;

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    this.image = null;
    this.box = { x: -1, y: -1, w: 2, h: 2 };
    this.run = null;
  }

  setScene(run) {
    this.run = run;
    const svg = run.scene.svg;
    const vb = /viewBox\s*=\s*"([^"]+)"/.exec(svg);
    if (vb) {
      const [x, y, w, h] = vb[1].trim().split(/[\s,]+/).map(Number);
      this.box = { x, y, w, h };
    }
    this.canvas.style.aspectRatio = `${this.box.w} / ${this.box.h}`;
    const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
    const image = new Image();
    this.image = null;
    image.onload = () => { this.image = image; URL.revokeObjectURL(url); if (this.onready) this.onready(); };
    image.src = url;
  }

  fitCanvas() {
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(this.canvas.clientWidth * dpr);
    const h = Math.round(this.canvas.clientHeight * dpr);
    if (w > 0 && h > 0 && (this.canvas.width !== w || this.canvas.height !== h)) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
  }

  /// World (x, y up) to canvas pixels: the drawing's viewBox holds (x, -y).
  toCanvas(x, y) {
    const { box, canvas } = this;
    return [((x - box.x) / box.w) * canvas.width, ((-y - box.y) / box.h) * canvas.height];
  }

  scale() { return this.canvas.width / this.box.w; }

  draw(tick, { trails = false, links = false, selected = -1 } = {}) {
    this.fitCanvas();
    const { canvas, run } = this;
    const ctx = canvas.getContext('2d');
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    if (this.image) ctx.drawImage(this.image, 0, 0, canvas.width, canvas.height);
    if (!run || run.received === 0) return;
    tick = Math.max(0, Math.min(tick, run.received - 1));
    const n = run.robots;
    const at = tick * n;
    const k = this.scale();
    const r = run.scene.robot_radius * k;
    if (trails) {
      ctx.lineWidth = Math.max(1, r * 0.25);
      for (let i = 0; i < n; i++) {
        ctx.strokeStyle = i === selected ? 'rgba(224,160,0,0.8)' : 'rgba(37,99,235,0.35)';
        ctx.beginPath();
        for (let t = Math.max(0, tick - TRAIL); t <= tick; t++) {
          const [px, py] = this.toCanvas(run.x[t * n + i], run.y[t * n + i]);
          if (t === Math.max(0, tick - TRAIL)) ctx.moveTo(px, py); else ctx.lineTo(px, py);
        }
        ctx.stroke();
      }
    }
    if (links) {
      const range2 = run.scene.rab_range * run.scene.rab_range;
      ctx.strokeStyle = 'rgba(46,125,50,0.45)';
      ctx.lineWidth = Math.max(1, r * 0.12);
      ctx.beginPath();
      for (let i = 0; i < n; i++) {
        for (let j = i + 1; j < n; j++) {
          const dx = run.x[at + i] - run.x[at + j];
          const dy = run.y[at + i] - run.y[at + j];
          if (dx * dx + dy * dy <= range2) {
            ctx.moveTo(...this.toCanvas(run.x[at + i], run.y[at + i]));
            ctx.lineTo(...this.toCanvas(run.x[at + j], run.y[at + j]));
          }
        }
      }
      ctx.stroke();
    }
    for (let i = 0; i < n; i++) {
      const [px, py] = this.toCanvas(run.x[at + i], run.y[at + i]);
      const led = run.led[at + i];
      ctx.beginPath();
      ctx.arc(px, py, r, 0, 2 * Math.PI);
      ctx.fillStyle = led ? `#${(led & 0xffffff).toString(16).padStart(6, '0')}` : '#9aa3ad';
      ctx.fill();
      ctx.lineWidth = i === selected ? Math.max(2, r * 0.35) : Math.max(1, r * 0.12);
      ctx.strokeStyle = i === selected ? '#e0a000' : '#1d2430';
      ctx.stroke();
      const yaw = run.yaw[at + i];
      ctx.beginPath();
      ctx.moveTo(px, py);
      ctx.lineTo(px + Math.cos(yaw) * r, py - Math.sin(yaw) * r);
      ctx.lineWidth = Math.max(1, r * 0.2);
      ctx.strokeStyle = '#1d2430';
      ctx.stroke();
    }
  }

  /// The robot under a click (client coordinates), or -1.
  pick(clientX, clientY, tick) {
    const { run, canvas } = this;
    if (!run || run.received === 0) return -1;
    const rect = canvas.getBoundingClientRect();
    const cx = ((clientX - rect.left) / rect.width) * canvas.width;
    const cy = ((clientY - rect.top) / rect.height) * canvas.height;
    const n = run.robots;
    const at = Math.max(0, Math.min(tick, run.received - 1)) * n;
    const limit = Math.max(run.scene.robot_radius * this.scale() * 1.8, 8);
    let best = -1;
    let bestD = limit * limit;
    for (let i = 0; i < n; i++) {
      const [px, py] = this.toCanvas(run.x[at + i], run.y[at + i]);
      const d = (px - cx) ** 2 + (py - cy) ** 2;
      if (d <= bestD) { bestD = d; best = i; }
    }
    return best;
  }
}
