"""Renders a scene that pm-export-scene wrote with Blender's Cycles: the lab's second renderer.

    blender -b --factory-startup -P scripts/cycles/render.py -- SCENE_DIR [--samples 32] [--only pass|sequence] [--limit N]

(--limit N: the first N views of the pass and N frames of the sequence only, for a look.)

Writes into SCENE_DIR, beside what pm-export-scene put there:
  views/     the pass as a user's rig records it (left_%02d.png, right_%02d.png, background_left_%02d.png,
             background_right_%02d.png, pose_fPh_%02d.yaml): pm-make-model --views SCENE_DIR/views --rig SCENE_DIR/rig.json
  sequence/  left_%04d.png, right_%04d.png and truth.csv (the toy frame in the hand frame, mm and quaternion vector)
  cycles.json  how it was rendered (samples, light, noise, time)

What Cycles adds to the lab's rasterizer: a square area light fixed in the world (soft cast shadows with a
penumbra, the toy darkening its backdrop where it rests), light bounced between the toy and its backdrop,
highlights of the area light on the toy's plastic, a depth of field focused on the toy, and a sensor's
noise (Gaussian, sigma 2 grey levels, a fixed seed per image; Cycles' own noise at 32 samples is 0.4 to
1.3 grey levels, in the penumbrae the most). About 7 s an image on 2 cores. The backdrop is the lab's sea bottom or a
green cloth made here (scene.json's backdrop kind). Images already rendered are kept: an interrupted run
is resumed by running it again. The script fetches nothing.
"""
import json
import math
import os
import shutil
import sys
import time

import bpy
import cv2
import numpy as np
from mathutils import Matrix, Vector

SENSOR_WIDTH_MM = 36.0
NOISE_SIGMA = 2.0          # grey levels, per channel (the lab's sensor noise)
APERTURE_MM = 4.0          # the lens's aperture diameter: about half a pixel of blur 50 mm off the focus at 500 mm
LIGHT_POWER_W = 13.0
WORLD_FILL = 0.03


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = {"samples": 32, "only": "all", "limit": 100000}
    positional = []
    i = 0
    while i < len(argv):
        if argv[i] in ("--samples", "--only", "--limit"):
            if i + 1 >= len(argv):
                sys.exit("error: %s needs a value" % argv[i])
            args[argv[i][2:]] = argv[i + 1]
            i += 2
        elif argv[i] in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        else:
            positional.append(argv[i])
            i += 1
    if len(positional) != 1:
        sys.exit("error: give one scene folder (written by pm-export-scene); --help for usage")
    args["dir"] = positional[0]
    args["samples"] = int(args["samples"])
    args["limit"] = int(args["limit"])
    if args["only"] not in ("all", "pass", "sequence"):
        sys.exit("error: --only takes pass or sequence")
    return args


def matrix(rows):
    return Matrix([list(r) for r in rows])


def import_obj(path):
    before = set(bpy.data.objects)
    # Blender's own axes (z up, y forward): the file's coordinates are taken as they are.
    bpy.ops.wm.obj_import(filepath=path, forward_axis='Y', up_axis='Z')
    obj = [o for o in bpy.data.objects if o not in before][0]
    obj.matrix_world = Matrix.Identity(4)
    for poly in obj.data.polygons:
        poly.use_smooth = True
    return obj


def image_material(name, texture_path, roughness, specular):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = bpy.data.images.load(texture_path)
    tex.interpolation = 'Linear'
    links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Specular"].default_value = specular
    return mat


def cloth_material():
    """A green cloth: a fine weave and a slow mottling, matte with a little sheen."""
    mat = bpy.data.materials.new("cloth")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    coord = nodes.new("ShaderNodeTexCoord")
    mottle = nodes.new("ShaderNodeTexNoise")
    mottle.inputs["Scale"].default_value = 6.0
    mottle.inputs["Detail"].default_value = 4.0
    weave = nodes.new("ShaderNodeTexWave")
    weave.inputs["Scale"].default_value = 400.0
    weave.inputs["Distortion"].default_value = 2.0
    ramp = nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].color = (0.035, 0.16, 0.07, 1)
    ramp.color_ramp.elements[1].color = (0.09, 0.30, 0.16, 1)
    mix = nodes.new("ShaderNodeMixRGB")
    mix.blend_type = 'MULTIPLY'
    mix.inputs["Fac"].default_value = 0.25
    links.new(coord.outputs["UV"], mottle.inputs["Vector"])
    links.new(coord.outputs["UV"], weave.inputs["Vector"])
    links.new(mottle.outputs["Fac"], ramp.inputs["Fac"])
    links.new(ramp.outputs["Color"], mix.inputs["Color1"])
    links.new(weave.outputs["Color"], mix.inputs["Color2"])
    links.new(mix.outputs["Color"], bsdf.inputs["Base Color"])
    bsdf.inputs["Roughness"].default_value = 1.0
    bsdf.inputs["Specular"].default_value = 0.2
    bsdf.inputs["Sheen"].default_value = 0.5
    return mat


