// Modules: how often designs use each module, one heat map per flavour and kind of module.
// Rows are the flavour's modules from the catalogue (unused ones show 0); columns are the
// (mission, condition) cells in which the flavour was available.
import { el, figure, formatFraction, section } from './dom.js';
import { axis, baseLayout, drawPlot, plotTitle } from './plots.js';

const KINDS = [
  { kind: 'behaviour', title: 'behaviours', list: 'behaviours' },
  { kind: 'condition', title: 'conditions', list: 'conditions' },
];
const COLOUR_SCALE = [[0, '#ffffff'], [0.5, '#6baed6'], [1, '#08306b']];
const ROW_HEIGHT = 24;
const WIDE_AFTER_COLUMNS = 4; // more columns than this take the page's whole width

const twoDigits = (id) => String(id).padStart(2, '0');

/// Columns of a flavour: per-mission rows when the document has them, else the "*" rows.
function columnsOf(report, flavour, rows) {
  const perMission = rows.some((r) => r.mission !== '*');
  const columns = [];
  if (perMission) {
    for (const mission of report.missions) {
      for (const condition of report.conditions) {
        const offered = (condition.per_mission?.[mission.name]?.flavours || []).includes(flavour);
        const used = rows.some((r) => r.mission === mission.name && r.condition === condition.name && r.flavour === flavour);
        if ((offered || used) && report.box(mission.name, condition.name)) columns.push({ mission: mission.name, condition: condition.name });
      }
    }
  } else {
    for (const condition of report.conditions) {
      if (rows.some((r) => r.condition === condition.name && r.flavour === flavour)) columns.push({ mission: '*', condition: condition.name });
    }
  }
  return columns;
}

function columnLabel(report, column) {
  const where = column.mission === '*' ? 'all missions' : column.mission;
  return `${where}<br><span style="color:${report.colourOf(column.condition)}">■</span> ${column.condition}`;
}

function heatmap(report, flavour, spec, modules, columns, rows, container) {
  const cell = (module, column) => rows.find((r) => r.kind === spec.kind && r.module === module.id
    && r.mission === column.mission && r.condition === column.condition);
  const z = modules.map((m) => columns.map((c) => (cell(m, c) ? cell(m, c).fraction : 0)));
  const text = modules.map((m) => columns.map((c) => {
    const r = cell(m, c);
    return r ? `${formatFraction(r.fraction)}` : '0';
  }));
  const hover = modules.map((m) => columns.map((c) => {
    const r = cell(m, c);
    return `${twoDigits(m.id)} ${m.name}<br>${c.condition} · ${c.mission}<br>${r ? `${r.designs_with} of ${r.designs} designs` : 'no design'}`;
  }));
  const trace = {
    type: 'heatmap', z, x: columns.map((_, i) => i), y: modules.map((m) => `${twoDigits(m.id)} ${m.name}`),
    zmin: 0, zmax: 1, colorscale: COLOUR_SCALE, showscale: false, xgap: 2, ygap: 2,
    text, texttemplate: '%{text}', textfont: { size: 11 }, hovertext: hover, hoverinfo: 'text',
  };
  const layout = baseLayout({
    title: plotTitle(`${flavour} · ${spec.title}`),
    width: container.clientWidth, height: 96 + ROW_HEIGHT * modules.length,
    margin: { l: 150, r: 10, t: 36, b: 54 },
    xaxis: axis('', {
      tickmode: 'array', tickvals: columns.map((_, i) => i), ticktext: columns.map((c) => columnLabel(report, c)),
      showline: false, ticks: '', showgrid: false, side: 'bottom',
    }),
    yaxis: axis('', { autorange: 'reversed', showline: false, ticks: '', showgrid: false }),
  });
  return drawPlot(container, [trace], layout);
}

export function renderModules(report, root) {
  const node = section('modules', 'Modules',
    'Fraction of the designs of each cell that use a module at least once (a state, a transition, an action or a condition node).');
  root.append(node);
  const rows = report.data.module_frequency || [];
  const catalogue = report.catalogue;
  if (!rows.length || !catalogue) {
    node.append(el('p', { className: 'note' }, rows.length ? 'The document has no catalogue.' : 'No module use to show (no design with modules).'));
    return;
  }
  const flavours = (catalogue.flavours || []).map((f) => f.name).filter((name) => rows.some((r) => r.flavour === name));
  for (const flavour of flavours) {
    const flavourRows = rows.filter((r) => r.flavour === flavour);
    const columns = columnsOf(report, flavour, flavourRows);
    const grid = el('div', { className: 'plot-grid heatmap-grid', dataset: { flavour } });
    node.append(el('h3', {}, `${flavour}`), grid);
    for (const spec of KINDS) {
      const modules = (catalogue[spec.list] || []).filter((m) => m.flavour === flavour).sort((a, b) => a.id - b.id);
      if (!modules.length) continue;
      const { node: fig, body } = figure('plot plot-heatmap', null);
      fig.classList.toggle('wide', columns.length > WIDE_AFTER_COLUMNS);
      grid.append(fig);
      heatmap(report, flavour, spec, modules, columns, flavourRows, body);
    }
  }
}
