// Small DOM and number-formatting helpers shared by the report's sections.

/// el('p', {className: 'x'}, 'text', child, ...): an element with properties and children.
export function el(tag, props = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(props)) {
    if (key === 'dataset') Object.assign(node.dataset, value);
    else if (key in node) node[key] = value;
    else node.setAttribute(key, value);
  }
  for (const child of children.flat()) {
    if (child === null || child === undefined || child === false) continue;
    node.append(child instanceof Node ? child : String(child));
  }
  return node;
}

/// A numbered report section with a title and an optional one-line explanation.
export function section(id, title, intro) {
  return el('section', { className: 'report-section', id: `section-${id}` },
    el('h2', {}, title),
    intro ? el('p', { className: 'section-intro' }, intro) : null);
}

/// A figure: the plot or drawing container plus a caption under it.
export function figure(className, caption) {
  const body = el('div', { className });
  const node = el('figure', { className: 'report-figure' }, body, caption ? el('figcaption', {}, caption) : null);
  return { node, body };
}

const fourDigits = new Intl.NumberFormat('en-GB', { maximumSignificantDigits: 4, useGrouping: false });
const grouped = new Intl.NumberFormat('en-GB', { maximumFractionDigits: 0 });

/// Scores in the mission's units: four significant digits are what the assessment supports,
/// but large scores keep all their integer digits (16398, not 16400).
export function formatScore(value) {
  if (value === null || value === undefined || Number.isNaN(value)) return '–';
  return Math.abs(value) >= 1000 ? value.toFixed(0) : fourDigits.format(value);
}

export function formatCount(value) { return grouped.format(value); }

export function formatP(p) {
  if (p === null || p === undefined || Number.isNaN(p)) return '–';
  return p >= 0.001 ? p.toFixed(3) : p.toExponential(1);
}

export function formatFraction(f) { return f.toFixed(2); }

/// 3725.5 s -> "1 h 02 min"; 75 s -> "1 min 15 s"; 9.4 s -> "9.4 s".
export function formatDuration(seconds) {
  if (seconds < 60) return `${seconds.toFixed(1)} s`;
  const total = Math.round(seconds);
  const h = Math.floor(total / 3600);
  const m = Math.floor((total % 3600) / 60);
  const s = total % 60;
  if (h) return `${h} h ${String(m).padStart(2, '0')} min`;
  return `${m} min ${String(s).padStart(2, '0')} s`;
}

/// ISO time stamps shown in UTC, minutes precision: the report is read far from where it ran.
export function formatDate(iso) {
  if (!iso) return '–';
  const date = new Date(iso);
  if (Number.isNaN(date.getTime())) return iso;
  return `${date.toISOString().slice(0, 16).replace('T', ' ')} UTC`;
}
