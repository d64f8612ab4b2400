// The sun's position for a UTC instant and a place, as terrashade's C++ gives it
// (core/light/sun_position.cpp): azimuth clockwise from north in [0, 360), topocentric elevation
// with atmospheric refraction, and the same elevation without refraction.
//
// Algorithm: the NREL SPA's chain of steps (Reda & Andreas, NREL/TP-560-34302, 2008, section 3;
// the same steps as Meeus, "Astronomical Algorithms", 2nd ed., ch. 25 "higher accuracy") with two
// cheaper ingredients:
//   - the Earth's heliocentric position from VSOP87 periodic terms (Reda & Andreas Table A4.2,
//     i.e. Meeus Appendix III) cut to the 87 terms whose amplitude times |JME|^i can reach
//     50e-8 rad (0.1 arcsec) for 1950..2100 (JME = Julian millennia from J2000, |JME| <= 0.1):
//     the full table has 195; the dropped terms move the longitude by at most 0.0002 deg there;
//   - nutation from the four largest terms of the IAU 1980 series (Meeus ch. 22: 0.5 arcsec in
//     longitude, 0.1 arcsec in obliquity) instead of the 63-term table, and the IAU mean
//     obliquity (Meeus eq. 22.2) instead of Laskar's polynomial (they differ by < 0.01 arcsec here).
// Everything else is the SPA's formula as terrashade's C++ has it: Julian day from the Unix epoch
// (UT1 = UTC), delta T by the Espenak-Meeus polynomials (core/light/delta_t.cpp), aberration,
// apparent sidereal time, parallax of an observer on the ellipsoid at its height, refraction by
// Saemundsson's formula with the ICAO standard atmosphere at the height (Atmosphere::standard_at)
// and the SPA's threshold (no refraction below -(0.26667 + 0.5667) deg).
//
// Why: the truncated tables keep the module small (87 of the 195 VSOP87 terms, 4 of the 63 nutation
// terms: about a quarter of the C++ tables' numbers) while the error stays far below the 0.01 deg
// this module promises. Stated accuracy: within 0.001 deg of the SPA for 1950..2100 by
// construction (0.0002 deg truncation + 0.00014 deg nutation in the sun's longitude). Outside
// 1950..2100 the truncation error grows slowly (the dropped L1/L2 terms scale with |JME|).
// Measured against terrashade's SPA (`terrashade sun --json`; tests/web/sun_position_test.mjs,
// 208 reference cases of 1990..2060, latitudes -70..70, heights 0..3000 m, 97 with the sun below
// the horizon, 32 at grazing sun): max |elevation diff| 1.7e-4 deg (refracted and unrefracted alike), max |azimuth
// diff| 6.4e-4 deg (1.1e-4 deg times cos(elevation)); 60 further cases in 1950..1989 and
// 2061..2100: max 9.5e-5 deg in elevation, 1.3e-4 deg in azimuth.
//
// Plain ES module, no dependencies: runs unchanged in Node >= 18 and in browsers.

const RAD = Math.PI / 180;
const sinD = (d) => Math.sin(d * RAD);
const cosD = (d) => Math.cos(d * RAD);
const wrap360 = (d) => {
  d %= 360;
  return d < 0 ? d + 360 : d;
};

