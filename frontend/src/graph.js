// Control software drawn with cytoscape: a MODEL (see src/web/API.md) becomes nodes and edges,
// laid out by dagre. Used by the editor and, read-only, by Exec and the design monitor.
import cytoscape from 'cytoscape';
import dagre from 'cytoscape-dagre';
import edgehandles from 'cytoscape-edgehandles';
import { findModule, twoDigits } from './catalogue.js';

cytoscape.use(dagre);
cytoscape.use(edgehandles);

const BT_SYMBOL = { selector: '?', 'selector*': '?*', sequence: '→', 'sequence*': '→*', negation: '!' };

function paramsText(parameters) {
  return Object.entries(parameters || {}).map(([k, v]) => `${k}=${v}`).join(' ');
}

function moduleText(kind, module) {
  const spec = findModule(kind, module.id);
  return `${twoDigits(module.id)} ${spec ? spec.name : '?'}`;
}

/// Cytoscape elements of a MODEL.
export function elementsOf(model) {
  const els = [];
  if (!model) return els;
  if (model.architecture === 'fsm') {
    model.states.forEach((state, i) => {
      const p = paramsText(state.behaviour.parameters);
      els.push({
        group: 'nodes',
        data: { id: `s${i}`, index: i, kind: 'state', base: `S${i}: ${moduleText('behaviour', state.behaviour)}${p ? `\n${p}` : ''}` },
        classes: i === 0 ? 'state initial' : 'state',
      });
    });
    model.states.forEach((state, i) => {
      state.transitions.forEach((t, j) => {
        const p = paramsText(t.condition.parameters);
        els.push({
          group: 'edges',
          data: { id: `t${i}_${j}`, source: `s${i}`, target: `s${t.target}`, state: i, transition: j, kind: 'transition',
                  label: `${moduleText('condition', t.condition)}${p ? `\n${p}` : ''}`, lx: 0, ly: 0 },
        });
      });
    });
  } else if (model.architecture === 'bt') {
    model.nodes.forEach((node, i) => {
      let base;
      let cls = 'bt';
      if (node.type === 'action') {
        const p = paramsText(node.module.parameters);
        base = `${moduleText('behaviour', node.module)}${p ? `\n${p}` : ''}`;
        cls += ' action';
      } else if (node.type === 'condition') {
        const p = paramsText(node.module.parameters);
        base = `${moduleText('condition', node.module)}${p ? `\n${p}` : ''}`;
        cls += ' condition';
      } else {
        base = BT_SYMBOL[node.type] || node.type;
        cls += ' composite';
      }
      if (i === 0) cls += ' root';
      els.push({ group: 'nodes', data: { id: `n${i}`, index: i, kind: 'btnode', type: node.type, base }, classes: cls });
    });
    model.nodes.forEach((node, i) => {
      (node.children || []).forEach((c, k) => {
        els.push({ group: 'edges', data: { id: `e${i}_${c}`, source: `n${i}`, target: `n${c}`, order: k, kind: 'child', label: '' } });
      });
    });
  }
  return els;
}

const nodeLabel = (n) => (n.data('count') !== undefined ? `${n.data('base')}\n● ${n.data('count')} robots` : n.data('base'));
// Node boxes sized from their label (about 6.5 px per character at font size 11).
const labelWidth = (n) => Math.max(...nodeLabel(n).split('\n').map((l) => l.length)) * 6.5 + 4;
const labelHeight = (n) => nodeLabel(n).split('\n').length * 14;

