// Relights a lightable data tile (`terrashade tiles --style lightable`) for one sun and sky, as
// `terrashade tiles --style relief` lights the same pixels (docs/web-map.md):
//
//   L = <T, L_sky> + vis * max(0, n . s) * E_sun / pi        (grey Lambert ground, albedo 1)
//   grey = 0.5 * (lum(L) / lum(L_flat))^contrast, clamped; sRGB-encoded
//
// T: the pixel's diffuse transfer (9 SH coefficients) from the tile's principal components; L_sky:
// the sky's SH from lightable.json, turned to the sun's azimuth; vis: the part of the sun's disc
// above the horizon interpolated between the pixel's stored azimuths; L_flat: open flat ground
// under the same light. Plain functions on typed arrays: the same code in Node and browsers.

const DEG = Math.PI / 180;
const LUM = [0.2126, 0.7152, 0.0722];

// The tile's header, planes and sampling from its decoded PNG ({width, height, channels: 1, data};
// the format: core/tiles/lightable_tile.hpp).
export function readLightableTile(img) {
  const d = img.data, W = img.width;
  if (img.channels !== 1 || d[0] !== 84 || d[1] !== 83 || d[2] !== 76 || d[3] !== 49)
    throw new Error('not a terrashade lightable tile (no TSL1 header)');
  const u16 = (i) => d[i] | (d[i + 1] << 8);
  const u32 = (i) => (d[i] | (d[i + 1] << 8) | (d[i + 2] << 16) | (d[i + 3] << 24)) >>> 0;
  const version = d[4];
  if (version !== 1 && version !== 2) throw new Error(`lightable tile version ${version}: this reader knows 1 and 2`);
  const K = d[5], D = u16(6), P = u16(8), S = u16(10), headerRows = u16(12);
  const separable = d[16] === 1, step = d[17];
  const levelW = u32(18), levelH = u32(22), x0 = u32(26), y0 = u32(30), tw = u16(34), th = u16(36);
  // Version 2: horizon planes other than every keyInterval-th are differences from a prediction.
  // Horizon codes run 0..levels over each plane's range (version 1: 255).
  const keyInterval = version >= 2 ? u16(38) : 0, levels = version >= 2 ? u16(40) : 255;
  const dirsAt = version >= 2 ? 42 : 38;
  const dirs = Array.from({length: P}, (_, j) => u16(dirsAt + 2 * j));
  const start = (dirsAt + 2 * P + 3) & ~3;
  const nodes = separable ? 2 * S : 2 * (S / step + 1) ** 2;
  const floats = new Float32Array(2 * P + 9 + 9 * K + 2 * K + nodes);
  const view = new DataView(d.buffer, d.byteOffset + start, 4 * floats.length);
  for (let i = 0; i < floats.length; ++i) floats[i] = view.getFloat32(4 * i, true);
  // Each stored direction's horizon range (radians), by plane.
  const hLo = new Float32Array(P), hHi = new Float32Array(P);
  for (let j = 0; j < P; ++j) hLo[j] = floats[2 * j], hHi[j] = floats[2 * j + 1];
  // What code 255 would stand for (sunVisibility reads h = hLo + q (hHi - hLo) / 255).
  const hAt255 = Float64Array.from(hLo, (lo, j) => lo + (hHi[j] - lo) * 255 / levels);
  const f0 = 2 * P;
  const mean = floats.subarray(f0, f0 + 9), basis = floats.subarray(f0 + 9, f0 + 9 + 9 * K);
  const wLo = floats.subarray(f0 + 9 + 9 * K, f0 + 9 + 10 * K), wHi = floats.subarray(f0 + 9 + 10 * K, f0 + 9 + 11 * K);
  const coords = floats.subarray(f0 + 9 + 11 * K);
  // Plane rows: pixels' coverage (S rows), then the texel planes (th rows each), W bytes a row.
  const rowOf = (r) => (headerRows + r) * W;
  const coverage = new Uint8Array(S * S);
  for (let r = 0; r < S; ++r) coverage.set(d.subarray(rowOf(r), rowOf(r) + S), r * S);
  const n = tw * th;
  // Planes below 4 + K are th rows each; the horizon planes interleave by texel row (row r of
  // stored direction j is row r * P + j of their block).
  const cache = [];
  const texelPlane = (k) => (cache[k] ??= copyPlane(k));  // copied out once, kept
  const copyPlane = (k) => {
    const out = new Uint8Array(n);
    for (let r = 0; r < th; ++r) {
      const row = k < 4 + K ? S + k * th + r : S + (4 + K) * th + r * P + (k - 4 - K);
      out.set(d.subarray(rowOf(row), rowOf(row) + tw), r * tw);
    }
    const j = k - 4 - K;
    if (j > 0 && keyInterval > 0 && j % keyInterval !== 0 && dirs[j] === dirs[j - 1] + 1) {
      // A difference from the code nearest the previous plane's horizon (the writer's
      // predicted_horizon_codes, the same double operations in the same order).
      const prev = texelPlane(k - 1), predict = new Uint8Array(256);
      const pl = hLo[j - 1], pr = hHi[j - 1] - pl, l = hLo[j], rr = hHi[j] - l;
      for (let q = 0; q <= levels; ++q) {
        const h = pl + q * pr / levels;
        predict[q] = Math.floor(Math.min(levels, Math.max(0, (h - l) / rr * levels)) + 0.5);
      }
      for (let t = 0; t < n; ++t) out[t] += predict[prev[t]];
    }
    return out;
  };
  // direction -> its index among the stored ones (-1: the sun never shines from there)
  const stored = new Int32Array(D).fill(-1);
  dirs.forEach((dir, j) => (stored[dir] = j));
  const planeOf = (dir) => (stored[dir] >= 0 ? 4 + K + stored[dir] : -1);
  // hHi: what code 255 stands for (sunVisibility's scale); hTop: the range's top, code hLevels.
  return {size: S, n, K, D, dirs, hLo, hHi: hAt255, hTop: hHi, hLevels: levels, mean, basis, wLo, wHi, planeOf, plane: texelPlane,
          coverage, separable, step, coords, levelW, levelH, x0, y0, tw, th,
          valid: texelPlane(0), nHiX: texelPlane(1), nHiY: texelPlane(2), nLo: texelPlane(3)};
}