// VSOP87 series for the Earth, truncated as said above. Each row is one power of JME, flat
// triples A (1e-8 rad or 1e-8 au), B (rad), C (rad per millennium): term = A cos(B + C JME).
const EARTH_L = [
  [
    175347046, 0, 0, 3341656, 4.6692568, 6283.07585, 34894, 4.6261, 12566.1517,
    3497, 2.7441, 5753.3849, 3418, 2.8289, 3.5231, 3136, 3.6277, 77713.7715,
    2676, 4.4181, 7860.4194, 2343, 6.1352, 3930.2097, 1324, 0.7425, 11506.7698,
    1273, 2.0371, 529.691, 1199, 1.1096, 1577.3435, 990, 5.233, 5884.927, 902, 2.045, 26.298,
    857, 3.508, 398.149, 780, 1.179, 5223.694, 753, 2.533, 5507.553, 505, 4.583, 18849.228,
    492, 4.205, 775.523, 357, 2.92, 0.067, 317, 5.849, 11790.629, 284, 1.899, 796.298,
    271, 0.315, 10977.079, 243, 0.345, 5486.778, 206, 4.806, 2544.314, 205, 1.869, 5573.143,
    202, 2.458, 6069.777, 156, 0.833, 213.299, 132, 3.411, 2942.463, 126, 1.083, 20.775,
    115, 0.645, 0.98, 103, 0.636, 4694.003, 102, 0.976, 15720.839, 102, 4.267, 7.114,
    99, 6.21, 2146.17, 98, 0.68, 155.42, 86, 5.98, 161000.69, 85, 1.3, 6275.96,
    85, 3.67, 71430.7, 80, 1.81, 17260.15, 79, 3.04, 12036.46, 75, 1.76, 5088.63,
    74, 3.5, 3154.69, 74, 4.68, 801.82, 70, 0.83, 9437.76, 62, 3.98, 8827.39, 61, 1.82, 7084.9,
    57, 2.78, 6286.6, 56, 4.39, 14143.5, 56, 3.47, 6279.55, 52, 0.19, 12139.55,
    52, 1.33, 1748.02, 51, 0.28, 5856.48,
  ],
  [
    628331966747, 0, 0, 206059, 2.678235, 6283.07585, 4303, 2.6351, 12566.1517,
  ],
  [
    52919, 0, 0, 8720, 1.0721, 6283.0758,
  ],
];
const EARTH_B = [
  [
    280, 3.199, 84334.662, 102, 5.422, 5507.553, 80, 3.88, 5223.69,
  ],
];
const EARTH_R = [
  [
    100013989, 0, 0, 1670700, 3.0984635, 6283.07585, 13956, 3.05525, 12566.1517,
    3084, 5.1985, 77713.7715, 1628, 1.1739, 5753.3849, 1576, 2.8469, 7860.4194,
    925, 5.453, 11506.77, 542, 4.564, 3930.21, 472, 3.661, 5884.927, 346, 0.964, 5507.553,
    329, 5.9, 5223.694, 307, 0.299, 5573.143, 243, 4.273, 11790.629, 212, 5.847, 1577.344,
    186, 5.022, 10977.079, 175, 3.012, 18849.228, 110, 5.055, 5486.778, 98, 0.89, 6069.78,
    86, 5.69, 15720.84, 86, 1.27, 161000.69, 65, 0.27, 17260.15, 63, 0.92, 529.69,
    57, 2.01, 83996.85, 56, 5.24, 71430.7,
  ],
  [
    103019, 1.10749, 6283.07585, 1721, 1.0644, 12566.1517, 702, 3.142, 0,
  ],
];

// Sum_i (sum_j A cos(B + C JME)) JME^i / 1e8 (SPA eq. 9-11).
function series(rows, jme) {
  let total = 0;
  let power = 1;
  for (const row of rows) {
    let sum = 0;
    for (let k = 0; k < row.length; k += 3) sum += row[k] * Math.cos(row[k + 1] + row[k + 2] * jme);
    total += sum * power;
    power *= jme;
  }
  return total / 1e8;
}

