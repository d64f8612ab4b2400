// Test of app/web/png.mjs and tileset.mjs in Node.
//   node tests/web/png_test.mjs TERRASHADE_BINARY TMPDIR
// Fixtures come from other encoders available here: GDAL's PNG driver
// (libpng) writes PNGs of each colour type from raw rasters whose values this
// test chooses, and `terrashade tiles` writes a real tile set as an XYZ folder
// and as MBTiles. PNGs built by the test itself cover what those encoders may
// not choose (all five row filters, many IDATs) and the unsupported kinds.
// Everything made lives in one fresh directory under TMPDIR,
// removed at the end. Exits 1 with "FAIL: ..." on the first failed check.

import { execFileSync } from 'node:child_process';
import { mkdir, mkdtemp, readFile, writeFile, readdir, rm } from 'node:fs/promises';
import { deflateSync, inflateSync } from 'node:zlib';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const { decodePng, encodePng, crc32 } = await import(join(here, '../../app/web/png.mjs'));
const { readTile, readMetadata, readJsonBeside } = await import(join(here, '../../app/web/tileset.mjs'));

const [binary, tmpRoot] = process.argv.slice(2);
if (!binary || !tmpRoot) {
  console.error('usage: node tests/web/png_test.mjs TERRASHADE_BINARY TMPDIR');
  process.exit(2);
}
await mkdir(tmpRoot, { recursive: true });  // the build's folder for it may not exist yet

function check(cond, msg) {
  if (!cond) throw new Error(msg);
}
function sameBytes(a, b, what) {
  check(a.length === b.length, `${what}: length ${a.length} != ${b.length}`);
  for (let i = 0; i < a.length; i++) check(a[i] === b[i], `${what}: byte ${i} is ${a[i]}, expected ${b[i]}`);
}
async function throwsLike(fn, re, what) {
  try {
    await fn();
  } catch (e) {
    check(re.test(e.message), `${what}: wrong error message: ${e.message}`);
    check(!e.message.includes('\n'), `${what}: error message is not one line: ${e.message}`);
    return;
  }
  throw new Error(`${what}: no error thrown`);
}
const gdal = (args) => execFileSync('gdal_translate', ['-q', ...args], { stdio: ['ignore', 'pipe', 'pipe'] });

// Deterministic pixels mixing smooth gradients (which libpng filters with
// Sub/Up/Average/Paeth) and noise (which it tends to leave unfiltered).
function pixels(w, h, c, seed = 1) {
  const d = new Uint8Array(w * h * c);
  let s = seed;
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++)
      for (let k = 0; k < c; k++) {
        s = (s * 1103515245 + 12345) >>> 0;
        const noisy = ((x >> 3) + (y >> 2)) % 3 === 0;
        d[(y * w + x) * c + k] = noisy ? s >>> 24 : (x * (k + 1) + y * (3 - k) + 40 * k) & 255;
      }
  return d;
}

// Walk PNG chunks: which filter types the rows use and how many IDATs there
// are, to report what the external fixtures actually exercised.
function pngStats(bytes, seen) {
  let idats = 0;
  const parts = [];
  let w = 0, h = 0, c = 0;
  for (let p = 8; p < bytes.length; ) {
    const len = new DataView(bytes.buffer, bytes.byteOffset).getUint32(p);
    const type = String.fromCharCode(...bytes.subarray(p + 4, p + 8));
    if (type === 'IHDR') {
      const dv = new DataView(bytes.buffer, bytes.byteOffset + p + 8);
      w = dv.getUint32(0); h = dv.getUint32(4); c = { 0: 1, 2: 3, 4: 2, 6: 4 }[bytes[p + 17]];
    }
    if (type === 'IDAT') { idats++; parts.push(bytes.subarray(p + 8, p + 8 + len)); }
    p += 12 + len;
  }
  const raw = new Uint8Array(inflateSync(Buffer.concat(parts)));
  for (let y = 0; y < h; y++) seen.add(raw[y * (w * c + 1)]);
  seen.idats = Math.max(seen.idats ?? 0, idats);
}

