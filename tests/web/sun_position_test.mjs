// app/web/sun_position.mjs against terrashade's SPA: the cases of tests/web/sun_reference.json
// (made by scripts/make_sun_reference.sh from `terrashade sun --json`).
// Run: node tests/web/sun_position_test.mjs   (exit 0 on pass, 1 with the failing cases otherwise)
//
// Checked per case, tolerance 0.01 deg:
//   - |elevation difference| (refracted), and the unrefracted elevation too;
//   - |azimuth difference| (wrapped to [-180, 180]) times cos(elevation), only where the
//     reference elevation is above -1 deg (below it the azimuth matters to nobody) and skipped
//     above 89 deg (near the zenith the azimuth is ill-defined); the product is the angular
//     distance along the horizon circle through the sun, which is what an azimuth error costs.
// The refracted elevation of a case whose unrefracted elevation lies within 0.002 deg of the
// refraction threshold (-0.83337 deg) is not compared: there the refraction switches off, so any
// model's sub-0.002 deg error may flip it (the reference script avoids such instants anyway).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { sunPosition } from '../../app/web/sun_position.mjs';

const TOLERANCE_DEG = 0.01;
const THRESHOLD_DEG = -(0.26667 + 0.5667);
const here = dirname(fileURLToPath(import.meta.url));
const reference = JSON.parse(readFileSync(join(here, 'sun_reference.json'), 'utf8'));
const cases = reference.cases;
if (!Array.isArray(cases) || cases.length < 100) {
  console.error(`sun_position_test: expected 100+ cases in sun_reference.json, got ${cases?.length}`);
  process.exit(1);
}

const max = { azimuth: { v: 0 }, elevation: { v: 0 }, unrefracted: { v: 0 } };
const note = (key, v, c) => {
  if (v > max[key].v) max[key] = { v, c };
};
const failures = [];
let azimuthCompared = 0;
let below = 0;
for (const c of cases) {
  const got = sunPosition(new Date(c.time), { latitudeDeg: c.lat, longitudeDeg: c.lon, heightM: c.height_m });
  const dEl0 = Math.abs(got.elevationUnrefractedDeg - c.elevation_unrefracted_deg);
  note('unrefracted', dEl0, c);
  if (dEl0 > TOLERANCE_DEG) failures.push(`unrefracted elevation off by ${dEl0.toFixed(5)} deg at ${JSON.stringify(c)}`);
  if (Math.abs(c.elevation_unrefracted_deg - THRESHOLD_DEG) >= 0.002) {
    const dEl = Math.abs(got.elevationDeg - c.elevation_deg);
    note('elevation', dEl, c);
    if (dEl > TOLERANCE_DEG) failures.push(`elevation off by ${dEl.toFixed(5)} deg at ${JSON.stringify(c)}`);
  }
  if (c.elevation_deg < 0) below++;
  if (c.elevation_deg > -1 && c.elevation_deg <= 89) {
    azimuthCompared++;
    const dAz = Math.abs((((got.azimuthDeg - c.azimuth_deg) % 360) + 540) % 360 - 180);
    const weighted = dAz * Math.cos((c.elevation_deg * Math.PI) / 180);
    note('azimuth', weighted, c);
    if (weighted > TOLERANCE_DEG)
      failures.push(`azimuth off by ${dAz.toFixed(5)} deg (x cos(elevation) = ${weighted.toFixed(5)}) at ${JSON.stringify(c)}`);
  }
  if (!(got.azimuthDeg >= 0 && got.azimuthDeg < 360)) failures.push(`azimuth ${got.azimuthDeg} outside [0, 360) at ${c.time}`);
}

const where = (m) => (m.c ? ` (${m.c.time}, lat ${m.c.lat}, lon ${m.c.lon}, ${m.c.height_m} m)` : '');
console.log(`sun_position_test: ${cases.length} cases (${below} with the sun below the horizon), azimuth compared in ${azimuthCompared}`);
console.log(`  max |elevation diff|             ${max.elevation.v.toExponential(3)} deg${where(max.elevation)}`);
console.log(`  max |unrefracted elevation diff| ${max.unrefracted.v.toExponential(3)} deg${where(max.unrefracted)}`);
console.log(`  max |azimuth diff| cos(elev)     ${max.azimuth.v.toExponential(3)} deg${where(max.azimuth)}`);
if (failures.length) {
  console.error(`FAIL: ${failures.length} check(s) beyond ${TOLERANCE_DEG} deg:`);
  for (const f of failures.slice(0, 20)) console.error('  ' + f);
  process.exit(1);
}
console.log(`PASS: all within ${TOLERANCE_DEG} deg of terrashade's SPA`);
