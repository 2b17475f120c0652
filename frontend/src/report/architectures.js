// Architectures: what each cell's designs chose (FSM, behaviour tree, neural network), counted.
import { el, figure, section } from './dom.js';
import { axis, baseLayout, drawPlot, plotTitle } from './plots.js';
import { ARCHITECTURE_COLOURS, ARCHITECTURE_NAMES } from './report_data.js';
import { conditionCell, reportTable } from './tables.js';

const ARCHITECTURES = ['fsm', 'bt', 'nn'];

function stackedBars(rows, container) {
  // Two-level categories: mission, then condition, so cells of one mission stand together.
  const x = [rows.map((r) => r.mission), rows.map((r) => r.condition)];
  const traces = ARCHITECTURES.filter((a) => rows.some((r) => r[a] > 0)).map((a) => ({
    type: 'bar', name: `${a} (${ARCHITECTURE_NAMES[a]})`, x, y: rows.map((r) => r[a]),
    marker: { color: ARCHITECTURE_COLOURS[a], line: { color: '#4a4a4a', width: 1 } },
    hovertemplate: `%{x}: %{y} ${a}<extra></extra>`,
  }));
  const layout = baseLayout({
    title: plotTitle('Architecture of the designs'),
    width: container.clientWidth, height: 320, barmode: 'stack', bargap: 0.35,
    showlegend: true, legend: { orientation: 'h', traceorder: 'normal', x: 0, y: 1.02, yanchor: 'bottom', xanchor: 'left' },
    margin: { l: 60, r: 16, t: 64, b: 60 },
    xaxis: axis('', { showgrid: false }),
    yaxis: axis('designs', { dtick: 1, rangemode: 'tozero' }),
  });
  return drawPlot(container, traces, layout);
}

export function renderArchitectures(report, root) {
  const node = section('architectures', 'Architectures', 'The architecture of each final design; conditions offering several let the optimiser choose.');
  root.append(node);
  const rows = report.data.architectures || [];
  if (!rows.length) { node.append(el('p', { className: 'note' }, 'No design yet.')); return; }
  const total = (r) => ARCHITECTURES.reduce((s, a) => s + (r[a] || 0), 0);
  const offered = (r) => (report.condition(r.condition).per_mission?.[r.mission]?.architectures || []).join(', ') || '–';
  const layout = el('div', { className: 'side-by-side' });
  node.append(layout);
  layout.append(reportTable([
    { title: 'mission', value: (r) => r.mission },
    { title: 'condition', value: (r) => conditionCell(report, r.condition) },
    { title: 'offered', value: offered },
    ...ARCHITECTURES.map((a) => ({ title: a, numeric: true, value: (r) => r[a] ?? 0 })),
    { title: 'designs', numeric: true, value: total },
  ], rows, { testid: 'architectures' }));
  const { node: fig, body } = figure('plot plot-architectures', null);
  layout.append(fig);
  stackedBars(rows, body);
}