// A PNG built here with a chosen filter per row and its zlib stream cut into
// many IDATs, so all five filters and IDAT joining are covered whatever
// libpng happens to choose.
function chunk(type, body) {
  const out = new Uint8Array(12 + body.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, body.length);
  out.set([...type].map((ch) => ch.charCodeAt(0)), 4);
  out.set(body, 8);
  dv.setUint32(8 + body.length, crc32(out, 4, 8 + body.length));
  return out;
}
function handMadePng(w, h, c, data, { depth = 8, colour = { 1: 0, 2: 4, 3: 2, 4: 6 }[c], interlace = 0, idatSize = 97 } = {}) {
  const stride = w * c, raw = new Uint8Array(h * (stride + 1));
  const at = (y, i) => (y < 0 || i < 0 ? 0 : data[y * stride + i]);
  for (let y = 0; y < h; y++) {
    const f = y % 5, r = y * (stride + 1);
    raw[r] = f;
    for (let i = 0; i < stride; i++) {
      const a = at(y, i - c), b = at(y - 1, i), cc = y > 0 ? at(y - 1, i - c) : 0;
      const p = a + b - cc, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - cc);
      const pred = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : cc][f];
      raw[r + 1 + i] = (data[y * stride + i] - pred) & 255;
    }
  }
  const z = deflateSync(raw), ihdr = new Uint8Array(13), dv = new DataView(ihdr.buffer);
  dv.setUint32(0, w); dv.setUint32(4, h);
  ihdr.set([depth, colour, 0, 0, interlace], 8);
  const parts = [Uint8Array.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr)];
  for (let o = 0; o < z.length; o += idatSize) parts.push(chunk('IDAT', z.subarray(o, o + idatSize)));
  parts.push(chunk('IEND', new Uint8Array(0)));
  return new Uint8Array(Buffer.concat(parts));
}

// Raw band-sequential bytes + ENVI header: a raster GDAL reads with exactly our values.
async function writeEnvi(path, w, h, c, interleaved) {
  const bsq = new Uint8Array(w * h * c);
  for (let i = 0; i < w * h; i++) for (let k = 0; k < c; k++) bsq[k * w * h + i] = interleaved[i * c + k];
  await writeFile(path, bsq);
  await writeFile(path.replace(/\.raw$/, '.hdr'),
    `ENVI\nsamples = ${w}\nlines = ${h}\nbands = ${c}\nheader offset = 0\nfile type = ENVI Standard\ndata type = 1\ninterleave = bsq\nbyte order = 0\n`);
}
// GDAL's own reading of a PNG, as band-interleaved-by-pixel bytes.
async function gdalPixels(png, out) {
  gdal(['-of', 'ENVI', '-co', 'INTERLEAVE=BIP', png, out]);
  return new Uint8Array(await readFile(out));
}

