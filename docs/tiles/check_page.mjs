// Opens index.html in headless Chromium (Debian's /usr/bin/chromium, driven by playwright-core)
// and checks that the relief tiles loaded and show: at least MIN_TILES tile loads and no tile
// error, and on the map's own pixels most of the view is relief (not the paper background)
// with the grey spread of shaded terrain. Exit 0 if so, 1 with one line otherwise.
//   node docs/tiles/check_page.mjs [SCREENSHOT.png]
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { launchHeadlessChromium } from './headless_chromium.mjs';
import { serve } from './serve.mjs';

const MIN_TILES = 4;
const screenshot = process.argv[2];
const server = await serve(0);
const profile = mkdtempSync(join(tmpdir(), 'terrashade-chromium-'));
let context;
let failure = null;
try {
  context = await launchHeadlessChromium(profile);
  const page = context.pages()[0] || await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // Nothing but the local server: a request elsewhere means the page needs the internet.
  const outside = [];
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith(`http://127.0.0.1:${server.address().port}/`)) return route.continue();
    outside.push(url);
    return route.abort();
  });
  await page.goto(`http://127.0.0.1:${server.address().port}/index.html`);
  await page.waitForFunction(() => window.tileStats && window.tileStats.idle, null, { timeout: 90000 });
  const stats = await page.evaluate(() => window.tileStats);
  // The map's pixels, through a 2D canvas.
  const pixels = await page.evaluate(() => new Promise((resolve) => {
    const gl = document.querySelector('#map canvas');
    const img = new Image();
    img.onload = () => {
      const c = document.createElement('canvas');
      c.width = img.width, c.height = img.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const d = ctx.getImageData(0, 0, c.width, c.height).data;
      let relief = 0, sum = 0, sum2 = 0;
      const n = d.length / 4;
      for (let k = 0; k < d.length; k += 4) {
        const paper = Math.abs(d[k] - 0xf4) + Math.abs(d[k + 1] - 0xf1) + Math.abs(d[k + 2] - 0xea) < 6;
        if (paper) continue;
        relief += 1;
        sum += d[k], sum2 += d[k] * d[k];
      }
      const mean = relief ? sum / relief : 0;
      resolve({ share: relief / n, mean, sd: relief ? Math.sqrt(sum2 / relief - mean * mean) : 0 });
    };
    img.src = gl.toDataURL('image/png');
  }));
  if (screenshot) await page.screenshot({ path: screenshot });
  console.log(`tiles loaded ${stats.loaded}, failed ${stats.failed}; relief on ${(100 * pixels.share).toFixed(1)}% ` +
              `of the view, grey mean ${pixels.mean.toFixed(1)} sd ${pixels.sd.toFixed(1)}`);
  if (errors.length) failure = `page error: ${errors[0]}`;
  else if (outside.length) failure = `the page asked for ${outside[0]} (it must work offline)`;
  else if (stats.failed > 0) failure = `${stats.failed} tile errors`;
  else if (stats.loaded < MIN_TILES) failure = `only ${stats.loaded} tiles loaded (expected at least ${MIN_TILES})`;
  else if (pixels.share < 0.5) failure = `relief covers only ${(100 * pixels.share).toFixed(1)}% of the view`;
  else if (pixels.sd < 10) failure = `the relief is nearly flat grey (sd ${pixels.sd.toFixed(1)}): tiles not drawn?`;
} catch (e) {
  failure = String(e.message || e).split('\n')[0];
} finally {
  if (context) await context.close();
  server.close();
  rmSync(profile, { recursive: true, force: true });
}
if (failure) {
  console.error(`check_page: ${failure}`);
  process.exit(1);
}
