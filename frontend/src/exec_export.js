// Exec's downloads: the run as a WebM video (MediaRecorder on a canvas drawn as the viewer draws
// it, with the tick and objective written on it) at a chosen speed and height, and the frame on
// screen as PNG or SVG. Everything is drawn in the page from the run already received.
import { download } from './download.js';
import { Viewer } from './viewer.js';
import { withDuration } from './webm_duration.js';

const FPS = 30;

export { download };

/// What the overlay says at tick t.
function overlayLines(run, t) {
  const s = run.scene;
  return [
    `${s.mission.name} · seed ${s.seed}`,
    `tick ${t} / ${run.ticks} · ${(t * s.tick_seconds).toFixed(1)} s`,
    `objective ${Number(run.objective[t]).toPrecision(6).replace(/\.?0+$/, '')}`,
  ];
}

function even(n) { return Math.max(2, 2 * Math.round(n / 2)); }

/// An off-screen canvas of `height` pixels (width from the arena's aspect) and its viewer.
function offscreen(liveViewer, run, height) {
  const canvas = document.createElement('canvas');
  canvas.height = even(height);
  canvas.width = even((height * liveViewer.box.w) / liveViewer.box.h);
  const viewer = new Viewer(canvas);
  viewer.run = run;
  viewer.box = liveViewer.box;
  viewer.image = liveViewer.image;
  return { canvas, viewer };
}

function drawFrame(viewer, run, t, options) {
  viewer.draw(t, options);
  const ctx = viewer.canvas.getContext('2d');
  const size = Math.max(12, Math.round(viewer.canvas.height / 36));
  const lines = overlayLines(run, t);
  ctx.font = `${size}px sans-serif`;
  const width = Math.max(...lines.map((l) => ctx.measureText(l).width)) + size;
  ctx.fillStyle = 'rgba(255,255,255,0.82)';
  ctx.fillRect(size * 0.4, size * 0.4, width, size * (lines.length * 1.3 + 0.5));
  ctx.fillStyle = '#1d2430';
  lines.forEach((l, i) => ctx.fillText(l, size * 0.9, size * (1.6 + i * 1.3)));
}

const baseName = (run) => `${run.scene.mission.name.replace(/[^A-Za-z0-9._-]+/g, '_')}-seed${run.scene.seed}`;

export function framePng(liveViewer, run, t, options, height) {
  const { canvas, viewer } = offscreen(liveViewer, run, height);
  drawFrame(viewer, run, t, options);
  return new Promise((resolve) => canvas.toBlob((blob) => resolve({ blob, name: `${baseName(run)}-tick${t}.png` }), 'image/png'));
}