// Linear interpolation in a sky table at elevation e (degrees): {sh: 27 numbers, sun: [r, g, b]}.
function skyAtElevation(table, e) {
  const els = table.elevations;
  let i = 0;
  if (e <= els[0]) i = 0;
  else if (e >= els[els.length - 1]) i = els.length - 2;
  else { let lo = 0, hi = els.length - 1; while (hi - lo > 1) { const m = (lo + hi) >> 1; if (els[m] <= e) lo = m; else hi = m; } i = lo; }
  const t = Math.min(1, Math.max(0, (e - els[i]) / (els[i + 1] - els[i])));
  const a = table.sh[i], b = table.sh[i + 1];
  const sh = a.map((v, k) => v + t * (b[k] - v));
  const sa = table.sun[i], sb = table.sun[i + 1];
  const sun = sa.map((v, k) => v + t * (sb[k] - v));
  return {sh, sun};
}

// Turns the sky's SH (sun at azimuth 90, the table's frame) to the sun at `azimuthDeg`
// (clockwise from north): the twin of turn_sky_sh in core/tiles/lightable_sky.cpp.
function turnSh(sh, azimuthDeg) {
  const a = (90 - azimuthDeg) * DEG;
  const out = sh.slice();
  for (let l = 1; l <= 2; ++l)
    for (let m = 1; m <= l; ++m) {
      const ip = l * l + l + m, im = l * l + l - m;
      const c = Math.cos(m * a), s = Math.sin(m * a);
      for (let ch = 0; ch < 3; ++ch) {
        out[3 * ip + ch] = sh[3 * ip + ch] * c - sh[3 * im + ch] * s;
        out[3 * im + ch] = sh[3 * im + ch] * c + sh[3 * ip + ch] * s;
      }
    }
  return out;
}