def build_scene(scene_dir, desc, samples):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = 'CYCLES'
    sc.cycles.device = 'CPU'
    sc.cycles.samples = samples
    sc.cycles.use_adaptive_sampling = True
    sc.cycles.adaptive_threshold = 0.03
    sc.cycles.use_denoising = False
    sc.cycles.max_bounces = 4
    sc.cycles.diffuse_bounces = 1
    sc.cycles.glossy_bounces = 2
    sc.cycles.transmission_bounces = 0
    sc.cycles.volume_bounces = 0
    sc.cycles.caustics_reflective = False
    sc.cycles.caustics_refractive = False
    cam0 = desc["cameras"][0]
    sc.render.resolution_x = cam0["width"]
    sc.render.resolution_y = cam0["height"]
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = 'PNG'
    sc.render.image_settings.color_depth = '16'
    sc.render.image_settings.color_mode = 'RGB'
    sc.view_settings.view_transform = 'Standard'
    sc.view_settings.look = 'None'

    world = bpy.data.worlds.new("room")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (WORLD_FILL, WORLD_FILL, WORLD_FILL, 1)
    sc.world = world

    toy = import_obj(os.path.join(scene_dir, desc["toy"]["mesh"]))
    toy.data.materials.clear()
    toy.data.materials.append(image_material("toy", os.path.join(scene_dir, "toy_texture.png"), desc["toy"]["roughness"], 0.5))
    backdrop = import_obj(os.path.join(scene_dir, desc["backdrop"]["mesh"]))
    backdrop.data.materials.clear()
    if desc["backdrop"]["kind"] == "cloth":
        backdrop.data.materials.append(cloth_material())
    else:
        backdrop.data.materials.append(image_material("sea-bottom", os.path.join(scene_dir, "backdrop_texture.png"), 0.85, 0.3))

    light_data = bpy.data.lights.new("area", type='AREA')
    light_data.shape = 'SQUARE'
    light_data.size = desc["light"]["size_m"]
    light_data.energy = LIGHT_POWER_W
    light = bpy.data.objects.new("area", light_data)
    sc.collection.objects.link(light)
    pos, aim = Vector(desc["light"]["fMl_position"]), Vector(desc["light"]["aim"])
    z = (pos - aim).normalized()                      # an area light shines along its -z
    x = Vector((0, 0, 1)).cross(z)
    if x.length < 1e-6:
        x = Vector((1, 0, 0))
    x.normalize()
    y = z.cross(x)
    light.matrix_world = Matrix(((x[0], y[0], z[0], pos[0]), (x[1], y[1], z[1], pos[1]), (x[2], y[2], z[2], pos[2]), (0, 0, 0, 1)))

    cams = []
    for c in desc["cameras"]:
        data = bpy.data.cameras.new(c["name"])
        data.sensor_fit = 'HORIZONTAL'
        data.sensor_width = SENSOR_WIDTH_MM
        data.lens = c["px"] * SENSOR_WIDTH_MM / c["width"]
        # ViSP's pixel centres are at integers, Blender's at i + 0.5: the principal point at u0 + 0.5.
        data.shift_x = (c["width"] / 2.0 - (c["u0"] + 0.5)) / c["width"]
        data.shift_y = ((c["v0"] + 0.5) - c["height"] / 2.0) / c["width"]
        sc.render.pixel_aspect_x = 1.0
        sc.render.pixel_aspect_y = c["px"] / c["py"]
        data.clip_start = 0.01
        data.clip_end = 10.0
        data.dof.use_dof = True
        data.dof.aperture_fstop = data.lens / APERTURE_MM
        obj = bpy.data.objects.new(c["name"], data)
        sc.collection.objects.link(obj)
        cams.append((obj, matrix(c["hMc"])))
    return sc, toy, backdrop, cams


# ViSP's camera looks along +z with y down; Blender's along -z with y up.
VISP_TO_BLENDER = Matrix(((1, 0, 0, 0), (0, -1, 0, 0), (0, 0, -1, 0), (0, 0, 0, 1)))


