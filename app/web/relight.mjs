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
// The first transfer plane among a tile's texel planes (after valid, normal and albedo).
const FIRST_TRANSFER = 7;
// The bounced light's sun part: T_b's bands 0..1 (kLightBounce in core/tiles/lightable_tile.hpp).
const BOUNCE = 4;
const LUM = [0.2126, 0.7152, 0.0722];

// The tile's header, planes and sampling from its decoded PNG ({width, height, channels: 1, data};
// the format: core/tiles/lightable_tile.hpp).
export function readLightableTile(img) {
  const d = img.data, W = img.width;
  if (img.channels !== 1 || d[0] !== 84 || d[1] !== 83 || d[2] !== 76 || d[3] !== 49)
    throw new Error('not a terrashade lightable tile (no TSL1 header)');
  if (d[4] !== 3) throw new Error(`lightable tile version ${d[4]}: this reader reads version 3 (make the tiles again)`);
  const u16 = (i) => d[i] | (d[i + 1] << 8);
  const u32 = (i) => (d[i] | (d[i + 1] << 8) | (d[i + 2] << 16) | (d[i + 3] << 24)) >>> 0;
  const K = d[5], D = u16(6), P = u16(8), S = u16(10), headerRows = u16(12);
  const separable = d[16] === 1, step = d[17];
  const levelW = u32(18), levelH = u32(22), x0 = u32(26), y0 = u32(30), tw = u16(34), th = u16(36);
  // Horizon planes other than every keyInterval-th are differences from a prediction; their
  // codes run 0..levels over each plane's range.
  const keyInterval = u16(38), levels = u16(40);
  const dirsAt = 42;
  const dirs = Array.from({length: P}, (_, j) => u16(dirsAt + 2 * j));
  const start = (dirsAt + 2 * P + 3) & ~3;
  const nodes = separable ? 2 * S : 2 * (S / step + 1) ** 2;
  const floats = new Float32Array(2 * P + 6 + 9 + 9 * K + 2 * K + 2 * BOUNCE + nodes);
  const view = new DataView(d.buffer, d.byteOffset + start, 4 * floats.length);
  for (let i = 0; i < floats.length; ++i) floats[i] = view.getFloat32(4 * i, true);
  // Each stored direction's horizon range (radians), by plane.
  const hLo = new Float32Array(P), hHi = new Float32Array(P);
  for (let j = 0; j < P; ++j) hLo[j] = floats[2 * j], hHi[j] = floats[2 * j + 1];
  const albedoLo = floats.slice(2 * P, 2 * P + 3), albedoHi = floats.slice(2 * P + 3, 2 * P + 6);
  const f0 = 2 * P + 6;
  const mean = floats.subarray(f0, f0 + 9), basis = floats.subarray(f0 + 9, f0 + 9 + 9 * K);
  const wLo = floats.subarray(f0 + 9 + 9 * K, f0 + 9 + 10 * K), wHi = floats.subarray(f0 + 9 + 10 * K, f0 + 9 + 11 * K);
  const bounceLo = floats.subarray(f0 + 9 + 11 * K, f0 + 9 + 11 * K + BOUNCE);
  const bounceHi = floats.subarray(f0 + 9 + 11 * K + BOUNCE, f0 + 9 + 11 * K + 2 * BOUNCE);
  const coords = floats.subarray(f0 + 9 + 11 * K + 2 * BOUNCE);
  // Plane rows: pixels' coverage (S rows), then the texel planes (th rows each), W bytes a row.
  const rowOf = (r) => (headerRows + r) * W;
  const coverage = new Uint8Array(S * S);
  for (let r = 0; r < S; ++r) coverage.set(d.subarray(rowOf(r), rowOf(r) + S), r * S);
  const n = tw * th;
  // Texel planes: valid, normal (3), albedo (3), transfer (K), bounce (4), each th rows; then the
  // horizon planes, interleaved by texel row (row r of stored direction j is row r * P + j of their block).
  const firstBounce = FIRST_TRANSFER + K, firstHorizon = firstBounce + BOUNCE;
  const cache = [];
  const texelPlane = (k) => (cache[k] ??= copyPlane(k));  // copied out once, kept
  const copyPlane = (k) => {
    const out = new Uint8Array(n);
    for (let r = 0; r < th; ++r) {
      const row = k < firstHorizon ? S + k * th + r : S + firstHorizon * th + r * P + (k - firstHorizon);
      out.set(d.subarray(rowOf(row), rowOf(row) + tw), r * tw);
    }
    const j = k - firstHorizon;
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
  const planeOf = (dir) => (stored[dir] >= 0 ? firstHorizon + stored[dir] : -1);
  return {size: S, n, K, D, dirs, hLo, hHi, hLevels: levels, mean, basis, wLo, wHi, planeOf,
          plane: texelPlane, firstHorizon, firstBounce, bounceLo, bounceHi, albedoLo, albedoHi,
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

// The sun ({azimuthDeg, elevationDeg}, azimuth from true north as sunPosition gives it) on the
// DEM's grid, where the tiles' horizons, normals and transfers are: a projected grid's north is
// not true north (site.grid_north_deg, the meridian convergence; 0 on geographic grids).
export function onGrid(meta, sun) {
  const turn = meta.site.grid_north_deg ?? 0;
  return turn === 0 ? sun : {...sun, azimuthDeg: (((sun.azimuthDeg + turn) % 360) + 360) % 360};
}

// The light of one instant: the sun at {azimuthDeg, elevationDeg} (sunPosition's) under the
// tile set's `sky` ('clear' or 'overcast'; default the job's). Luminance-weighted for relief.
export function lightFor(meta, trueSun, skyName = meta.sky) {
  const sun = onGrid(meta, trueSun);
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
  // Per channel, for colours: the sky's SH and the sun's irradiance over pi.
  const skyRgb = [0, 1, 2].map((c) => Float64Array.from({length: 9}, (_, i) => turned[3 * i + c]));
  const eRgb = e.map((v) => (up ? v / Math.PI : 0));
  return {skyLum, eDiffuse, skyRgb, eRgb, s, el, azimuthDeg: sun.azimuthDeg, radius, flat};
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
    const j = p - tile.firstHorizon;
    return {q: tile.plane(p), lo: tile.hLo[j], scale: (tile.hHi[j] - tile.hLo[j]) / tile.hLevels};
  };
  const a = side(d0), b = side(d1);
  for (let k = 0; k < n; ++k) {
    const ha = a ? a.lo + a.q[k] * a.scale : -Math.PI / 2, hb = b ? b.lo + b.q[k] * b.scale : -Math.PI / 2;
    out[k] = discVisible(ha + t * (hb - ha), light.el, light.radius);
  }
  return out;
}

// The sky `sky` (9 SH coefficients) through a texel's transfer, T = mean + sum_k w_k basis_k
// with w_k = lo_k + q_k (hi_k - lo_k) / 255: <T, sky> = base + sum_k wk[k] q_k.
function skyThroughTransfer(tile, sky) {
  const {K, mean, basis, wLo, wHi} = tile;
  let base = 0;
  for (let i = 0; i < 9; ++i) base += mean[i] * sky[i];
  const wk = new Float64Array(K);
  for (let k = 0; k < K; ++k) {
    let b = 0;
    for (let i = 0; i < 9; ++i) b += basis[9 * k + i] * sky[i];
    wk[k] = b * (wHi[k] - wLo[k]) / 255;
    base += b * wLo[k];
  }
  return {base, wk};
}

// Per texel of the window: the bounced light's sun part <T_b, Y(s)> (times E_sun it is light,
// as FrameRenderer adds it; core/render/bounce_transfer.hpp), or null when the sun is down.
function bounceSun(tile, light) {
  if (!(light.eDiffuse > 0)) return null;
  const [sx, sy, sz] = light.s;
  const y = [0.28209479177387814, 0.4886025119029199 * sy, 0.4886025119029199 * sz, 0.4886025119029199 * sx];
  let base = 0;
  const step = new Float64Array(BOUNCE), planes = [];
  for (let i = 0; i < BOUNCE; ++i) {
    base += tile.bounceLo[i] * y[i];
    step[i] = (tile.bounceHi[i] - tile.bounceLo[i]) / 255 * y[i];
    planes.push(tile.plane(tile.firstBounce + i));
  }
  const out = new Float32Array(tile.n);
  for (let k = 0; k < tile.n; ++k) {
    let u = base;
    for (let i = 0; i < BOUNCE; ++i) u += step[i] * planes[i][k];
    out[k] = u;
  }
  return out;
}

// What texelGrey and texelColor read per texel: the transfer's component planes and, when the sun
// is up, its visible fraction, the normals and the bounce's sun part (else null).
function texelTerms(tile, light) {
  const planes = [];
  for (let k = 0; k < tile.K; ++k) planes.push(tile.plane(FIRST_TRANSFER + k));
  const vis = light.eDiffuse > 0 ? sunVisibility(tile, light) : null;
  return {planes, vis, normal: vis ? texelNormals(tile) : null, bounce: bounceSun(tile, light)};
}

// Per texel of the window: relief's display-linear grey under `light` (NaN where not valid).
export function texelGrey(tile, light, {contrast = 1, flatGrey = 0.5} = {}) {
  const {n, K, valid} = tile;
  const {base, wk} = skyThroughTransfer(tile, light.skyLum);
  const {planes, vis, normal, bounce} = texelTerms(tile, light);
  const [sx, sy, sz] = light.s;
  const inv = 1 / light.flat;
  const grey = new Float32Array(n);
  for (let k = 0; k < n; ++k) {
    if (!valid[k]) { grey[k] = NaN; continue; }
    let lum = base;
    for (let c = 0; c < K; ++c) lum += wk[c] * planes[c][k];
    if (lum < 0) lum = 0;  // the sky's irradiance clamped at 0, as FrameRenderer does
    if (vis) {
      const cos = normal.x[k] * sx + normal.y[k] * sy + normal.z[k] * sz;
      if (cos > 0) lum += vis[k] * cos * light.eDiffuse;
      lum += bounce[k] * Math.PI * light.eDiffuse;
    }
    const ratio = Math.max(0, lum * inv);
    grey[k] = Math.min(1, Math.max(0, flatGrey * (contrast === 1 ? ratio : Math.pow(ratio, contrast))));
  }
  return grey;
}

// Per texel of the window: `color`'s scene-linear light for the filmic curve under `light`, one
// array per channel (NaN where not valid): the land's albedo times the sky through the transfer
// and the sun, times exposure / lum(L_flat) as `color` exposes it (kColorExposure, from
// lightable.json). Every texel is Lambert: water's mirror and snow's sheen are not stored.
export function texelColor(tile, light, exposure) {
  const {n, K, valid, albedoLo, albedoHi} = tile;
  const {planes, vis, normal, bounce} = texelTerms(tile, light);
  const [sx, sy, sz] = light.s;
  const scale = exposure / light.flat;
  // Per channel, interleaved (wk[3 k + c]) for the loop below.
  const base = new Float64Array(3), wk = new Float64Array(3 * K);
  for (let c = 0; c < 3; ++c) {
    const through = skyThroughTransfer(tile, light.skyRgb[c]);
    base[c] = through.base;
    for (let k = 0; k < K; ++k) wk[3 * k + c] = through.wk[k];
  }
  const aR = tile.plane(4), aG = tile.plane(5), aB = tile.plane(6);
  const aLo = albedoLo, aStep = [0, 1, 2].map((c) => (albedoHi[c] - albedoLo[c]) / 255);
  const [eR, eG, eB] = light.eRgb;
  const r = new Float32Array(n), g = new Float32Array(n), b = new Float32Array(n);
  for (let k = 0; k < n; ++k) {
    if (!valid[k]) { r[k] = g[k] = b[k] = NaN; continue; }
    let lr = base[0], lg = base[1], lb = base[2];
    for (let q = 0; q < K; ++q) {
      const v = planes[q][k];
      lr += wk[3 * q] * v, lg += wk[3 * q + 1] * v, lb += wk[3 * q + 2] * v;
    }
    lr = Math.max(0, lr), lg = Math.max(0, lg), lb = Math.max(0, lb);  // as FrameRenderer
    if (vis) {
      const cos = normal.x[k] * sx + normal.y[k] * sy + normal.z[k] * sz;
      if (cos > 0) { const d = vis[k] * cos; lr += d * eR, lg += d * eG, lb += d * eB; }
      const u = bounce[k] * Math.PI;
      lr += u * eR, lg += u * eG, lb += u * eB;
    }
    r[k] = Math.max(0, lr) * (aLo[0] + aR[k] * aStep[0]) * scale;
    g[k] = Math.max(0, lg) * (aLo[1] + aG[k] * aStep[1]) * scale;
    b[k] = Math.max(0, lb) * (aLo[2] + aB[k] * aStep[2]) * scale;
  }
  return [r, g, b];
}

// The display transform of a pixel of exposed light (the twin of Srgb8Encoder::pixel,
// core/render/tone_map.hpp: ts_display_gain and ts_srgb_oetf of core/raster/display_shared.h),
// in float as the C++: the filmic curve's gain at the largest channel scales all three alike,
// so a colour keeps its chromaticity (beyond the curve's white it turns white); then each
// display-linear value's sRGB code, the smallest value of each code found once by bisection and
// tabulated, so a channel costs a table look-up instead of a pow.
const f32 = Math.fround;
function filmicGain(m) {
  m = Math.max(f32(m), 0);
  if (m >= 8) return f32(1 / m);
  const g = f32(f32(f32(f32(2.51) * m) + f32(0.03)) / f32(f32(m * f32(f32(f32(2.43) * m) + f32(0.59))) + f32(0.14)));
  return f32(m * g) > 1 ? f32(1 / m) : g;
}
function srgb8Code(y) {
  y = Math.min(1, Math.max(0, f32(y)));
  const v = y <= 0.0031308 ? f32(12.92 * y) : f32(f32(1.055 * f32(Math.pow(y, 1 / 2.4))) - f32(0.055));
  return Math.round(f32(255 * v));
}
const OETF_UP = (() => {
  const up = new Float64Array(256);  // up[k]: the smallest display-linear value with code >= k
  for (let k = 1; k <= 255; ++k) {
    let lo = 0, hi = 1;
    for (let it = 0; it < 60; ++it) { const m = 0.5 * (lo + hi); if (srgb8Code(m) >= k) hi = m; else lo = m; }
    up[k] = hi;
  }
  return up;
})();
// The code at each of OETF_BINS equal steps of [0, 1) and the value inside the step where the
// code goes up (a step holds at most one change: checked when built, else oetfCode falls back
// to bisection).
const OETF_BINS = 1 << 16;
const OETF_TABLE = (() => {
  const code = new Uint8Array(OETF_BINS), step = new Float64Array(OETF_BINS).fill(Infinity);
  let k = 1;
  for (let b = 0; b < OETF_BINS; ++b) {
    const start = b / OETF_BINS, end = (b + 1) / OETF_BINS;
    while (k <= 255 && OETF_UP[k] <= start) ++k;
    code[b] = k - 1;
    if (k <= 255 && OETF_UP[k] < end) {
      if (k + 1 <= 255 && OETF_UP[k + 1] < end) return null;
      step[b] = OETF_UP[k];
    }
  }
  return {code, step};
})();
function oetfCode(y) {
  if (!(y >= OETF_UP[1])) return 0;
  if (y >= OETF_UP[255]) return 255;
  if (OETF_TABLE) {
    const b = Math.floor(y * OETF_BINS);
    return OETF_TABLE.code[b] + (y >= OETF_TABLE.step[b] ? 1 : 0);
  }
  let lo = 1, hi = 255;  // up[lo] <= y; find the largest such k
  while (hi - lo > 1) { const m = (lo + hi) >> 1; if (OETF_UP[m] <= y) lo = m; else hi = m; }
  return lo;
}
// The curve's white (TS_FILMIC_WHITE): beyond it a pixel is mixed towards white by 1 - white / m.
const FILMIC_WHITE = f32(7.2416563);
function displayChannel(c, gain, whitening) {
  const v = Math.min(f32(c * gain), 1);
  return f32(v + f32(f32(1 - v) * whitening));
}
// The RGB codes of an exposed pixel (finite channels) into out[o .. o + 2].
function displayCodes(r, g, b, out, o) {
  r = Math.max(f32(r), 0), g = Math.max(f32(g), 0), b = Math.max(f32(b), 0);
  const m = Math.max(r, g, b), gain = filmicGain(m);
  const whitening = Math.max(f32(1 - f32(FILMIC_WHITE / Math.max(m, FILMIC_WHITE))), 0);
  out[o] = oetfCode(displayChannel(r, gain, whitening));
  out[o + 1] = oetfCode(displayChannel(g, gain, whitening));
  out[o + 2] = oetfCode(displayChannel(b, gain, whitening));
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

// A separable tile's taps per pixel column and per pixel row (window indices and weights).
function axisTaps(tile) {
  if (tile.axisTaps) return tile.axisTaps;
  const {size} = tile;
  const make = (coordOf, origin, levelSize) => {
    const index = new Int32Array(4 * size), weight = new Float64Array(4 * size);
    const t = {i: new Int32Array(4), w: new Float64Array(4)};
    for (let p = 0; p < size; ++p) {
      taps(coordOf(p), origin, levelSize, t);
      for (let k = 0; k < 4; ++k) index[4 * p + k] = t.i[k], weight[4 * p + k] = t.w[k];
    }
    return {index, weight};
  };
  tile.axisTaps = {
    cols: make((i) => tile.coords[i], tile.x0, tile.levelW),
    rows: make((j) => tile.coords[size + j], tile.y0, tile.levelH),
  };
  return tile.axisTaps;
}

// The first of a separable tile's two Catmull-Rom passes (Catmull-Rom is a product of its axes):
// along each window row, for every pixel column, into `across` (th x size).
function resampleAcross(tile, texels, across) {
  const {size, tw, th} = tile;
  const {index: ci, weight: cw} = axisTaps(tile).cols;
  for (let r = 0; r < th; ++r) {
    const base = r * tw, o = r * size;
    for (let i = 0, t = 0; i < size; ++i, t += 4) {
      across[o + i] = cw[t] * texels[base + ci[t]] + cw[t + 1] * texels[base + ci[t + 1]] +
                      cw[t + 2] * texels[base + ci[t + 2]] + cw[t + 3] * texels[base + ci[t + 3]];
    }
  }
  return across;
}

// Resamples a per-texel value of the window (e.g. texelGrey) to the tile's pixels by Catmull-Rom,
// as relief does: NaN where a tap is not valid or the pixel is not covered.
export function resampleToPixels(tile, texels, out = new Float32Array(tile.size * tile.size)) {
  const {size, coverage} = tile;
  if (tile.separable) {
    // In two passes (~4x fewer operations than 16 taps): resampleAcross, then down its columns
    // for every pixel row.
    const across = resampleAcross(tile, texels, tile.across ??= new Float64Array(tile.th * size));
    const {index: ri, weight: rw} = axisTaps(tile).rows;
    for (let j = 0; j < size; ++j) {
      const t = 4 * j;
      const a0 = ri[t] * size, a1 = ri[t + 1] * size, a2 = ri[t + 2] * size, a3 = ri[t + 3] * size;
      const w0 = rw[t], w1 = rw[t + 1], w2 = rw[t + 2], w3 = rw[t + 3];
      for (let i = 0, k = j * size; i < size; ++i, ++k) {
        out[k] = coverage[k] ? w0 * across[a0 + i] + w1 * across[a1 + i] + w2 * across[a2 + i] + w3 * across[a3 + i] : NaN;
      }
    }
    return out;
  }
  const {index, weight} = pixelTaps(tile);
  for (let k = 0, n = size * size; k < n; ++k) {
    if (!coverage[k]) { out[k] = NaN; continue; }
    let sum = 0;
    for (let t = 16 * k, e = t + 16; t < e; ++t) sum += weight[t] * texels[index[t]];
    out[k] = sum;
  }
  return out;
}

// The tile's pixels lit by `light` into `out` (RGBA bytes, size^2 * 4), alpha 0 where relief's
// tile is transparent: relief's grey, or with options.colors (lightable.json's "colors") the
// land's colours as `color` shows them.
export function relightTile(tile, light, out, options = {}) {
  if (options.colors) return relightColors(tile, light, out, options.colors.exposure);
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

function relightColors(tile, light, out, exposure) {
  const texels = texelColor(tile, light, exposure);
  const {size, coverage} = tile;
  if (!tile.separable) {
    const [r, g, b] = texels.map((t) => resampleToPixels(tile, t));
    for (let k = 0, o = 0; k < r.length; ++k, o += 4) {
      if (Number.isNaN(r[k] + g[k] + b[k])) { out[o] = out[o + 1] = out[o + 2] = out[o + 3] = 0; continue; }
      displayCodes(r[k], g[k], b[k], out, o);
      out[o + 3] = 255;
    }
    return out;
  }
  // resampleToPixels' two passes, the second for the three channels at once, each pixel encoded
  // as it is made.
  const across = tile.acrossRgb ??= [0, 1, 2].map(() => new Float64Array(tile.th * size));
  for (let c = 0; c < 3; ++c) resampleAcross(tile, texels[c], across[c]);
  const [ar, ag, ab] = across;
  const {index: ri, weight: rw} = axisTaps(tile).rows;
  for (let j = 0; j < size; ++j) {
    const t = 4 * j;
    const a0 = ri[t] * size, a1 = ri[t + 1] * size, a2 = ri[t + 2] * size, a3 = ri[t + 3] * size;
    const w0 = rw[t], w1 = rw[t + 1], w2 = rw[t + 2], w3 = rw[t + 3];
    for (let i = 0, k = j * size, o = 4 * k; i < size; ++i, ++k, o += 4) {
      if (!coverage[k]) { out[o] = out[o + 1] = out[o + 2] = out[o + 3] = 0; continue; }
      const x = w0 * ar[a0 + i] + w1 * ar[a1 + i] + w2 * ar[a2 + i] + w3 * ar[a3 + i];
      const y = w0 * ag[a0 + i] + w1 * ag[a1 + i] + w2 * ag[a2 + i] + w3 * ag[a3 + i];
      const z = w0 * ab[a0 + i] + w1 * ab[a1 + i] + w2 * ab[a2 + i] + w3 * ab[a3 + i];
      if (x !== x || y !== y || z !== z) { out[o] = out[o + 1] = out[o + 2] = out[o + 3] = 0; continue; }
      displayCodes(x, y, z, out, o);
      out[o + 3] = 255;
    }
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
    const sun = onGrid(meta, sunAt(new Date(day + m * 60000)));
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
