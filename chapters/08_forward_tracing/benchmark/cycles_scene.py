"""Render a course scene (assets/scenes/*.json) with Blender Cycles, for chapter 08's comparison.

Run inside Blender (Debian's blender 3.4):

    blender -b --factory-startup --python cycles_scene.py -- --scene cornell.json --size 300 \
        --spp 64 --seed 1 --threads 2 --out cycles.pfm

It builds the same scene in Cycles (what the scene-kind suite uses: quads, transformed boxes, triangles, faceted
OBJ and PLY meshes, a sphere as a smooth 256x128 UV mesh, diffuse, emissive, mirror and dielectric materials, a
constant environment, and the medium between the shapes as the World's volume; and a plane, as a large quad,
for ch04_analytic.json's units check; anything else is refused), renders it on the CPU with a 1-pixel box
filter, no denoising, no clamping, no adaptive sampling and 64 bounces of every kind, and writes the linear
image as a PFM with the course's orientation (rows bottom up, as common/rt/io/image_io.cpp writes them). It
prints one line

    cycles_scene: render_seconds <wall time of bpy.ops.render.render> spp <n> size <w>x<h> ...

with, when Cycles reported them in the render's metadata, its own times in seconds (0.01 s resolution):
cycles_render_time (path tracing only, the like of the course's "time"), cycles_synchronization_time (scene
export and BVH build) and cycles_total_time.

The course's geometry (its transform, a box's six faces, a quad's corners) comes from scene_geometry.py, beside
this script.
"""
import argparse
import json
import math
import os
import struct
import sys
import tempfile
import time

import bmesh
import bpy
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # scene_geometry.py, beside this script
from scene_geometry import box_quads, camera_vfov, mesh_triangles, quad_corners  # noqa: E402


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles_scene.py")
    p.add_argument("--scene", required=True, help="the course's scene JSON")
    p.add_argument("--size", type=int, default=None, help="width and height (default: the scene's image)")
    p.add_argument("--width", type=int, default=None)
    p.add_argument("--height", type=int, default=None)
    p.add_argument("--spp", type=int, default=None, help="samples per pixel (default: the scene's image.spp)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--bounces", type=int, default=64, help="max bounces, of every kind")
    p.add_argument("--light-threshold", type=float, default=None,
                   help="Cycles' light_sampling_threshold (default: Cycles' own, 0.01; 0 switches it off)")
    p.add_argument("--guiding", action="store_true",
                   help="Cycles' path guiding on (use_guiding, surfaces and volumes; refused where the build has no "
                        "OpenPGL, whose use_guiding changes nothing)")
    p.add_argument("--two-sided-emission", action="store_true",
                   help="diagnosis only: emit on both sides (the course's lamps emit on one)")
    p.add_argument("--plane-size", type=float, default=1e4,
                   help="half the side of the square quad that stands for an infinite plane")
    p.add_argument("--sphere-segments", type=int, default=256, help="UV sphere segments (rings: half)")
    p.add_argument("--out", required=True, help="the PFM to write")
    p.add_argument("--blend", default=None, help="also save the built scene as a .blend (for inspection)")
    return p.parse_args(argv)


# --- materials ---------------------------------------------------------------------------------------------

