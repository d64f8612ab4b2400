#include "core/tiles/tile_viewer.hpp"

#include <string_view>
#include <vector>

namespace ts::tiles {

namespace {

// The page below, with @NAME@, @DESCRIPTION@ and the MapLibre links filled in. Plain ES, no
// build step. window.tileStats is what docs/tiles/check_viewer.mjs reads.
constexpr std::string_view kPage = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="generator" content="terrashade">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>@NAME@</title>
<link rel="stylesheet" href="@CSS_URL@" integrity="@CSS_SRI@" crossorigin="anonymous">
<script src="@JS_URL@" integrity="@JS_SRI@" crossorigin="anonymous"></script>
<style>
  html, body { margin: 0; height: 100%; font: 13px/1.4 sans-serif; background: #f4f1ea; }
  #map { position: absolute; inset: 0; }
  .panel { position: absolute; left: 10px; padding: 6px 10px; background: #fffe; border-radius: 4px;
           box-shadow: 0 0 0 2px #0001; max-width: calc(100% - 80px); }
  #head { top: 10px; }
  #head h1 { margin: 0; font-size: 15px; }
  #legend { bottom: 40px; padding: 4px; }
  #legend img { display: block; max-width: 100%; }
  #notice { top: 50%; left: 50%; transform: translate(-50%, -50%); max-width: 36em; padding: 14px 18px;
            border: 2px solid #b55; }
  code { background: #eee; padding: 1px 4px; user-select: all; }
</style>
</head>
<body>
<div id="map"></div>
<div id="head" class="panel"><h1>@NAME@</h1><div>@DESCRIPTION@</div></div>
<div id="legend" class="panel" hidden></div>
<div id="notice" class="panel" hidden></div>
<script>
'use strict';
// What a test reads: tiles loaded and failed, whether the map has settled, and why not.
window.tileStats = { loaded: 0, failed: 0, idle: false, problem: '' };

function notice(html) {
  const box = document.getElementById('notice');
  box.innerHTML = html;
  box.hidden = false;
  window.tileStats.problem = box.textContent;
}

function escapeHtml(s) {
  return s.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

// The legend is TileJSON's HTML; only its picture is taken (never its markup as it is).
function showLegend(html, tilejsonUrl) {
  const img = new DOMParser().parseFromString(html, 'text/html').querySelector('img');
  if (!img || !img.getAttribute('src')) return;
  const shown = document.createElement('img');
  shown.src = new URL(img.getAttribute('src'), tilejsonUrl).href;
  shown.alt = img.getAttribute('alt') || 'legend';
  const box = document.getElementById('legend');
  box.appendChild(shown);
  box.hidden = false;
}

function showMap(tj, tilejsonUrl) {
  // MapLibre fetches tiles from a worker, which needs absolute URLs: the TileJSON's tile
  // endpoints are relative to the TileJSON itself.
  const tiles = tj.tiles.map((t) => new URL(t, tilejsonUrl).href.replace(/%7B/g, '{').replace(/%7D/g, '}'));
  const map = new maplibregl.Map({
    container: 'map',
    center: [tj.center[0], tj.center[1]],
    zoom: tj.center[2],
    fadeDuration: 0,
    canvasContextAttributes: { preserveDrawingBuffer: true },  // so a test can read the map's pixels
    attributionControl: { compact: false },
    style: {
      version: 8,
      sources: {
        tiles: {
          type: 'raster', tiles, scheme: tj.scheme || 'xyz', tileSize: tj.tile_size || 256,
          minzoom: tj.minzoom, maxzoom: tj.maxzoom, bounds: tj.bounds, attribution: tj.attribution,
        },
      },
      layers: [
        { id: 'paper', type: 'background', paint: { 'background-color': '#f4f1ea' } },
        { id: 'tiles', type: 'raster', source: 'tiles' },
      ],
    },
  });
  // The whole tile set in view, but not below its first zoom (nothing to show there).
  const camera = map.cameraForBounds(tj.bounds, { padding: 40 });
  if (camera) map.jumpTo({ center: camera.center, zoom: Math.min(Math.max(camera.zoom, tj.minzoom), tj.maxzoom + 2) });
  map.addControl(new maplibregl.NavigationControl());
  map.addControl(new maplibregl.ScaleControl({ unit: 'metric' }));
  map.on('data', (e) => {
    if (e.sourceId === 'tiles' && e.dataType === 'source' && e.tile) window.tileStats.loaded += 1;
  });
  map.on('error', (e) => {
    window.tileStats.failed += 1;
    console.error(e.error ? e.error.message : e);
  });
  map.on('idle', () => { window.tileStats.idle = true; });
  if (tj.legend) showLegend(tj.legend, tilejsonUrl);
}

if (location.protocol === 'file:') {
  const dir = decodeURIComponent(location.pathname.replace(/\/[^/]*$/, '')) || '.';
  notice('<b>Browsers do not let this page load its tiles from a file.</b> Serve the folder, e.g.<br>' +
         '<code>python3 -m http.server -b 127.0.0.1 -d ' + escapeHtml(dir) + '</code><br>' +
         'then open <a href="http://127.0.0.1:8000/">http://127.0.0.1:8000/</a>');
} else if (!window.maplibregl) {
  notice('<b>MapLibre GL JS did not load</b> from @CDN_HOST@ (offline?). This page needs it to draw the map.');
} else {
  const tilejsonUrl = new URL('tiles.json', location.href).href;
  fetch(tilejsonUrl)
    .then((r) => { if (!r.ok) throw new Error('tiles.json: HTTP ' + r.status); return r.json(); })
    .then((tj) => showMap(tj, tilejsonUrl))
    .catch((e) => notice('<b>Cannot show the tiles:</b> ' + escapeHtml(String(e.message || e))));
}
</script>
</body>
</html>
)html";

struct Fill {
    std::string_view key;
    std::string value;
};

// The template with each key replaced by its value, in one pass: a value (a user's name) is
// never scanned for keys itself.
std::string filled(std::string_view page, const std::vector<Fill>& fills) {
    std::string out;
    out.reserve(page.size() + 1024);
    for (std::size_t at = 0; at < page.size();) {
        const Fill* hit = nullptr;
        if (page[at] == '@')
            for (const Fill& f : fills)
                if (page.substr(at, f.key.size()) == f.key) hit = &f;
        if (hit) {
            out += hit->value;
            at += hit->key.size();
        } else {
            out += page[at++];
        }
    }
    return out;
}

}  // namespace

std::string viewer_page_html(const TileSetInfo& info) {
    return filled(kPage, {{"@CSS_URL@", kMaplibreCssUrl},
                          {"@CSS_SRI@", kMaplibreCssSri},
                          {"@JS_URL@", kMaplibreJsUrl},
                          {"@JS_SRI@", kMaplibreJsSri},
                          {"@CDN_HOST@", "unpkg.com"},
                          {"@NAME@", html_text(info.name)},
                          {"@DESCRIPTION@", html_text(info.description)}});
}

}  // namespace ts::tiles