// Delta T = TT - UT1 in seconds: Espenak & Meeus (NASA, 2006) polynomials, branch by branch as
// core/light/delta_t.cpp has them.
function deltaT(y) {
  const longTerm = (yr) => {
    const u = (yr - 1820) / 100;
    return -20 + 32 * u * u;
  };
  if (y < -500) return longTerm(y);
  if (y < 500) {
    const u = y / 100;
    return 10583.6 + u * (-1014.41 + u * (33.78311 + u * (-5.952053 + u * (-0.1798452 + u * (0.022174192 + u * 0.0090316521)))));
  }
  if (y < 1600) {
    const u = (y - 1000) / 100;
    return 1574.2 + u * (-556.01 + u * (71.23472 + u * (0.319781 + u * (-0.8503463 + u * (-0.005050998 + u * 0.0083572073)))));
  }
  if (y < 1700) {
    const t = y - 1600;
    return 120 + t * (-0.9808 + t * (-0.01532 + t / 7129));
  }
  if (y < 1800) {
    const t = y - 1700;
    return 8.83 + t * (0.1603 + t * (-0.0059285 + t * (0.00013336 - t / 1174000)));
  }
  if (y < 1860) {
    const t = y - 1800;
    return 13.72 + t * (-0.332447 + t * (0.0068612 + t * (0.0041116 + t * (-0.00037436 + t * (0.0000121272 + t * (-0.0000001699 + t * 0.000000000875))))));
  }
  if (y < 1900) {
    const t = y - 1860;
    return 7.62 + t * (0.5737 + t * (-0.251754 + t * (0.01680668 + t * (-0.0004473624 + t / 233174))));
  }
  if (y < 1920) {
    const t = y - 1900;
    return -2.79 + t * (1.494119 + t * (-0.0598939 + t * (0.0061966 - t * 0.000197)));
  }
  if (y < 1941) {
    const t = y - 1920;
    return 21.2 + t * (0.84493 + t * (-0.0761 + t * 0.0020936));
  }
  if (y < 1961) {
    const t = y - 1950;
    return 29.07 + t * (0.407 + t * (-1 / 233 + t / 2547));
  }
  if (y < 1986) {
    const t = y - 1975;
    return 45.45 + t * (1.067 + t * (-1 / 260 - t / 718));
  }
  if (y < 2005) {
    const t = y - 2000;
    return 63.86 + t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + t * 0.00002373599))));
  }
  if (y < 2050) {
    const t = y - 2000;
    return 62.92 + t * (0.32217 + t * 0.005589);
  }
  if (y < 2150) return longTerm(y) - 0.5628 * (2150 - y);
  return longTerm(y);
}

// The instant as a decimal year on the UTC calendar (as core/light/utc_time.cpp's decimal_year).
function decimalYear(ms) {
  const year = new Date(ms).getUTCFullYear();
  const start = Date.UTC(year, 0, 1);
  const end = Date.UTC(year + 1, 0, 1);
  return year + (ms - start) / (end - start);
}

// The ICAO standard atmosphere at a height (Atmosphere::standard_at): 1013.25 hPa and 15 C at sea
// level, a lapse of 6.5 C/km, the height clamped to -500..11000 m.
function standardAtmosphere(heightM) {
  const h = Math.min(Math.max(heightM, -500), 11000);
  const kelvin = 288.15 - 0.0065 * h;
  return { pressureHpa: 1013.25 * Math.pow(kelvin / 288.15, 5.25588), temperatureC: kelvin - 273.15 };
}

// SPA eq. 42 (Saemundsson), degrees, for the unrefracted elevation e0; 0 when the sun is wholly
// below the horizon (e0 < -(sun radius 0.26667 + horizon refraction 0.5667)).
function refractionDeg(e0, atm) {
  if (e0 < -(0.26667 + 0.5667)) return 0;
  return ((atm.pressureHpa / 1010) * (283 / (273 + atm.temperatureC)) * 1.02) / (60 * Math.tan((e0 + 10.3 / (e0 + 5.11)) * RAD));
}