def make_material(name, desc, two_sided=False):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    kind = desc["type"]
    emission = desc.get("emission", [0, 0, 0])
    if kind == "diffuse":
        albedo = desc.get("albedo", [0.8, 0.8, 0.8])
        bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*albedo, 1)
        bsdf.inputs["Roughness"].default_value = 0.0  # Lambert
        surface = bsdf.outputs["BSDF"]
        if max(emission) > 0:
            # One-sided emission: the front (the side of the face normal) emits; the back is black.
            peak = max(emission)
            em = nt.nodes.new("ShaderNodeEmission")
            em.inputs["Color"].default_value = (emission[0] / peak, emission[1] / peak, emission[2] / peak, 1)
            em.inputs["Strength"].default_value = peak
            front = em.outputs["Emission"]
            if max(albedo) > 0:
                add_node = nt.nodes.new("ShaderNodeAddShader")
                nt.links.new(em.outputs["Emission"], add_node.inputs[0])
                nt.links.new(bsdf.outputs["BSDF"], add_node.inputs[1])
                front = add_node.outputs["Shader"]
            if two_sided:
                nt.links.new(front, out.inputs["Surface"])
                m.cycles.sample_as_light = True
                return m
            geo = nt.nodes.new("ShaderNodeNewGeometry")
            mix = nt.nodes.new("ShaderNodeMixShader")
            nt.links.new(geo.outputs["Backfacing"], mix.inputs["Fac"])
            nt.links.new(front, mix.inputs[1])                 # Fac 0: front face
            nt.links.new(bsdf.outputs["BSDF"], mix.inputs[2])  # Fac 1: back face, reflects only
            surface = mix.outputs["Shader"]
        m.cycles.sample_as_light = True
    elif kind == "mirror":
        # The course's mirror reflects `reflectance` of the light at every angle (no Fresnel): Glossy, Sharp.
        if max(emission) > 0:
            raise SystemExit("cycles_scene.py: mirror '%s': emission is not translated" % name)
        bsdf = nt.nodes.new("ShaderNodeBsdfGlossy")
        bsdf.distribution = "SHARP"
        bsdf.inputs["Color"].default_value = (*desc.get("reflectance", [1, 1, 1]), 1)
        surface = bsdf.outputs["BSDF"]
    elif kind == "dielectric":
        for key in ("absorption", "roughness", "medium"):
            if key in desc:
                raise SystemExit("cycles_scene.py: dielectric '%s': %s is not translated" % (name, key))
        bsdf = nt.nodes.new("ShaderNodeBsdfGlass")
        bsdf.distribution = "SHARP"
        bsdf.inputs["Color"].default_value = (1, 1, 1, 1)
        bsdf.inputs["IOR"].default_value = desc.get("ior", 1.5)
        surface = bsdf.outputs["BSDF"]
    else:
        raise SystemExit("cycles_scene.py: material type '%s' is not translated" % kind)
    nt.links.new(surface, out.inputs["Surface"])
    return m


def link_mesh_object(name, mesh, material, smooth):
    """Give `mesh` its material and smooth or flat shading, and link it into the scene as the object `name`."""
    for poly in mesh.polygons:
        poly.use_smooth = smooth
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def quads_object(name, quads, material):
    verts, faces = [], []
    for quad in quads:
        # Counter-clockwise seen from u x v: Blender's face normal is then the course's quad normal.
        i = len(verts)
        verts += quad_corners(quad)
        faces.append((i, i + 1, i + 2, i + 3))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    return link_mesh_object(name, mesh, material, smooth=False)


def sphere_object(name, center, radius, segments, material):
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=segments, v_segments=segments // 2, radius=radius)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)  # outward
    bmesh.ops.translate(bm, verts=bm.verts, vec=Vector(center))
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    return link_mesh_object(name, mesh, material, smooth=True)


def triangles_object(name, triangles, material):
    """Triangles [(p0, p1, p2)] as one faceted mesh, each counter-clockwise as given (its normal (p1 − p0) ×
    (p2 − p0), as the course's)."""
    verts, faces = [], []
    for tri in triangles:
        i = len(verts)
        verts += list(tri)
        faces.append((i, i + 1, i + 2))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    return link_mesh_object(name, mesh, material, smooth=False)


def world_volume(world, medium):
    """The course's medium between the shapes as the World's volume: Volume Scatter (σs = colour × density,
    Henyey–Greenstein anisotropy g) plus Volume Absorption (σa = (1 − colour) × density)."""
    nt = world.node_tree
    out = nt.nodes.get("World Output")
    sigma_s = medium.get("sigma_s", [0, 0, 0])
    sigma_a = medium.get("sigma_a", [0, 0, 0])
    shaders = []
    if max(sigma_s) > 0:
        scatter = nt.nodes.new("ShaderNodeVolumeScatter")
        d = max(sigma_s)
        scatter.inputs["Color"].default_value = (sigma_s[0] / d, sigma_s[1] / d, sigma_s[2] / d, 1)
        scatter.inputs["Density"].default_value = d
        scatter.inputs["Anisotropy"].default_value = medium.get("g", 0.0)
        shaders.append(scatter.outputs["Volume"])
    if max(sigma_a) > 0:
        absorb = nt.nodes.new("ShaderNodeVolumeAbsorption")
        d = max(sigma_a)
        absorb.inputs["Color"].default_value = (1 - sigma_a[0] / d, 1 - sigma_a[1] / d, 1 - sigma_a[2] / d, 1)
        absorb.inputs["Density"].default_value = d
        shaders.append(absorb.outputs["Volume"])
    if not shaders:
        return
    volume = shaders[0]
    if len(shaders) == 2:
        add_node = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(shaders[0], add_node.inputs[0])
        nt.links.new(shaders[1], add_node.inputs[1])
        volume = add_node.outputs["Shader"]
    nt.links.new(volume, out.inputs["Volume"])


