#!/usr/bin/env bash
# Checks of scripts/cycles_reference.py against closed forms (docs/accuracy.md, "Against Blender
# Cycles"), about 40 s: a level plane under a sun alone (albedo E sin h / pi), under the analytic
# overcast sky (albedo 7/9 L_z) and a uniform one (albedo L); and the sky map's orientation:
# planes tilted 26.6 degrees towards east and north under a map ten times brighter in that
# quarter of the sky (by the layout sky_equirect_dump writes) must be the brighter ones.
# Usage: scripts/cycles_checks.sh   (needs blender, python3-gdal)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
/usr/bin/python3 - <<'PY'
import json
import numpy as np
from osgeo import gdal, osr
srs = osr.SpatialReference()
srs.SetFromUserInput("+proj=tmerc +lat_0=39.6 +lon_0=40.4 +k=1 +datum=WGS84")
i = np.arange(24) * 90.0
planes = {"flat": np.full((24, 24), 1000.0),
          "east": np.tile(1000 - 0.5 * i, (24, 1)),          # columns run east: downhill east
          "west": np.tile(1000 + 0.5 * i, (24, 1)),
          "north": np.tile((1000 + 0.5 * i)[:, None], (1, 24)),  # rows run south: uphill south
          "south": np.tile((1000 - 0.5 * i)[:, None], (1, 24))}
for name, z in planes.items():
    ds = gdal.GetDriverByName("GTiff").Create(f"{name}.tif", 24, 24, 1, gdal.GDT_Float32)
    ds.SetGeoTransform([0, 90, 0, 0, 0, -90])
    ds.SetProjection(srs.ExportToWkt())
    ds.GetRasterBand(1).WriteArray(z)
    ds = None
W, H = 256, 128
az = (90 + ((np.arange(W) + 0.5) / W - 0.5) * 360) % 360  # sky_equirect_dump's column azimuths
for name, cols in (("east", (az > 45) & (az < 135)), ("north", (az > 315) | (az < 45))):
    m = np.ones((H, W, 3), np.float32)
    m[: H // 2, cols] = 10.0
    m.tofile(f"sky_{name}.f32")
    json.dump({"width": W, "height": H, "sun_irradiance_rgb": [0, 0, 0], "sun_angular_radius_rad": 0.004654,
               "sun_azimuth_deg": 0, "sun_elevation_deg": 45}, open(f"sky_{name}.json", "w"))
PY
cycles() { blender -b --factory-startup -P "$root/scripts/cycles_reference.py" -- "$@" --samples 128 --bounces 0 >/dev/null 2>&1; }
centre() { /usr/bin/python3 -c "from osgeo import gdal; print(gdal.Open('$1').ReadAsArray()[0, 12, 12])"; }
cycles flat.tif sun.tif --sky none --sun-irradiance 100 --sun-elevation 30 --albedo 0.5
echo "level plane, sun only:       $(centre sun.tif)  expected $(python3 -c 'import math; print(0.5*100*0.5/math.pi)')"
cycles flat.tif overcast.tif --sky overcast --sky-radiance 3 --albedo 0.5
echo "level plane, overcast L_z 3: $(centre overcast.tif)  expected $(python3 -c 'print(0.5*7/9*3)')"
cycles flat.tif uniform.tif --sky uniform --sky-radiance 2 --albedo 0.5
echo "level plane, uniform 2:      $(centre uniform.tif)  expected 1.0"
for q in east north; do
  other=$([ $q = east ] && echo west || echo south)
  cycles $q.tif $q.out.tif --sky map --sky-map sky_$q --albedo 1
  cycles $other.tif $other.out.tif --sky map --sky-map sky_$q --albedo 1
  echo "bright $q sky: $q-facing $(centre $q.out.tif), $other-facing $(centre $other.out.tif) (the first must be brighter)"
done
