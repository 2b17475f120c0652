// The report's head: what the experiment is, whether it is finished, and its protocol.
import { el, formatCount, formatDate } from './dom.js';
import { directionText, isMaximised } from './report_data.js';
import { conditionCell, reportTable } from './tables.js';

function stateBanner(experiment) {
  if (experiment.state === 'finished') return null;
  const done = experiment.designs_done ?? 0;
  const planned = experiment.designs_planned ?? '?';
  return el('div', { className: `state-banner state-${experiment.state || 'unknown'}`, role: 'status', dataset: { testid: 'state-banner' } },
    el('strong', {}, experiment.state || 'unfinished'),
    ` — ${done} of ${planned} designs done. Every number below covers the finished designs only and may change.`);
}

function facts(pairs) {
  return el('dl', { className: 'facts' }, pairs.filter(([, v]) => v !== null && v !== undefined && v !== '')
    .map(([k, v]) => el('div', {}, el('dt', {}, k), el('dd', {}, v))));
}

function designsPerCell(report) {
  const cells = report.missions.length * report.conditions.length;
  const planned = report.experiment.designs_planned;
  if (!cells || !planned) return null;
  return planned % cells === 0 ? String(planned / cells) : `${planned} in all`;
}

function missionTable(report) {
  return reportTable([
    { title: 'mission', value: (m) => m.name },
    { title: 'objective', value: (m) => `${isMaximised(m) ? 'maximise' : 'minimise'} (${directionText(m)})` },
    { title: 'budget (runs)', numeric: true, value: (m) => (m.budget ? formatCount(m.budget) : '–') },
    { title: 'description', value: (m) => m.description || '' },
  ], report.missions, { testid: 'missions', caption: 'Missions' });
}

/// One row per condition and mission (long, so that five missions still fit the page).
function conditionTable(report) {
  const rows = [];
  for (const c of report.conditions) {
    for (const m of report.missions) {
      const p = c.per_mission?.[m.name];
      if (p) rows.push({ c, m, p });
    }
  }
  const list = (xs) => (xs && xs.length ? xs.join(', ') : '–');
  return reportTable([
    { title: 'condition', value: (r) => conditionCell(report, r.c.name) },
    { title: 'method', value: (r) => r.c.method || '' },
    { title: 'mission', value: (r) => r.m.name },
    { title: 'architectures', value: (r) => (r.c.method === 'evostick' ? 'neural network' : list(r.p.architectures)) },
    { title: 'flavours', value: (r) => (r.c.method === 'evostick' ? '–' : list(r.p.flavours)) },
    { title: 'budget (runs)', numeric: true, value: (r) => (r.p.budget ? formatCount(r.p.budget) : '–') },
  ], rows, { testid: 'conditions', caption: 'Conditions' });
}

export function renderHeader(report, root) {
  const x = report.experiment;
  const header = el('header', { className: 'report-header' },
    el('div', { className: 'kicker' }, 'SwarmDesign experiment report'),
    el('h1', {}, x.name || 'experiment'),
    el('div', { className: 'subtitle' }, x.project ? `project ${x.project}` : ''),
    stateBanner(x));
  const seeds = x.assessment_seeds;
  header.append(facts([
    ['protocol', `${report.missions.length} mission${report.missions.length === 1 ? '' : 's'} × ${report.conditions.length} condition${report.conditions.length === 1 ? '' : 's'}`],
    ['designs per mission and condition', designsPerCell(report)],
    ['budgets (runs per design)', report.missions.map((m) => `${m.name} ${m.budget ? formatCount(m.budget) : '–'}`).join(' · ')],
    ['designs done', `${x.designs_done ?? 0} of ${x.designs_planned ?? '?'}`],
    ['assessment', seeds ? `${seeds} runs per design on fresh seeds` : null],
    ['budget scale', x.budget_scale ?? null],
    ['experiment seed', x.seed ?? null],
    ['state', x.state || null],
    ['created', formatDate(x.created_at)],
    ['finished', x.finished_at ? formatDate(x.finished_at) : 'not yet'],
    ['report generated', formatDate(x.generated_at)],
    ['SwarmDesign', [x.swarmdesign_version, x.results_version !== undefined ? `results version ${x.results_version}` : null].filter(Boolean).join(', ')],
  ]));
  root.append(header);
  const protocol = el('section', { className: 'report-section', id: 'section-protocol' }, el('h2', {}, 'Protocol'),
    missionTable(report), conditionTable(report));
  if (x.protocol) {
    protocol.append(el('details', { className: 'protocol-json' }, el('summary', {}, 'the resolved protocol as stored'),
      el('pre', {}, JSON.stringify(x.protocol, null, 2))));
  }
  root.append(protocol);
}
