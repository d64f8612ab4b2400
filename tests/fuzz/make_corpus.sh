#!/usr/bin/env bash
# Writes the fuzz seed corpus, tests/fuzz/corpus/<reader>/: a few tiny valid inputs per
# reader (each well under 20 KB) so the fuzzers start past the format checks. GeoTIFFs are
# crops of the shared DEMs in the layouts and codecs DEM files come in (gdal_translate,
# gdal-bin); .hgt and .hgt.zip inputs are built by python3 from the shared tiles.
# Run again only to change the seeds; the result is committed.
set -euo pipefail
cd "$(dirname "$0")/../.."
DEM="${TS_SHARED_DATA:-$PWD/../shared/data}/dem"
OUT=tests/fuzz/corpus
for f in "$DEM/srtm3_N39E040_1000px.tif" "$DEM/etopo1_global_1deg.tif" "$DEM/copernicus_N45E005_grenoble_500px.tif" \
         "$DEM/N00E010.hgt" "$DEM/N00E011.hgt.zip"; do
  [ -f "$f" ] || { echo "make_corpus: missing $f (set TS_SHARED_DATA)" >&2; exit 1; }
done
rm -rf "$OUT"
mkdir -p "$OUT/geotiff" "$OUT/hgt" "$OUT/hgt_zip"

# GDAL writes no .aux.xml sidecars into the corpus.
export GDAL_PAM_ENABLED=NO
gt() { gdal_translate -q "$@"; }
SRTM="$DEM/srtm3_N39E040_1000px.tif"
gt -srcwin 100 100 16 16 "$SRTM" "$OUT/geotiff/int16_strips.tif"
gt -srcwin 100 100 40 24 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co COMPRESS=DEFLATE -co PREDICTOR=2 \
   "$SRTM" "$OUT/geotiff/int16_tiled_deflate.tif"
# Half outside the source, so whole tiles are nodata and SPARSE_OK leaves them out.
gt -srcwin 984 984 32 32 -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 -co SPARSE_OK=TRUE \
   "$SRTM" "$OUT/geotiff/int16_sparse_tiles.tif" 2>/dev/null
gt -srcwin 0 0 24 12 -co COMPRESS=LZW -co PREDICTOR=3 "$DEM/etopo1_global_1deg.tif" "$OUT/geotiff/float32_lzw.tif"
gt -srcwin 0 0 8 8 -ot Float64 "$DEM/etopo1_global_1deg.tif" "$OUT/geotiff/float64.tif"
gt -srcwin 200 200 16 16 -co COMPRESS=PACKBITS "$DEM/copernicus_N45E005_grenoble_500px.tif" "$OUT/geotiff/pixel_is_point_packbits.tif"
gt -srcwin 300 300 16 16 -co ENDIANNESS=BIG -co BIGTIFF=YES "$SRTM" "$OUT/geotiff/bigtiff_big_endian.tif"
gt -srcwin 400 400 16 16 -co COMPRESS=ZSTD -co TILED=YES -co BLOCKXSIZE=16 -co BLOCKYSIZE=16 "$SRTM" "$OUT/geotiff/zstd_tiled.tif"
# Valid and tiny, yet 40000x40000 cells: every 4096x4096 tile sparse. Refused for memory
# under the fuzzers' cap; its mutations claim bytes for those tiles.
gdal_create -q -of GTiff -outsize 40000 40000 -ot Int16 -a_nodata -32768 -a_srs EPSG:4326 -a_ullr 40 40 41 39 \
   -co TILED=YES -co BLOCKXSIZE=4096 -co BLOCKYSIZE=4096 -co SPARSE_OK=TRUE "$OUT/geotiff/huge_all_sparse.tif"
gdalwarp -q -overwrite -t_srs EPSG:32637 -ts 12 12 -te 500000 4400000 501000 4401000 "$SRTM" "$OUT/geotiff/utm_projected.tif"

python3 - "$DEM" "$OUT" <<'EOF'
import sys, zipfile, io
dem, out = sys.argv[1], sys.argv[2]
SIDE = 1201
tile = open(f"{dem}/N00E010.hgt", "rb").read()
with zipfile.ZipFile(f"{dem}/N00E011.hgt.zip") as z:
    east = z.read(z.namelist()[0])

# .hgt inputs (dem_fuzz_inputs.hpp): a flags byte, the file name, '\n', the tile's bytes.
# Flag 1 pads the bytes to a whole 1201x1201 tile.
def hgt(name, flags, file_name, data):
    open(f"{out}/hgt/{name}", "wb").write(bytes([flags]) + file_name.encode() + b"\n" + data)
hgt("padded_north_east", 1, "N00E010.hgt", tile[: 8 * SIDE * 2])
hgt("padded_south_west_voids", 1, "S33W071.hgt", b"\x80\x00" * 600 + tile[: 2 * SIDE * 2])
hgt("short", 0, "N45E006.hgt", tile[:64])
hgt("no_corner", 1, "tile.hgt", tile[:100])

# .hgt.zip inputs: whole tiles (the first rows real, the rest zeros, so they deflate small).
def tile_from(rows, source):
    return source[: rows * SIDE * 2] + bytes(SIDE * SIDE * 2 - rows * SIDE * 2)
def write_zip(name, entries, method=zipfile.ZIP_DEFLATED):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", method, compresslevel=9) as z:
        for entry, data in entries:
            info = zipfile.ZipInfo(entry, date_time=(2000, 1, 1, 0, 0, 0))  # same bytes on every run
            info.compress_type = method
            z.writestr(info, data, compresslevel=9)
    open(f"{out}/hgt_zip/{name}", "wb").write(buf.getvalue())
write_zip("tile.hgt.zip", [("N00E011.hgt", tile_from(4, east))])
write_zip("folder_upper_case.hgt.zip", [("readme.txt", b"SRTM3"), ("srtm/N00E011.HGT", tile_from(2, east))])
write_zip("stored_truncated.hgt.zip", [("N00E011.hgt", east[:200])], zipfile.ZIP_STORED)
write_zip("no_tile.hgt.zip", [("readme.txt", b"no tile here")])
EOF

find "$OUT" -type f -size +20k -print | while read -r f; do echo "make_corpus: $f is over 20 KB" >&2; exit 1; done
du -sh "$OUT"