// The part of the sun's disc (radius r) centred at elevation e above a horizon h (radians): the
// twin of sun_disc_visible_fraction (core/visibility/sun_visibility.cpp).
export function discVisible(h, e, r) {
  const x = (e - h) / r;
  if (x >= 1) return 1;
  if (x <= -1) return 0;
  const below = (Math.acos(x) - x * Math.sqrt(1 - x * x)) / Math.PI;
  return Math.min(1, Math.max(0, 1 - below));
}

// The unit vector towards the sun (east, north, up) from {azimuthDeg, elevationDeg}.
function sunDirection(sun) {
  const el = sun.elevationDeg * DEG, az = sun.azimuthDeg * DEG;
  return [Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az), Math.sin(el)];
}

// The texels' unit normals from their 12-bit east and north components, decoded once per tile.
function texelNormals(tile) {
  if (tile.normals) return tile.normals;
  const {n, nHiX, nHiY, nLo} = tile;
  const x = new Float64Array(n), y = new Float64Array(n), z = new Float64Array(n);
  for (let k = 0; k < n; ++k) {
    const qx = (nHiX[k] << 4) | (nLo[k] >> 4), qy = (nHiY[k] << 4) | (nLo[k] & 15);
    x[k] = qx / 4095 * 2 - 1, y[k] = qy / 4095 * 2 - 1;
    z[k] = Math.sqrt(Math.max(0, 1 - x[k] * x[k] - y[k] * y[k]));
  }
  tile.normals = {x, y, z};
  return tile.normals;
}

// The site lightable.json places the sun at, as sunPosition takes it.
export function siteOf(meta) {
  return {latitudeDeg: meta.site.latitude_deg, longitudeDeg: meta.site.longitude_deg, heightM: meta.site.height_m};
}

// The light of one instant: the sun at {azimuthDeg, elevationDeg} (sunPosition's) under the
// tile set's `sky` ('clear' or 'overcast'; default the job's). Luminance-weighted for relief.
export function lightFor(meta, sun, skyName = meta.sky) {
  const table = meta.skies[skyName];
  if (!table) throw new Error(`no sky "${skyName}" in lightable.json`);
  const {sh, sun: e} = skyAtElevation(table, sun.elevationDeg);
  const turned = turnSh(sh, sun.azimuthDeg);
  const skyLum = Float64Array.from({length: 9}, (_, i) => LUM[0] * turned[3 * i] + LUM[1] * turned[3 * i + 1] + LUM[2] * turned[3 * i + 2]);
  const eLum = LUM[0] * e[0] + LUM[1] * e[1] + LUM[2] * e[2];
  const el = sun.elevationDeg * DEG;
  const s = sunDirection(sun);
  const radius = table.sun_radius_rad;
  const up = eLum > 0 && sun.elevationDeg > -radius / DEG;
  const eDiffuse = up ? eLum / Math.PI : 0;
  let flat = 0;
  for (let i = 0; i < 9; ++i) flat += meta.flat_transfer[i] * skyLum[i];
  flat += discVisible(0, el, radius) * Math.max(0, s[2]) * eDiffuse;
  return {skyLum, eDiffuse, s, el, azimuthDeg: sun.azimuthDeg, radius, flat};
}

// Display-linear 0..1 -> sRGB code through the same 2^14-entry table as the C++ tiles
// (tile_renderer.cpp), so equal values give equal codes.
const SRGB = (() => {
  const size = 1 << 14, t = new Uint8Array(size);
  for (let i = 0; i < size; ++i) {
    const c = i / (size - 1);
    const v = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
    t[i] = Math.round(255 * Math.fround(v));
  }
  return t;
})();

// Per texel of the tile's window: the sun's visible fraction (0..1) for `light`.
export function sunVisibility(tile, light, out = new Float32Array(tile.n)) {
  const {n, D} = tile;
  const u = ((light.azimuthDeg % 360) + 360) % 360 / (360 / D);
  const d0 = Math.floor(u) % D, d1 = (d0 + 1) % D, t = u - Math.floor(u);
  // A direction not stored is one the sun never shines from: nothing there hides it.
  const side = (d) => {
    const p = tile.planeOf(d);
    if (p < 0) return null;
    const j = p - 4 - tile.K;
    return {q: tile.plane(p), lo: tile.hLo[j], scale: (tile.hHi[j] - tile.hLo[j]) / 255};
  };
  const a = side(d0), b = side(d1);
  for (let k = 0; k < n; ++k) {
    const ha = a ? a.lo + a.q[k] * a.scale : -Math.PI / 2, hb = b ? b.lo + b.q[k] * b.scale : -Math.PI / 2;
    out[k] = discVisible(ha + t * (hb - ha), light.el, light.radius);
  }
  return out;
}