const STYLE = [
  { selector: 'node', style: {
    label: nodeLabel,
    'text-wrap': 'wrap', 'text-valign': 'center', 'text-halign': 'center', 'font-size': 11,
    'font-family': 'system-ui, sans-serif', width: labelWidth, height: labelHeight, padding: 10,
    shape: 'round-rectangle', 'background-color': '#e3edff', 'border-width': 1.5, 'border-color': '#5b7fc7', color: '#1d2430',
  } },
  { selector: 'node.initial', style: { 'border-width': 4, 'border-style': 'double', 'border-color': '#1b4fb8' } },
  { selector: 'node.bt.composite', style: { shape: 'round-rectangle', 'background-color': '#eef1f5', 'border-color': '#6b7584', 'font-size': 16, 'font-weight': 700, width: 34, height: 28, padding: 4 } },
  { selector: 'node.bt.condition', style: { shape: 'ellipse', 'background-color': '#fff1d6', 'border-color': '#c9962c', padding: 14 } },
  { selector: 'node.bt.action', style: { 'background-color': '#e3edff' } },
  { selector: 'node.bt.root', style: { 'border-width': 3 } },
  { selector: 'node.busy', style: { 'background-color': '#c8f0cf', 'border-color': '#2e7d32' } },
  { selector: 'node:selected', style: { 'border-color': '#e0a000', 'border-width': 3, 'overlay-opacity': 0 } },
  { selector: 'edge', style: {
    label: 'data(label)', 'curve-style': 'bezier', 'target-arrow-shape': 'triangle', 'arrow-scale': 1.2,
    width: 1.8, 'line-color': '#8a94a3', 'target-arrow-color': '#8a94a3', 'font-size': 10, 'text-wrap': 'wrap',
    'text-background-color': '#ffffff', 'text-background-opacity': 0.9, 'text-background-padding': 2, 'color': '#7a4d00',
    'control-point-step-size': 60,
  } },
  { selector: 'edge[kind = "transition"]', style: { 'text-margin-x': 'data(lx)', 'text-margin-y': 'data(ly)' } },
  { selector: 'edge[kind = "child"]', style: { 'curve-style': 'taxi', 'taxi-direction': 'downward', 'target-arrow-shape': 'none' } },
  { selector: 'edge:selected', style: { 'line-color': '#e0a000', 'target-arrow-color': '#e0a000', width: 3 } },
  { selector: '.eh-handle, .eh-ghost-node', style: { 'background-color': '#e0a000', width: 10, height: 10, shape: 'ellipse', label: '' } },
  { selector: '.eh-preview, .eh-ghost-edge', style: { 'line-color': '#e0a000', 'target-arrow-color': '#e0a000', 'line-style': 'dashed', label: '' } },
];

export function createGraph(container, { readOnly = false } = {}) {
  const cy = cytoscape({
    container, style: STYLE, minZoom: 0.2, maxZoom: 3,
    autoungrabify: readOnly, boxSelectionEnabled: false,
    selectionType: 'single',
  });
  cy.scratch('_sdCompact', readOnly); // narrow side panels: FSMs top to bottom
  // A dragged state moves its transitions' curves, and their labels with them.
  cy.on('position', 'node', (event) => placeEdgeLabels(event.target.connectedEdges()));
  // A window resized (or a tab shown again at another size): the drawing is fitted again, so it
  // never sits in a corner of the area it had before.
  let size = '';
  new ResizeObserver(() => {
    const now = `${container.clientWidth}x${container.clientHeight}`;
    if (!container.clientWidth || !container.clientHeight || now === size) return;
    size = now;
    cy.resize();
    if (cy.nodes().length) {
      cy.fit(undefined, readOnly ? 10 : 30);
      if (cy.zoom() > 1.6) { cy.zoom(1.6); cy.center(); }
    }
  }).observe(container);
  return cy;
}

/// The box of an edge label (font size 10, about 6 px per character, with its padding): where
/// the label moves off its curve, and the background SVG export draws under it.
export function edgeLabelBox(label) {
  const lines = String(label).split('\n');
  return { lines, w: Math.max(...lines.map((l) => l.length)) * 6 + 6, h: lines.length * 12 + 4 };
}

/// Where an edge's label is drawn: the curve's midpoint, moved by the label's margin.
export function labelCentre(edge) {
  const m = edge.midpoint();
  return { x: m.x + (edge.data('lx') || 0), y: m.y + (edge.data('ly') || 0) };
}

