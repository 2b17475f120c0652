// The reality gap (Ligot & Birattari, Swarm Intelligence 14, 2020), when the protocol asked for
// pseudo-realities: per mission, each condition's designs in the design model and in the
// pseudo-realities as paired box plots (each design's two scores joined by a line), then a table
// of the drop with its paired test and the conditions' ranks in both worlds.
import { el, figure, formatP, formatScore, section } from './dom.js';
import { conditionsLayout, drawPlot, translucent } from './plots.js';
import { conditionCell, reportTable } from './tables.js';

const ALPHA = 0.05;
const OFFSET = 0.2;
const BOX_WIDTH = 0.32;

function box(b, position, colour, fill, name) {
  return {
    type: 'box', name, x: [position],
    q1: [b.q1], median: [b.median], q3: [b.q3], lowerfence: [b.whisker_low], upperfence: [b.whisker_high],
    boxpoints: false, width: BOX_WIDTH, fillcolor: fill, line: { color: colour, width: 1.6 }, hoverinfo: 'y',
  };
}

function missionPlot(report, gap, mission, container) {
  const cells = report.conditions.map((c) => gap.cells.find((x) => x.mission === mission.name && x.condition === c.name) || null);
  const traces = [];
  cells.forEach((cell, i) => {
    if (!cell) return;
    const colour = report.colourOf(cell.condition);
    traces.push(box(cell.design_model, i - OFFSET, colour, translucent(colour, 0.35), `${cell.condition}, design model`));
    traces.push(box(cell.pseudo_reality, i + OFFSET, colour, '#ffffff', `${cell.condition}, pseudo-reality`));
    // Each design: its score in the design model joined to its score in the pseudo-realities.
    const designs = report.designsOf(mission.name, cell.condition).filter((d) => d.pseudo_reality);
    for (const d of designs) {
      traces.push({
        type: 'scatter', mode: 'lines+markers', x: [i - OFFSET, i + OFFSET], y: [d.score, d.pseudo_reality.score],
        line: { color: translucent(colour, 0.45), width: 1 }, marker: { color: colour, size: 5 },
        text: [`design ${d.id}: ${formatScore(d.score)} in the design model`,
          `design ${d.id}: ${formatScore(d.pseudo_reality.score)} in the pseudo-realities (drop ${formatScore(d.pseudo_reality.drop)}, p ${formatP(d.pseudo_reality.p_value)})`],
        hoverinfo: 'text',
      });
    }
  });
  const ticks = report.conditions.map((c, i) => (cells[i]
    ? `${c.name}<br><span style="font-size:10px;color:#666">design model | pseudo-reality</span>` : c.name));
  const layout = conditionsLayout(report, mission, container, ticks,
    traces.length ? '' : 'no design assessed in the pseudo-realities yet');
  return drawPlot(container, traces, layout);
}

function gapTable(report, gap) {
  const rank = (cell) => gap.ranks.find((r) => r.mission === cell.mission && r.condition === cell.condition) || {};
  const p = (cell) => (cell.wilcoxon ? cell.wilcoxon.p_value : null);
  const rankText = (v) => (v == null ? '–' : Number.isInteger(v) ? String(v) : v.toFixed(1));
  return reportTable([
    { title: 'mission', value: (c) => c.mission },
    { title: 'condition', value: (c) => conditionCell(report, c.condition) },
    { title: 'designs', numeric: true, value: (c) => c.n },
    { title: 'design model', numeric: true, value: (c) => formatScore(c.design_model.median) },
    { title: 'pseudo', numeric: true, value: (c) => formatScore(c.pseudo_reality.median) },
    { title: 'drop', numeric: true, value: (c) => formatScore(c.median_drop) },
    { title: 'dropping', numeric: true, value: (c) => `${c.designs_dropping} of ${c.n}` },
    { title: 'p', numeric: true, value: (c) => (p(c) != null && p(c) < ALPHA ? el('strong', {}, `${formatP(p(c))} *`) : formatP(p(c))) },
    { title: 'rank', numeric: true, value: (c) => {
      const r = rank(c);
      const changed = r.design_model_rank !== r.pseudo_reality_rank;
      const text = `${rankText(r.design_model_rank)} → ${rankText(r.pseudo_reality_rank)}`;
      return changed ? el('strong', { className: 'rank-changed' }, text) : text;
    } },
  ], gap.cells, {
    testid: 'reality-gap',
    caption: 'Medians over the designs in the design model and in the pseudo-realities. Drop: the median score lost '
      + 'from the design model to the pseudo-realities, per design (positive is worse); dropping: designs whose own '
      + 'drop is significant. '
      + `A design drops when its paired Wilcoxon test over the seeds gives p < ${ALPHA}; p compares the `
      + `designs' scores in both worlds (Wilcoxon signed-rank, two-sided; * marks p < ${ALPHA}). Rank: the condition's rank `
      + 'by median on the mission in the design model → in the pseudo-realities, 1 = best.',
  });
}

export function renderRealityGap(report, root) {
  const gap = report.data.pseudo_reality;
  if (!gap) return;
  const node = section('reality-gap', 'Reality gap (pseudo-realities)',
    `Every design also ran on its assessment seeds in samples 1–${gap.samples} of pseudo-reality ${gap.name}`
    + `${gap.description ? ` (${gap.description})` : ''}: robot models other than the design model, which mimic the `
    + 'reality gap in simulation (Ligot & Birattari, Swarm Intelligence 14, 2020). Filled boxes: the design model; '
    + 'white boxes: the pseudo-realities; a line joins each design\'s two scores.');
  node.dataset.testid = 'reality-gap-section';
  const grid = el('div', { className: 'plot-grid' });
  node.append(grid);
  root.append(node);
  for (const mission of report.missions) {
    const { node: fig, body } = figure('plot plot-box', null);
    body.dataset.mission = mission.name;
    grid.append(fig);
    missionPlot(report, gap, mission, body);
  }
  node.append(gapTable(report, gap));
  const inversions = gap.inversions || [];
  node.append(el('p', { className: 'note', dataset: { testid: 'rank-inversions' } }, inversions.length
    ? `The pseudo-realities invert ${inversions.length} pair${inversions.length > 1 ? 's' : ''} of conditions: `
      + inversions.map((i) => `${i.a} and ${i.b} on ${i.mission} (${i.better_in_design_model} is better in the design model)`).join('; ') + '.'
    : 'No pair of conditions changes order between the design model and the pseudo-realities.'));
}
