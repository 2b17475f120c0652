// Typical designs: per (mission, condition), the best and the median design drawn as the web app
// draws control software (graph.js: cytoscape + dagre), with its score and configuration string.
import { createGraph, renderModel } from '../graph.js';
import { el, formatScore, section } from './dom.js';
import { ARCHITECTURE_NAMES, isMaximised } from './report_data.js';
import { conditionCell } from './tables.js';

const EXPORT_SCALE = 2; // image pixels per CSS pixel: sharp on screen and when printed
const STAGE_WIDTH = 900;
const STAGE_HEIGHT = 500;

/// Lays the MODEL out with the web app's graph (cytoscape + dagre, FSMs left to right) in a
/// hidden stage, keeps it as an image at natural size (shrunk to the page when wider) and frees
/// the cytoscape instance: a report can hold dozens of drawings, live canvases would not scale.
async function drawModel(container, model, description) {
  const stage = el('div', { className: 'drawing-stage', style: `width:${STAGE_WIDTH}px;height:${STAGE_HEIGHT}px` });
  container.append(stage);
  const cy = createGraph(stage);
  let image;
  try {
    renderModel(cy, model, { relayout: true });
    const box = cy.elements().boundingBox({ includeLabels: true });
    image = el('img', {
      src: cy.png({ full: true, scale: EXPORT_SCALE, bg: '#ffffff', output: 'base64uri' }),
      alt: description, width: Math.round(box.w), height: Math.round(box.h),
    });
  } finally {
    cy.destroy();
    stage.remove();
  }
  container.append(image);
  await image.decode();
  container.dataset.drawn = 'true';
}

/// The panel of one design; its drawing is queued on `drawings` and made once the panel is in the
/// page (cytoscape needs a container that the page lays out).
function designPanel(report, role, design, drawings) {
  const panel = el('div', { className: 'design-panel', dataset: { role, design: design.id } });
  const runs = (design.scores || []).length;
  panel.append(
    el('div', { className: 'design-head' },
      el('strong', {}, role),
      ` · design ${design.id}, replicate ${design.replicate}`),
    el('div', { className: 'design-score' },
      `score ${formatScore(design.score)}`,
      runs ? el('span', { className: 'muted' }, ` (mean of ${runs} runs; optimiser's estimate ${formatScore(design.design_score)})`) : null),
  );
  if (design.model && (design.architecture === 'fsm' || design.architecture === 'bt')) {
    const drawing = el('div', { className: 'report-drawing', dataset: { architecture: design.architecture } });
    panel.append(drawing);
    drawings.push(() => drawModel(drawing, design.model, `${ARCHITECTURE_NAMES[design.architecture]} of design ${design.id}`));
  } else {
    panel.append(el('div', { className: 'drawing-none' }, `${ARCHITECTURE_NAMES[design.architecture] || design.architecture}: not drawn (shown as its string only)`));
  }
  panel.append(el('code', { className: 'configuration' }, design.configuration || ''));
  return panel;
}

export function renderDesigns(report, root) {
  const node = section('designs', 'Typical designs',
    'For each mission and condition, the design with the best assessment score and the one with the median score. '
    + 'Double border: the initial state; ellipses: conditions of behaviour trees.');
  root.append(node);
  const drawings = [];
  const typical = report.data.typical || [];
  if (!typical.length) node.append(el('p', { className: 'note' }, 'No design yet.'));
  for (const mission of report.missions) {
    for (const condition of report.conditions) {
      const entry = typical.find((t) => t.mission === mission.name && t.condition === condition.name);
      if (!entry) continue;
      const best = report.design(entry.best);
      const median = report.design(entry.median);
      const n = report.designsOf(mission.name, condition.name).length;
      const card = el('div', { className: 'design-card', dataset: { mission: mission.name, condition: condition.name } },
        el('h3', {}, `${mission.name} · `, conditionCell(report, condition.name),
          el('span', { className: 'muted' }, ` — ${n} design${n === 1 ? '' : 's'}, ${isMaximised(mission) ? 'highest' : 'lowest'} score is best`)));
      const panels = el('div', { className: 'design-pair' });
      if (best) panels.append(designPanel(report, best === median ? 'best and median' : 'best', best, drawings));
      if (median && median !== best) panels.append(designPanel(report, 'median', median, drawings));
      card.append(panels);
      node.append(card);
    }
  }
  return Promise.all(drawings.map((draw) => draw()));
}
