// The time-of-day page (app/web/map.html) in headless Chromium (Debian's /usr/bin/chromium,
// driven by playwright-core): makes a lightable tile set of the DEM at zooms 9-11 with the built
// terrashade, serves the repository (the page, its modules, MapLibre in docs/tiles/node_modules)
// and the tile set on 127.0.0.1, refuses any other request, opens the page on 16 tiles of zoom 10
// (1024 x 1024) for 21 June 2024 and:
//   (a) at 05:30Z, 11:30Z and 18:30Z compares the page's relit pixels of a fully covered tile with
//       `terrashade tiles --style relief --time T` of that tile (the grey look) and with
//       `--style color --time T` (the land's colours, every channel): p99 of |difference| in codes;
//   (b) moves the time 5 times in the land's colours (the page's default) and prints the median
//       time to relight and draw the visible tiles;
//   (c) with LIGHTABLE_SCREENSHOTS=DIR, saves a screenshot per instant there (in colours);
//   (d) fails on a page error or a request off 127.0.0.1;
// and that the slider does not refetch tiles, a drag ends at its last instant, play runs, the
// second layer draws, the attribution shows, from file:// the page says how to serve it, and the
// page `tiles` writes beside the tile set (its index.html, MapLibre pinned on a CDN) relights it.
// LIGHTABLE_PAGE_QUERY=update=settiles&encode=png adds to the page's query (to time its other ways).
// Exit 0 if all holds, 1 with one line otherwise.
//   node docs/tiles/check_lightable_page.mjs TERRASHADE DEM
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { launchHeadlessChromium } from './headless_chromium.mjs';
import { serve } from './serve.mjs';
import { decodePng } from '../../app/web/png.mjs';

const [terrashade, dem] = process.argv.slice(2);
if (!terrashade || !dem) {
  console.error('usage: node docs/tiles/check_lightable_page.mjs TERRASHADE DEM');
  process.exit(2);
}
const P99_BOUND = 3;            // codes (docs/web-map.md, "Agreement": 2 is the goal; shadow rims)
const ZOOM = 10;                // the tiles' zoom in view: MapLibre's zoom 9 with 256-px tiles
const DATE = '2024-06-21';
const instants = ['05:30', '11:30', '18:30'].map((t) => `${DATE}T${t}:00Z`);
const shots = process.env.LIGHTABLE_SCREENSHOTS;

