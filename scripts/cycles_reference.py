"""An independent picture of a DEM: Blender Cycles path-traces it as a grid mesh (issue #32).

Run inside Blender (it bundles bpy; Debian's blender uses the system python, so osgeo imports):

    blender -b --factory-startup -P scripts/cycles_reference.py -- DEM OUT.tif [options]

scripts/cycles_reference.sh wraps it with terrashade on the same crop and the comparison
(docs/accuracy.md, "Against Blender Cycles").

Scene, chosen to be what terrashade's map view computes, with nothing approximated:
- the DEM (a projected CRS in metres; geographic grids have non-square texels, reproject first)
  as one vertex per texel centre, x east, y north, z up, each cell cut into --subdivide x
  --subdivide quads (default 4) on the bilinear surface between its corners: the surface
  terrashade's horizons and sun shadows sample. With one quad (two triangles) per cell the
  shadow edges move by a fraction of a texel, and under a 20 degree sun that alone was 0.8% of
  the relative RMSE (docs/accuracy.md);
- shading normals set to terrashade's (central differences, one-sided at the border,
  core/terrain/terrain_normals.hpp) as custom split normals; shadows and visibility come from
  the triangles themselves, their rays leaving the surface with Cycles' shadow terminator
  geometry offset (--terminator-offset, Cycles' default 0.1: a ray leaves from where the smooth
  normals put the surface, so a texel whose smooth normal faces the sun is not shadowed by the
  facet it sits on; 0: from the facet itself). Where the two differ the reference itself is
  undecided (scripts/cycles_compare.py --alternative; docs/accuracy.md, "Where the reference is
  undecided");
- a Lambert material (Diffuse BSDF, roughness 0) of grey albedo --albedo;
- the sky as a world shader: an equirectangular float map (--sky-map PREFIX, PREFIX.f32 and
  PREFIX.json as tests/light/sky_equirect_dump writes them from terrashade's own sky, so the
  radiance is the same to the float, in kcd/m^2), or an analytic --sky uniform / overcast of
  radiance --sky-radiance (overcast: L(theta) = L_z (1 + 2 cos theta) / 3, L_z = --sky-radiance;
  below the horizon both give a Lambert ground of albedo --ground-albedo under that sky);
- a sun lamp of 0.533 degrees angular diameter at --sun-azimuth / --sun-elevation (clockwise
  from north) of irradiance --sun-irradiance (normal to the beam; RGB from the sky map's JSON
  when given). Cycles' sun strength is that irradiance: a Lambert plane facing it has radiance
  albedo x E / pi;
- an orthographic camera straight down, one pixel per texel centred on the vertices, a pixel
  filter of 0.01 px (every sample hits the texel centre, as terrashade shades texel centres);
- Standard view transform, no denoising, no adaptive sampling; the output is linear radiance
  (RGB float32 GeoTIFF with the crop's georeferencing; OUT.exr if the name ends in .exr).
"""
import argparse
import json
import math
import sys
import time

import bpy
import numpy as np
from mathutils import Vector
from osgeo import gdal, osr


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles_reference.py")
    p.add_argument("dem", help="DEM GeoTIFF in a projected CRS (metres)")
    p.add_argument("out", help="output: .tif (float32 RGB GeoTIFF) or .exr")
    p.add_argument("--srcwin", help="crop XOFF,YOFF,XSIZE,YSIZE in texels (as gdal_translate -srcwin)")
    p.add_argument("--sun-azimuth", type=float, default=135.0, help="degrees clockwise from north")
    p.add_argument("--sun-elevation", type=float, default=20.0, help="degrees above the horizon")
    p.add_argument("--sun-irradiance", type=float, default=0.0,
                   help="grey sun irradiance normal to the beam (0 = no sun; --sky-map's JSON overrides)")
    p.add_argument("--sky", choices=["map", "uniform", "overcast", "none"], default="map")
    p.add_argument("--sky-map", help="PREFIX of PREFIX.f32 + PREFIX.json (tests/light/sky_equirect_dump)")
    p.add_argument("--sky-radiance", type=float, default=1.0,
                   help="uniform: the radiance; overcast: the zenith radiance L_z")
    p.add_argument("--ground-albedo", type=float, default=0.2,
                   help="analytic skies: the ground below the horizon is this albedo under the sky")
    p.add_argument("--albedo", type=float, default=0.3, help="grey Lambert albedo of the terrain")
    p.add_argument("--bounces", type=int, default=4, help="max bounces: 0 = direct light only")
    p.add_argument("--samples", type=int, default=128)
    p.add_argument("--threads", type=int, default=0, help="0 = all cores")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--subdivide", type=int, default=4,
                   help="N x N quads per cell on the bilinear surface between the texel centres "
                        "(the surface terrashade's horizons sample); 1 = the plain grid of two triangles per cell")
    p.add_argument("--terminator-offset", type=float, default=0.1,
                   help="the terrain's shadow terminator geometry offset, 0..1 (Cycles' default 0.1; 0: "
                        "shadow rays leave from the facets themselves)")
    args = p.parse_args(argv)
    if not 0.0 <= args.terminator_offset <= 1.0:
        p.error("--terminator-offset must be within 0..1")
    if args.sky == "map" and not args.sky_map:
        p.error("--sky map needs --sky-map PREFIX")
    return args


