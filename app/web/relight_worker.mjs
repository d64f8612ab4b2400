// The map page's tile work (map.mjs): fetch and decode each lightable data tile once, keep it,
// and light it for an instant or sum its hours of direct sun for a day. Used on the page's main
// thread (?workers=0) or as a module Web Worker, several of them sharing the tiles by z/x/y.
import {decodePng} from './png.mjs';
import {readTile} from './tileset.mjs';
import {readLightableTile, relightTile, sunHoursTexels, resampleToPixels, siteOf} from './relight.mjs';
import {sunPosition} from './sun_position.mjs';

// tileset: the folder's absolute URL without the trailing slash; meta: its lightable.json.
export function makeEngine(tileset, meta, maxTiles = 400) {
  const site = siteOf(meta);
  // 'relief': relief's grey; 'colors': the land's colours (lightable.json's palette).
  const optsFor = (look) => ({contrast: meta.relief_contrast, flatGrey: meta.flat_grey ?? 0.5,
                              colors: look === 'colors' ? meta.colors : null});
  const tiles = new Map();       // z/x/y -> Promise of the tile (null where the set has none)
  const hoursCache = new Map();  // date|z/x/y -> per-pixel hours
  const remember = (cache, key, value) => {
    cache.set(key, value);
    if (cache.size > maxTiles) cache.delete(cache.keys().next().value);   // the oldest
  };
  const getTile = (z, x, y) => {
    const key = `${z}/${x}/${y}`;
    let p = tiles.get(key);
    if (!p) {
      p = readTile(tileset, z, x, y).then(async (bytes) => bytes ? readLightableTile(await decodePng(bytes)) : null);
      p.catch(() => tiles.delete(key));
      remember(tiles, key, p);
    }
    return p;
  };
  return {
    // The tile lit by `light` (lightFor's) in `look` as RGBA bytes, or null where the set has no tile.
    async relight(z, x, y, light, look = 'relief') {
      const tile = await getTile(z, x, y);
      if (!tile) return null;
      const t0 = performance.now();
      const rgba = relightTile(tile, light, new Uint8ClampedArray(tile.size * tile.size * 4), optsFor(look));
      return {rgba, size: tile.size, ms: performance.now() - t0};
    },
    // Per pixel, hours of direct sun on the UTC day `date` (YYYY-MM-DD); NaN where transparent.
    async hours(z, x, y, date) {
      const tile = await getTile(z, x, y);
      if (!tile) return null;
      const key = `${date}|${z}/${x}/${y}`;
      let hours = hoursCache.get(key);
      if (!hours) {
        const texels = sunHoursTexels(tile, meta, new Date(`${date}T00:00Z`), (d) => sunPosition(d, site), 10);
        hours = resampleToPixels(tile, texels);
        remember(hoursCache, key, hours);
      }
      return {hours, size: tile.size};
    },
  };
}

// As a worker: {type: 'init', tileset, meta}, then {id, type: 'relight'|'hours', z, x, y, light, look|date};
// answers {id, result} (buffers transferred) or {id, error}.
if (typeof WorkerGlobalScope !== 'undefined' && self instanceof WorkerGlobalScope) {
  let engine = null;
  self.onmessage = async ({data: m}) => {
    if (m.type === 'init') {
      engine = makeEngine(m.tileset, m.meta);
      return;
    }
    try {
      if (m.type === 'relight') {
        const r = await engine.relight(m.z, m.x, m.y, m.light, m.look);
        self.postMessage({id: m.id, result: r}, r ? [r.rgba.buffer] : []);
      } else if (m.type === 'hours') {
        const r = await engine.hours(m.z, m.x, m.y, m.date);
        const copy = r && {hours: r.hours.slice(), size: r.size};     // the cache keeps its own
        self.postMessage({id: m.id, result: copy}, copy ? [copy.hours.buffer] : []);
      } else {
        throw new Error(`unknown request ${m.type}`);
      }
    } catch (e) {
      self.postMessage({id: m.id, error: String(e.message || e)});
    }
  };
}
