// Minimal PNG codec for the light table: 8-bit, non-interlaced grey, grey+alpha,
// RGB and RGBA. Plain ES module with no dependencies so the same file runs in
// Node (>= 18) and in a browser without a build step. Only zlib differs between
// the two, so it is the only thing chosen per environment.

// Node is detected by its version string rather than by bundler conventions,
// which a plain <script type="module"> never sees.
const IS_NODE = typeof process !== 'undefined' && !!process.versions?.node;

let zlibPromise = null; // node:zlib, imported once and only in Node
function nodeZlib() {
  zlibPromise ??= import('node:zlib');
  return zlibPromise;
}

// Push bytes through a (De)CompressionStream and collect the result; 'deflate'
// is the zlib-wrapped format PNG uses, in both directions.
async function throughStream(stream, bytes) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(stream));
  return new Uint8Array(await out.arrayBuffer());
}

async function inflate(bytes) {
  if (IS_NODE) return new Uint8Array((await nodeZlib()).inflateSync(bytes));
  return throughStream(new DecompressionStream('deflate'), bytes);
}

async function deflate(bytes) {
  if (IS_NODE) return new Uint8Array((await nodeZlib()).deflateSync(bytes));
  return throughStream(new CompressionStream('deflate'), bytes);
}

// CRC-32 (ISO 3309, as PNG specifies), table built here rather than shipped.
const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

export function crc32(bytes, start = 0, end = bytes.length) {
  let c = 0xffffffff;
  for (let i = start; i < end; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

const SIGNATURE = [137, 80, 78, 71, 13, 10, 26, 10];
// Colour type -> samples per pixel; palette (3) is deliberately absent.
const CHANNELS = { 0: 1, 2: 3, 4: 2, 6: 4 };
const COLOUR_TYPE = { 1: 0, 2: 4, 3: 2, 4: 6 };

const u32 = (b, p) => ((b[p] << 24) | (b[p + 1] << 16) | (b[p + 2] << 8) | b[p + 3]) >>> 0;
const chunkType = (b, p) => String.fromCharCode(b[p], b[p + 1], b[p + 2], b[p + 3]);

export async function decodePng(bytes) {
  if (!(bytes instanceof Uint8Array)) throw new Error('decodePng: expected a Uint8Array');
  if (bytes.length < 8 || SIGNATURE.some((v, i) => bytes[i] !== v))
    throw new Error('decodePng: not a PNG (bad signature)');
  let width = 0, height = 0, channels = 0, sawHeader = false, sawEnd = false;
  const idat = [];
  let idatLength = 0;
  for (let p = 8; p < bytes.length && !sawEnd; ) {
    if (p + 12 > bytes.length) throw new Error(`decodePng: truncated chunk header at byte ${p}`);
    const length = u32(bytes, p);
    const type = chunkType(bytes, p + 4);
    const body = p + 8, next = body + length + 4;
    if (next > bytes.length) throw new Error(`decodePng: chunk ${type} runs past the end of the file`);
    // The CRC covers type and body; checking it turns silent corruption into an error.
    if (crc32(bytes, p + 4, body + length) !== u32(bytes, body + length))
      throw new Error(`decodePng: CRC mismatch in chunk ${type}`);
    if (type === 'IHDR') {
      width = u32(bytes, body);
      height = u32(bytes, body + 4);
      const [depth, colour, compression, filter, interlace] = bytes.subarray(body + 8, body + 13);
      if (depth !== 8) throw new Error(`decodePng: bit depth ${depth} not supported (8-bit only)`);
      if (colour === 3) throw new Error('decodePng: palette PNGs (colour type 3) not supported');
      channels = CHANNELS[colour];
      if (!channels) throw new Error(`decodePng: unknown colour type ${colour}`);
      if (compression !== 0 || filter !== 0)
        throw new Error(`decodePng: unknown compression ${compression} or filter method ${filter}`);
      if (interlace !== 0) throw new Error('decodePng: interlaced (Adam7) PNGs not supported');
      if (width === 0 || height === 0) throw new Error('decodePng: zero width or height');
      sawHeader = true;
    } else if (type === 'IDAT') {
      // Encoders split the zlib stream over several IDATs; it is one stream.
      idat.push(bytes.subarray(body, body + length));
      idatLength += length;
    } else if (type === 'IEND') {
      sawEnd = true;
    }
    p = next;
  }
  if (!sawHeader) throw new Error('decodePng: no IHDR chunk');
  if (idat.length === 0) throw new Error('decodePng: no IDAT chunk');
  let compressed = idat[0];
  if (idat.length > 1) {
    compressed = new Uint8Array(idatLength);
    let o = 0;
    for (const part of idat) { compressed.set(part, o); o += part.length; }
  }
  let raw;
  try {
    raw = await inflate(compressed);
  } catch (e) {
    throw new Error(`decodePng: corrupt image data (zlib: ${e.message})`);
  }
  const stride = width * channels;
  if (raw.length < height * (stride + 1))
    throw new Error(`decodePng: image data too short (${raw.length} < ${height * (stride + 1)} bytes)`);
  const data = new Uint8Array(height * stride);
  unfilter(raw, data, width, height, channels);
  return { width, height, channels, data };
}

// Reverse the per-row filters (PNG spec section 9) straight into `out`, whose
// previous row serves as "up"; bpp = channels since samples are 8-bit.
// Each filter has its own tight loop: a switch per byte would be several times slower.
function unfilter(raw, out, width, height, bpp) {
  const stride = width * bpp;
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)];
    const s = y * (stride + 1) + 1; // row start in raw
    const o = y * stride;           // row start in out
    const u = o - stride;           // row above in out (unused when y == 0)
    const first = y === 0;
    switch (f) {
      case 0: // None
        out.set(raw.subarray(s, s + stride), o);
        break;
      case 1: // Sub: add the byte one pixel to the left
        for (let i = 0; i < bpp; i++) out[o + i] = raw[s + i];
        for (let i = bpp; i < stride; i++) out[o + i] = (raw[s + i] + out[o + i - bpp]) & 255;
        break;
      case 2: // Up: add the byte above (zero on the first row)
        if (first) out.set(raw.subarray(s, s + stride), o);
        else for (let i = 0; i < stride; i++) out[o + i] = (raw[s + i] + out[u + i]) & 255;
        break;
      case 3: // Average of left and above, rounded down
        if (first) {
          for (let i = 0; i < bpp; i++) out[o + i] = raw[s + i];
          for (let i = bpp; i < stride; i++) out[o + i] = (raw[s + i] + (out[o + i - bpp] >> 1)) & 255;
        } else {
          for (let i = 0; i < bpp; i++) out[o + i] = (raw[s + i] + (out[u + i] >> 1)) & 255;
          for (let i = bpp; i < stride; i++)
            out[o + i] = (raw[s + i] + ((out[o + i - bpp] + out[u + i]) >> 1)) & 255;
        }
        break;
      case 4: // Paeth predictor of left (a), above (b), upper-left (c)
        if (first) { // b = c = 0, so Paeth picks a: same as Sub
          for (let i = 0; i < bpp; i++) out[o + i] = raw[s + i];
          for (let i = bpp; i < stride; i++) out[o + i] = (raw[s + i] + out[o + i - bpp]) & 255;
        } else {
          for (let i = 0; i < bpp; i++) out[o + i] = (raw[s + i] + out[u + i]) & 255;
          for (let i = bpp; i < stride; i++) {
            const a = out[o + i - bpp], b = out[u + i], c = out[u + i - bpp];
            const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - c - c);
            const pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            out[o + i] = (raw[s + i] + pred) & 255;
          }
        }
        break;
      default:
        throw new Error(`decodePng: bad filter type ${f} on row ${y}`);
    }
  }
}