def read_dem(path, srcwin):
    ds = gdal.Open(path)
    if ds is None:
        sys.exit(f"cycles_reference: cannot open {path}")
    srs = osr.SpatialReference(wkt=ds.GetProjection())
    if not srs.IsProjected():
        sys.exit("cycles_reference: the DEM must be in a projected CRS in metres "
                 "(reproject it, e.g. gdalwarp -t_srs '+proj=tmerc ...' -tr 90 90)")
    x0, y0, w, h = (0, 0, ds.RasterXSize, ds.RasterYSize) if not srcwin else map(int, srcwin.split(","))
    band = ds.GetRasterBand(1)
    z = band.ReadAsArray(x0, y0, w, h).astype(np.float64)
    nodata = band.GetNoDataValue()
    if nodata is not None and np.any(z == nodata):
        sys.exit("cycles_reference: the crop has nodata texels; pick another window")
    gt = list(ds.GetGeoTransform())
    if abs(abs(gt[1]) - abs(gt[5])) > 1e-6 * abs(gt[1]) or gt[2] or gt[4]:
        sys.exit("cycles_reference: texels must be square and north-up")
    cell = abs(gt[1]) * srs.GetLinearUnits()
    gt[0] += x0 * gt[1]
    gt[3] += y0 * gt[5]
    return z, cell, gt, ds.GetProjection()