// Per texel of the window: relief's display-linear grey under `light` (NaN where not valid).
export function texelGrey(tile, light, {contrast = 1, flatGrey = 0.5} = {}) {
  const {n, K, mean, basis, wLo, wHi, valid} = tile;
  // The sky's light per principal component: <mean, L> + sum_k w_k <basis_k, L>.
  let base = 0;
  for (let i = 0; i < 9; ++i) base += mean[i] * light.skyLum[i];
  const wk = new Float64Array(K);
  for (let k = 0; k < K; ++k) {
    let b = 0;
    for (let i = 0; i < 9; ++i) b += basis[9 * k + i] * light.skyLum[i];
    wk[k] = b * (wHi[k] - wLo[k]) / 255;
    base += b * wLo[k];
  }
  const planes = [];
  for (let k = 0; k < K; ++k) planes.push(tile.plane(4 + k));
  const vis = light.eDiffuse > 0 ? sunVisibility(tile, light) : null;
  const normal = vis ? texelNormals(tile) : null;
  const [sx, sy, sz] = light.s;
  const inv = 1 / light.flat;
  const grey = new Float32Array(n);
  for (let k = 0; k < n; ++k) {
    if (!valid[k]) { grey[k] = NaN; continue; }
    let lum = base;
    for (let c = 0; c < K; ++c) lum += wk[c] * planes[c][k];
    if (vis) {
      const cos = normal.x[k] * sx + normal.y[k] * sy + normal.z[k] * sz;
      if (cos > 0) lum += vis[k] * cos * light.eDiffuse;
    }
    const ratio = Math.max(0, lum * inv);
    grey[k] = Math.min(1, Math.max(0, flatGrey * (contrast === 1 ? ratio : Math.pow(ratio, contrast))));
  }
  return grey;
}

// Catmull-Rom (a = -0.5) weights at t, as the C++ tiles' CatmullRom.
function cubicWeights(t, w) {
  const t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2 * t2 - t);
  w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
  w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
}

// Where pixel (i, j) samples the window: {x, y} relative to its origin, clamped to the level.
function pixelAt(tile, i, j) {
  const {separable, coords, size, step, x0, y0, levelW, levelH} = tile;
  let x, y;
  if (separable) {
    x = coords[i], y = coords[size + j];
  } else {
    const m = size / step + 1, gi = Math.min(Math.floor(i / step), m - 2), gj = Math.min(Math.floor(j / step), m - 2);
    const fx = (i - gi * step) / step, fy = (j - gj * step) / step;
    const node = (a, b, c) => coords[2 * (b * m + a) + c];
    const lerp2 = (c) => (node(gi, gj, c) * (1 - fx) + node(gi + 1, gj, c) * fx) * (1 - fy) +
                         (node(gi, gj + 1, c) * (1 - fx) + node(gi + 1, gj + 1, c) * fx) * fy;
    x = Math.min(Math.max(lerp2(0), -x0), levelW - 1 - x0);
    y = Math.min(Math.max(lerp2(1), -y0), levelH - 1 - y0);
  }
  return {x, y};
}

// The taps of one axis at window coordinate v: indices into the window and weights.
function taps(v, origin, levelSize, out) {
  const a = v + origin;                      // the level's coordinate, as relief clamps it
  const i0 = Math.min(Math.floor(a), levelSize - 1);
  cubicWeights(Math.fround(a - i0), out.w);
  for (let k = 0; k < 4; ++k) out.i[k] = Math.min(Math.max(i0 - 1 + k, 0), levelSize - 1) - origin;
}

