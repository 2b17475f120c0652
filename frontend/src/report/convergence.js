// Convergence: per mission, the optimiser's estimate of its best design against the runs it
// has used, one thin line per design, coloured by condition.
import { el, figure, formatCount, section } from './dom.js';
import { axis, baseLayout, drawPlot, emptyNote, plotTitle } from './plots.js';
import { directionText } from './report_data.js';

function missionPlot(report, mission, container) {
  const traces = [];
  for (const condition of report.conditions) {
    const designs = report.designsOf(mission.name, condition.name).filter((d) => (d.convergence || []).length);
    designs.forEach((d, k) => {
      traces.push({
        type: 'scatter', mode: 'lines', line: { color: report.colourOf(condition.name), width: 1.2, shape: 'hv' },
        opacity: 0.85, x: d.convergence.map((p) => p[0]), y: d.convergence.map((p) => p[1]),
        name: condition.name, legendgroup: condition.name, showlegend: k === 0,
        hovertemplate: `design ${d.id} (${condition.name})<br>%{x} runs: %{y}<extra></extra>`,
      });
    });
  }
  const layout = baseLayout({
    title: plotTitle(mission.name),
    width: container.clientWidth, height: 320,
    showlegend: true, legend: { orientation: 'h', x: 1, xanchor: 'right', y: 1.02, yanchor: 'bottom' },
    xaxis: axis('runs used', { rangemode: 'tozero' }),
    yaxis: axis(`estimated best score (${directionText(mission)})`),
    annotations: traces.length ? [] : emptyNote('no finished design yet'),
  });
  return drawPlot(container, traces, layout);
}

export function renderConvergence(report, root) {
  const node = section('convergence', 'Convergence',
    'The optimiser\'s estimate of its best design so far (mean of that design\'s runs so far), after each step. '
    + 'Estimates are on the design seeds, not the assessment seeds: they are optimistic.');
  root.append(node);
  const grid = el('div', { className: 'plot-grid' });
  node.append(grid);
  for (const mission of report.missions) {
    const budget = mission.budget ? `budget ${formatCount(mission.budget)} runs` : null;
    const { node: fig, body } = figure('plot plot-convergence', budget);
    body.dataset.mission = mission.name;
    grid.append(fig);
    missionPlot(report, mission, body);
  }
}
