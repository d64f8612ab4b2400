// The time-of-day map (map.html): a lightable tile set (`terrashade tiles --style lightable`,
// docs/web-map.md) relit in the browser with MapLibre GL JS. Each data tile is fetched and decoded
// once (cached by z/x/y); moving the time slider only relights the cached tiles for the new sun.
// Plain ES module, no build step.
//
// Query: ?tiles=URL_OF_FOLDER/ (default ./)  ?date=YYYY-MM-DD (default today)  ?time=HH:MM (UTC)
//        ?sky=clear|overcast  ?look=colors|relief (the land's colours, default, or grey relief)
//        ?maplibre=URL_PREFIX of maplibre-gl's dist/
//        ?update=refresh|settiles (how a change reaches MapLibre; default refresh, the faster)
//        ?encode=bitmap|png (what the protocol returns; default bitmap, the faster)
//        ?workers=N (module workers sharing the tile work; default 0: all on the page's thread)
// The view is in the URL's hash (#zoom/lat/lon), else tiles.json's centre.
// For tests: window.relitStats, window.setInstant(iso), window.setSky(s), window.setLook(l),
// window.relitTile(z, x, y).
import {encodePng} from './png.mjs';
import {readJsonBeside} from './tileset.mjs';
import {lightFor, siteOf} from './relight.mjs';
import {sunPosition} from './sun_position.mjs';
import {makeEngine} from './relight_worker.mjs';

const query = new URLSearchParams(location.search);
const $ = (id) => document.getElementById(id);
const problem = (text) => { $('problem').textContent = text; window.relitStats.problem = text; };

// lastRelightMs: from a change until MapLibre is idle with every visible tile relit and drawn;
// relightComputeMs: the time spent in relightTile (summed over the workers, which run at once).
window.relitStats = {lastRelightMs: null, tilesRelit: 0, relightComputeMs: 0, ready: false, changes: 0, problem: null};

// The tile set's folder, absolute, without the trailing slash tileset.mjs adds itself.
const tileset = new URL(query.get('tiles') || './', location.href).href.replace(/\/+$/, '');
let mlPrefix = new URL(query.get('maplibre') || '../../docs/tiles/node_modules/maplibre-gl/dist/', location.href).href;
if (!mlPrefix.endsWith('/')) mlPrefix += '/';
const updateMode = query.get('update') === 'settiles' ? 'settiles' : 'refresh';
const encodeMode = query.get('encode') === 'png' ? 'png' : 'bitmap';
// Measured on 2 cores under SwiftShader (docs/tiles/check_lightable_page.mjs), the page's own thread
// relit 16 tiles fastest: workers compete with the renderer. More cores are not measured yet.
const workerCount = query.has('workers') ? Math.max(0, Math.min(16, +query.get('workers') || 0)) : 0;

// The tile work on this thread (n = 0) or spread over n workers by the tile's z/x/y.
function makeWork(n, tileset, meta) {
  if (n === 0) return makeEngine(tileset, meta);
  const workers = [], waiting = new Map();
  let next = 0;
  for (let i = 0; i < n; ++i) {
    const w = new Worker(new URL('./relight_worker.mjs', import.meta.url), {type: 'module'});
    w.onmessage = ({data}) => {
      const p = waiting.get(data.id);
      waiting.delete(data.id);
      if (data.error) p.reject(new Error(data.error));
      else p.resolve(data.result);
    };
    w.onerror = (e) => problem(`tile worker: ${e.message || 'failed to start'}`);
    w.postMessage({type: 'init', tileset, meta});
    workers.push(w);
  }
  const call = (message) => new Promise((resolve, reject) => {
    const id = ++next;
    waiting.set(id, {resolve, reject});
    const {z, x, y} = message;
    workers[(((x * 73856093) ^ (y * 19349663) ^ (z * 83492791)) >>> 0) % n].postMessage({...message, id});
  });
  return {
    relight: (z, x, y, light, look) => call({type: 'relight', z, x, y, light, look}),
    hours: (z, x, y, date) => call({type: 'hours', z, x, y, date}),
  };
}

// ---- the instant ------------------------------------------------------------------------------

