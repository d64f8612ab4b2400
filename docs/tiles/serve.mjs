// A static file server for a folder (by default this one: the sample page and its tiles; or any
// tile folder `terrashade tiles` wrote, with its viewer), on 127.0.0.1 only: the browser does not
// let MapLibre fetch tiles from file:// URLs.
//   node docs/tiles/serve.mjs [PORT [DIR]]      then open http://127.0.0.1:PORT/index.html
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = fileURLToPath(new URL('.', import.meta.url));
const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.png': 'image/png', '.json': 'application/json', '.map': 'application/json',
};

// Resolves to the listening server (port 0 = any free port) of the files under `dir`.
export function serve(port = 0, dir = here) {
  const root = resolve(dir);
  const server = createServer(async (req, res) => {
    const asked = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    const path = normalize(join(root, asked.endsWith('/') ? asked + 'index.html' : asked));
    if (!path.startsWith(root.endsWith(sep) ? root : root + sep)) {
      res.writeHead(403).end();
      return;
    }
    try {
      const body = await readFile(path);
      res.writeHead(200, { 'content-type': types[extname(path)] || 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((resolve) => server.listen(port, '127.0.0.1', () => resolve(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const dir = process.argv[3] || here;
  const server = await serve(Number(process.argv[2] || 8000), dir);
  console.log(`serving ${dir} at http://127.0.0.1:${server.address().port}/index.html`);
}
