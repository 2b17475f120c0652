// Scores shown for reading (a few significant digits) while the full value stays at hand:
// on hover (title) and when copied (the copy handler puts data-full on the clipboard).

/// 4 significant digits, never an exponent for the magnitudes scores have.
export function readable(value) {
  if (value === null || value === undefined || !Number.isFinite(Number(value))) return '–';
  const v = Number(value);
  const digits = Math.abs(v) >= 1000 ? 0 : Math.abs(v) >= 100 ? 1 : Math.abs(v) >= 10 ? 2 : 3;
  return v.toFixed(digits);
}

/// The full value as the server sent it (17 significant digits at most).
export function fullText(value) { return String(value); }

/// An element showing `value` rounded, with the full value on hover and copy.
export function scoreSpan(el, value, attrs = {}) {
  return el('span', { ...attrs, class: `score-value ${attrs.class || ''}`.trim(), title: fullText(value), 'data-full': fullText(value), text: readable(value) });
}

/// Copying a selection that lies within one rounded score copies its full value.
export function copyFullScores(doc = document) {
  doc.addEventListener('copy', (e) => {
    const node = doc.getSelection()?.anchorNode;
    const holder = node && (node.nodeType === 1 ? node : node.parentElement)?.closest('[data-full]');
    if (!holder) return;
    e.clipboardData.setData('text/plain', holder.dataset.full);
    e.preventDefault();
  });
}

/// "840 B", "2.1 kB", "1.0 MB": sizes as the server's messages write them (powers of 1000).
export function bytesText(bytes) {
  const units = ['B', 'kB', 'MB', 'GB', 'TB'];
  let v = Number(bytes);
  let unit = 0;
  while (v >= 1000 && unit < units.length - 1) { v /= 1000; unit++; }
  return unit === 0 ? `${Math.round(v)} B` : `${v.toFixed(1)} ${units[unit]}`;
}

/// A count of runs, thousands grouped as the rest of the page writes them ("100,000").
export function countText(n) { return Number(n).toLocaleString('en'); }