def build(scene_desc, args):
    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for data in (bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras):
        for block in list(data):
            data.remove(block)

    materials = {name: make_material(name, d, args.two_sided_emission) for name, d in scene_desc.get("materials", {}).items()}
    for i, s in enumerate(scene_desc.get("shapes", [])):
        name = "shape%02d_%s" % (i, s["type"])
        mat = materials[s["material"]]
        if s["type"] == "quad":
            quads_object(name, [(tuple(s["origin"]), tuple(s["u"]), tuple(s["v"]))], mat)
        elif s["type"] == "box":
            quads_object(name, box_quads(s), mat)
        elif s["type"] == "sphere":
            sphere_object(name, s["center"], s["radius"], args.sphere_segments, mat)
        elif s["type"] == "plane":
            # An infinite plane as a square quad of half-size --plane-size around its point, facing `normal`.
            n = Vector(s["normal"]).normalized()
            t = (Vector((1, 0, 0)) if abs(n.x) < 0.9 else Vector((0, 1, 0))).cross(n).normalized()
            b = n.cross(t)  # t x b = n: the quad's front is the plane's front
            h = args.plane_size
            origin = Vector(s["point"]) - h * t - h * b
            quads_object(name, [(tuple(origin), tuple(2 * h * t), tuple(2 * h * b))], mat)
        elif s["type"] == "triangle":
            triangles_object(name, [tuple(tuple(v) for v in s["vertices"])], mat)
        elif s["type"] == "mesh":
            try:
                triangles = mesh_triangles(s, os.path.dirname(os.path.abspath(args.scene)))
            except ValueError as e:
                raise SystemExit("cycles_scene.py: %s" % e)
            triangles_object(name, triangles, mat)
        else:
            raise SystemExit("cycles_scene.py: shape type '%s' is not translated" % s["type"])

    # World: the environment light's constant radiance (black without one), and the medium between the shapes.
    radiance = [0, 0, 0]
    for light in scene_desc.get("lights", []):
        if light["type"] != "environment" or "image" in light:
            raise SystemExit("cycles_scene.py: lights other than a constant environment are not translated")
        radiance = light["radiance"]
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    bg = world.node_tree.nodes.get("Background")
    peak = max(radiance)
    bg.inputs["Color"].default_value = (*(c / peak for c in radiance), 1) if peak > 0 else (0, 0, 0, 1)
    bg.inputs["Strength"].default_value = peak
    if "medium" in scene_desc:
        world_volume(world, scene_desc["medium"])
        world.cycles.homogeneous_volume = True  # one density everywhere, as the course's medium
    scene.world = world

    # Camera: pinhole, vertical field of view, the course's basis (right = forward x up, up' = right x forward),
    # as scene_geometry.camera_basis builds it, but in Blender's single-precision vectors: computed in double
    # precision it can differ in the last bit, and Cycles' samples (the image's noise) with it.
    cam_desc = scene_desc["camera"]
    eye = Vector(cam_desc["from"])
    forward = (Vector(cam_desc["at"]) - eye).normalized()
    right = forward.cross(Vector(cam_desc.get("up", [0, 1, 0]))).normalized()
    up = right.cross(forward)
    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "PERSP"
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(camera_vfov(cam_desc))
    cam_data.clip_start = 1e-3
    cam_data.clip_end = 1e7
    cam = bpy.data.objects.new("camera", cam_data)
    rot = Matrix((right, up, -forward)).transposed()  # columns: camera x (right), y (up), z (backward)
    cam.matrix_world = Matrix.Translation(eye) @ rot.to_4x4()
    scene.collection.objects.link(cam)
    scene.camera = cam


def configure(scene_desc, args):
    scene = bpy.context.scene
    image = scene_desc.get("image", {})
    width = args.width or args.size or image.get("width", 320)
    height = args.height or args.size or image.get("height", 240)
    spp = args.spp or image.get("spp", 16)
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1
    r.threads_mode = "FIXED"
    r.threads = args.threads
    r.use_persistent_data = False
    r.film_transparent = False
    r.use_motion_blur = False
    c = scene.cycles
    c.device = "CPU"
    c.feature_set = "SUPPORTED"
    c.samples = spp
    c.seed = args.seed
    c.use_animated_seed = False
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.time_limit = 0
    c.sample_clamp_direct = 0
    c.sample_clamp_indirect = 0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    n = args.bounces
    c.max_bounces = n
    c.diffuse_bounces = n
    c.glossy_bounces = n
    c.transmission_bounces = n
    c.volume_bounces = n
    c.transparent_max_bounces = n
    c.min_light_bounces = 0
    c.min_transparent_bounces = 0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.blur_glossy = 0.0
    if args.light_threshold is not None:
        c.light_sampling_threshold = args.light_threshold
    c.use_fast_gi = False
    if args.guiding:
        import _cycles
        if not _cycles.with_path_guiding:
            sys.stderr.write("cycles_scene.py: --guiding: Blender %s was built without path guiding (OpenPGL): "
                             "use_guiding would render the unguided image\n" % bpy.app.version_string)
            sys.exit(2)
        c.use_guiding = c.use_surface_guiding = c.use_volume_guiding = True
    c.film_exposure = 1.0
    c.use_auto_tile = False  # one tile: the image is small
    scene.view_layers[0].cycles.use_denoising = False
    scene.view_layers[0].cycles.denoising_store_passes = False
    vs = scene.view_settings
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "Linear"
    settings = r.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGBA"
    settings.color_depth = "32"
    settings.exr_codec = "NONE"
    return width, height, spp


