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

// The tile's header and planes from its decoded PNG ({width, height, channels: 1, data}).
export function readLightableTile(img) {
  const d = img.data, S = img.width;
  if (img.channels !== 1 || d[0] !== 84 || d[1] !== 83 || d[2] !== 76 || d[3] !== 49)
    throw new Error('not a terrashade lightable tile (no TSL1 header)');
  const K = d[5], D = d[6], P = d[7];
  const headerRows = d[10] | (d[11] << 8);
  const dirs = Array.from(d.subarray(12, 12 + P));
  let at = 12 + P;
  at = (at + 3) & ~3;
  const view = new DataView(d.buffer, d.byteOffset + at, 4 * (2 + 9 + 9 * K + 2 * K));
  const f = (i) => view.getFloat32(4 * i, true);
  const hLo = f(0), hHi = f(1);
  const mean = Float64Array.from({length: 9}, (_, i) => f(2 + i));
  const basis = Float64Array.from({length: 9 * K}, (_, i) => f(11 + i));
  const wLo = Float64Array.from({length: K}, (_, k) => f(11 + 9 * K + k));
  const wHi = Float64Array.from({length: K}, (_, k) => f(11 + 10 * K + k));
  const n = S * S;
  const plane = (p) => d.subarray((headerRows + p * S) * S, (headerRows + (p + 1) * S) * S);
  // direction index -> plane index (-1: not stored: the sun never shines from there)
  const planeOf = new Int16Array(D).fill(-1);
  dirs.forEach((dir, j) => (planeOf[dir] = 4 + K + j));
  return {size: S, n, K, D, dirs, hLo, hHi, mean, basis, wLo, wHi, plane, planeOf,
          cover: plane(0), nHiX: plane(1), nHiY: plane(2), nLo: plane(3)};
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

// The light of one instant: the sun at {azimuthDeg, elevationDeg} (sunPosition's) under the
// tile set's `sky` ('clear' or 'overcast'; default the job's). Luminance-weighted for relief.
export function lightFor(meta, sun, skyName = meta.sky) {
  const table = meta.skies[skyName];
  if (!table) throw new Error(`no sky "${skyName}" in lightable.json`);
  const {sh, sun: e} = skyAtElevation(table, sun.elevationDeg);
  const turned = turnSh(sh, sun.azimuthDeg);
  const skyLum = Float64Array.from({length: 9}, (_, i) => LUM[0] * turned[3 * i] + LUM[1] * turned[3 * i + 1] + LUM[2] * turned[3 * i + 2]);
  const eLum = LUM[0] * e[0] + LUM[1] * e[1] + LUM[2] * e[2];
  const el = sun.elevationDeg * DEG, az = sun.azimuthDeg * DEG;
  const s = [Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az), Math.sin(el)];
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

// Per pixel: the sun's visible fraction (0..1, NaN where no data) for `light`.
export function sunVisibility(tile, light, out = new Float32Array(tile.n)) {
  const {n, D, planeOf, hLo, hHi, cover} = tile;
  const u = ((light.azimuthDeg % 360) + 360) % 360 / (360 / D);
  const d0 = Math.floor(u) % D, d1 = (d0 + 1) % D, t = u - Math.floor(u);
  const p0 = planeOf[d0], p1 = planeOf[d1];
  const scale = (hHi - hLo) / 255;
  const h0 = p0 >= 0 ? tile.plane(p0) : null, h1 = p1 >= 0 ? tile.plane(p1) : null;
  for (let k = 0; k < n; ++k) {
    if (!cover[k]) { out[k] = NaN; continue; }
    // A direction not stored is one the sun never shines from: nothing there hides it.
    const a = h0 ? hLo + h0[k] * scale : -Math.PI / 2, b = h1 ? hLo + h1[k] * scale : -Math.PI / 2;
    out[k] = discVisible(a + t * (b - a), light.el, light.radius);
  }
  return out;
}

// The tile's pixels lit by `light` into `out` (RGBA bytes, size^2 * 4): relief's grey, alpha 0
// where the tile has no data.
export function relightTile(tile, light, out, {contrast = 1, flatGrey = 0.5} = {}) {
  const {n, K, mean, basis, wLo, wHi, cover, nHiX, nHiY, nLo} = tile;
  // The sky's light per principal component: <mean, L> + sum_k w_k <basis_k, L>.
  let base = 0;
  for (let i = 0; i < 9; ++i) base += mean[i] * light.skyLum[i];
  const wk = new Float64Array(K), w0 = new Float64Array(K);
  for (let k = 0; k < K; ++k) {
    let b = 0;
    for (let i = 0; i < 9; ++i) b += basis[9 * k + i] * light.skyLum[i];
    wk[k] = b * (wHi[k] - wLo[k]) / 255;
    w0[k] = b * wLo[k];
    base += w0[k];
  }
  const planes = [];
  for (let k = 0; k < K; ++k) planes.push(tile.plane(4 + k));
  const vis = light.eDiffuse > 0 ? sunVisibility(tile, light) : null;
  const [sx, sy, sz] = light.s;
  const inv = 1 / light.flat;
  for (let k = 0; k < n; ++k) {
    const o = 4 * k;
    if (!cover[k]) { out[o] = out[o + 1] = out[o + 2] = out[o + 3] = 0; continue; }
    let sky = base;
    for (let c = 0; c < K; ++c) sky += wk[c] * planes[c][k];
    let lum = sky;
    if (vis) {
      const qx = (nHiX[k] << 4) | (nLo[k] >> 4), qy = (nHiY[k] << 4) | (nLo[k] & 15);
      const nx = qx / 4095 * 2 - 1, ny = qy / 4095 * 2 - 1;
      const nz = Math.sqrt(Math.max(0, 1 - nx * nx - ny * ny));
      const cos = nx * sx + ny * sy + nz * sz;
      if (cos > 0) lum += vis[k] * cos * light.eDiffuse;
    }
    const ratio = Math.max(0, lum * inv);
    const grey = Math.min(1, Math.max(0, flatGrey * (contrast === 1 ? ratio : Math.pow(ratio, contrast))));
    const code = SRGB[Math.round(Math.fround(grey) * 16383)];
    out[o] = out[o + 1] = out[o + 2] = code;
    out[o + 3] = 255;
  }
  return out;
}
