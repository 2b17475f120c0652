// The offline report page as `swarmdesign report` writes it, and how a test looks at it.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const escapeHtml = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/// report.html from a built web root (report.js, report.css) and a report document: the same
/// template as the C++ side. "</" becomes "<\/" so the JSON cannot end its <script> early.
export function assembleReportHtml(webRoot, data) {
  const css = readFileSync(path.join(webRoot, 'report.css'), 'utf8');
  const js = readFileSync(path.join(webRoot, 'report.js'), 'utf8');
  // '<' only occurs inside JSON strings: as \u003c no '</script' or '<!--' can end the element.
  const json = JSON.stringify(data).replaceAll('<', '\\u003c');
  const title = `SwarmDesign report: ${data.experiment?.name ?? 'experiment'} (${data.experiment?.project ?? ''})`;
  return '<!doctype html><html><head><meta charset="utf-8">'
    + `<title>${escapeHtml(title)}</title><style>${css}</style></head>\n`
    + '<body><div id="report"></div>\n'
    + `<script id="report-data" type="application/json">${json}</script>\n`
    + `<script>${js}</script></body></html>\n`;
}

/// Opens file://htmlPath (or an http URL: the page as the server serves it), waits for window.__sdReportReady, takes a full-page screenshot and
/// returns what the page shows: {plots, tables, drawings, errors, problems, requests}.
/// errors: uncaught exceptions and console errors; requests: every URL the page asked for.
export async function checkReport(page, htmlPath, screenshotPath) {
  const errors = [];
  const requests = [];
  const onConsole = (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); };
  const onPageError = (e) => errors.push(`page: ${e.message}`);
  const onRequest = (r) => requests.push(r.url());
  page.on('console', onConsole);
  page.on('pageerror', onPageError);
  page.on('request', onRequest);
  try {
    // Parsing a 5 MB inline script takes seconds on a slow machine.
    const url = /^https?:/.test(htmlPath) ? htmlPath : pathToFileURL(path.resolve(htmlPath)).href;
    await page.goto(url, { timeout: 120000 });
    await page.waitForFunction(() => window.__sdReportReady === true, null, { timeout: 120000 });
    const counts = await page.evaluate(() => ({
      plots: document.querySelectorAll('.js-plotly-plot').length,
      tables: document.querySelectorAll('table.report-table').length,
      drawings: [...document.querySelectorAll('.report-drawing[data-drawn="true"]')].filter((d) => d.querySelector('img, canvas, svg')).length,
      problems: [...document.querySelectorAll('.report-problem')].map((p) => p.textContent),
    }));
    if (screenshotPath) await page.screenshot({ path: screenshotPath, fullPage: true });
    return { ...counts, errors, requests };
  } finally {
    page.off('console', onConsole);
    page.off('pageerror', onPageError);
    page.off('request', onRequest);
  }
}
