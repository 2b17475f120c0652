// Bundles the front end: node build.mjs --outdir DIR
// src/main.js (and the CSS it imports, uPlot's included) -> DIR/main.js + DIR/main.css; index.html copied;
// favicon.svg and favicon.ico drawn (favicon.mjs).
// src/report/report_main.js -> DIR/report.js + DIR/report.css: a classic script (iife) that
// `swarmdesign report` inlines into the offline report.html.
import * as esbuild from 'esbuild';
import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { writeFavicons } from './favicon.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const at = args.indexOf('--outdir');
const outdir = resolve(at >= 0 && args[at + 1] ? args[at + 1] : join(here, '..', 'build', 'web-root'));
const dev = args.includes('--dev');

/// report.js ends up inside <script>...</script>: esbuild already escapes "</script"; "<!--" (in
/// Plotly's HTML regexps) could still switch the HTML parser into its escaped state, so it
/// becomes "\x3C!--", the same text inside the string and regexp literals where it occurs.
function makeInlineSafe(file) {
  const code = readFileSync(file, 'utf8');
  if (/<\/script/i.test(code)) throw new Error(`${file} contains "</script" and cannot be inlined`);
  writeFileSync(file, code.replaceAll('<!--', '\\x3C!--'));
}

mkdirSync(outdir, { recursive: true });
const started = Date.now();
await esbuild.build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  format: 'esm',
  target: ['chrome100', 'firefox100', 'safari15'],
  minify: !dev,
  sourcemap: dev ? 'inline' : false,
  outdir,
  logLevel: 'warning',
  legalComments: 'linked',
});
// Inlined in a <script> without type=module, opened from file://: one self-contained classic script.
await esbuild.build({
  entryPoints: { report: join(here, 'src', 'report', 'report_main.js') },
  bundle: true,
  format: 'iife',
  target: ['chrome100', 'firefox100', 'safari15'],
  minify: true,
  sourcemap: false,
  outdir,
  logLevel: 'warning',
  legalComments: 'inline',
});
makeInlineSafe(join(outdir, 'report.js'));
copyFileSync(join(here, 'index.html'), join(outdir, 'index.html'));
writeFavicons(outdir);
console.log(`front end built into ${outdir} in ${Date.now() - started} ms`);