def write_pfm(path, width, height, rgba):
    """PF, little-endian (scale -1), rows bottom up: Blender's pixel order is already bottom row first."""
    rgb = [0.0] * (width * height * 3)
    rgb[0::3] = rgba[0::4]
    rgb[1::3] = rgba[1::4]
    rgb[2::3] = rgba[2::4]
    tmp = path + ".part"
    with open(tmp, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        f.write(struct.pack("<%df" % len(rgb), *rgb))
    os.replace(tmp, path)


def main():
    args = parse_args()
    with open(args.scene) as f:
        scene_desc = json.load(f)
    build(scene_desc, args)
    width, height, spp = configure(scene_desc, args)
    c = bpy.context.scene.cycles
    w = bpy.context.scene.world.cycles
    print("cycles_scene: blender %s, sampling_pattern %s, light_sampling_threshold %g, use_guiding %s, "
          "scrambling_distance %g, sample_as_light on emitters, world: sampling_method %s, volume_sampling %s, "
          "homogeneous_volume %s"
          % (bpy.app.version_string, c.sampling_pattern, c.light_sampling_threshold, c.use_guiding,
             c.scrambling_distance, w.sampling_method, w.volume_sampling, w.homogeneous_volume), flush=True)
    if args.blend:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.blend))

    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    render_seconds = time.perf_counter() - t0

    result = bpy.data.images["Render Result"]
    with tempfile.TemporaryDirectory() as tmp:
        exr = os.path.join(tmp, "render.exr")
        result.save_render(exr, scene=bpy.context.scene)
        img = bpy.data.images.load(exr)
        img.colorspace_settings.is_data = True  # no colour conversion: the linear values as rendered
        if tuple(img.size) != (width, height):
            raise SystemExit("cycles_scene.py: the render is %dx%d, expected %dx%d" % (*img.size, width, height))
        rgba = list(img.pixels[:])
        cycles_times = read_exr_times(exr)
    write_pfm(args.out, width, height, rgba)
    # Cycles' own times (resolution 0.01 s): path tracing only, its scene synchronisation (BVH included), total.
    extra = " ".join("cycles_%s %s" % (k, v) for k, v in sorted(cycles_times.items()))
    print("cycles_scene: render_seconds %.4f spp %d size %dx%d threads %d seed %d %s" %
          (render_seconds, spp, width, height, args.threads, args.seed, extra), flush=True)
    print("cycles_scene: wrote %s" % args.out, flush=True)


def seconds_of(text):
    """Cycles' "[hh:]mm:ss.xx" as seconds."""
    total = 0.0
    for part in text.strip().split(":"):
        total = total * 60 + float(part)
    return total


def read_exr_times(path):
    """Cycles' own times from the EXR header's string attributes (cycles.*.render_time, ...), if present."""
    found = {}
    try:
        with open(path, "rb") as f:
            data = f.read(1 << 16)
        i = 8  # magic and version
        while i < len(data) and data[i] != 0:
            j = data.index(b"\0", i)
            name = data[i:j].decode("latin-1")
            k = data.index(b"\0", j + 1)
            kind = data[j + 1:k].decode("latin-1")
            size = struct.unpack("<i", data[k + 1:k + 5])[0]
            value = data[k + 5:k + 5 + size]
            if kind == "string" and name.startswith("cycles.") and name.endswith("time"):
                found[name.split(".")[-1]] = "%.2f" % seconds_of(value.decode("latin-1").rstrip("\0"))
            i = k + 5 + size
    except Exception as e:  # the times are extra information only
        found["exr_header_error"] = repr(e).replace(" ", "_")
    return found


if __name__ == "__main__":
    main()
