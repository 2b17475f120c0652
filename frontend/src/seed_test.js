// "Test on seeds" under the current best: test-design from the page. The server scores the
// control software on the project's mission; the page shows mean, sd and median, and a box plot
// with every seed's score as a point (hover: seed and score).
import { api } from './api.js';
import { readable } from './numbers.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attrs) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

/// The q-quantile of sorted values (linear interpolation, as R's type 7).
function quantile(sorted, q) {
  const at = (sorted.length - 1) * q;
  const lo = Math.floor(at);
  return sorted[lo] + (sorted[Math.min(lo + 1, sorted.length - 1)] - sorted[lo]) * (at - lo);
}

/// A horizontal box plot of `runs` ([{seed, score}]) as an SVG element. `range` ([lo, hi]) puts
/// several plots on one scale, so that they can be compared by eye.
export function boxPlot(runs, width = 260, height = 56, range = null) {
  const scores = runs.map((r) => r.score).sort((a, b) => a - b);
  const [lo, hi] = range || [scores[0], scores[scores.length - 1]];
  const pad = 10;
  const x = (v) => (hi === lo ? width / 2 : pad + ((v - lo) / (hi - lo)) * (width - 2 * pad));
  const root = svg('svg', { width, height, viewBox: `0 0 ${width} ${height}`, class: 'box-plot', role: 'img',
    'aria-label': `box plot of ${runs.length} scores from ${readable(lo)} to ${readable(hi)}` });
  const mid = 22;
  const [q1, med, q3] = [0.25, 0.5, 0.75].map((q) => quantile(scores, q));
  root.append(svg('line', { x1: x(scores[0]), x2: x(scores[scores.length - 1]), y1: mid, y2: mid, class: 'whisker' }));
  const [least, most] = [scores[0], scores[scores.length - 1]];
  for (const v of [least, most]) root.append(svg('line', { x1: x(v), x2: x(v), y1: mid - 6, y2: mid + 6, class: 'whisker' }));
  root.append(svg('rect', { x: x(q1), y: mid - 10, width: Math.max(1, x(q3) - x(q1)), height: 20, class: 'box' }));
  root.append(svg('line', { x1: x(med), x2: x(med), y1: mid - 10, y2: mid + 10, class: 'median' }));
  runs.forEach((r, i) => {
    const dot = svg('circle', { cx: x(r.score), cy: mid + 16 + (i % 3) * 4, r: 2.2, class: 'seed-point' });
    dot.append(Object.assign(svg('title', {}), { textContent: `seed ${r.seed}: ${r.score}` }));
    root.append(dot);
  });
  for (const [v, anchor] of [[lo, 'start'], [hi, 'end']]) {
    const t = svg('text', { x: anchor === 'start' ? 2 : width - 2, y: 8, 'text-anchor': anchor, class: 'axis' });
    t.textContent = readable(v);
    root.append(t);
  }
  return root;
}

/// Wires the form; `current()` gives {project, text} of the best shown (null when none).
export function initSeedTest(current) {
  const $ = (id) => document.getElementById(id);
  const result = $('test-result');
  $('test-form').addEventListener('submit', async (event) => {
    event.preventDefault();
    const target = current();
    if (!target) return;
    const seeds = $('test-seeds').value.trim();
    result.replaceChildren(document.createTextNode(`testing on seeds ${seeds}…`));
    $('test-run').disabled = true;
    try {
      const answer = await api(`/api/projects/${encodeURIComponent(target.project)}/test`,
        { body: { seeds, text: target.text }, quiet: true });
      const n = answer.runs.length;
      const summary = n > 1
        ? `mean ${readable(answer.mean)} · sd ${readable(answer.sd)} · median ${readable(answer.median)} over ${n} seeds (${seeds}, ${answer.direction})`
        : `score ${readable(answer.runs[0].score)} on seed ${answer.runs[0].seed}`;
      const line = document.createElement('div');
      line.textContent = summary;
      line.dataset.testid = 'test-summary';
      line.dataset.mean = String(answer.mean ?? answer.runs[0].score);
      result.replaceChildren(line, ...(n > 1 ? [boxPlot(answer.runs)] : []));
    } catch (e) {
      const line = document.createElement('div');
      line.className = 'error';
      line.textContent = e.message;
      result.replaceChildren(line);
    } finally {
      $('test-run').disabled = !current();
    }
  });
}
