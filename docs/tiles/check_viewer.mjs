// The viewer `terrashade tiles` writes beside an XYZ tile set (index.html, tiles.json,
// legend.png), in headless Chromium (Debian's /usr/bin/chromium, driven by playwright-core):
// makes a small insolation tile set with the built terrashade, serves its folder on 127.0.0.1,
// answers the page's requests for MapLibre on the CDN with the same version's files from
// node_modules (so the page's Subresource Integrity is checked against them: a wrong hash and
// MapLibre does not load), aborts any other request off the local server, and checks: tiles
// loaded with no error and show, the legend picture is shown, the attribution is on the map;
// opened from file://, the page says how to serve it. Exit 0 if so, 1 with one line otherwise.
//   node docs/tiles/check_viewer.mjs TERRASHADE DEM [SCREENSHOT.png]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { launchHeadlessChromium } from './headless_chromium.mjs';
import { serve } from './serve.mjs';

const [terrashade, dem, screenshot] = process.argv.slice(2);
const attribution = 'Copernicus DEM © DLR/Airbus';
const scratch = mkdtempSync(join(tmpdir(), 'terrashade-viewer-'));
const tilesDir = join(scratch, 'tiles');
execFileSync(terrashade, ['tiles', dem, '--crop', '5.70,45.15,5.80,45.25', '--style', 'insolation',
                          '--from', '2024-06-20', '--to', '2024-06-21', '--zoom', '10-12',
                          '--attribution', attribution, '--out', tilesDir], { stdio: 'ignore' });
const dist = fileURLToPath(new URL('node_modules/maplibre-gl/dist/', import.meta.url));
const server = await serve(0, tilesDir);
const local = `http://127.0.0.1:${server.address().port}/`;
const profile = join(scratch, 'chromium');
let context;
let failure = null;
try {
  context = await launchHeadlessChromium(profile);
  const page = context.pages()[0] || await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const outside = [];
  let cdn = 0;
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith(local) || url.startsWith('file:')) return route.continue();
    const m = url.match(/^https:\/\/unpkg\.com\/maplibre-gl@[0-9.]+\/dist\/(maplibre-gl\.(js|css))$/);
    if (m) {
      cdn += 1;
      return route.fulfill({
        status: 200,
        headers: { 'content-type': m[2] === 'js' ? 'text/javascript' : 'text/css', 'access-control-allow-origin': '*' },
        body: readFileSync(join(dist, m[1])),
      });
    }
    outside.push(url);
    return route.abort();
  });
  await page.goto(local);
  await page.waitForFunction(() => window.tileStats && (window.tileStats.idle || window.tileStats.problem), null,
                             { timeout: 15000 });
  const seen = await page.evaluate(() => {
    const legend = document.querySelector('#legend img');
    const attrib = document.querySelector('.maplibregl-ctrl-attrib');
    return {
      stats: window.tileStats,
      maplibre: !!window.maplibregl,
      legend: legend && !document.getElementById('legend').hidden && legend.complete ? legend.naturalWidth : 0,
      attribution: attrib ? attrib.textContent : '',
      title: document.title,
    };
  });
  // The tiles' colours on the map's pixels: the inferno ramp is far from the grey paper.
  const coloured = await page.evaluate(() => new Promise((resolve) => {
    const img = new Image();
    img.onload = () => {
      const c = document.createElement('canvas');
      c.width = img.width, c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let k = 0; k < d.length; k += 4) n += Math.abs(d[k] - d[k + 2]) > 40;
      resolve(n / (d.length / 4));
    };
    img.src = document.querySelector('#map canvas').toDataURL('image/png');
  }));
  if (screenshot) await page.screenshot({ path: screenshot });
  // From file://: the page must say how to serve it.
  await page.goto(pathToFileURL(join(tilesDir, 'index.html')).href);
  const fileNotice = await page.evaluate(() => window.tileStats.problem);
  const s = seen.stats;
  console.log(`tiles loaded ${s.loaded}, failed ${s.failed}; coloured ${(100 * coloured).toFixed(1)}% of the view; ` +
              `legend ${seen.legend} px wide; attribution "${seen.attribution}"; MapLibre from the CDN ${cdn} requests`);
  if (errors.length) failure = `page error: ${errors[0]}`;
  else if (outside.length) failure = `the page asked for ${outside[0]}`;
  else if (!seen.maplibre) failure = 'MapLibre did not load (its Subresource Integrity does not match node_modules?)';
  else if (s.problem) failure = `the page says: ${s.problem}`;
  else if (s.failed > 0) failure = `${s.failed} tile errors`;
  else if (s.loaded < 1) failure = 'no tile loaded';
  else if (coloured < 0.1) failure = `the tiles cover only ${(100 * coloured).toFixed(1)}% of the view`;
  else if (seen.legend < 200) failure = 'the legend picture is not shown';
  else if (!seen.attribution.includes(attribution)) failure = `no attribution "${attribution}" on the map`;
  else if (!seen.title.includes('insolation')) failure = `page title "${seen.title}" does not name the tile set`;
  else if (!fileNotice.includes('python3 -m http.server')) failure = 'opened from file://, the page does not say how to serve it';
} catch (e) {
  failure = String(e.message || e).split('\n')[0];
} finally {
  if (context) await context.close();
  server.close();
  rmSync(scratch, { recursive: true, force: true });
}
if (failure) {
  console.log(`FAIL: ${failure}`);
  process.exit(1);
}
console.log('ok');