const repo = fileURLToPath(new URL('../../', import.meta.url));
const scratch = mkdtempSync(join(tmpdir(), 'terrashade-lightable-page-'));
const run = (args) => execFileSync(terrashade, args, { stdio: ['ignore', 'ignore', 'inherit'] });
let repoServer, tilesServer, context;
let failure = null;
try {
  const lightable = join(scratch, 'lightable');
  run(['tiles', dem, '--zoom', '9-11', '--style', 'lightable', '--out', lightable]);
  const meta = JSON.parse(readFileSync(join(lightable, 'tiles.json'), 'utf8'));
  // Two roots on 127.0.0.1: the repository and the tile set (fetched cross-origin by the page).
  repoServer = await serve(0, repo);
  tilesServer = await serve(0, lightable);
  const withCors = (server) => {
    const handlers = server.listeners('request');
    server.removeAllListeners('request');
    server.on('request', (req, res) => { res.setHeader('access-control-allow-origin', '*'); for (const h of handlers) h(req, res); });
  };
  withCors(tilesServer);
  const base = `http://127.0.0.1:${repoServer.address().port}/`;
  const tilesUrl = `http://127.0.0.1:${tilesServer.address().port}/`;

  // The view: the corner of four tiles of zoom 10 near the data's centre, so that 4 x 4 tiles fill it.
  const [w, s, e, n] = meta.bounds;
  const tx = Math.round(((w + e) / 2 + 180) / 360 * 2 ** ZOOM);
  const merc = (lat) => (1 - Math.log(Math.tan(Math.PI / 4 + lat * Math.PI / 360)) / Math.PI) / 2 * 2 ** ZOOM;
  const ty = Math.round(merc((s + n) / 2));
  const lon = tx / 2 ** ZOOM * 360 - 180;
  const lat = Math.atan(Math.sinh(Math.PI * (1 - 2 * ty / 2 ** ZOOM))) * 180 / Math.PI;
  // LIGHTABLE_PAGE_QUERY (e.g. update=settiles&encode=png) adds to the page's query: to compare its ways.
  const extra = process.env.LIGHTABLE_PAGE_QUERY ? `&${process.env.LIGHTABLE_PAGE_QUERY}` : '';
  const url = `${base}app/web/map.html?tiles=${encodeURIComponent(tilesUrl)}&date=${DATE}&look=relief${extra}` +
              `#${ZOOM - 1}/${lat.toFixed(6)}/${lon.toFixed(6)}`;

  context = await launchHeadlessChromium(join(scratch, 'chromium'));
  const page = context.pages()[0] || await context.newPage();
  await page.setViewportSize({ width: 1024, height: 1024 });
  const errors = [];
  page.on('pageerror', (err) => errors.push(err.message));
  const outside = [];
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith('http://127.0.0.1:') || u.startsWith('blob:') || u.startsWith('data:') || u.startsWith('file:')) return route.continue();
    outside.push(u);
    return route.abort();
  });
  let tileFetches = 0;
  page.on('request', (req) => { if (req.url().startsWith(tilesUrl) && req.url().endsWith('.png')) tileFetches += 1; });
  await page.goto(url);
  await page.waitForFunction(() => window.relitStats && (window.relitStats.ready || window.relitStats.problem), null,
                             { timeout: 60000 });
  const first = await page.evaluate(() => window.relitStats);
  if (first.problem) throw new Error(`the page says: ${first.problem}`);
  console.log(`first view: ${first.tilesRelit} tiles (${tileFetches} requests) fetched, decoded and relit in ${first.lastRelightMs} ms`);

  const fetchedFirst = tileFetches;
  if (fetchedFirst < 16) throw new Error(`only ${fetchedFirst} data tiles fetched for a view of 16`);

  // (a) agreement with relief, on a tile inside the view whose pixels are all covered.
  const candidates = [];
  for (const dx of [-1, 0]) for (const dy of [-1, 0]) candidates.push([ZOOM, tx + dx, ty + dy]);
  let chosen = null;
  const p99s = [];
  for (const [look, when] of [...instants.map((w) => ['relief', w]), ...instants.map((w) => ['colors', w])]) {
    if (when === instants[0]) await page.evaluate((l) => window.setLook(l), look);
    const stats = await page.evaluate((iso) => window.setInstant(iso), when);
    if (shots && look === 'colors') {
      mkdirSync(shots, { recursive: true });
      await page.screenshot({ path: join(shots, `lightable-${when.slice(11, 16).replace(':', '')}Z.png`) });
    }
    const style = look === 'colors' ? 'color' : 'relief', colours = look === 'colors' ? 3 : 1;
    const relief = join(scratch, `${style}-${when.slice(11, 16).replace(':', '')}`);
    // The browser lights through SH: against tiles lit the same way (docs/web-map.md, "Agreement").
    run(['tiles', dem, '--zoom', `${ZOOM}`, '--style', style, '--time', when, '--sky-light', 'sh', '--bounce-sun', 'sh', '--out', relief]);
    let got = null;
    for (const c of chosen ? [chosen] : candidates) {
      const r = await page.evaluate(([z, x, y]) => window.relitTile(z, x, y), c);
      if (!r || !existsSync(join(relief, `${c.join('/')}.png`))) continue;
      let covered = true;
      for (let k = 3; k < r.rgba.length; k += 4) if (r.rgba[k] !== 255) { covered = false; break; }
      if (!covered) continue;
      chosen = c, got = r;
      break;
    }
    if (!got) throw new Error(`no fully covered tile among ${candidates.map((c) => c.join('/')).join(', ')} was relit`);
    if (got.instant !== new Date(when).toISOString()) throw new Error(`tile ${chosen.join('/')} is lit for ${got.instant}, not ${when}`);
    const ref = await decodePng(readFileSync(join(relief, `${chosen.join('/')}.png`)));
    const diffs = [];
    let alpha = 0;
    for (let k = 0; k < ref.width * ref.height; ++k) {
      const a = got.rgba[4 * k + 3] > 0, b = ref.data[ref.channels * k + ref.channels - 1] > 0;
      if (a !== b) { ++alpha; continue; }
      if (a) for (let c = 0; c < colours; ++c) diffs.push(Math.abs(got.rgba[4 * k + c] - ref.data[ref.channels * k + c]));
    }
    diffs.sort((p, q) => p - q);
    const q = (p) => diffs[Math.min(diffs.length - 1, Math.floor(p * diffs.length))];
    p99s.push(`${look} ${q(0.99)}`);
    if (got.look !== look) throw new Error(`tile ${chosen.join('/')} is drawn in ${got.look}, not ${look}`);
    console.log(`${when} ${look}: tile ${chosen.join('/')}, ${diffs.length} values, |page - ${style}| codes p50 ${q(0.5)} ` +
                `p90 ${q(0.9)} p99 ${q(0.99)} max ${diffs[diffs.length - 1]}; coverage differs at ${alpha}; ` +
                `${stats.tilesRelit} tiles relit in ${stats.lastRelightMs} ms`);
    if (alpha) throw new Error(`${when}: coverage differs from ${style} at ${alpha} pixels`);
    if (q(0.99) > P99_BOUND) throw new Error(`${when}: p99 ${q(0.99)} codes > ${P99_BOUND}`);
  }

  // (b) the time slider moved 5 times: relight and draw every visible tile.
  const times = [];
  const counts = [], compute = [];
  for (let i = 0; i < 5; ++i) {
    const r = await page.evaluate((v) => {
      const slider = document.getElementById('time');
      slider.value = String(v);
      const done = new Promise((resolve) => {
        const poll = () => (window.relitStats.ready ? resolve(window.relitStats) : setTimeout(poll, 5));
        setTimeout(poll, 0);
      });
      slider.dispatchEvent(new Event('input'));
      return done;
    }, 420 + 120 * i);
    times.push(r.lastRelightMs);
    counts.push(r.tilesRelit);
    compute.push(r.relightComputeMs);
  }
  const sorted = [...times].sort((p, q) => p - q);
  console.log(`slider moved 5 times: ${counts.join(', ')} tiles relit; ${times.map((t) => t.toFixed(0)).join(', ')} ms; ` +
              `median ${sorted[2].toFixed(0)} ms to relight and draw the view ` +
              `(of which in relightTile: ${compute.map((t) => t.toFixed(0)).join(', ')} ms)`);
  // A dragged slider: many changes at once end drawn at the last one.
  const dragged = await page.evaluate(async (probe) => {
    const passesBefore = window.relitStats.changes;
    const slider = document.getElementById('time');
    let last;
    for (let v = 600; v <= 700; v += 5) {
      slider.value = String(v);
      last = new Promise((resolve) => {
        const poll = () => (window.relitStats.ready ? resolve() : setTimeout(poll, 5));
        setTimeout(poll, 0);
      });
      slider.dispatchEvent(new Event('input'));
    }
    await last;
    return {instant: window.relitTile(...probe).instant, passes: window.relitStats.changes - passesBefore};
  }, chosen);
  console.log(`slider dragged over 21 steps: drawn at ${dragged.instant} in ${dragged.passes} relight passes`);
  if (dragged.instant !== `${DATE}T11:40:00.000Z`) throw new Error(`after a drag to 11:40 the tile is lit for ${dragged.instant}`);
  // The other sky, and play for a moment.
  const overcast = await page.evaluate(() => window.setSky('overcast'));
  const played = await page.evaluate(async () => {
    const slider = document.getElementById('time'), before = +slider.value, play = document.getElementById('play');
    play.click();
    await new Promise((r) => setTimeout(r, 1500));
    play.click();
    await new Promise((r) => setTimeout(r, 500));
    return (+slider.value - before + 1440) % 1440;
  });
  console.log(`overcast sky: ${overcast.tilesRelit} tiles relit in ${overcast.lastRelightMs} ms; ` +
              `play moved the time ${played} minutes in 1.5 s`);
  if (played < 10) throw new Error(`play moved the time only ${played} minutes in 1.5 s`);
  if (tileFetches !== fetchedFirst) throw new Error(`changing the instant fetched ${tileFetches - fetchedFirst} tiles again`);
  // The second layer.
  const t0 = Date.now();
  await page.evaluate(() => { const b = document.getElementById('hours'); b.checked = true; b.dispatchEvent(new Event('change')); });
  await page.waitForFunction(() => window.map.getSource('sunhours').loaded() && window.map.loaded(), null, { timeout: 60000 });
  console.log(`hours of direct sun: the view's tiles computed and drawn in ${Date.now() - t0} ms`);
  if (shots) await page.screenshot({ path: join(shots, 'lightable-sunhours.png') });
  const problemBefore = await page.evaluate(() => window.relitStats.problem);
  const attribution = await page.evaluate(() => document.querySelector('.maplibregl-ctrl-attrib')?.textContent || '');
  const pageErrors = errors.length;
  // The page `tiles` wrote beside the tiles (index.html and the modules, embedded in terrashade):
  // MapLibre from its pinned CDN URLs, answered with docs/tiles/node_modules' bytes so that the
  // page's integrity hashes are checked against that version; everything else from the folder.
  const dist = join(repo, 'docs/tiles/node_modules/maplibre-gl/dist');
  let cdn = 0;
  await page.unroute('**/*');
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith('http://127.0.0.1:') || u.startsWith('blob:') || u.startsWith('data:') || u.startsWith('file:')) return route.continue();
    const m = u.match(/^https:\/\/unpkg\.com\/maplibre-gl@[0-9.]+\/dist\/(maplibre-gl\.(js|css))$/);
    if (m) {
      cdn += 1;
      return route.fulfill({ status: 200, body: readFileSync(join(dist, m[1])),
        headers: { 'content-type': m[2] === 'js' ? 'text/javascript' : 'text/css', 'access-control-allow-origin': '*' } });
    }
    outside.push(u);
    return route.abort();
  });
  await page.goto(`${tilesUrl}index.html?date=${DATE}&time=11:30#${ZOOM - 1}/${lat.toFixed(6)}/${lon.toFixed(6)}`);
  await page.waitForFunction(() => window.relitStats && (window.relitStats.ready || window.relitStats.problem), null,
                             { timeout: 60000 });
  const generated = await page.evaluate(() => window.relitStats);
  const genTile = await page.evaluate(([z, x, y]) => window.relitTile(z, x, y), chosen);
  let genSame = 0;
  if (genTile) {
    // Its default look: the land's colours.
    const ref = await decodePng(readFileSync(join(scratch, 'color-1130', `${chosen.join('/')}.png`)));
    for (let k = 0; k < ref.width * ref.height; ++k) {
      let same = true;
      for (let c = 0; c < 3; ++c) same &&= Math.abs(genTile.rgba[4 * k + c] - ref.data[ref.channels * k + c]) <= P99_BOUND;
      genSame += same;
    }
  }
  console.log(`the page written beside the tiles: ${generated.tilesRelit} tiles relit at 11:30 (MapLibre from its CDN URLs: ` +
              `${cdn} files), tile ${chosen.join('/')} within ${P99_BOUND} codes of color at ${genSame} of 65536 pixels`);
  if (generated.problem) throw new Error(`the written page says: ${generated.problem}`);
  if (cdn < 2 || genSame < 0.99 * 65536) throw new Error('the page written beside the tiles does not show them relit as color');
  // From file://, the page must say how to serve it.
  await page.goto(pathToFileURL(join(repo, 'app/web/map.html')).href);
  const fileNotice = await page.evaluate(() => window.relitStats?.problem || '');
  console.log(`p99 per instant: ${p99s.join(', ')} codes; attribution "${attribution}"`);
  if (pageErrors) failure = `page error: ${errors[0]}`;
  else if (problemBefore) failure = `the page says: ${problemBefore}`;
  else if (outside.length) failure = `the page asked for ${outside[0]} (off 127.0.0.1)`;
  else if (meta.attribution && !attribution.includes(meta.attribution)) failure = `no attribution "${meta.attribution}" on the map`;
  else if (!fileNotice.includes('serve')) failure = 'opened from file://, the page does not say how to serve it';
} catch (err) {
  failure = String(err.message || err).split('\n')[0];
} finally {
  if (context) await context.close();
  repoServer?.close();
  tilesServer?.close();
  rmSync(scratch, { recursive: true, force: true });
}
if (failure) {
  console.log(`FAIL: ${failure}`);
  process.exit(1);
}
console.log('ok');
