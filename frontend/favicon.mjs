// The web app's icon, written by build.mjs: favicon.svg (linked by index.html) and favicon.ico
// (asked for by browsers that do not read the link), both the same drawing: three robots, the
// middle one lit, on the arena's grey.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';

const ROBOTS = [[0.3, 0.62, '#9aa3ad'], [0.5, 0.36, '#2563eb'], [0.7, 0.62, '#9aa3ad']];
const RADIUS = 0.16;

export const FAVICON_SVG = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1 1">
<rect width="1" height="1" rx="0.18" fill="#1d2430"/>
${ROBOTS.map(([x, y, c]) => `<circle cx="${x}" cy="${y}" r="${RADIUS}" fill="${c}" stroke="#ffffff" stroke-width="0.04"/>`).join('\n')}
</svg>
`;

const hex = (c) => [1, 3, 5].map((i) => parseInt(c.slice(i, i + 2), 16));

/// RGBA of the drawing at (u, v) in [0, 1]².
function pixel(u, v) {
  for (const [x, y, c] of ROBOTS) {
    const d = Math.hypot(u - x, v - y);
    if (d <= RADIUS - 0.02) return [...hex(c), 255];
    if (d <= RADIUS + 0.02) return [255, 255, 255, 255];
  }
  return [0x1d, 0x24, 0x30, 255];
}

/// A 32×32 32-bit ICO (BMP payload: bottom-up BGRA rows, then an all-zero AND mask).
export function faviconIco(size = 32) {
  const pixels = size * size * 4;
  const mask = ((size + 31) >> 5) * 4 * size;
  const bmp = Buffer.alloc(40 + pixels + mask);
  bmp.writeUInt32LE(40, 0);
  bmp.writeInt32LE(size, 4);
  bmp.writeInt32LE(size * 2, 8);  // XOR and AND halves
  bmp.writeUInt16LE(1, 12);
  bmp.writeUInt16LE(32, 14);
  bmp.writeUInt32LE(pixels + mask, 20);
  for (let row = 0; row < size; row++) {
    for (let col = 0; col < size; col++) {
      const [r, g, b, a] = pixel((col + 0.5) / size, 1 - (row + 0.5) / size);
      bmp.set([b, g, r, a], 40 + (row * size + col) * 4);
    }
  }
  const header = Buffer.alloc(22);
  header.writeUInt16LE(0, 0);
  header.writeUInt16LE(1, 2);  // icon
  header.writeUInt16LE(1, 4);  // one image
  header.writeUInt8(size, 6);
  header.writeUInt8(size, 7);
  header.writeUInt16LE(1, 10);
  header.writeUInt16LE(32, 12);
  header.writeUInt32LE(bmp.length, 14);
  header.writeUInt32LE(22, 18);
  return Buffer.concat([header, bmp]);
}

export function writeFavicons(outdir) {
  writeFileSync(join(outdir, 'favicon.svg'), FAVICON_SVG);
  writeFileSync(join(outdir, 'favicon.ico'), faviconIco());
}
