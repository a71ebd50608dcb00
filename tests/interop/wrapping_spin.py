# Blender writes an FBX whose object spins about Z through keys of 0°, 170°, 190°, 350°, 530° (XYZ Euler,
# linear), the spin a wrapped representation (Assimp's quaternions, angles in (−180°, 180°]) saw-tooths, with
# Blender's own evaluation of the object's world rotation at each key. tst_blender_euler_filter imports it
# with gyre-cli import --euler-filter.
#
#   blender -b --factory-startup --python tests/interop/wrapping_spin.py -- OUTDIR
#
# Written for Blender 3.4; exported with Blender's default FBX settings.

import json
import math
import os
import sys

import bpy

FPS = 30
KEYS = [(1, 0.0), (11, 170.0), (21, 190.0), (31, 350.0), (41, 530.0)]  # (frame, degrees about Z)


def main():
    folder = sys.argv[sys.argv.index("--") + 1]  # OUTDIR, after Blender's own arguments
    os.makedirs(folder, exist_ok=True)
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.render.fps_base = 1.0
    scene.frame_start = KEYS[0][0]
    scene.frame_end = KEYS[-1][0]
    mesh = bpy.data.meshes.new("SpinMesh")
    mesh.from_pydata([(0.5, 0.0, 0.0), (-0.25, 0.4, 0.0), (-0.25, -0.4, 0.0), (0.0, 0.0, 0.8)], [],
                     [(0, 2, 1), (0, 1, 3), (1, 2, 3), (2, 0, 3)])
    mesh.update()
    spin = bpy.data.objects.new("Spin", mesh)
    scene.collection.objects.link(spin)
    spin.rotation_mode = 'XYZ'
    for frame, degrees in KEYS:
        spin.rotation_euler = (0.0, 0.0, math.radians(degrees))
        spin.keyframe_insert("rotation_euler", frame=frame)
    for curve in spin.animation_data.action.fcurves:
        for point in curve.keyframe_points:
            point.interpolation = 'LINEAR'
    keys = []
    for frame, degrees in KEYS:
        scene.frame_set(frame)
        rotation = spin.matrix_world.to_quaternion()
        keys.append({"frame": frame, "degrees": degrees,
                     "rotation": [rotation.w, rotation.x, rotation.y, rotation.z]})
    with open(os.path.join(folder, "wrapping_spin.json"), "w") as out:
        json.dump({"fps": FPS, "frame_start": KEYS[0][0], "keys": keys}, out, indent=1)
    bpy.ops.export_scene.fbx(filepath=os.path.join(folder, "wrapping_spin.fbx"))


main()
