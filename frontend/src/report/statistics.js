// Statistics: Wilcoxon rank-sum tests per mission and pair of conditions; the Friedman test
// across missions with the conditions' mean ranks.
import { el, figure, formatP, formatScore, section } from './dom.js';
import { axis, baseLayout, drawPlot, plotTitle } from './plots.js';
import { conditionCell, reportTable } from './tables.js';

const ALPHA = 0.05;

function betterCell(report, row) {
  if (!row.better) return el('span', { className: 'muted' }, 'no difference');
  return conditionCell(report, row.better === 'a' ? row.a : row.b);
}

function wilcoxonTable(report) {
  const rows = report.data.wilcoxon || [];
  if (!rows.length) return el('p', { className: 'note' }, 'No pair of conditions to compare.');
  const significant = (r) => r.p_value != null && r.p_value < ALPHA;
  return reportTable([
    { title: 'mission', value: (r) => r.mission },
    { title: 'condition A', value: (r) => conditionCell(report, r.a) },
    { title: 'condition B', value: (r) => conditionCell(report, r.b) },
    { title: 'nA', numeric: true, value: (r) => r.n_a },
    { title: 'nB', numeric: true, value: (r) => r.n_b },
    { title: 'W', numeric: true, value: (r) => (r.W == null ? '–' : Number.isInteger(r.W) ? String(r.W) : r.W.toFixed(1)) },
    { title: 'p', numeric: true, value: (r) => (significant(r) ? el('strong', {}, `${formatP(r.p_value)} *`) : formatP(r.p_value)) },
    { title: 'p from', value: (r) => (r.exact ? 'exact' : 'normal approx.') },
    { title: 'better median', value: (r) => betterCell(report, r) },
  ], rows, {
    testid: 'wilcoxon',
    caption: `Wilcoxon rank-sum tests, two-sided; * marks p < ${ALPHA}. W is the rank sum of A minus nA(nA+1)/2.`,
  });
}

function friedmanTable(friedman) {
  return reportTable([
    { title: 'blocks (missions)', value: () => friedman.blocks.join(', ') },
    { title: 'conditions', value: () => friedman.conditions.join(', ') },
    { title: 'χ²', numeric: true, value: () => formatScore(friedman.statistic) },
    { title: 'df', numeric: true, value: () => friedman.df },
    { title: 'p', numeric: true, value: () => (friedman.p_value < ALPHA ? el('strong', {}, `${formatP(friedman.p_value)} *`) : formatP(friedman.p_value)) },
    { title: 'critical difference', numeric: true, value: () => (friedman.critical_difference == null ? '–' : formatScore(friedman.critical_difference)) },
  ], [friedman], { testid: 'friedman', caption: 'Friedman test over missions: conditions ranked by their median score on each mission (1 = best).' });
}

/// Mean ranks as dots; ±CD/2 bars so that two conditions differ when their bars do not overlap.
function ranksPlot(report, friedman, container) {
  const rows = friedman.expected_ranks;
  const cd = friedman.critical_difference;
  const traces = rows.map((r) => ({
    type: 'scatter', mode: 'markers', x: [r.rank], y: [r.condition], name: r.condition,
    marker: { color: report.colourOf(r.condition), size: 11, symbol: 'diamond' },
    error_x: cd == null ? { visible: false } : { type: 'constant', value: cd / 2, color: report.colourOf(r.condition), thickness: 2, width: 6 },
    hovertemplate: `${r.condition}: mean rank %{x:.2f}<extra></extra>`,
  }));
  const k = friedman.conditions.length;
  const layout = baseLayout({
    title: plotTitle('Mean rank per condition'),
    width: container.clientWidth, height: 90 + 34 * rows.length,
    margin: { l: 90, r: 16, t: 36, b: 44 },
    xaxis: axis('mean rank over missions (1 = best)', { range: [0.8, k + 0.2], dtick: 1 }),
    yaxis: axis('', { type: 'category', categoryorder: 'array', categoryarray: [...friedman.conditions].reverse(), showgrid: false, ticks: '' }),
  });
  return drawPlot(container, traces, layout);
}

export function renderStatistics(report, root) {
  const node = section('statistics', 'Statistics', 'The unit of every test is the design (its mean assessment score); designs are independent replicates.');
  root.append(node);
  node.append(el('h3', {}, 'Pairwise comparisons per mission'), wilcoxonTable(report));
  node.append(el('h3', {}, 'Across missions'));
  const friedman = report.data.friedman;
  if (!friedman) {
    node.append(el('p', { className: 'note', dataset: { testid: 'friedman-missing' } },
      'No Friedman test: it needs at least two missions that share the same conditions (at least two), '
      + 'each with finished designs. This experiment does not have them (yet).'));
    return;
  }
  node.append(friedmanTable(friedman));
  const cdNote = friedman.critical_difference == null
    ? 'No critical difference: the test does not reject equal ranks at 5 %.'
    : `Bars: ± half the critical difference (${formatScore(friedman.critical_difference)}); conditions whose bars do not overlap differ at 5 %.`;
  const { node: fig, body } = figure('plot plot-ranks', cdNote);
  node.append(fig);
  ranksPlot(report, friedman, body);
}