def render_image(sc, cam, hMc, fMh, focus_point, seed, path):
    if os.path.exists(path):
        return False
    obj = cam
    fMc = fMh @ hMc
    obj.matrix_world = fMc @ VISP_TO_BLENDER
    obj.data.dof.focus_distance = max(0.05, (fMc.inverted() @ focus_point).z)
    sc.camera = obj
    sc.cycles.seed = seed
    tmp = path + ".render.png"
    sc.render.filepath = tmp
    bpy.ops.render.render(write_still=True)
    img = cv2.imread(tmp, cv2.IMREAD_UNCHANGED).astype(np.float64) * (255.0 / 65535.0)
    rng = np.random.default_rng(seed)
    img += rng.normal(0.0, NOISE_SIGMA, img.shape)
    out = path + ".part.png"
    if not cv2.imwrite(out, np.clip(np.rint(img), 0, 255).astype(np.uint8)):
        sys.exit("error: cannot write %s" % out)
    os.replace(out, path)
    os.remove(tmp)
    return True


def main():
    args = parse_args()
    scene_dir = args["dir"]
    spec = os.path.join(scene_dir, "scene.json")
    if not os.path.isfile(spec):
        sys.exit("error: %s not found: write the scene first (pm-export-scene --out %s)" % (spec, scene_dir))
    with open(spec) as f:
        desc = json.load(f)
    if desc.get("format") != "visp-photomodel-scene":
        sys.exit("error: %s is not a scene of pm-export-scene" % spec)
    sc, toy, backdrop, cams = build_scene(scene_dir, desc, args["samples"])
    t0 = time.time()
    rendered = 0
    fMo_pass = matrix(desc["pass"]["fMo"])
    if args["only"] in ("all", "pass"):
        views = os.path.join(scene_dir, "views")
        os.makedirs(views, exist_ok=True)
        n = len(desc["pass"]["views"])
        for k, v in enumerate(desc["pass"]["views"][:args["limit"]]):
            fMh = matrix(v["fMh"])
            toy.matrix_world = fMo_pass
            backdrop.matrix_world = fMo_pass
            focus = fMo_pass.translation
            for with_toy in (True, False):
                toy.hide_render = not with_toy
                for ci, (cam, hMc) in enumerate(cams):
                    stem = ("" if with_toy else "background_") + cam.name
                    seed = 1000 + 4 * k + 2 * (not with_toy) + ci
                    rendered += render_image(sc, cam, hMc, fMh, focus, seed, os.path.join(views, "%s_%02d.png" % (stem, k)))
            shutil.copyfile(os.path.join(scene_dir, "lab_views", "pose_fPh_%02d.yaml" % k), os.path.join(views, "pose_fPh_%02d.yaml" % k))
            print("pass view %d of %d rendered (%.0f s)" % (k + 1, n, time.time() - t0), flush=True)
        toy.hide_render = False
    if args["only"] in ("all", "sequence"):
        seq = os.path.join(scene_dir, "sequence")
        os.makedirs(seq, exist_ok=True)
        frames = desc["sequence"]["frames"][:args["limit"]]
        for k, fr in enumerate(frames):
            fMh, fMo = matrix(fr["fMh"]), matrix(fr["fMo"])
            toy.matrix_world = fMo
            backdrop.matrix_world = matrix(fr["fMb"])
            for ci, (cam, hMc) in enumerate(cams):
                seed = 100000 + 2 * k + ci
                rendered += render_image(sc, cam, hMc, fMh, fMo.translation, seed, os.path.join(seq, "%s_%04d.png" % (cam.name, k)))
            if k % 10 == 9 or k + 1 == len(frames):
                print("sequence frame %d of %d rendered (%.0f s)" % (k + 1, len(frames), time.time() - t0), flush=True)
        if len(frames) == len(desc["sequence"]["frames"]):
            shutil.copyfile(os.path.join(scene_dir, "lab_sequence", "truth.csv"), os.path.join(seq, "truth.csv"))
    record = {"renderer": "Blender %s, Cycles" % bpy.app.version_string, "samples": args["samples"], "adaptive_threshold": 0.03,
              "light_power_w": LIGHT_POWER_W, "light_size_m": desc["light"]["size_m"], "world_fill": WORLD_FILL,
              "aperture_mm": APERTURE_MM, "noise_sigma": NOISE_SIGMA, "images_rendered_now": rendered,
              "seconds_now": round(time.time() - t0, 1)}
    with open(os.path.join(scene_dir, "cycles.json"), "w") as f:
        json.dump(record, f, indent=1)
    print("rendered %d images in %.0f s into %s" % (rendered, time.time() - t0, scene_dir))


if __name__ == "__main__":
    main()
