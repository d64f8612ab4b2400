#!/usr/bin/env node
// The tiles of one zoom of an XYZ folder in one RGB PNG (transparent pixels light grey), for
// figures: node scripts/mosaic_tiles.mjs DIR ZOOM OUT.png
import fs from 'node:fs';
import {decodePng, encodePng} from '../app/web/png.mjs';

const [dir, zoomText, out] = process.argv.slice(2);
if (!out) {
  console.error('usage: node scripts/mosaic_tiles.mjs DIR ZOOM OUT.png');
  process.exit(2);
}
const z = Number(zoomText), n = 2 ** z;
let size = 0, image = null;
for (let x = 0; x < n; ++x)
  for (let y = 0; y < n; ++y) {
    const file = `${dir}/${z}/${x}/${y}.png`;
    if (!fs.existsSync(file)) continue;
    const t = await decodePng(fs.readFileSync(file));
    if (!image) size = t.width, image = new Uint8Array(3 * (size * n) ** 2).fill(235);
    const w = size * n, ch = t.channels;
    for (let j = 0; j < size; ++j)
      for (let i = 0; i < size; ++i) {
        const k = j * size + i, o = 3 * ((y * size + j) * w + x * size + i);
        if (!t.data[ch * k + ch - 1]) continue;  // alpha 0
        for (let c = 0; c < 3; ++c) image[o + c] = t.data[ch * k + (ch >= 3 ? c : 0)];
      }
  }
if (!image) {
  console.error(`${dir}: no tile of zoom ${z}`);
  process.exit(1);
}
fs.writeFileSync(out, await encodePng(size * n, size * n, 3, image));