def terrain_normals(z, cell):
    """terrashade's normals: central differences, one-sided on the border (row 0 is north)."""
    dzdx = np.gradient(z, cell, axis=1)  # east
    dzdy = -np.gradient(z, cell, axis=0)  # north: rows run south
    n = np.stack([-dzdx, -dzdy, np.ones_like(z)], axis=-1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def bilinear_refine(a, n):
    """a (rows, cols, ...) sampled n times finer, bilinearly, keeping the original samples."""
    if n == 1:
        return a
    h, w = a.shape[:2]
    r = np.arange((h - 1) * n + 1) / n
    c = np.arange((w - 1) * n + 1) / n
    r0 = np.minimum(np.floor(r).astype(int), h - 2)
    c0 = np.minimum(np.floor(c).astype(int), w - 2)
    fr = (r - r0).reshape((-1, 1) + (1,) * (a.ndim - 2))
    fc = (c - c0).reshape((1, -1) + (1,) * (a.ndim - 2))
    a00, a01 = a[r0][:, c0], a[r0][:, c0 + 1]
    a10, a11 = a[r0 + 1][:, c0], a[r0 + 1][:, c0 + 1]
    return (a00 * (1 - fr) * (1 - fc) + a01 * (1 - fr) * fc + a10 * fr * (1 - fc) + a11 * fr * fc)


def build_terrain(z, cell, albedo, subdivide=1, terminator_offset=0.1):
    # Subdivided, the mesh follows the bilinear surface between the texel centres, which is what
    # terrashade's horizons and sun shadows sample; the plain grid's two triangles per cell put
    # the shadow edge up to a few metres elsewhere. The texel centres stay vertices (the camera's
    # pixels), with terrashade's normals; the new vertices get the normals interpolated.
    normals = bilinear_refine(terrain_normals(z, cell), subdivide)
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    z = bilinear_refine(z, subdivide)
    cell = cell / subdivide
    h, w = z.shape
    xs = (np.arange(w) - (w - 1) / 2.0) * cell
    ys = ((h - 1) / 2.0 - np.arange(h)) * cell
    gx, gy = np.meshgrid(xs, ys)
    verts = np.stack([gx, gy, z], axis=-1).reshape(-1, 3)
    idx = np.arange(h * w).reshape(h, w)
    quads = np.stack([idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:], idx[:-1, :-1]], axis=-1).reshape(-1, 4)
    mesh = bpy.data.meshes.new("terrain")
    mesh.vertices.add(len(verts))
    mesh.vertices.foreach_set("co", verts.astype(np.float32).ravel())
    mesh.loops.add(quads.size)
    mesh.loops.foreach_set("vertex_index", quads.astype(np.int32).ravel())
    mesh.polygons.add(len(quads))
    mesh.polygons.foreach_set("loop_start", (np.arange(len(quads)) * 4).astype(np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(quads), 4, np.int32))
    mesh.polygons.foreach_set("use_smooth", np.ones(len(quads), bool))
    mesh.update()
    mesh.validate()
    mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices([tuple(v) for v in normals.reshape(-1, 3)])
    obj = bpy.data.objects.new("terrain", mesh)
    obj.cycles.shadow_terminator_geometry_offset = terminator_offset
    obj.cycles.shadow_terminator_offset = 0.0  # the shading offset: none, as Cycles' default
    bpy.context.scene.collection.objects.link(obj)

    mat = bpy.data.materials.new("lambert")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (albedo, albedo, albedo, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    mesh.materials.append(mat)
    return obj


def analytic_sky_map(kind, radiance, ground_albedo, width=1024):
    """Uniform or CIE overcast sky as an equirectangular map (row 0 the zenith), ground below."""
    height = width // 2
    zenith = (np.arange(height) + 0.5) / height * math.pi
    cos_t = np.cos(zenith)
    if kind == "uniform":
        sky = np.full(height, radiance)
        horizontal_irradiance = math.pi * radiance
    else:  # overcast: L_z (1 + 2 cos theta) / 3, horizontal irradiance 7 pi / 9 L_z
        sky = radiance * (1.0 + 2.0 * np.clip(cos_t, 0.0, None)) / 3.0
        horizontal_irradiance = 7.0 * math.pi / 9.0 * radiance
    row = np.where(cos_t > 0.0, sky, ground_albedo * horizontal_irradiance / math.pi)
    return np.repeat(np.repeat(row[:, None], width, axis=1)[:, :, None], 3, axis=2).astype(np.float32)


def set_world(pixels, scratch_exr):
    """An equirectangular map in Blender's layout: centre column east (+x), clockwise seen from above."""
    height, width, _ = pixels.shape
    buf = bpy.data.images.new("sky_buffer", width, height, alpha=True, float_buffer=True)
    buf.colorspace_settings.name = "Non-Color"  # else save() encodes the values as sRGB
    rgba = np.concatenate([pixels, np.ones((height, width, 1), np.float32)], axis=2)
    buf.pixels.foreach_set(rgba[::-1].ravel())  # Blender stores the bottom row first
    # Cycles does not see the edited pixels of a generated image in background mode: go
    # through a float EXR file and load it back as an ordinary image.
    buf.filepath_raw = scratch_exr
    buf.file_format = "OPEN_EXR"
    buf.save()
    img = bpy.data.images.load(scratch_exr)
    img.colorspace_settings.name = "Non-Color"  # linear values as given, no view transform
    world = bpy.data.worlds.new("sky")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    env = nodes.new("ShaderNodeTexEnvironment")
    env.image = img
    env.interpolation = "Linear"
    bg = nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(env.outputs["Color"], bg.inputs["Color"])
    links.new(bg.outputs["Background"], out.inputs["Surface"])


def add_sun(azimuth_deg, elevation_deg, irradiance_rgb, angular_diameter_rad):
    if max(irradiance_rgb) <= 0.0:
        return
    az, el = math.radians(azimuth_deg), math.radians(elevation_deg)
    towards_sun = Vector((math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)))
    light = bpy.data.lights.new("sun", type="SUN")
    peak = max(irradiance_rgb)
    light.energy = peak  # W/m^2 in Blender's words: the irradiance normal to the beam
    light.color = tuple(c / peak for c in irradiance_rgb)
    light.angle = angular_diameter_rad
    light.cycles.cast_shadow = True
    obj = bpy.data.objects.new("sun", light)
    obj.rotation_mode = "QUATERNION"
    obj.rotation_quaternion = towards_sun.to_track_quat("Z", "Y")  # a sun lamp shines along -z
    bpy.context.scene.collection.objects.link(obj)


