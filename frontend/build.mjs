// Bundles the front end: node build.mjs --outdir DIR
// src/main.js (and the CSS it imports, uPlot's included) -> DIR/main.js + DIR/main.css; index.html copied.
import * as esbuild from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const at = args.indexOf('--outdir');
const outdir = resolve(at >= 0 && args[at + 1] ? args[at + 1] : join(here, '..', 'build', 'web-root'));
const dev = args.includes('--dev');

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
copyFileSync(join(here, 'index.html'), join(outdir, 'index.html'));
console.log(`front end built into ${outdir} in ${Date.now() - started} ms`);