// date: a JS Date (UTC instant). site: {latitudeDeg, longitudeDeg, heightM}
// returns {azimuthDeg, elevationDeg, elevationUnrefractedDeg}
export function sunPosition(date, site) {
  const ms = date instanceof Date ? date.getTime() : NaN;
  const { latitudeDeg, longitudeDeg } = site;
  const heightM = site.heightM ?? 0;
  if (!Number.isFinite(ms)) throw new RangeError('sunPosition: date is not a valid Date');
  if (!(latitudeDeg >= -90 && latitudeDeg <= 90)) throw new RangeError('sunPosition: latitudeDeg outside [-90, 90]');
  if (!Number.isFinite(longitudeDeg)) throw new RangeError('sunPosition: longitudeDeg is not finite');
  if (!Number.isFinite(heightM)) throw new RangeError('sunPosition: heightM is not finite');

  // Julian day (UT, from the Unix epoch) and ephemeris day (TT).
  const jd = 2440587.5 + ms / 86400000;
  const jde = jd + deltaT(decimalYear(ms)) / 86400;
  const jc = (jd - 2451545) / 36525;
  const jce = (jde - 2451545) / 36525;
  const jme = jce / 10;

  // Geocentric sun: the Earth's heliocentric longitude + 180 deg, minus its latitude.
  const theta = wrap360(series(EARTH_L, jme) / RAD + 180);
  const beta = -series(EARTH_B, jme) / RAD;
  const r = series(EARTH_R, jme);

  // Nutation (Meeus ch. 22, four terms) and the true obliquity, degrees.
  const omega = 125.04452 - 1934.136261 * jce + 0.0020708 * jce * jce + (jce * jce * jce) / 450000;
  const lSun = 280.4665 + 36000.7698 * jce;
  const lMoon = 218.3165 + 481267.8813 * jce;
  const dPsi = (-17.2 * sinD(omega) - 1.32 * sinD(2 * lSun) - 0.23 * sinD(2 * lMoon) + 0.21 * sinD(2 * omega)) / 3600;
  const dEps = (9.2 * cosD(omega) + 0.57 * cosD(2 * lSun) + 0.1 * cosD(2 * lMoon) - 0.09 * cosD(2 * omega)) / 3600;
  const eps0 = 23.43929111111111 + (jce * (-46.815 + jce * (-0.00059 + jce * 0.001813))) / 3600;
  const eps = eps0 + dEps;

  // Aberration, apparent longitude, apparent sidereal time at Greenwich.
  const lambda = theta + dPsi - 20.4898 / (3600 * r);
  const nu0 = wrap360(280.46061837 + 360.98564736629 * (jd - 2451545) + 0.000387933 * jc * jc - (jc * jc * jc) / 38710000);
  const nu = nu0 + dPsi * cosD(eps);

  // Geocentric right ascension and declination, and the observer's hour angle.
  const alpha = wrap360(Math.atan2(sinD(lambda) * cosD(eps) - Math.tan(beta * RAD) * sinD(eps), cosD(lambda)) / RAD);
  const delta = Math.asin(sinD(beta) * cosD(eps) + cosD(beta) * sinD(eps) * sinD(lambda));
  const hourAngle = wrap360(nu + longitudeDeg - alpha) * RAD;

  // Topocentric parallax on the ellipsoid (1 - flattening 0.99664719, equatorial radius 6378140 m).
  const phi = latitudeDeg * RAD;
  const xi = (8.794 / (3600 * r)) * RAD;
  const u = Math.atan(0.99664719 * Math.tan(phi));
  const x = Math.cos(u) + (heightM / 6378140) * Math.cos(phi);
  const y = 0.99664719 * Math.sin(u) + (heightM / 6378140) * Math.sin(phi);
  const denominator = Math.cos(delta) - x * Math.sin(xi) * Math.cos(hourAngle);
  const deltaAlpha = Math.atan2(-x * Math.sin(xi) * Math.sin(hourAngle), denominator);
  const deltaPrime = Math.atan2((Math.sin(delta) - y * Math.sin(xi)) * Math.cos(deltaAlpha), denominator);
  const hPrime = hourAngle - deltaAlpha;

  // Topocentric elevation, refraction, azimuth clockwise from north.
  const e0 = Math.asin(Math.sin(phi) * Math.sin(deltaPrime) + Math.cos(phi) * Math.cos(deltaPrime) * Math.cos(hPrime)) / RAD;
  const elevationDeg = e0 + refractionDeg(e0, standardAtmosphere(heightM));
  const gamma = Math.atan2(Math.sin(hPrime), Math.cos(hPrime) * Math.sin(phi) - Math.tan(deltaPrime) * Math.cos(phi)) / RAD;
  return { azimuthDeg: wrap360(gamma + 180), elevationDeg, elevationUnrefractedDeg: e0 };
}