def add_camera(z, cell):
    h, w = z.shape
    cam = bpy.data.cameras.new("ortho")
    cam.type = "ORTHO"
    cam.sensor_fit = "AUTO"  # ortho_scale spans the longer side
    cam.ortho_scale = max(w, h) * cell
    cam.clip_start = 1.0
    cam.clip_end = 4.0 * (float(z.max() - z.min()) + 1000.0)
    obj = bpy.data.objects.new("camera", cam)
    obj.location = (0.0, 0.0, float(z.max()) + 1000.0)  # looks down -z with +y (north) up
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def configure_render(scene, w, h, args, out_exr):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args.samples
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.seed = args.seed
    scene.cycles.max_bounces = args.bounces
    scene.cycles.diffuse_bounces = args.bounces
    scene.cycles.glossy_bounces = 0
    scene.cycles.transmission_bounces = 0
    scene.cycles.volume_bounces = 0
    scene.cycles.transparent_max_bounces = 0
    scene.cycles.sample_clamp_direct = 0.0
    scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.caustics_reflective = False
    scene.cycles.caustics_refractive = False
    scene.cycles.filter_width = 0.01
    scene.render.threads_mode = "FIXED" if args.threads else "AUTO"
    if args.threads:
        scene.render.threads = args.threads
    scene.render.resolution_x, scene.render.resolution_y = w, h
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.filepath = out_exr


def main():
    args = parse_args()
    scene = bpy.context.scene
    for obj in list(bpy.data.objects):  # --factory-startup's cube, lamp and camera
        bpy.data.objects.remove(obj, do_unlink=True)
    z, cell, gt, wkt = read_dem(args.dem, args.srcwin)
    h, w = z.shape
    build_terrain(z, cell, args.albedo, args.subdivide, args.terminator_offset)

    sun_rgb = [args.sun_irradiance] * 3
    sun_diameter = math.radians(0.533)
    if args.sky == "map":
        meta = json.load(open(args.sky_map + ".json"))
        pixels = np.fromfile(args.sky_map + ".f32", np.float32).reshape(meta["height"], meta["width"], 3)
        sun_rgb = meta["sun_irradiance_rgb"]
        sun_diameter = 2.0 * meta["sun_angular_radius_rad"]
        args.sun_azimuth, args.sun_elevation = meta["sun_azimuth_deg"], meta["sun_elevation_deg"]
    elif args.sky == "none":
        pixels = np.zeros((2, 4, 3), np.float32)
    else:
        pixels = analytic_sky_map(args.sky, args.sky_radiance, args.ground_albedo)
    set_world(pixels, args.out + ".sky.exr")
    add_sun(args.sun_azimuth, args.sun_elevation, sun_rgb, sun_diameter)
    add_camera(z, cell)

    out_exr = args.out if args.out.endswith(".exr") else args.out + ".cycles.exr"
    configure_render(scene, w, h, args, out_exr)
    t0 = time.time()
    bpy.ops.render.render(write_still=True)
    seconds = time.time() - t0

    if not args.out.endswith(".exr"):
        img = bpy.data.images.load(out_exr)
        rgba = np.array(img.pixels[:], np.float32).reshape(h, w, 4)[::-1]
        drv = gdal.GetDriverByName("GTiff")
        ds = drv.Create(args.out, w, h, 3, gdal.GDT_Float32, ["COMPRESS=DEFLATE", "PREDICTOR=3"])
        ds.SetGeoTransform(gt)
        ds.SetProjection(wkt)
        for b in range(3):
            ds.GetRasterBand(b + 1).WriteArray(rgba[:, :, b])
        ds = None
    print(json.dumps({"cycles_seconds": round(seconds, 2), "samples": args.samples, "bounces": args.bounces,
                      "albedo": args.albedo, "width": w, "height": h, "cell_m": cell,
                      "sun_irradiance_rgb": sun_rgb, "blender": bpy.app.version_string}))


main()