function chunk(type, body) {
  const out = new Uint8Array(12 + body.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, body.length);
  for (let i = 0; i < 4; i++) out[4 + i] = type.charCodeAt(i);
  out.set(body, 8);
  dv.setUint32(8 + body.length, crc32(out, 4, 8 + body.length));
  return out;
}

// Encode 8-bit pixels (channels 1..4: grey, grey+alpha, RGB, RGBA). Rows are
// filtered with Up (None on the first row): cheap, and it helps the smooth
// relief images the light table writes far more than it costs.
export async function encodePng(width, height, channels, data) {
  const colour = COLOUR_TYPE[channels];
  if (colour === undefined) throw new Error(`encodePng: channels must be 1..4, got ${channels}`);
  if (!(Number.isInteger(width) && width > 0 && Number.isInteger(height) && height > 0))
    throw new Error(`encodePng: bad size ${width}x${height}`);
  const stride = width * channels;
  if (!data || data.length !== height * stride)
    throw new Error(`encodePng: data has ${data?.length} bytes, expected ${height * stride}`);
  const raw = new Uint8Array(height * (stride + 1));
  for (let y = 0; y < height; y++) {
    const r = y * (stride + 1), o = y * stride;
    if (y === 0) {
      raw[r] = 0;
      raw.set(data.subarray(0, stride), 1);
    } else {
      raw[r] = 2;
      for (let i = 0; i < stride; i++) raw[r + 1 + i] = (data[o + i] - data[o - stride + i]) & 255;
    }
  }
  const ihdr = new Uint8Array(13);
  const dv = new DataView(ihdr.buffer);
  dv.setUint32(0, width);
  dv.setUint32(4, height);
  ihdr.set([8, colour, 0, 0, 0], 8);
  const parts = [Uint8Array.from(SIGNATURE), chunk('IHDR', ihdr),
    chunk('IDAT', await deflate(raw)), chunk('IEND', new Uint8Array(0))];
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) { out.set(p, o); o += p.length; }
  return out;
}