// Each covered pixel's 16 Catmull-Rom taps (window indices) and weights, found once per tile: a
// slider move then only multiplies and adds.
function pixelTaps(tile) {
  if (tile.taps) return tile.taps;
  const {size, tw, coverage} = tile;
  const index = new Int32Array(size * size * 16), weight = new Float32Array(size * size * 16);
  const tx = {i: new Int32Array(4), w: new Float64Array(4)}, ty = {i: new Int32Array(4), w: new Float64Array(4)};
  for (let j = 0; j < size; ++j)
    for (let i = 0; i < size; ++i) {
      const k = j * size + i;
      if (!coverage[k]) continue;
      const p = pixelAt(tile, i, j);
      taps(p.x, tile.x0, tile.levelW, tx);
      taps(p.y, tile.y0, tile.levelH, ty);
      for (let b = 0; b < 4; ++b)
        for (let a = 0; a < 4; ++a) {
          index[16 * k + 4 * b + a] = ty.i[b] * tw + tx.i[a];
          weight[16 * k + 4 * b + a] = ty.w[b] * tx.w[a];
        }
    }
  tile.taps = {index, weight};
  return tile.taps;
}

// Resamples a per-texel value of the window (e.g. texelGrey) to the tile's pixels by Catmull-Rom,
// as relief does: NaN where a tap is not valid or the pixel is not covered.
export function resampleToPixels(tile, texels, out = new Float32Array(tile.size * tile.size)) {
  const {size, coverage} = tile;
  const {index, weight} = pixelTaps(tile);
  for (let k = 0, n = size * size; k < n; ++k) {
    if (!coverage[k]) { out[k] = NaN; continue; }
    let sum = 0;
    for (let t = 16 * k, e = t + 16; t < e; ++t) sum += weight[t] * texels[index[t]];
    out[k] = sum;
  }
  return out;
}

// The tile's pixels lit by `light` into `out` (RGBA bytes, size^2 * 4): relief's grey, alpha 0
// where relief's tile is transparent.
export function relightTile(tile, light, out, options = {}) {
  const grey = resampleToPixels(tile, texelGrey(tile, light, options));
  for (let k = 0; k < grey.length; ++k) {
    const o = 4 * k, v = grey[k];
    if (Number.isNaN(v)) { out[o] = out[o + 1] = out[o + 2] = out[o + 3] = 0; continue; }
    const code = SRGB[Math.round(Math.min(1, Math.max(0, v)) * 16383)];
    out[o] = out[o + 1] = out[o + 2] = code;
    out[o + 3] = 255;
  }
  return out;
}

// Hours of direct sun per texel of the window on the UTC day of `date` (the part of the sun's
// disc seen, summed every `stepMinutes`): the page's second layer. `sunAt(date)` gives the sun
// ({azimuthDeg, elevationDeg}) at an instant, e.g. sunPosition at the tile set's site.
export function sunHoursTexels(tile, meta, date, sunAt, stepMinutes = 10) {
  const hours = new Float32Array(tile.n);
  const vis = new Float32Array(tile.n);
  const {valid} = tile;
  const normal = texelNormals(tile);
  const day = Date.UTC(date.getUTCFullYear(), date.getUTCMonth(), date.getUTCDate());
  const radius = meta.skies.clear.sun_radius_rad;
  for (let m = stepMinutes / 2; m < 24 * 60; m += stepMinutes) {
    const sun = sunAt(new Date(day + m * 60000));
    if (sun.elevationDeg < -1) continue;
    const s = sunDirection(sun);
    sunVisibility(tile, {azimuthDeg: sun.azimuthDeg, el: sun.elevationDeg * DEG, radius}, vis);
    for (let k = 0; k < tile.n; ++k) {
      if (!valid[k]) continue;
      // Direct sun on the surface: its disc seen and the surface facing it.
      if (normal.x[k] * s[0] + normal.y[k] * s[1] + normal.z[k] * s[2] > 0) hours[k] += vis[k] * stepMinutes / 60;
    }
  }
  for (let k = 0; k < tile.n; ++k) if (!valid[k]) hours[k] = NaN;
  return hours;
}
