#!/usr/bin/env node
// One lightable tile relit for an instant, as a grey + alpha PNG (relief's look), or with
// --colors as an RGBA PNG of the land's colours (`color`'s look) (docs/web-map.md):
//   node scripts/relight_tile.mjs TILESET Z/X/Y TIME OUT.png [--sky clear|overcast] [--colors]
// TILESET: an XYZ folder or an MBTiles file of `terrashade tiles --style lightable`; TIME: ISO
// 8601 with a zone (2024-06-21T17:00Z). The sun is placed where `tiles --time` places it: the
// DEM's centre (lightable.json's site).
import fs from 'node:fs';
import path from 'node:path';
import {decodePng, encodePng} from '../app/web/png.mjs';
import {readTile, readJsonBeside} from '../app/web/tileset.mjs';
import {readLightableTile, lightFor, relightTile, siteOf} from '../app/web/relight.mjs';
import {sunPosition} from '../app/web/sun_position.mjs';

function fail(message) {
  console.error(`relight_tile: ${message}`);
  process.exit(2);
}

const args = process.argv.slice(2);
let sky;
const skyAt = args.indexOf('--sky');
if (skyAt >= 0) [, sky] = args.splice(skyAt, 2);
const colorsAt = args.indexOf('--colors');
const colors = colorsAt >= 0;
if (colors) args.splice(colorsAt, 1);
if (args.length !== 4) fail('usage: node scripts/relight_tile.mjs TILESET Z/X/Y TIME OUT.png [--sky clear|overcast] [--colors]');
const [tileset, zxy, timeText, out] = args;
const m = /^(\d+)\/(\d+)\/(\d+)$/.exec(zxy);
if (!m) fail(`${zxy}: give the tile as Z/X/Y`);
if (!/(Z|[+-]\d\d:?\d\d)$/.test(timeText) || Number.isNaN(Date.parse(timeText)))
  fail(`${timeText}: give an ISO 8601 time with a zone, e.g. 2024-06-21T17:00Z`);
if (!fs.existsSync(tileset)) fail(`${tileset}: no such tile set`);
if (path.resolve(out) === path.resolve(tileset)) fail(`${out}: would overwrite the tile set`);

try {
  const meta = await readJsonBeside(tileset, fs.statSync(tileset).isDirectory() ? 'lightable.json' : 'terrashade_lightable');
  if (!meta || meta.format !== 'terrashade-lightable') fail(`${tileset}: not a lightable tile set (no lightable.json)`);
  const bytes = await readTile(tileset, +m[1], +m[2], +m[3]);
  if (!bytes) fail(`${tileset}: no tile ${zxy}`);
  const tile = readLightableTile(await decodePng(bytes));
  const sun = sunPosition(new Date(timeText), siteOf(meta));
  const rgba = relightTile(tile, lightFor(meta, sun, sky ?? meta.sky), new Uint8Array(tile.size * tile.size * 4),
                           {contrast: meta.relief_contrast, flatGrey: meta.flat_grey, colors: colors ? meta.colors : null});
  const pixels = tile.size * tile.size;
  let png;
  if (colors) {
    png = await encodePng(tile.size, tile.size, 4, rgba);
  } else {
    const ga = new Uint8Array(pixels * 2);
    for (let k = 0; k < pixels; ++k) ga[2 * k] = rgba[4 * k], ga[2 * k + 1] = rgba[4 * k + 3];
    png = await encodePng(tile.size, tile.size, 2, ga);
  }
  // Whole or nothing: a temporary file renamed into place.
  const tmp = `${out}.tmp-${process.pid}`;
  fs.writeFileSync(tmp, png);
  fs.renameSync(tmp, out);
  console.log(`${out}: ${zxy} at ${timeText}, sun azimuth ${sun.azimuthDeg.toFixed(2)} deg, elevation ${sun.elevationDeg.toFixed(2)} deg`);
} catch (e) {
  fail(e.message);
}