/// The arena's SVG with the robots (and trails, links) at tick t and the overlay as text.
export function frameSvg(run, t, { trails = false, links = false } = {}) {
  const s = run.scene;
  const n = run.robots;
  const at = t * n;
  const r = s.robot_radius;
  const parts = ['<g class="robots" transform="scale(1 -1)">'];
  if (trails) {
    for (let i = 0; i < n; i++) {
      const pts = [];
      for (let k = Math.max(0, t - 60); k <= t; k++) pts.push(`${run.x[k * n + i]},${run.y[k * n + i]}`);
      parts.push(`<polyline points="${pts.join(' ')}" fill="none" stroke="rgba(37,99,235,0.35)" stroke-width="${r * 0.25}"/>`);
    }
  }
  if (links) {
    for (let i = 0; i < n; i++) {
      for (let j = i + 1; j < n; j++) {
        const dx = run.x[at + i] - run.x[at + j];
        const dy = run.y[at + i] - run.y[at + j];
        if (dx * dx + dy * dy <= s.rab_range * s.rab_range)
          parts.push(`<line x1="${run.x[at + i]}" y1="${run.y[at + i]}" x2="${run.x[at + j]}" y2="${run.y[at + j]}" stroke="rgba(46,125,50,0.45)" stroke-width="${r * 0.12}"/>`);
      }
    }
  }
  for (let i = 0; i < n; i++) {
    const x = run.x[at + i];
    const y = run.y[at + i];
    const led = run.led[at + i];
    const fill = led ? `#${(led & 0xffffff).toString(16).padStart(6, '0')}` : '#9aa3ad';
    parts.push(`<circle cx="${x}" cy="${y}" r="${r}" fill="${fill}" stroke="#1d2430" stroke-width="${r * 0.12}"/>`);
    parts.push(`<line x1="${x}" y1="${y}" x2="${x + Math.cos(run.yaw[at + i]) * r}" y2="${y + Math.sin(run.yaw[at + i]) * r}" stroke="#1d2430" stroke-width="${r * 0.2}"/>`);
  }
  parts.push('</g>');
  const vb = /viewBox\s*=\s*"([^"]+)"/.exec(s.svg);
  const [bx, by, , bh] = vb ? vb[1].trim().split(/[\s,]+/).map(Number) : [0, 0, 1, 1];
  const line = bh / 30;
  const lines = overlayLines(run, t);
  // A pale band behind the text, so that it reads over the arena (about 0.55 em per character).
  parts.push(`<rect class="overlay-band" x="${bx}" y="${by}" width="${line * (1 + 0.8 * 0.55 * Math.max(...lines.map((l) => l.length)))}" height="${line * (lines.length * 1.2 + 0.6)}" fill="#ffffff" fill-opacity="0.8"/>`);
  lines.forEach((text, i) => {
    // Text drawn at 1000x and scaled down, as the arena's captions: renderers hint tiny fonts badly.
    parts.push(`<text class="overlay" transform="translate(${bx + line * 0.5} ${by + line * (1.2 + i * 1.2)}) scale(0.001)" font-family="sans-serif" font-size="${line * 800}" fill="#1d2430">${text}</text>`);
  });
  const svg = s.svg.replace(/<\/svg>\s*$/, `${parts.join('\n')}\n</svg>\n`);
  return { blob: new Blob([svg], { type: 'image/svg+xml' }), name: `${baseName(run)}-tick${t}.svg` };
}

/// Records ticks 0 .. last at `speed` times real time; resolves to the WebM and its name.
/// onProgress(fraction) while it records (it takes the video's own length).
export async function recordVideo(liveViewer, run, { speed, height, options, last, onProgress = () => {} }) {
  const { canvas, viewer } = offscreen(liveViewer, run, height);
  const mimeType = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'].find((m) => MediaRecorder.isTypeSupported(m));
  if (!mimeType) throw new Error('this browser cannot record WebM video');
  drawFrame(viewer, run, 0, options);
  const stream = canvas.captureStream(0);
  const track = stream.getVideoTracks()[0];
  const recorder = new MediaRecorder(stream, { mimeType, videoBitsPerSecond: Math.round(height * height * 8) });
  const chunks = [];
  recorder.ondataavailable = (e) => { if (e.data.size) chunks.push(e.data); };
  const stopped = new Promise((resolve) => { recorder.onstop = resolve; });
  const ticksPerFrame = (speed / FPS) / run.scene.tick_seconds;
  const started = performance.now();
  recorder.start(1000);
  for (let frame = 0; ; frame++) {
    const t = Math.min(last, Math.round(frame * ticksPerFrame));
    drawFrame(viewer, run, t, options);
    track.requestFrame();
    onProgress(last ? t / last : 1);
    // Frames are paced in real time: MediaRecorder stamps them with the clock.
    const due = started + ((frame + 1) * 1000) / FPS;
    await new Promise((resolve) => setTimeout(resolve, Math.max(0, due - performance.now())));
    if (t >= last) break;
  }
  recorder.stop();
  await stopped;
  track.stop();
  const ms = performance.now() - started;
  const bytes = withDuration(await new Blob(chunks).arrayBuffer(), ms);
  return { blob: new Blob([bytes], { type: 'video/webm' }), name: `${baseName(run)}-${speed}x.webm` };
}
