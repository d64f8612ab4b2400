"""Reference sky radiance from Blender's Nishita sky (Cycles render), tabulated per direction.

blender -b --factory-startup --python-exit-code 1 -P scripts/nishita_sky_reference.py --
  --out OUT.csv [--sun-elevations 3,10,20,45] [--dust-density D] [--air-density A]
  [--ozone-density O] [--altitude M] [--width 720]   (or: nishita_sky_reference.sh OUT.csv ...)
Negative elevations need the '=' form (--sun-elevations=-2,3). Writes OUT.csv and, next to it,
one equirectangular panorama OUT_elev<E>.exr per sun elevation.

Blender's Nishita model, as read in Blender 3.x intern/sky/source/sky_nishita.cpp (its constant
tables are byte-identical in this 3.4 binary) and in the Cycles 3.4 kernel source shipped with
this Blender (summary in my words):
* Single scattering only: no multiple scattering, no ground-reflected light. Below the horizon
  Cycles fades the horizon colour to black by ~24 deg down (dir.z = -0.4), a stand-in ground.
* Spherical Earth radius 6360 km, atmosphere top 6420 km. Observer at 6360 km + altitude; Cycles
  clamps altitude to [1, 59999] m (0, 0.5 and 1 m render bit-identical images here).
* Rayleigh: scattering exactly ~ lambda^-4, 5.4248e-5 /m at 380 nm (1.236e-5 /m at 550 nm) at sea
  level x air_density; scale height 8 km; phase 3/(16 pi) (1 + mu^2); no absorption.
* Mie: sea-level scattering 2.0e-5 /m x dust_density at every wavelength; extinction 1.11 x that
  (2.22e-5 /m, albedo 0.9); scale height 1.2 km; Cornette-Shanks phase, g = 0.76.
* Ozone: absorption only, per-wavelength table (peak 2.736e-6 /m at 600 nm) x ozone_density,
  density a tent: 0 below 10 km, 1 at 25 km, 0 above 40 km.
* 21 wavelengths, 380..780 nm step 20. Sun = 5778 K Planck spectrum x the Sun's solid angle at
  1 AU (6.79e-5 sr): top-of-atmosphere irradiance in W m^-2 nm^-1 (1.79 at 500 nm, ~1366 W/m^2
  in total). For the sky the sun is a point; the Earth's shadow is honoured.
* Numerics: 32 equal segments along the view ray to the atmosphere top; optical depth toward
  the sun by 8-node Gauss-Laguerre quadrature.
* Units: radiance (W m^-2 sr^-1 nm^-1) x CIE 1931 2-deg functions x 20 nm, summed, with NO
  683 lm/W factor: Y = 1.0 is 1 W m^-2 sr^-1 of photopic-weighted radiance = 683 cd/m^2. XYZ ->
  scene-linear Rec.709 by the inverse standard sRGB/D65 matrix, negatives clamped to 0; with
  Background strength 1 the pixel value is that radiance, unscaled.
* The sky is precomputed into a 512x128 table (360 deg azimuth, mirrored about the sun; rows
  quadratic in elevation, dense at the horizon) read bilinearly. Its half-texel conventions make
  Blender read the model slightly off the asked direction: elevation 0.5/1/4/10 deg reads
  0.45/0.93/3.87/9.80, azimuth ~0.35 deg farther from the sun (0.7 deg at rel az 0). The CSV
  records what Blender renders, offsets included.

Pixel <-> direction (verified, not assumed: a 2-deg sun disc at 20 deg, W=720, had its centroid
at row 219.51, column 359.50; sun_rotation +30 deg moved it +60 columns; every run re-checks the
sun column). The camera at the origin, rotation (90, 0, 0) deg, looks along world +Y, where
sun_rotation = 0 puts the sun. In Blender's bottom-up pixel array (H = W/2 rows) the centre of
pixel (row j, column i) looks at  elevation = -90 + (j + 0.5) * 180 / H  and
rel_az = (i + 0.5) * 360 / W - 180  (degrees; positive = right in the image = clockwise seen
from above): the sun's azimuth is the boundary of columns W/2 - 1 and W/2 (the image centre).
"""
import argparse
import math
import os
import sys
import time

import bpy
import numpy as np  # bundled with Blender

