# Does Blender deform a skinned mesh Gyre exports as Blender itself did? Blender's skinned bar
# (make_fixtures.py: a bar weighted to a two-bone armature whose bones turn, exported as glb) is imported
# with `gyre-cli import`, exported with `gyre-cli export` as glb (checked by the Khronos validator: no
# errors), FBX or Collada, and imported by Blender's glTF, FBX or Collada importer (default settings). At every
# frame of the original, the world position of every vertex of Blender's evaluated (deformed) mesh must lie
# within 1e-6 m of a vertex of Blender's own evaluation of the original scene, and the other way round;
# tst_blender_fixtures checks Gyre's own skinning against the same evaluation, so Blender plays Gyre's skin as
# Gyre does.
#
# Times: the original's frame f is at (f - frame_start) / fps in Gyre (the import puts the first key at
# 0); glTF and Gyre's Collada store no frame rate, and Blender's importers key time t at frame t × 24; FBX
# keeps the frame rate, and Blender's importer puts time 0 at frame 1. Gyre's glTF is Y-up and Blender's
# importer turns it Z-up, Gyre's FBX is Z-up as Blender is (blender_import_gyre.py). Gyre's Collada is Y-up
# too: Blender's Collada importer turns every top-level object by the file's up axis, but an animated
# object's action then sets its transform again (so rigid objects lie turned, blender_import_gyre.py); the
# armature object it makes for the joints has no action of its own and keeps the turn, and the skinned mesh
# is its child. So world positions compare as they are for every format.
#
#   blender -b --factory-startup --python tests/interop/blender_skin_gyre.py -- \
#       glb|fbx|dae GYRE_CLI NODE VALIDATE_GLTF_SCRIPT VALIDATOR_PREFIX SCENE.glb EVALUATION.json

import json
import math
import os
import subprocess
import sys
import tempfile
import warnings

import bpy
from mathutils import Vector
from mathutils.kdtree import KDTree

POSITION_TOLERANCE = 1e-6
MIN_DEFORMATION = 0.5  # metres a vertex of the original moves between its first and last frame
# What each format's skin looks like in the file: glTF's skins, FBX's Cluster deformers, Collada's skin controller.
SKIN_MARK = {"glb": b'"skins"', "fbx": b"Cluster", "dae": b"<skin source="}


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) != 7 or args[0] not in ("glb", "fbx", "dae"):
        sys.exit("usage: blender -b --factory-startup --python blender_skin_gyre.py -- "
                 "glb|fbx|dae GYRE_CLI NODE VALIDATE_GLTF_SCRIPT VALIDATOR_PREFIX SCENE.glb EVALUATION.json")
    return args


def farthest_from(points, others):
    """The largest distance from one of `points` to the nearest of `others`."""
    tree = KDTree(len(others))
    for i, p in enumerate(others):
        tree.insert(p, i)
    tree.balance()
    return max(tree.find(p)[2] for p in points)


def load_gltf(path):
    # Debian's Blender 3.4 glTF importer uses numpy.bool, which numpy 1.24 removed.
    import numpy
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FutureWarning)
        if not hasattr(numpy, "bool"):
            numpy.bool = bool
    bpy.ops.import_scene.gltf(filepath=path)


def main():
    kind, gyre_cli, node, validate_script, validator, scene_file, evaluation_file = arguments()
    with open(evaluation_file, encoding="utf-8") as f:
        evaluation = json.load(f)
    problems = []
    with tempfile.TemporaryDirectory() as folder:
        project = os.path.join(folder, "skinned.gyre")
        exported = os.path.join(folder, "skinned." + kind)
        subprocess.run([gyre_cli, "import", scene_file, "-o", project], check=True)
        subprocess.run([gyre_cli, "export", project, "-o", exported], check=True)
        with open(exported, "rb") as f:
            if SKIN_MARK[kind] not in f.read():
                problems.append("the %s has no skin" % kind)
        bpy.ops.wm.read_factory_settings(use_empty=True)
        if kind == "glb":
            if subprocess.run([node, validate_script, "--validator", validator, exported]).returncode != 0:
                problems.append("the glb does not pass the validator")
            load_gltf(exported)
        elif kind == "fbx":
            bpy.ops.import_scene.fbx(filepath=exported)
        else:
            bpy.ops.wm.collada_import(filepath=exported)

    scene = bpy.context.scene
    obj = bpy.data.objects.get(evaluation["object"])
    if obj is None or obj.type != "MESH":
        sys.exit("FAILED: no mesh object '%s'" % evaluation["object"])
    if not any(m.type == "ARMATURE" and m.object for m in obj.modifiers):
        problems.append("'%s' is not deformed by an armature" % obj.name)
    frames = evaluation["frames"]
    first = [Vector(v) for v in frames[0]["vertices"]]
    last = [Vector(v) for v in frames[-1]["vertices"]]
    deformation = max((a - b).length for a, b in zip(first, last))
    if deformation < MIN_DEFORMATION:
        problems.append("the original moves its vertices only %g m" % deformation)
    worst = 0.0
    for entry in frames:
        time = (entry["frame"] - evaluation["frame_start"]) / evaluation["fps"]
        frame = time * scene.render.fps / scene.render.fps_base + (1.0 if kind == "fbx" else 0.0)
        scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
        evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        world = evaluated.matrix_world
        deformed = [world @ v.co for v in evaluated.to_mesh().vertices]
        evaluated.to_mesh_clear()
        expected = [Vector(v) for v in entry["vertices"]]
        worst = max(worst, farthest_from(expected, deformed), farthest_from(deformed, expected))
    if worst > POSITION_TOLERANCE:
        problems.append("vertices off by %g m" % worst)
    print("%s, skinned %s: %d frames, vertices move up to %.3f m; worst vertex %.1e m%s"
          % (kind, os.path.basename(scene_file), len(frames), deformation, worst,
             "" if not problems else " -- FAILED: " + "; ".join(problems)))
    sys.exit(1 if problems else 0)


main()