const pad = (n) => String(n).padStart(2, '0');
const hhmm = (minutes) => {
  const m = ((Math.round(minutes) % 1440) + 1440) % 1440;
  return `${pad(Math.floor(m / 60))}:${pad(m % 60)}`;
};
const today = () => new Date().toISOString().slice(0, 10);

const state = {
  date: /^\d{4}-\d\d-\d\d$/.test(query.get('date') || '') ? query.get('date') : today(),
  minutes: 720,              // UTC minutes of the day; may be off the slider's 5-minute steps
  sky: query.get('sky') === 'overcast' ? 'overcast' : 'clear',
  look: query.get('look') === 'relief' ? 'relief' : 'colors',
  instantMs: 0, sun: null, light: null,
};
{
  const t = /^(\d\d):(\d\d)$/.exec(query.get('time') || '');
  if (t) state.minutes = 60 * +t[1] + +t[2];
}

// The equation of time in minutes (apparent minus mean solar time; a few seconds' accuracy).
function equationOfTimeMinutes(ms) {
  const d = (ms / 86400000) + 2440587.5 - 2451545.0;
  const g = (357.529 + 0.98560028 * d) * Math.PI / 180;
  const q = 280.459 + 0.98564736 * d;
  const l = (q + 1.915 * Math.sin(g) + 0.020 * Math.sin(2 * g)) * Math.PI / 180;
  const e = (23.439 - 0.00000036 * d) * Math.PI / 180;
  const ra = Math.atan2(Math.cos(e) * Math.sin(l), Math.cos(l)) * 180 / Math.PI;
  let eot = (q - ra) % 360;
  if (eot > 180) eot -= 360;
  if (eot < -180) eot += 360;
  return 4 * eot;
}

// ---- start ------------------------------------------------------------------------------------

// A page terrashade writes beside a tile set pins MapLibre on a CDN with Subresource Integrity
// (window.TERRASHADE_MAPLIBRE = {js, jsIntegrity, css, cssIntegrity}); the repository's page takes
// ?maplibre= or docs/tiles/node_modules.
const pinned = window.TERRASHADE_MAPLIBRE;

function loadScript(src, integrity) {
  return new Promise((resolve, reject) => {
    const s = document.createElement('script');
    s.src = src;
    if (integrity) s.integrity = integrity, s.crossOrigin = 'anonymous';
    s.onload = resolve;
    s.onerror = () => reject(new Error(`could not load MapLibre from ${src} (give ?maplibre=URL_PREFIX of maplibre-gl/dist/)`));
    document.head.appendChild(s);
  });
}