VIEW_ELEVATIONS = [0.5, 1, 2, 4, 6, 10, 15, 20, 30, 45, 60, 75, 90]
REL_AZIMUTHS = [0, 5, 10, 20, 30, 45, 60, 90, 120, 150, 180]
# Linear Rec.709/D65 -> CIE XYZ; Blender's own srgb_to_xyz.spimtx, which rounds to
# 0.4124/0.3576/0.1805, 0.2126/0.7152/0.0722, 0.0193/0.1192/0.9505. Using Blender's exact
# matrix recovers the XYZ the sky model computed (up to the clamp of negative RGB).
RGB_TO_XYZ = np.array([[0.4124564, 0.3575761, 0.1804375],
                       [0.2126729, 0.7151522, 0.0721750],
                       [0.0193339, 0.1191920, 0.9503041]])


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="nishita_sky_reference.py")
    p.add_argument("--out", required=True, help="CSV path; EXRs go next to it")
    p.add_argument("--sun-elevations", default="3,10,20,45", help="degrees, comma separated")
    for name in ("dust", "air", "ozone"):
        p.add_argument("--%s-density" % name, type=float, default=1.0)  # Blender's defaults
    p.add_argument("--altitude", type=float, default=0.0, help="metres (Cycles clamps to >= 1)")
    p.add_argument("--width", type=int, default=720)
    a = p.parse_args(argv)
    a.sun_elevations = [float(s) for s in a.sun_elevations.split(",") if s.strip()]
    # W >= 360 keeps the 0.5-deg row off the below-horizon pixels; even W puts the sun on a
    # column boundary and makes H = W/2 exact.
    if a.width < 360 or a.width % 2:
        p.error("--width must be even and >= 360")
    return a


def build_scene(a):
    """Empty scene, sky world, equirectangular camera; returns the Sky Texture node."""
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    sc = bpy.context.scene
    world = sc.world = bpy.data.worlds.new("NishitaWorld")
    world.use_nodes = True
    nt = world.node_tree
    nt.nodes.clear()
    sky = nt.nodes.new("ShaderNodeTexSky")
    sky.sky_type = "NISHITA"
    sky.sun_disc, sky.sun_rotation = False, 0.0  # sky only: the disc is a separate term
    sky.altitude, sky.air_density = a.altitude, a.air_density
    sky.dust_density, sky.ozone_density = a.dust_density, a.ozone_density
    bg = nt.nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    nt.links.new(sky.outputs["Color"], bg.inputs["Color"])
    nt.links.new(bg.outputs["Background"], nt.nodes.new("ShaderNodeOutputWorld").inputs["Surface"])
    cam_data = bpy.data.cameras.new("Pano")
    cam_data.type = "PANO"
    cam_data.cycles.panorama_type = "EQUIRECTANGULAR"
    cam_data.cycles.latitude_min, cam_data.cycles.latitude_max = -math.pi / 2, math.pi / 2
    cam_data.cycles.longitude_min, cam_data.cycles.longitude_max = -math.pi, math.pi
    cam = bpy.data.objects.new("Pano", cam_data)
    sc.collection.objects.link(cam)
    sc.camera = cam
    cam.rotation_euler = (math.pi / 2, 0.0, 0.0)  # horizontal, looking along +Y (the sun)
    sc.render.engine, sc.cycles.device = "CYCLES", "CPU"
    sc.cycles.samples = 4  # the world is smooth and deterministic; samples only jitter
    sc.cycles.use_adaptive_sampling, sc.cycles.seed = False, 0
    sc.cycles.use_denoising = False  # also: this build has no OpenImageDenoise
    # Narrowest filter allowed: each pixel becomes a point sample at its centre.
    sc.cycles.pixel_filter_type, sc.cycles.filter_width = "GAUSSIAN", 0.01
    r = sc.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = a.width, a.width // 2, 100
    vs = sc.view_settings  # EXR stores scene-linear anyway; set as documented
    vs.view_transform, vs.look, vs.exposure, vs.gamma = "Standard", "None", 0.0, 1.0
    r.image_settings.file_format, r.image_settings.color_depth = "OPEN_EXR", "32"
    r.image_settings.color_mode = "RGB"
    return sc, sky


def load_exr(path, w, h):
    img = bpy.data.images.load(path, check_existing=False)
    img.colorspace_settings.name = "Non-Color"  # no transform: EXR holds scene-linear values
    nch, px = img.channels, np.empty(w * h * img.channels, np.float32)
    img.pixels.foreach_get(px)  # checked equal to OpenImageIO's read of the same file
    bpy.data.images.remove(img)
    return px.reshape(h, w, nch)[:, :, :3].astype(np.float64)  # row 0 = bottom (elev -90)