async function main() {
  const t0 = performance.now();
  const dir = await mkdtemp(join(tmpRoot, 'png_test-'));
  let lap = t0; // per-section times show where the run time goes (mostly child processes)
  const log = (s) => {
    const t = performance.now();
    console.log(`  ${s} [${((t - lap) / 1000).toFixed(2)} s]`);
    lap = t;
  };
  try {
    // 1. encodePng -> decodePng round trips, odd sizes included.
    for (const c of [1, 2, 3, 4])
      for (const [w, h] of [[1, 1], [7, 5], [33, 17], [256, 256]]) {
        const data = pixels(w, h, c, w + h + c);
        const img = await decodePng(await encodePng(w, h, c, data));
        check(img.width === w && img.height === h && img.channels === c, `round trip ${w}x${h}x${c}: header`);
        sameBytes(img.data, data, `round trip ${w}x${h}x${c}`);
      }
    log('round trips: channels 1-4, sizes 1x1 to 256x256');

    // 2. Speed: a 256 x (256*40) grey strip, best of 5 decodes.
    {
      const w = 256, h = 256 * 40, data = pixels(w, h, 1, 7);
      const png = await encodePng(w, h, 1, data);
      let best = Infinity;
      for (let i = 0; i < 5; i++) {
        const t = performance.now();
        const img = await decodePng(png);
        best = Math.min(best, performance.now() - t);
        if (i === 0) sameBytes(img.data, data, 'big grey');
      }
      // Brief: "a few tens of ms"; 200 ms leaves room for slow CI machines.
      check(best < 200, `256x10240 grey decode took ${best.toFixed(1)} ms (limit 200)`);
      log(`256x10240 grey decode: ${best.toFixed(1)} ms (best of 5)`);
    }

    // 3. All five filters and many IDATs, each colour type.
    for (const c of [1, 2, 3, 4]) {
      const w = 23, h = 31, data = pixels(w, h, c, 3 * c);
      sameBytes((await decodePng(handMadePng(w, h, c, data))).data, data, `hand-made filters 0-4, ${c} channels`);
    }
    log('hand-made PNGs: rows cycling filters None/Sub/Up/Average/Paeth, IDATs of 97 bytes');

    // 4. Unsupported kinds: one-line errors.
    const px = pixels(4, 4, 1);
    await throwsLike(() => decodePng(handMadePng(4, 4, 1, px, { depth: 16 })), /bit depth 16/, '16-bit');
    await throwsLike(() => decodePng(handMadePng(4, 4, 1, px, { colour: 3 })), /palette/, 'palette');
    await throwsLike(() => decodePng(handMadePng(4, 4, 1, px, { interlace: 1 })), /interlaced/, 'interlaced');
    await throwsLike(() => decodePng(new Uint8Array([1, 2, 3, 4, 5, 6, 7, 8, 9])), /not a PNG/, 'not a PNG');
    const bad = handMadePng(4, 4, 1, px); bad[40] ^= 1;
    await throwsLike(() => decodePng(bad), /CRC mismatch|IDAT/, 'corrupted');
    await writeEnvi(join(dir, 'u16src.raw'), 4, 4, 1, px); // a 16-bit PNG from libpng too
    gdal(['-of', 'PNG', '-ot', 'UInt16', join(dir, 'u16src.raw'), join(dir, 'u16.png')]);
    await throwsLike(async () => decodePng(new Uint8Array(await readFile(join(dir, 'u16.png')))), /bit depth 16/, 'GDAL 16-bit');
    log('errors: 16-bit (hand-made and GDAL), palette, interlaced, bad signature, bad CRC');

    // 5. PNGs written by GDAL (libpng) from rasters of known values, each colour type.
    const seen = new Set();
    for (const c of [1, 2, 3, 4])
      for (const [w, h] of [[37, 23], [300, 200]]) {
        const data = pixels(w, h, c, 11 * c + w);
        const src = join(dir, `src${c}_${w}.raw`), png = join(dir, `gdal${c}_${w}.png`);
        await writeEnvi(src, w, h, c, data);
        gdal(['-of', 'PNG', src, png]);
        const bytes = new Uint8Array(await readFile(png));
        pngStats(bytes, seen);
        const img = await decodePng(bytes);
        check(img.width === w && img.height === h && img.channels === c, `GDAL ${w}x${h}x${c}: header`);
        sameBytes(img.data, data, `GDAL PNG ${w}x${h}x${c}`);
      }
    log(`GDAL PNGs, colour types 0/4/2/6: filters used ${[...seen].sort()}, up to ${seen.idats} IDATs`);

    // 6. A terrashade tile set, as folder and as MBTiles.
    const xyz = join(dir, 'xyz'), mb = join(dir, 'set.mbtiles'), dem = join(here, '../../data/grenoble_500px.tif');
    for (const out of [xyz, mb])
      execFileSync(binary, ['tiles', dem, '--zoom', '9-10', '--out', out], { stdio: ['ignore', 'pipe', 'pipe'] });
    const tiles = [];
    for (const z of await readdir(xyz)) {
      if (!/^\d+$/.test(z)) continue;
      for (const x of await readdir(join(xyz, z)))
        for (const f of await readdir(join(xyz, z, x))) tiles.push([+z, +x, +f.replace(/\.png$/, '')]);
    }
    check(tiles.length > 0, 'terrashade wrote no tiles');
    const inMb = +execFileSync('sqlite3', ['-readonly', mb, 'select count(*) from tiles']).toString().trim();
    check(inMb === tiles.length, `MBTiles holds ${inMb} tiles, folder ${tiles.length}`);
    const tileSeen = new Set();
    // GDAL's reading is compared on the largest tile of each zoom only: each
    // gdal_translate costs ~0.2 s, and all tiles come from the same encoder.
    const largest = {};
    for (const [z, x, y] of tiles) {
      const a = await readTile(xyz, z, x, y), b = await readTile(mb, z, x, y);
      check(a && b, `tile ${z}/${x}/${y} missing from ${a ? 'MBTiles' : 'folder'}`);
      sameBytes(b, a, `tile ${z}/${x}/${y} MBTiles vs folder`);
      pngStats(a, tileSeen);
      const img = await decodePng(a);
      check(img.width === 256 && img.height === 256, `tile ${z}/${x}/${y} is ${img.width}x${img.height}`);
      if (!largest[z] || a.length > largest[z].size) largest[z] = { size: a.length, zxy: `${z}/${x}/${y}`, img };
    }
    for (const { zxy, img } of Object.values(largest)) {
      const ref = await gdalPixels(join(xyz, `${zxy}.png`), join(dir, 'tile.raw'));
      sameBytes(img.data, ref, `tile ${zxy} decoded vs GDAL`);
    }
    for (const ts of [xyz, mb]) {
      check((await readTile(ts, 9, 0, 0)) === null, `${ts}: missing tile 9/0/0 not null`);
      check((await readTile(ts, 3, 4, 2)) === null, `${ts}: tile of an absent zoom not null`);
    }
    log(`terrashade tiles: ${tiles.length} identical in folder and MBTiles, largest per zoom decoded = GDAL; filters ${[...tileSeen].sort()}, up to ${tileSeen.idats} IDATs; missing tiles null`);

    // 7. Metadata on both sides of the same job.
    const mMb = await readMetadata(mb), mXyz = await readMetadata(xyz);
    check(mMb.format === 'png' && mMb.minzoom === '9' && mMb.maxzoom === '10', `MBTiles metadata: ${JSON.stringify(mMb)}`);
    check(mXyz.tilejson && mXyz.name === mMb.name, `tiles.json name ${mXyz.name} != MBTiles name ${mMb.name}`);
    const jobMb = await readJsonBeside(mb, 'terrashade_job'), jobXyz = await readJsonBeside(xyz, '.terrashade-tiles.json');
    check(jobMb && JSON.stringify(jobMb) === JSON.stringify(jobXyz), 'job JSON differs between MBTiles and folder');
    check((await readJsonBeside(mb, 'no_such_key')) === null && (await readJsonBeside(xyz, 'no_such.json')) === null,
      'absent JSON not null');
    check(JSON.stringify(await readMetadata(dir)) === '{}', 'folder without tiles.json not {}');
    const path = process.env.PATH;
    process.env.PATH = join(dir, 'empty'); // sqlite3 not findable
    try {
      await throwsLike(() => readTile(mb, 9, 263, 182), /package sqlite3/, 'no sqlite3');
    } finally {
      process.env.PATH = path;
    }
    log('metadata: MBTiles table, tiles.json, job JSON equal both ways, absent -> null, missing sqlite3 named');
  } finally {
    await rm(dir, { recursive: true, force: true });
  }
  console.log(`png_test: OK in ${((performance.now() - t0) / 1000).toFixed(2)} s`);
}

main().catch((e) => {
  console.error(`FAIL: ${e.message}`);
  process.exit(1);
});
