// Read tiles and metadata from what `terrashade tiles` writes: an XYZ folder
// (DIR/z/x/y.png beside tiles.json) or one MBTiles 1.3 file. MBTiles is read
// through the sqlite3 command-line program so this module needs no npm
// package or native addon; that part is Node only. In a browser a folder
// is read over HTTP with fetch, relative to the page.

const IS_NODE = typeof process !== 'undefined' && !!process.versions?.node;

// Node built-ins are imported lazily so that merely loading this module in a
// browser does not fail on node: specifiers.
const fsp = () => import('node:fs/promises');

const isMbtiles = (tileset) => /\.mbtiles$/i.test(String(tileset));

function checkZxy(z, x, y) {
  // Integers only: they are pasted into SQL and paths.
  for (const [k, v] of Object.entries({ z, x, y }))
    if (!Number.isInteger(v) || v < 0) throw new Error(`tileset: ${k} must be a non-negative integer, got ${v}`);
  if (z > 30 || x >= 2 ** z || y >= 2 ** z) throw new Error(`tileset: tile ${z}/${x}/${y} is outside the zoom's grid`);
}

// Run one query; every column we ask for is hex() so that blobs, newlines and
// separators in values cannot break the line-based output.
async function sqlite(file, sql) {
  const { execFileSync } = await import('node:child_process');
  const { stat } = await fsp();
  try {
    await stat(file);
  } catch {
    throw new Error(`tileset: no such MBTiles file: ${file}`);
  }
  try {
    return execFileSync('sqlite3', ['-readonly', file, sql], {
      encoding: 'latin1', maxBuffer: 1 << 30, stdio: ['ignore', 'pipe', 'pipe'],
    });
  } catch (e) {
    if (e.code === 'ENOENT')
      throw new Error('tileset: the sqlite3 program is needed to read MBTiles: install the Debian package sqlite3 (apt-get install sqlite3)');
    throw new Error(`tileset: sqlite3 failed on ${file}: ${String(e.stderr || e.message).trim().split('\n')[0]}`);
  }
}

function fromHex(hex) {
  const out = new Uint8Array(hex.length >> 1);
  for (let i = 0; i < out.length; i++) out[i] = parseInt(hex.substr(2 * i, 2), 16);
  return out;
}
const hexText = (hex) => new TextDecoder().decode(fromHex(hex));
const textHex = (s) => Array.from(new TextEncoder().encode(s), (b) => b.toString(16).padStart(2, '0')).join('').toUpperCase();

async function readFileOrNull(path) {
  if (!IS_NODE) {
    const r = await fetch(path);
    if (r.status === 404) return null;
    if (!r.ok) throw new Error(`tileset: GET ${path}: HTTP ${r.status}`);
    return new Uint8Array(await r.arrayBuffer());
  }
  try {
    return new Uint8Array(await (await fsp()).readFile(path));
  } catch (e) {
    if (e.code === 'ENOENT') return null;
    throw e;
  }
}

// Bytes of tile z/x/y (XYZ numbering, y down from the north) or null when absent.
export async function readTile(tileset, z, x, y) {
  checkZxy(z, x, y);
  if (!isMbtiles(tileset)) return readFileOrNull(`${tileset}/${z}/${x}/${y}.png`);
  const row = 2 ** z - 1 - y; // MBTiles stores TMS rows, counted up from the south
  const out = (await sqlite(tileset,
    `select hex(tile_data) from tiles where zoom_level=${z} and tile_column=${x} and tile_row=${row};`)).trim();
  return out ? fromHex(out) : null;
}

// MBTiles: the metadata table as {name: value} (values stay strings, as stored).
// Folder: its TileJSON (tiles.json) or {} when there is none.
export async function readMetadata(tileset) {
  if (!isMbtiles(tileset)) return (await readJsonBeside(tileset, 'tiles.json')) ?? {};
  const out = await sqlite(tileset, "select hex(name) || ' ' || hex(value) from metadata;");
  const meta = {};
  for (const line of out.split('\n')) {
    if (!line.trim()) continue;
    const [name, value = ''] = line.trim().split(' ');
    meta[hexText(name)] = hexText(value);
  }
  return meta;
}

// A JSON document stored with the tile set, or null when absent: the file
// DIR/name for a folder, the metadata row `name` for MBTiles (where terrashade
// keeps e.g. its job description as JSON text).
export async function readJsonBeside(tileset, name) {
  let text;
  if (isMbtiles(tileset)) {
    // The 'v' prefix tells a row with an empty value from no row at all.
    const out = (await sqlite(tileset, `select 'v' || hex(value) from metadata where hex(name)='${textHex(name)}';`)).trim();
    if (!out) return null;
    text = hexText(out.slice(1));
  } else {
    if (/(^|[\\/])\.\.([\\/]|$)/.test(name)) throw new Error(`tileset: refusing a name leaving the folder: ${name}`);
    const bytes = await readFileOrNull(`${tileset}/${name}`);
    if (bytes === null) return null;
    text = new TextDecoder().decode(bytes);
  }
  try {
    return JSON.parse(text);
  } catch (e) {
    throw new Error(`tileset: ${name} in ${tileset} is not valid JSON: ${e.message}`);
  }
}