async function start() {
  if (location.protocol === 'file:') return;    // map.html says how to serve it
  const css = document.createElement('link');
  css.rel = 'stylesheet';
  css.href = pinned ? pinned.css : mlPrefix + 'maplibre-gl.css';
  if (pinned) css.integrity = pinned.cssIntegrity, css.crossOrigin = 'anonymous';
  document.head.appendChild(css);
  const [, tilejson, meta] = await Promise.all([
    pinned ? loadScript(pinned.js, pinned.jsIntegrity) : loadScript(mlPrefix + 'maplibre-gl.js'),
    readJsonBeside(tileset, 'tiles.json'),
    readJsonBeside(tileset, 'lightable.json'),
  ]);
  if (!meta || meta.format !== 'terrashade-lightable')
    throw new Error(`${tileset}/ is not a lightable tile set (no lightable.json): make one with terrashade tiles DEM --style lightable`);
  if (!meta.skies[state.sky]) state.sky = meta.sky;
  if (!meta.colors) state.look = 'relief';
  const site = siteOf(meta);
  const sunAt = (date) => sunPosition(date, site);
  const opts = {contrast: meta.relief_contrast, flatGrey: meta.flat_grey ?? 0.5};
  const tj = tilejson || {};
  if (tj.name) $('title').textContent = `${tj.name} by time of day`;
  document.title = `terrashade: ${tj.name || 'lightable tiles'} by time of day`;

  // The tile work (relight_worker.mjs): in `workers` module workers, each keeping the tiles whose
  // z/x/y hash to it, or on this thread with ?workers=0.
  const engine = makeWork(workerCount, tileset, meta);
  const parse = (url) => {
    const m = /^\w+:\/\/(\d+)\/(\d+)\/(\d+)/.exec(url);
    if (!m) throw new Error(`bad tile URL ${url}`);
    return {z: +m[1], x: +m[2], y: +m[3], key: `${m[1]}/${m[2]}/${m[3]}`};
  };
  const toImage = async (rgba, size) => encodeMode === 'png'
    ? {data: (await encodePng(size, size, 4, new Uint8Array(rgba.buffer))).buffer}
    : {data: await createImageBitmap(new ImageData(rgba, size, size))};
  const blank = () => toImage(new Uint8ClampedArray(4 * 256 * 256), 256);

  // relit://z/x/y: the data tile lit for the current instant and sky.
  const lastRelit = new Map();         // z/x/y -> {rgba, instantMs, sky, look}
  let relitThisChange = 0, relightMsThisChange = 0;   // tiles relit since the change, ms in relightTile
  maplibregl.addProtocol('relit', async (params) => {
    const {z, x, y, key} = parse(params.url);
    const {light, instantMs, sky, look} = state;
    const r = await engine.relight(z, x, y, light, look);
    if (!r) return blank();
    relightMsThisChange += r.ms;
    lastRelit.set(key, {rgba: r.rgba, instantMs, sky, look});
    if (lastRelit.size > 400) lastRelit.delete(lastRelit.keys().next().value);
    relitThisChange += 1;
    return toImage(r.rgba, r.size);
  });

  // sunhours://z/x/y?d=DATE: hours of direct sun on the day, a colour ramp at alpha 0.6.
  const RAMP = [[0, [48, 18, 59]], [0.25, [50, 136, 189]], [0.5, [102, 194, 165]], [0.75, [254, 224, 139]], [1, [215, 48, 39]]];
  const rampAt = (t) => {
    t = Math.min(1, Math.max(0, t));
    let i = 0;
    while (i < RAMP.length - 2 && t > RAMP[i + 1][0]) ++i;
    const [t0, a] = RAMP[i], [t1, b] = RAMP[i + 1], f = (t - t0) / (t1 - t0);
    return a.map((v, k) => Math.round(v + f * (b[k] - v)));
  };
  const dayHours = (date) => {     // flat open ground's hours of sun on the UTC day: the ramp's top
    const day = Date.parse(`${date}T00:00Z`);
    let h = 0;
    for (let m = 5; m < 1440; m += 10) if (sunAt(new Date(day + m * 60000)).elevationDeg > 0) h += 10 / 60;
    return Math.max(1, Math.ceil(h));
  };
  maplibregl.addProtocol('sunhours', async (params) => {
    const {z, x, y, key} = parse(params.url);
    const date = /[?&]d=(\d{4}-\d\d-\d\d)/.exec(params.url)?.[1] || state.date;
    const r = await engine.hours(z, x, y, date);
    if (!r) return blank();
    const {hours, size} = r;
    const top = dayHours(date);
    const rgba = new Uint8ClampedArray(size * size * 4);
    for (let k = 0; k < hours.length; ++k) {
      if (Number.isNaN(hours[k])) continue;
      const c = rampAt(hours[k] / top);
      rgba[4 * k] = c[0], rgba[4 * k + 1] = c[1], rgba[4 * k + 2] = c[2], rgba[4 * k + 3] = 153;   // alpha 0.6
    }
    return toImage(rgba, size);
  });

  // ---- the map --------------------------------------------------------------------------------
  const [lon, lat, z] = tj.center || [meta.site.longitude_deg, meta.site.latitude_deg, 10];
  const sourceBase = {type: 'raster', tileSize: 256, minzoom: tj.minzoom ?? 0, maxzoom: tj.maxzoom ?? 22,
                      bounds: tj.bounds, attribution: tj.attribution || ''};
  const map = new maplibregl.Map({
    container: 'map',
    hash: true,
    center: [lon, lat],
    zoom: z - 1,                    // tiles.json counts 256-px tiles, MapLibre's zoom 512-px ones
    attributionControl: {compact: false},
    style: {
      version: 8,
      sources: {
        relit: {...sourceBase, tiles: ['relit://{z}/{x}/{y}']},
        sunhours: {...sourceBase, tiles: [`sunhours://{z}/{x}/{y}?d=${state.date}`]},
      },
      layers: [
        {id: 'paper', type: 'background', paint: {'background-color': '#f4f1ea'}},
        {id: 'relit', type: 'raster', source: 'relit', paint: {'raster-fade-duration': 0}},
        {id: 'sunhours', type: 'raster', source: 'sunhours', layout: {visibility: 'none'},
         paint: {'raster-fade-duration': 0}},
      ],
    },
  });
  map.addControl(new maplibregl.NavigationControl(), 'top-right');
  map.addControl(new maplibregl.ScaleControl(), 'bottom-left');
  window.map = map;

  // ---- controls -------------------------------------------------------------------------------
  const dateInput = $('date'), slider = $('time'), skySelect = $('sky'), lookSelect = $('look'), hoursBox = $('hours');
  dateInput.value = state.date;
  skySelect.value = state.sky;
  lookSelect.value = state.look;
  lookSelect.disabled = !meta.colors;
  // The colours' legend: the palette's stops (metres, sRGB) over their height range.
  if (meta.colors) {
    const stops = meta.colors.stops, lo = stops[0][0], hi = stops[stops.length - 1][0];
    const at = (v) => (hi > lo ? (100 * (v - lo) / (hi - lo)).toFixed(1) : 0);
    $('colors-ramp').style.background =
      `linear-gradient(to right, ${stops.map(([v, r, g, b]) => `rgb(${r}, ${g}, ${b}) ${at(v)}%`).join(', ')})`;
    $('colors-labels').innerHTML = '';
    // One stop (e.g. `grey`): one colour at every height.
    for (const text of hi > lo ? [lo, (lo + hi) / 2, hi].map((v) => `${Math.round(v)} m`) : ['every height']) {
      const span = document.createElement('span');
      span.textContent = text;
      $('colors-labels').appendChild(span);
    }
    $('colors-title').textContent = `land colour by height (${meta.colors.name || 'palette'})` +
      (meta.colors.snow_line_m != null ? `, snow above ${Math.round(meta.colors.snow_line_m)} m` : '') +
      ', shaded by sun and sky';
  }
  const showLook = () => {
    $('relief-legend').hidden = state.look !== 'relief';
    $('colors-legend').hidden = state.look !== 'colors';
  };
  showLook();
  const flatCode = 255 * (1.055 * Math.pow(opts.flatGrey, 1 / 2.4) - 0.055);
  $('flat-mark').style.left = `${(100 * flatCode / 255).toFixed(1)}%`;
  $('flat-label').style.marginLeft = `${(100 * flatCode / 255 - 50).toFixed(1)}%`;

  const updateHoursLegend = () => {
    const top = dayHours(state.date);
    $('hours-ramp').style.background = `linear-gradient(to right, ${RAMP.map(([t, c]) => `rgb(${c}) ${100 * t}%`).join(', ')})`;
    $('hours-labels').innerHTML = '';
    for (const v of [0, top / 2, top]) {
      const s = document.createElement('span');
      s.textContent = `${+v.toFixed(1)} h`;
      $('hours-labels').appendChild(s);
    }
  };

  // Sets the light from state and shows the instant.
  const applyState = () => {
    state.instantMs = Date.parse(`${state.date}T00:00Z`) + state.minutes * 60000;
    const when = new Date(state.instantMs);
    state.sun = sunAt(when);
    state.light = lightFor(meta, state.sun, state.sky);
    slider.value = String(Math.min(1435, Math.round(state.minutes / 5) * 5));
    const solar = state.minutes + 4 * site.longitudeDeg + equationOfTimeMinutes(state.instantMs);
    $('clock').textContent = `solar ${hhmm(solar)} · UTC ${hhmm(state.minutes)}`;
    $('sun').textContent = `sun at ${site.latitudeDeg.toFixed(2)}°, ${site.longitudeDeg.toFixed(2)}°: azimuth ` +
      `${state.sun.azimuthDeg.toFixed(1)}°, elevation ${state.sun.elevationDeg.toFixed(1)}°`;
  };

  // Relights every visible tile (from the cache) and resolves when MapLibre has drawn them. A change
  // while one is being drawn (a dragged slider) waits for it, then one more pass draws the latest.
  let change = 0, inFlight = false, pending = false, changeStart = 0;
  const waiters = [];
  const startPass = () => {
    inFlight = true;
    change += 1;
    changeStart = performance.now();
    relitThisChange = 0, relightMsThisChange = 0;
    window.relitStats.ready = false;
    if (updateMode === 'settiles') map.getSource('relit').setTiles([`relit://{z}/{x}/{y}?t=${state.instantMs}&s=${state.sky}&l=${state.look}`]);
    else map.refreshTiles('relit');
  };
  const relight = () => {
    applyState();
    const done = new Promise((resolve) => waiters.push(resolve));
    if (inFlight) pending = true;
    else startPass();
    return done;
  };
  map.on('idle', () => {
    if (!map.getSource('relit')?.loaded()) return;
    if (pending) {
      pending = false;
      startPass();
      return;
    }
    const s = window.relitStats;
    if (!s.ready) {
      s.lastRelightMs = +(performance.now() - changeStart).toFixed(1);
      s.tilesRelit = relitThisChange;
      s.relightComputeMs = +relightMsThisChange.toFixed(1);
      s.changes = change;
      s.ready = true;
      $('stats').textContent = `${s.tilesRelit} tiles relit in ${s.lastRelightMs.toFixed(0)} ms`;
    }
    inFlight = false;
    for (const resolve of waiters.splice(0)) resolve({...s});
  });

  const setDate = (date) => {
    state.date = date;
    map.getSource('sunhours').setTiles([`sunhours://{z}/{x}/{y}?d=${date}`]);
    updateHoursLegend();
  };
  dateInput.addEventListener('change', () => {
    if (!/^\d{4}-\d\d-\d\d$/.test(dateInput.value)) return;
    setDate(dateInput.value);
    relight();
  });
  slider.addEventListener('input', () => { state.minutes = +slider.value; relight(); });
  skySelect.addEventListener('change', () => { state.sky = skySelect.value; relight(); });
  lookSelect.addEventListener('change', () => { state.look = lookSelect.value; showLook(); relight(); });
  hoursBox.addEventListener('change', () => {
    map.setLayoutProperty('sunhours', 'visibility', hoursBox.checked ? 'visible' : 'none');
    $('hours-legend').hidden = !hoursBox.checked;
  });

  // Play: 5 minutes a step, each step once the last is drawn.
  let playing = false;
  $('play').addEventListener('click', async () => {
    playing = !playing;
    $('play').textContent = playing ? '❚❚ pause' : '▶ play';
    while (playing) {
      state.minutes = (Math.round(state.minutes / 5) * 5 + 5) % 1440;
      const t = performance.now();
      await relight();
      const left = 60 - (performance.now() - t);
      if (left > 0) await new Promise((r) => setTimeout(r, left));
    }
  });

  window.setInstant = (iso) => {
    const ms = Date.parse(iso);
    if (Number.isNaN(ms)) throw new Error(`setInstant: not a time: ${iso}`);
    const date = new Date(ms).toISOString().slice(0, 10);
    state.minutes = (ms - Date.parse(`${date}T00:00Z`)) / 60000;
    dateInput.value = date;
    if (date !== state.date) setDate(date);
    return relight();
  };
  window.setSky = (sky) => { state.sky = skySelect.value = sky; return relight(); };
  window.setLook = (look) => { state.look = lookSelect.value = look; showLook(); return relight(); };
  // The RGBA bytes the page last made for tile z/x/y (an Array, for tests), with their instant.
  window.relitTile = (z, x, y) => {
    const r = lastRelit.get(`${z}/${x}/${y}`);
    return r ? {instant: new Date(r.instantMs).toISOString(), sky: r.sky, look: r.look, rgba: Array.from(r.rgba)} : null;
  };

  applyState();
  updateHoursLegend();
  changeStart = performance.now();
  map.on('error', (e) => problem(String(e.error?.message || e.error || e)));
}

start().catch((e) => problem(String(e.message || e)));
