# Does Blender import Gyre's FBX as Gyre plays it? For each project: `gyre-cli export` writes it as
# FBX, `gyre-cli bake` gives every object's pose relative to its parent at each frame and key time, and
# Blender's FBX importer (default settings: it takes the axes the file names, Z up like Gyre's world
# and Blender's, so it turns nothing) reads the file. At every baked time the object's transform
# relative to its parent in Blender (for a top-level object, its world transform, the importer's
# axis conversion taken out) must match the bake: orientation within 0.01°,
# position within 1e-4 units, scale 1 (UnitScaleFactor 100: one unit is one Blender metre). The
# scene's frame rate must be the project's, and each action must end at the project's end time.
#
# Run it with Blender 3.4 (Debian's `blender`), from the top of the source tree:
#   blender -b --factory-startup --python tests/interop/blender_import_fbx.py -- \
#       build/src/cli/gyre-cli resources/samples/*.gyre
# It prints one line per project and exits with status 1 if any check fails. Objects whose name
# another object shares are skipped (gyre-cli bake selects objects by name).
#
# One limit of Blender 3.4's importer shows here, not of the file: it places keys at the frame rate
# rounded to an integer (so a 12.5 fps project plays 4% fast; integer rates are exact).

import json
import math
import os
import subprocess
import sys
import tempfile

import bpy
from bpy_extras.io_utils import axis_conversion
from mathutils import Quaternion, Vector

ANGLE_TOLERANCE_DEGREES = 0.01
POSITION_TOLERANCE = 1e-4
SCALE_TOLERANCE = 1e-5


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) < 2:
        sys.exit("usage: blender -b --factory-startup --python blender_import_fbx.py -- GYRE_CLI PROJECT.gyre...")
    return args[0], args[1:]


def baked_poses(gyre_cli, project, name, fps, folder):
    """The object's poses from gyre-cli bake: (time, quaternion, position) rows."""
    csv = os.path.join(folder, "bake.csv")
    subprocess.run([gyre_cli, "bake", project, "--object", name, "--fps", repr(fps), "-o", csv], check=True)
    rows = []
    with open(csv, encoding="utf-8") as lines:
        next(lines)  # time,qw,qx,qy,qz,x,y,z
        for line in lines:
            t, qw, qx, qy, qz, x, y, z = map(float, line.split(","))
            rows.append((t, Quaternion((qw, qx, qy, qz)), Vector((x, y, z))))
    return rows


def angle_between(a, b):
    """The angle of the rotation from a to b, degrees, in [0, 180]. Through atan2 of the difference's
    parts rather than acos of a dot product: mathutils works in single precision, where acos near 1
    cannot resolve angles below 0.04°."""
    d = a.normalized().conjugated() @ b.normalized()
    return math.degrees(2.0 * math.atan2(Vector((d.x, d.y, d.z)).length, abs(d.w)))


def check_project(gyre_cli, project, folder):
    with open(project, encoding="utf-8") as f:
        document = json.load(f)
    fps = float(document["fps"])
    end = float(document["endTime"])
    names = [o["name"] for o in document["objects"]]
    parent_of = {o["id"]: o.get("parent") for o in document["objects"]}
    name_of = {o["id"]: o["name"] for o in document["objects"]}

    fbx = os.path.join(folder, "scene.fbx")
    subprocess.run([gyre_cli, "export", project, "-o", fbx], check=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.fbx(filepath=fbx)
    scene = bpy.context.scene
    problems = []
    blender_fps = scene.render.fps / scene.render.fps_base
    if abs(blender_fps - fps) > 1e-6 * fps:
        problems.append("frame rate %g, not %g" % (blender_fps, fps))
    # Blender 3.4's importer places the keys at time × render.fps, the frame rate rounded to an
    # integer (fps_base carries the rest): at 12.5 fps the keys land at 12 frames a second.
    key_fps = scene.render.fps
    if key_fps != fps:
        problems.append("keys placed at %d frames a second, so the motion plays at %g times its speed"
                        % (key_fps, blender_fps / key_fps))

    # The importer turns the file's axes into Blender's at the top level. Gyre's FBX names Blender's
    # own axes (UpAxis Z, FrontAxis -Y, which io_scene_fbx calls up "Z", forward "Y"), so this is the
    # identity: the scene stands as it does in Gyre.
    to_blender = axis_conversion(from_forward="Y", from_up="Z").to_4x4()
    if to_blender != to_blender.Identity(4):
        problems.append("the importer's axis conversion is not the identity")
    worst_angle = worst_position = worst_scale = 0.0
    for object_id, name in name_of.items():
        if names.count(name) > 1:
            continue
        obj = bpy.data.objects.get(name)
        if obj is None:
            problems.append("'%s' is missing" % name)
            continue
        parent_id = parent_of[object_id]
        expected_parent = name_of.get(parent_id) if parent_id else None
        if (obj.parent.name if obj.parent else None) != expected_parent:
            problems.append("'%s' has parent %s, not %s" % (name, obj.parent and obj.parent.name, expected_parent))
        rows = baked_poses(gyre_cli, project, name, fps, folder)
        action = obj.animation_data.action if obj.animation_data else None
        if len(rows) > 1:
            last_frame = 1.0 + rows[-1][0] * key_fps  # the importer puts time 0 at frame 1
            if action is None or abs(action.frame_range[1] - last_frame) > 1e-3:
                problems.append("'%s' ends at frame %s, not %g" % (name, action and action.frame_range[1], last_frame))
        for time, orientation, position in rows:
            frame = 1.0 + time * key_fps
            scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
            frame_of_parent = obj.parent.matrix_world if obj.parent else to_blender
            location, rotation, scale = (frame_of_parent.inverted() @ obj.matrix_world).decompose()
            worst_angle = max(worst_angle, angle_between(rotation, orientation))
            worst_position = max(worst_position, (location - position).length)
            worst_scale = max(worst_scale, max(abs(s - 1.0) for s in scale))
    if worst_angle > ANGLE_TOLERANCE_DEGREES:
        problems.append("orientation off by %.6f°" % worst_angle)
    if worst_position > POSITION_TOLERANCE:
        problems.append("position off by %g" % worst_position)
    if worst_scale > SCALE_TOLERANCE:
        problems.append("scale off by %g" % worst_scale)
    print("%s: %d objects, %g fps, %g s; worst angle %.2e°, position %.1e, scale %.1e%s"
          % (os.path.basename(project), len(names), blender_fps, end, worst_angle, worst_position, worst_scale,
             "" if not problems else " -- FAILED: " + "; ".join(problems)))
    return not problems


def main():
    gyre_cli, projects = arguments()
    passed = True
    with tempfile.TemporaryDirectory() as folder:
        for project in projects:
            passed = check_project(gyre_cli, project, folder) and passed
    sys.exit(0 if passed else 1)


main()