def sample(img, elev, rel_az):
    """Bilinear radiance at (elevation, azimuth from the sun), degrees; mapping in the header."""
    h, w, _ = img.shape
    if elev >= 90.0:
        # The zenith is the top edge, half a pixel above the last row: average that row over
        # all azimuths, which cancels the (linear) gradient across the zenith.
        return img[-1].mean(axis=0)
    r = min(max((elev + 90.0) * h / 180.0 - 0.5, 0.0), h - 1.0)
    c = (rel_az + 180.0) * w / 360.0 - 0.5
    r0, c0 = min(int(math.floor(r)), h - 2), int(math.floor(c))
    fr, fc = r - r0, c - c0
    c0, c1 = c0 % w, (c0 + 1) % w  # azimuth wraps
    lo = img[r0, c0] * (1 - fc) + img[r0, c1] * fc
    hi = img[r0 + 1, c0] * (1 - fc) + img[r0 + 1, c1] * fc
    return lo * (1 - fr) + hi * fr


def xyY(rgb):
    X, Y, Z = RGB_TO_XYZ @ rgb
    s = X + Y + Z
    return (X / s, Y / s, Y) if s > 0 else (float("nan"), float("nan"), Y)


def check_sun_column(img, sun_el):
    """Degrees between the expected sun azimuth and the brightest direction along the row at
    the sun's elevation (or 1 deg if the sun is lower): for sun_rotation = 0 it must be ~0."""
    h, w, _ = img.shape
    row = img[int(round((max(sun_el, 1.0) + 90.0) * h / 180.0 - 0.5))] @ RGB_TO_XYZ[1]
    i = int(np.argmax(row))
    a, b, c = row[i - 1], row[i], row[(i + 1) % w]
    den = a - 2 * b + c
    peak = i + (0.5 * (a - c) / den if den else 0.0)  # parabola through the 3 samples
    return (peak + 0.5) * 360.0 / w - 180.0


def main():
    a = parse_args()
    t0 = time.time()
    out = os.path.abspath(a.out)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    stem = os.path.splitext(out)[0]
    sc, sky = build_scene(a)
    w, h = a.width, a.width // 2
    rows, summary = [], []
    for sun_el in a.sun_elevations:
        sky.sun_elevation = math.radians(sun_el)
        exr = sc.render.filepath = "%s_elev%g.exr" % (stem, sun_el)
        t = time.time()
        bpy.ops.render.render(write_still=True)
        img = load_exr(exr, w, h)
        off = check_sun_column(img, sun_el)
        print("sun %g deg: rendered %s in %.1f s; brightest azimuth on the sun's row is %+.3f deg"
              " from the sun column" % (sun_el, exr, time.time() - t, off))
        if abs(off) > 360.0 / w and sun_el < 80:  # near the zenith the row has no clear peak
            raise SystemExit("sun azimuth column check FAILED; see the header for the mapping")
        got, asym = {}, 0.0
        for ve in VIEW_ELEVATIONS:
            for az in REL_AZIMUTHS:
                # The sky is mirror symmetric about the sun's azimuth: average both sides and
                # keep their difference as a second check of the column mapping.
                p, m = sample(img, ve, az), sample(img, ve, -az)
                asym = max(asym, 2 * float(np.max(np.abs(p - m) / np.maximum(p + m, 1e-30))))
                rgb = got[ve, az] = 0.5 * (p + m)
                rows.append("%g,%g,%g,%.6g,%.6g,%.6g,%.5f,%.5f,%.6g"
                            % ((sun_el, ve, az) + tuple(rgb) + xyY(rgb)))
        print("  max relative left/right asymmetry about the sun azimuth: %.2e" % asym)
        summary.append((sun_el, [xyY(got[4, az]) for az in (0, 5, 10)],
                        xyY(got[90, 0]), xyY(got[0.5, 180])))
    with open(out, "w") as f:
        f.write("sun_elevation_deg,view_elevation_deg,rel_azimuth_deg,r,g,b,x,y,Y\n")
        f.write("\n".join(rows) + "\n")
    print("\nCIE xy (Y in units of 683 cd/m^2); view elevation 4 deg at rel az 0/5/10, zenith,"
          " anti-sun horizon (view 0.5 deg, rel az 180)")
    print("%7s | %-13s %-13s %-13s | %-22s | %-22s" % ("sun_el", "4,0", "4,5", "4,10",
                                                       "zenith x y Y", "anti-sun x y Y"))
    for sun_el, near, zen, anti in summary:
        near_s = " ".join("%.4f,%.4f " % (x, y) for x, y, _ in near)
        print("%7g | %s| %.4f %.4f %-8.4g | %.4f %.4f %-8.4g"
              % (sun_el, near_s, zen[0], zen[1], zen[2], anti[0], anti[1], anti[2]))
    print("\nwrote %s (%d rows) and %d EXR(s) %s_elev*.exr; total %.1f s"
          % (out, len(rows), len(summary), stem, time.time() - t0))


main()