/// Two transitions between the same states bend apart, but a label centred on each curve is
/// wider than the gap between them, so the labels of a pair overlap (in the narrow
/// top-to-bottom drawing, side by side). Each bent edge's label therefore moves to the outside
/// of its bend, until its box just touches the curve's midpoint; straight edges keep theirs.
function placeEdgeLabels(edges) {
  edges.forEach((e) => {
    if (e.data('kind') !== 'transition') return;
    const s = e.sourceEndpoint();  // the chord between where the curve leaves and meets the boxes
    const t = e.targetEndpoint();
    const m = e.midpoint();
    const dx = m.x - (s.x + t.x) / 2;
    const dy = m.y - (s.y + t.y) / 2;
    const bend = Math.hypot(dx, dy);
    let lx = 0;
    let ly = 0;
    if (bend > 1) {
      const { w, h } = edgeLabelBox(e.data('label'));
      const reach = (Math.abs(dx) * w + Math.abs(dy) * h) / (2 * bend);
      lx = (dx / bend) * reach;
      ly = (dy / bend) * reach;
    }
    if (e.data('lx') !== lx || e.data('ly') !== ly) e.data({ lx, ly });
  });
  if (edges.length) separateLabels(edges.cy().edges('[kind = "transition"]'));
}

/// Three or more transitions between two states (or labels of different pairs that meet) can
/// still cover one another, or slip under a state's box: overlapping label boxes are pushed
/// apart, and out from under states (which stay put), along the axis where they overlap least,
/// a few rounds until none overlap. Cheap: a design has a few dozen labels.
function separateLabels(edges) {
  const states = edges.cy().nodes().map((n) => n.boundingBox({ includeLabels: false, includeOverlays: false }));
  const only = { includeNodes: false, includeEdges: false, includeLabels: true, includeOverlays: false, includeUnderlays: false };
  const boxes = edges.map((e) => {
    // The label as drawn when it has been (font metrics), else as estimated.
    const drawn = e.boundingBox(only);
    const { w, h } = drawn.w > 0 ? drawn : edgeLabelBox(e.data('label'));
    const m = e.midpoint();
    // Out from under a state, a label moves across its chord (never towards the states it joins).
    const src = e.sourceEndpoint(), dst = e.targetEndpoint();
    const len = Math.hypot(dst.x - src.x, dst.y - src.y);
    const nx = len > 1 ? -(dst.y - src.y) / len : 0, ny = len > 1 ? (dst.x - src.x) / len : 0;
    return { e, w, h, mx: m.x, my: m.y, lx: e.data('lx') || 0, ly: e.data('ly') || 0, nx, ny, cx: (src.x + dst.x) / 2, cy: (src.y + dst.y) / 2 };
  });
  const gap = 2;
  for (let round = 0; round < 200; round++) {
    let moved = false;
    for (let i = 0; i < boxes.length; i++)
      for (let j = i + 1; j < boxes.length; j++) {
        const a = boxes[i], b = boxes[j];
        const dx = (b.mx + b.lx) - (a.mx + a.lx), dy = (b.my + b.ly) - (a.my + a.ly);
        const ox = (a.w + b.w) / 2 + gap - Math.abs(dx), oy = (a.h + b.h) / 2 + gap - Math.abs(dy);
        if (ox <= 0 || oy <= 0) continue;
        moved = true;
        // Equal centres: split by index, so the result never depends on floating-point chance.
        if (oy <= ox) { const s = (dy > 0 || (dy === 0 && i < j) ? 1 : -1) * oy / 2; a.ly -= s; b.ly += s; }
        else { const s = (dx > 0 || (dx === 0 && i < j) ? 1 : -1) * ox / 2; a.lx -= s; b.lx += s; }
      }
    for (const a of boxes)
      for (const n of states) {
        const dx = (a.mx + a.lx) - (n.x1 + n.x2) / 2, dy = (a.my + a.ly) - (n.y1 + n.y2) / 2;
        const ox = (a.w + n.w) / 2 + gap - Math.abs(dx), oy = (a.h + n.h) / 2 + gap - Math.abs(dy);
        if (ox <= 0 || oy <= 0) continue;
        moved = true;
        if (a.nx === 0 && a.ny === 0) {  // a self-loop: straight out
          if (oy <= ox) a.ly += (dy >= 0 ? 1 : -1) * oy; else a.lx += (dx >= 0 ? 1 : -1) * ox;
          continue;
        }
        const side = (a.mx + a.lx - a.cx) * a.nx + (a.my + a.ly - a.cy) * a.ny >= 0 ? 1 : -1;
        a.lx += side * a.nx * 4;
        a.ly += side * a.ny * 4;
      }
    if (!moved) break;
  }
  for (const b of boxes) if (b.e.data('lx') !== b.lx || b.e.data('ly') !== b.ly) b.e.data({ lx: b.lx, ly: b.ly });
}

