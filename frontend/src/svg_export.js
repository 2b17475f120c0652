// The drawing as an SVG file, built from cytoscape's node boxes and edge geometry.
import { download } from './download.js';
import { edgeLabelBox, labelCentre } from './graph.js';

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

function textLines(lines, x, y, size, color) {
  const first = y - ((lines.length - 1) * size * 1.2) / 2;
  return lines.map((line, i) =>
    `<text x="${x}" y="${(first + i * size * 1.2).toFixed(1)}" font-size="${size}" fill="${color}" text-anchor="middle" dominant-baseline="central" font-family="sans-serif">${esc(line)}</text>`).join('');
}

export function graphToSvg(cy) {
  const bb = cy.elements().boundingBox({ includeLabels: true });
  const pad = 20;
  const parts = [];
  cy.edges().forEach((e) => {
    const s = e.sourceEndpoint();
    const t = e.targetEndpoint();
    const cps = e.controlPoints();
    const seg = e.segmentPoints();
    let d = `M${s.x},${s.y}`;
    let last = s;
    if (seg && seg.length) { for (const p of seg) d += ` L${p.x},${p.y}`; last = seg[seg.length - 1]; d += ` L${t.x},${t.y}`; }
    else if (cps && cps.length === 1) { d += ` Q${cps[0].x},${cps[0].y} ${t.x},${t.y}`; last = cps[0]; }
    else if (cps && cps.length >= 2) { d += ` C${cps[0].x},${cps[0].y} ${cps[1].x},${cps[1].y} ${t.x},${t.y}`; last = cps[1]; }
    else d += ` L${t.x},${t.y}`;
    const color = e.style('line-color');
    parts.push(`<path d="${d}" fill="none" stroke="${color}" stroke-width="1.8"/>`);
    if (e.style('target-arrow-shape') !== 'none') {
      const a = Math.atan2(t.y - last.y, t.x - last.x);
      const l = 9;
      const p1 = `${t.x - l * Math.cos(a - 0.4)},${t.y - l * Math.sin(a - 0.4)}`;
      const p2 = `${t.x - l * Math.cos(a + 0.4)},${t.y - l * Math.sin(a + 0.4)}`;
      parts.push(`<polygon points="${t.x},${t.y} ${p1} ${p2}" fill="${color}"/>`);
    }
    const label = e.data('label');
    if (label) {
      const m = labelCentre(e);
      const { lines, w, h } = edgeLabelBox(label);
      parts.push(`<rect x="${m.x - w / 2}" y="${m.y - h / 2}" width="${w}" height="${h}" fill="#fff" fill-opacity="0.9"/>`);
      parts.push(textLines(lines, m.x, m.y, 10, '#7a4d00'));
    }
  });
  cy.nodes().forEach((n) => {
    const p = n.position();
    const w = n.outerWidth();
    const h = n.outerHeight();
    const fill = n.style('background-color');
    const stroke = n.style('border-color');
    const sw = parseFloat(n.style('border-width')) || 1;
    if (n.style('shape') === 'ellipse') parts.push(`<ellipse cx="${p.x}" cy="${p.y}" rx="${w / 2}" ry="${h / 2}" fill="${fill}" stroke="${stroke}" stroke-width="${sw}"/>`);
    else parts.push(`<rect x="${p.x - w / 2}" y="${p.y - h / 2}" width="${w}" height="${h}" rx="6" fill="${fill}" stroke="${stroke}" stroke-width="${sw}"/>`);
    const label = n.style('label');
    parts.push(textLines(String(label).split('\n'), p.x, p.y, parseFloat(n.style('font-size')) || 11, '#1d2430'));
  });
  const vb = `${bb.x1 - pad} ${bb.y1 - pad} ${bb.w + 2 * pad} ${bb.h + 2 * pad}`;
  return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" viewBox="${vb}" width="${Math.ceil(bb.w + 2 * pad)}" height="${Math.ceil(bb.h + 2 * pad)}">\n<rect x="${bb.x1 - pad}" y="${bb.y1 - pad}" width="${bb.w + 2 * pad}" height="${bb.h + 2 * pad}" fill="#fff"/>\n${parts.join('\n')}\n</svg>\n`;
}

export function downloadSvg(cy, filename = 'control-software.svg') {
  download(new Blob([graphToSvg(cy)], { type: 'image/svg+xml' }), filename);
}
