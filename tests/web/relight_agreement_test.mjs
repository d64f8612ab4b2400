// Relit lightable tiles against `terrashade tiles --style relief --time T` and `--style color
// --time T` of the same tiles (docs/web-map.md, "Agreement"): for a morning, a noon and a low
// evening sun over the Grenoble crop, and under an overcast sky, every tile of a zoom is relit in
// Node, in grey and in the land's colours, and compared code by code (every channel) with the
// tile terrashade makes.
//   node tests/web/relight_agreement_test.mjs TERRASHADE DEM TMPDIR [ZOOM]
// Prints the differences' percentiles per instant and fails if they exceed the bounds below.
// LIGHT_ARGS and REF_ARGS add options to the lightable and to the relief/color jobs (studies:
// e.g. REF_ARGS="--bounces 0" shows what the bounce adds). WARP_SRS (and WARP_RES, metres)
// reprojects the DEM first with gdalwarp: a projected grid, whose pixels sample the level through
// a non-separable map and whose north is not true north (the polar stereographic EPSG:3413 turns
// it by 50 degrees at Grenoble).
import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import {decodePng} from '../../app/web/png.mjs';
import {readLightableTile, lightFor, relightTile, siteOf} from '../../app/web/relight.mjs';
import {sunPosition} from '../../app/web/sun_position.mjs';

const [binary, source, tmp, zoomText = '11'] = process.argv.slice(2);
if (!tmp) {
  console.error('usage: node tests/web/relight_agreement_test.mjs TERRASHADE DEM TMPDIR [ZOOM]');
  process.exit(2);
}
const zoom = Number(zoomText);
const instants = [['2024-06-21T05:30Z', 'clear'], ['2024-06-21T11:30Z', 'clear'], ['2024-06-21T18:30Z', 'clear'],
                  ['2024-06-21T09:00Z', 'overcast']];
// Bounds in sRGB codes, at the measured values with the default light directions (128) and
// components (6) at zoom 10 under the default (physical) clear sky: p99 5, 1, 4, means up to
// 0.41 (Preetham's sky: 3, 1, 2); the goal is 2. What remains (docs/web-map.md,
// "Agreement"): the compression (9 components and 512 directions give p99 3), shadow rims
// (relief's sun at one azimuth has its own rim error, which horizons stored at other azimuths
// cannot share), and the bounce: the data tiles' transfer bounces off the palette's albedo
// where relief's bounces off grey 0.18, so shadows relight 0.8 codes too bright.
// LIGHT_ARGS="--light-directions 64 ..." passes options to the lightable run (studies).
// BOUNDS (JSON) replaces some of them: the projected case measures a mean of 0.454 at 05:30.
const bounds = {p50: 0, p90: 1, p99: 5, mean: 0.45, ...JSON.parse(process.env.BOUNDS ?? '{}')};

fs.mkdirSync(tmp, {recursive: true});
const work = fs.mkdtempSync(path.join(tmp, 'relight-'));
let failed = false;
let dem = source;
try {
  if (process.env.WARP_SRS) {
    dem = path.join(work, 'warped.tif');
    execFileSync('gdalwarp', ['-q', '-t_srs', process.env.WARP_SRS, '-tr', process.env.WARP_RES ?? '250',
                              process.env.WARP_RES ?? '250', '-r', 'bilinear', source, dem]);
  }
  const run = (args) => execFileSync(binary, args, {stdio: ['ignore', 'ignore', 'inherit']});
  const lightable = path.join(work, 'lightable');
  run(['tiles', dem, '--zoom', `${zoom}`, '--style', 'lightable', ...(process.env.LIGHT_ARGS ? process.env.LIGHT_ARGS.split(' ') : []), '--out', lightable]);
  const meta = JSON.parse(fs.readFileSync(path.join(lightable, 'lightable.json'), 'utf8'));
  const site = siteOf(meta);
  const tiles = [];
  for (const x of fs.readdirSync(path.join(lightable, `${zoom}`)))
    for (const y of fs.readdirSync(path.join(lightable, `${zoom}`, x))) tiles.push(`${zoom}/${x}/${y}`);
  const decoded = new Map();
  for (const t of tiles) decoded.set(t, readLightableTile(await decodePng(fs.readFileSync(path.join(lightable, t)))));
  // Relief's grey, then `color`'s land colours (every channel) from the same data tiles.
  for (const [when, sky, style] of instants.flatMap(([w, s]) => [[w, s, 'relief'], [w, s, 'color']])) {
    const ref_dir = path.join(work, `${style}-${sky}-${when.replace(/:/g, '')}`);
    // The browser lights the sky, and the bounce's sun part, through SH: against relief and color
    // tiles lit the same way (the defaults, the sky over the horizons and the sun's bounce
    // gathered from the terrain's own shadows, differ by what SH misses: docs/web-map.md).
    run(['tiles', dem, '--zoom', `${zoom}`, '--style', style, '--time', when, '--sky', sky, '--sky-light', 'sh', '--bounce-sun', 'sh', ...(process.env.REF_ARGS ? process.env.REF_ARGS.split(' ') : []), '--out', ref_dir]);
    const sun = sunPosition(new Date(when), site);
    const light = lightFor(meta, sun, sky);
    const options = {contrast: meta.relief_contrast, colors: style === 'color' ? meta.colors : null};
    const diffs = [];
    let alpha = 0;
    for (const t of tiles) {
      const tile = decoded.get(t);
      const lit = relightTile(tile, light, new Uint8Array(tile.size * tile.size * 4), options);
      const ref = await decodePng(fs.readFileSync(path.join(ref_dir, t)));
      const ch = ref.channels, colours = style === 'color' ? 3 : 1;
      for (let k = 0; k < tile.size * tile.size; ++k) {
        const a = lit[4 * k + 3] > 0, b = ref.data[ch * k + ch - 1] > 0;
        if (a !== b) { ++alpha; continue; }
        if (a) for (let c = 0; c < colours; ++c) diffs.push(Math.abs(lit[4 * k + c] - ref.data[ch * k + c]));
      }
    }
    diffs.sort((p, q) => p - q);
    const q = (p) => diffs[Math.min(diffs.length - 1, Math.floor(p * diffs.length))];
    const mean = diffs.reduce((s, v) => s + v, 0) / diffs.length;
    const r = {p50: q(0.5), p90: q(0.9), p99: q(0.99), max: diffs[diffs.length - 1], mean: +mean.toFixed(3)};
    console.log(`${when} ${sky} ${style}: sun ${sun.azimuthDeg.toFixed(1)}/${sun.elevationDeg.toFixed(1)} deg, ${diffs.length} ` +
                `values of ${tiles.length} tiles, |relit - ${style}| codes: ${JSON.stringify(r)}, coverage differs at ${alpha}`);
    if (alpha || r.p50 > bounds.p50 || r.p90 > bounds.p90 || r.p99 > bounds.p99 || r.mean > bounds.mean) {
      console.error(`FAIL ${when} ${style}: beyond ${JSON.stringify(bounds)} or coverage differs`);
      failed = true;
    }
  }
} finally {
  fs.rmSync(work, {recursive: true, force: true});
}
process.exit(failed ? 1 : 0);
