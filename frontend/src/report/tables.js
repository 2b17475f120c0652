// Tables of the report: one builder so that every table looks and prints the same.
import { el } from './dom.js';

/// columns: [{title, value: (row) => text | Node, numeric?: bool}]
/// options.caption: shown above the table; options.footer: rows ([cells]) after the body.
export function reportTable(columns, rows, { caption, footer, testid } = {}) {
  const head = el('thead', {}, el('tr', {}, columns.map((c) => el('th', { className: c.numeric ? 'num' : '', scope: 'col' }, c.title))));
  const body = el('tbody', {}, rows.map((row) => el('tr', {},
    columns.map((c) => el('td', { className: c.numeric ? 'num' : '' }, c.value(row))))));
  const foot = footer && footer.length
    ? el('tfoot', {}, footer.map((cells) => el('tr', {}, cells.map((cell, i) => el('td', { className: columns[i] && columns[i].numeric ? 'num' : '' }, cell)))))
    : null;
  const table = el('table', { className: 'report-table' }, caption ? el('caption', {}, caption) : null, head, body, foot);
  if (testid) table.dataset.testid = testid;
  return el('div', { className: 'table-wrap' }, table);
}

/// A coloured square and the condition's name: ties tables to the plots' colours.
export function conditionCell(report, name) {
  return el('span', { className: 'condition-name' },
    el('span', { className: 'swatch', style: `background:${report.colourOf(name)}` }), name);
}
