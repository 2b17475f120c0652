// Performance: one notched box plot per mission, drawn from the precomputed `boxes` so the plot
// shows exactly the numbers of boxes.csv; each design's score is overlaid as a point.
import { el, figure, formatScore, section } from './dom.js';
import { conditionsLayout, drawPlot, translucent } from './plots.js';

const BOX_WIDTH = 0.5;
const WIDE_AFTER_CONDITIONS = 4; // more conditions than this take the page's whole width

/// Spreads points sideways without randomness (the report must render the same every time).
function sidewaysOffsets(count) {
  const golden = 0.6180339887;
  return Array.from({ length: count }, (_, k) => ((k * golden) % 1 - 0.5) * BOX_WIDTH * 0.6);
}

/// A notch that reaches past its hinges says nothing a reader can use (few designs): Plotly would
/// fold the box over it, so such a box is drawn without one; the CSV keeps the notch.
function notchInsideHinges(box) { return box.notch_low >= box.q1 && box.notch_high <= box.q3; }

function boxTrace(box, position, colour) {
  const notched = notchInsideHinges(box);
  return {
    type: 'box', name: box.condition, x: [position],
    q1: [box.q1], median: [box.median], q3: [box.q3],
    lowerfence: [box.whisker_low], upperfence: [box.whisker_high],
    ...(notched ? { notchspan: [(box.notch_high - box.notch_low) / 2], notched: true, notchwidth: 0.3 } : {}),
    boxpoints: false, width: BOX_WIDTH,
    fillcolor: translucent(colour, 0.18), line: { color: colour, width: 1.6 },
    hoverinfo: 'y',
  };
}

function pointsTrace(report, box, position, colour) {
  const values = box.values || [];
  const designs = report.designsOf(box.mission, box.condition);
  // Name each point by its design when the scores match one to one.
  const names = values.map((v) => {
    const d = designs.find((x) => x.score === v);
    return d ? `design ${d.id} (replicate ${d.replicate})<br>score ${formatScore(v)}` : `score ${formatScore(v)}`;
  });
  const offsets = sidewaysOffsets(values.length);
  return {
    type: 'scatter', mode: 'markers', x: values.map((_, k) => position + offsets[k]), y: values,
    marker: { color: colour, size: 7, opacity: 0.9, line: { color: '#ffffff', width: 1 } },
    text: names, hoverinfo: 'text',
  };
}

function missionPlot(report, mission, container) {
  const traces = [];
  const ticks = report.conditions.map((c) => {
    const box = report.box(mission.name, c.name);
    return `${c.name}<br><span style="font-size:10px;color:#666">n = ${box ? box.n : 0}</span>`;
  });
  report.conditions.forEach((c, position) => {
    const box = report.box(mission.name, c.name);
    if (!box) return;
    traces.push(boxTrace(box, position, report.colourOf(c.name)));
    traces.push(pointsTrace(report, box, position, report.colourOf(c.name)));
  });
  const layout = conditionsLayout(report, mission, container, ticks, traces.length ? '' : 'no finished design yet');
  return drawPlot(container, traces, layout);
}

export function renderPerformance(report, root) {
  const seeds = report.experiment.assessment_seeds;
  const node = section('performance', 'Performance',
    `Each point is one design: the mean of its ${seeds ?? ''} assessment runs on fresh seeds. `
    + 'Boxes span the hinges (R boxplot.stats), whiskers reach the most extreme scores within 1.5 IQR of them, '
    + 'notches show median ± 1.58 IQR/√n: non-overlapping notches suggest different medians. '
    + 'With few designs a notch reaches past its hinges; such a box is drawn without one (boxes.csv has it).');
  const grid = el('div', { className: 'plot-grid' });
  node.append(grid);
  root.append(node);
  for (const mission of report.missions) {
    const { node: fig, body } = figure('plot plot-box', mission.description || null);
    fig.classList.toggle('wide', report.conditions.length > WIDE_AFTER_CONDITIONS);
    body.dataset.mission = mission.name;
    grid.append(fig);
    missionPlot(report, mission, body);
  }
}