function layoutOptions(cy, model) {
  if (model && model.architecture === 'bt') return { name: 'dagre', rankDir: 'TB', nodeSep: 30, rankSep: 60, animate: false };
  return cy.scratch('_sdCompact')
    ? { name: 'dagre', rankDir: 'TB', nodeSep: 50, rankSep: 70, edgeSep: 20, animate: false }
    : { name: 'dagre', rankDir: 'LR', nodeSep: 70, rankSep: 140, edgeSep: 30, animate: false };
}

/// Replaces the drawing by the MODEL's. Positions of nodes that keep their id are kept unless
/// relayout; new nodes trigger a layout.
export function renderModel(cy, model, { relayout = false } = {}) {
  const positions = new Map();
  cy.nodes().forEach((n) => positions.set(n.id(), { ...n.position() }));
  const selected = cy.$(':selected').map((e) => e.id());
  cy.batch(() => {
    cy.elements().remove();
    cy.add(elementsOf(model));
  });
  const known = cy.nodes().every((n) => positions.has(n.id()));
  if (!relayout && known && cy.nodes().length) {
    cy.nodes().forEach((n) => n.position(positions.get(n.id())));
  } else if (cy.nodes().length) {
    layout(cy, model);
  }
  for (const id of selected) cy.getElementById(id).select();
  placeEdgeLabels(cy.edges());
}

/// dagre does not keep the order of children: put each node's children left to right in
/// their order, moving whole subtrees, from the root down.
function orderTree(cy, model) {
  const shift = (i, dx) => {
    const n = cy.getElementById(`n${i}`);
    n.position({ x: n.position('x') + dx, y: n.position('y') });
    for (const c of model.nodes[i].children || []) shift(c, dx);
  };
  const visit = (i) => {
    const children = model.nodes[i].children || [];
    const slots = children.map((c) => cy.getElementById(`n${c}`).position('x')).sort((a, b) => a - b);
    children.forEach((c, k) => shift(c, slots[k] - cy.getElementById(`n${c}`).position('x')));
    children.forEach(visit);
  };
  if (model.nodes.length) visit(0);
}

export function layout(cy, model) {
  const lay = cy.layout({ ...layoutOptions(cy, model), fit: false });
  lay.run();
  if (model && model.architecture === 'bt') orderTree(cy, model);
  placeEdgeLabels(cy.edges());
  cy.fit(undefined, cy.scratch('_sdCompact') ? 10 : 30);
  if (cy.zoom() > 1.6) { cy.zoom(1.6); cy.center(); }
}

/// counts: array indexed by state / node index, or null to hide the badges.
export function setCounts(cy, counts) {
  let resized = false;  // a count line came or went: the boxes changed size
  cy.batch(() => {
    cy.nodes().forEach((n) => {
      const index = n.data('index');
      const had = n.data('count') !== undefined;
      if (!counts) { n.removeData('count'); n.removeClass('busy'); resized ||= had; return; }
      const c = counts[index] || 0;
      if (n.data('kind') === 'btnode' && !(n.data('type') === 'action' || c > 0)) { n.removeData('count'); n.removeClass('busy'); resized ||= had; return; }
      if (n.data('count') !== c) n.data('count', c);
      resized ||= !had;
      n.toggleClass('busy', c > 0);
    });
  });
  // Labels were kept clear of the boxes as they were; every frame otherwise costs nothing here.
  if (resized) placeEdgeLabels(cy.edges());
}
