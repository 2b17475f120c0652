// Cost: simulation runs and wall time spent per (mission, condition).
import { el, formatCount, formatDuration, section } from './dom.js';
import { conditionCell, reportTable } from './tables.js';

export function renderCost(report, root) {
  const node = section('cost', 'Cost', 'Simulation runs and wall time as recorded by the experiment, on the machine that ran it.');
  root.append(node);
  const rows = report.data.wall_time || [];
  if (!rows.length) { node.append(el('p', { className: 'note' }, 'No design yet.')); return; }
  const sum = (key) => rows.reduce((s, r) => s + (r[key] || 0), 0);
  const perDesign = (r) => (r.designs ? formatDuration(r.wall_seconds / r.designs) : '–');
  node.append(reportTable([
    { title: 'mission', value: (r) => r.mission },
    { title: 'condition', value: (r) => conditionCell(report, r.condition) },
    { title: 'designs', numeric: true, value: (r) => formatCount(r.designs) },
    { title: 'runs', numeric: true, value: (r) => formatCount(r.runs) },
    { title: 'wall time', numeric: true, value: (r) => formatDuration(r.wall_seconds) },
    { title: 'per design', numeric: true, value: perDesign },
  ], rows, {
    testid: 'cost',
    footer: [['total', '', formatCount(sum('designs')), formatCount(sum('runs')), formatDuration(sum('wall_seconds')),
      perDesign({ designs: sum('designs'), wall_seconds: sum('wall_seconds') })]],
  }));
}
