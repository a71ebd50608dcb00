# Makes the Blender fixtures of tests/data: a scene of three animated objects exported with Blender's
# default FBX, glTF (glb) and Collada settings, with Blender's own evaluation of every object's world
# pose at every frame; a glb whose two animations move the same object; an animated Empty with an
# animated mesh object as its child, exported to FBX and glb, with Blender's evaluation likewise; and a
# bar skinned to a two-bone armature whose bones turn, as glb, with the world position of every vertex of
# Blender's evaluated (deformed) mesh at every frame.
#
#   blender -b --factory-startup --python tests/interop/make_fixtures.py -- OUTDIR
#
# Written for Blender 3.4 (Debian 12's), whose glTF exporter needs python3-numpy. The files are
# committed, so tst_blender_fixtures needs no Blender; tests/interop runs this script again on every
# test run and the same test on what it writes (tst_blender_exports), so Blender's exporters of the
# day are checked too.

import json
import math
import os
import sys

import bpy

FPS = 30
FRAME_START = 1
FRAME_END = 11


def output_folder():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 1:
        sys.exit("usage: blender -b --factory-startup --python make_fixtures.py -- OUTDIR")
    os.makedirs(arguments[0], exist_ok=True)
    return arguments[0]


def empty_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for action in list(bpy.data.actions):
        bpy.data.actions.remove(action)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.render.fps_base = 1.0
    scene.frame_start = FRAME_START
    scene.frame_end = FRAME_END
    return scene


def tetrahedron(name):
    # The smallest closed mesh, so that the files stay a few kilobytes.
    mesh = bpy.data.meshes.new(name + "Mesh")
    vertices = [(0.5, 0.0, 0.0), (-0.25, 0.4, 0.0), (-0.25, -0.4, 0.0), (0.0, 0.0, 0.8)]
    mesh.from_pydata(vertices, [], [(0, 2, 1), (0, 1, 3), (1, 2, 3), (2, 0, 3)])
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def key_rotations(obj, frames_and_angles):
    # Keys the rotation in the object's own rotation mode: Euler angles in degrees, or a quaternion
    # made from them (XYZ) for QUATERNION; inserting the first key creates the action "<name>Action".
    for frame, degrees in frames_and_angles:
        radians = [math.radians(a) for a in degrees]
        if obj.rotation_mode == 'QUATERNION':
            from mathutils import Euler
            obj.rotation_quaternion = Euler(radians, 'XYZ').to_quaternion()
            obj.keyframe_insert("rotation_quaternion", frame=frame)
        else:
            obj.rotation_euler = radians
            obj.keyframe_insert("rotation_euler", frame=frame)


def key_locations(obj, frames_and_locations):
    for frame, location in frames_and_locations:
        obj.location = location
        obj.keyframe_insert("location", frame=frame)


def build_three_objects():
    scene = empty_scene()
    quat = tetrahedron("Quat")
    quat.rotation_mode = 'QUATERNION'
    key_rotations(quat, [(1, (0, 0, 0)), (4, (40, 10, 70)), (8, (-20, 60, 150)), (11, (10, -30, 200))])
    key_locations(quat, [(1, (0, 0, 0)), (11, (0, 1.5, 0.5))])

    euler = tetrahedron("EulerXYZ")
    euler.rotation_mode = 'XYZ'
    euler.location = (3, 0, 0)
    # Z turns 290° between its last two keys: the long way, as Euler curves play it.
    key_rotations(euler, [(1, (10, 0, 0)), (6, (80, 45, -30)), (11, (170, 85, 260))])

    child = tetrahedron("ChildZXY")
    child.rotation_mode = 'ZXY'
    child.parent = euler
    child.location = (0, 2, 0)
    key_rotations(child, [(1, (0, 0, 0)), (3, (30, 60, 90)), (8, (-45, 20, 250)), (11, (0, 10, 300))])
    key_locations(child, [(1, (0, 2, 0)), (11, (0, 2, 1))])
    for obj in (quat, euler, child):
        assert obj.animation_data.action.name == obj.name + "Action", obj.animation_data.action.name
    return scene, [quat, euler, child]


def evaluated_poses(scene, objects):
    # Blender's own evaluation: each object's world rotation (w, x, y, z) and location at every frame,
    # in Blender's Z-up world, metres.
    frames = []
    for frame in range(FRAME_START, FRAME_END + 1):
        scene.frame_set(frame)
        poses = {}
        for obj in objects:
            location, rotation, _scale = obj.matrix_world.decompose()
            poses[obj.name] = [rotation.w, rotation.x, rotation.y, rotation.z, location.x, location.y, location.z]
        frames.append({"frame": frame, "poses": poses})
    scene.frame_set(FRAME_START)
    return {"fps": FPS, "frame_start": FRAME_START, "frame_end": FRAME_END, "up": "z", "unit": "m",
            "frames": frames}


def export_all(folder, stem):
    bpy.ops.export_scene.fbx(filepath=os.path.join(folder, stem + ".fbx"))
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, stem + ".glb"))
    bpy.ops.wm.collada_export(filepath=os.path.join(folder, stem + ".dae"))


def build_two_actions_one_object():
    # One object with two actions: "Spin" on an NLA track and the assigned "Wobble". Blender's glTF
    # exporter writes each as an animation of its own, both moving "Wheel": a choice, not a merge.
    scene = empty_scene()
    wheel = tetrahedron("Wheel")
    wheel.rotation_mode = 'XYZ'
    key_rotations(wheel, [(1, (0, 0, 0)), (11, (0, 0, 180))])
    spin = wheel.animation_data.action
    spin.name = "Spin"
    track = wheel.animation_data.nla_tracks.new()
    track.strips.new("Spin", FRAME_START, spin)
    wheel.animation_data.action = None
    key_rotations(wheel, [(1, (0, 0, 0)), (6, (30, 0, 0)), (11, (0, 0, 0))])
    wheel.animation_data.action.name = "Wobble"
    return scene


def build_empty_and_mesh():
    # An Empty (plain axes, Euler XYZ) that turns and slides, carrying a tetrahedron that turns on it.
    scene = empty_scene()
    pivot = bpy.data.objects.new("Pivot", None)
    pivot.empty_display_type = 'PLAIN_AXES'
    scene.collection.objects.link(pivot)
    pivot.rotation_mode = 'XYZ'
    key_rotations(pivot, [(1, (0, 0, 0)), (5, (20, -10, 60)), (11, (45, 30, 170))])
    key_locations(pivot, [(1, (1, 0, 0)), (11, (1, 2, 0.5))])
    blade = tetrahedron("Blade")
    blade.rotation_mode = 'QUATERNION'
    blade.parent = pivot
    blade.location = (0, 0, 1)
    key_rotations(blade, [(1, (0, 0, 0)), (6, (70, 0, 20)), (11, (100, 40, 90))])
    assert pivot.type == 'EMPTY' and blade.type == 'MESH'
    return scene, [pivot, blade]


def build_skinned_bar():
    # A bar along x from 0 to 2, a square section 0.2 wide at x = 0, 0.5, ..., 2, skinned to the bones
    # Upper (x 0 to 1) and Lower (1 to 2): the weights blend linearly over the middle section.
    scene = empty_scene()
    armature_data = bpy.data.armatures.new("RigData")
    rig = bpy.data.objects.new("Rig", armature_data)
    scene.collection.objects.link(rig)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='EDIT')
    upper = armature_data.edit_bones.new("Upper")
    upper.head, upper.tail = (0, 0, 0), (1, 0, 0)
    lower = armature_data.edit_bones.new("Lower")
    lower.head, lower.tail = (1, 0, 0), (2, 0, 0)
    lower.parent = upper
    lower.use_connect = True
    bpy.ops.object.mode_set(mode='OBJECT')

    sections = [0.0, 0.5, 1.0, 1.5, 2.0]
    corners = [(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)]
    vertices = [(x, y, z) for x in sections for (y, z) in corners]
    faces = []
    for s in range(len(sections) - 1):
        for c in range(4):
            a, b = 4 * s + c, 4 * s + (c + 1) % 4
            faces.append((a, b, b + 4, a + 4))
    faces += [(3, 2, 1, 0), (16, 17, 18, 19)]
    mesh = bpy.data.meshes.new("BarMesh")
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    bar = bpy.data.objects.new("Bar", mesh)
    scene.collection.objects.link(bar)
    bar.parent = rig
    groups = {"Upper": bar.vertex_groups.new(name="Upper"), "Lower": bar.vertex_groups.new(name="Lower")}
    for index, (x, _y, _z) in enumerate(vertices):
        lower_weight = min(1.0, max(0.0, x - 0.5))  # 0 up to x = 0.5, 1 from x = 1.5
        if lower_weight < 1.0:
            groups["Upper"].add([index], 1.0 - lower_weight, 'REPLACE')
        if lower_weight > 0.0:
            groups["Lower"].add([index], lower_weight, 'REPLACE')
    modifier = bar.modifiers.new("Armature", 'ARMATURE')
    modifier.object = rig

    for name, keys in (("Upper", [(1, (0, 0, 0)), (6, (0, 0, 35)), (11, (20, 0, 50))]),
                       ("Lower", [(1, (0, 0, 0)), (6, (0, 0, 60)), (11, (-30, 10, 90))])):
        bone = rig.pose.bones[name]
        bone.rotation_mode = 'XYZ'
        for frame, degrees in keys:
            bone.rotation_euler = [math.radians(a) for a in degrees]
            bone.keyframe_insert("rotation_euler", frame=frame)
    return scene, bar


def evaluated_vertices(scene, obj):
    # Blender's own evaluation of the deformed mesh: every vertex's world position at every frame.
    frames = []
    for frame in range(FRAME_START, FRAME_END + 1):
        scene.frame_set(frame)
        evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        world = evaluated.matrix_world
        frames.append({"frame": frame, "vertices": [list(world @ v.co) for v in evaluated.to_mesh().vertices]})
        evaluated.to_mesh_clear()
    scene.frame_set(FRAME_START)
    return {"fps": FPS, "frame_start": FRAME_START, "frame_end": FRAME_END, "object": obj.name, "frames": frames}


def main():
    folder = output_folder()
    scene, objects = build_three_objects()
    with open(os.path.join(folder, "blender_three_objects.json"), "w") as out:
        json.dump(evaluated_poses(scene, objects), out, indent=1)
    export_all(folder, "blender_three_objects")
    build_two_actions_one_object()
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "blender_two_actions.glb"))
    scene, objects = build_empty_and_mesh()
    with open(os.path.join(folder, "blender_empty_and_mesh.json"), "w") as out:
        json.dump(evaluated_poses(scene, objects), out, indent=1)
    bpy.ops.export_scene.fbx(filepath=os.path.join(folder, "blender_empty_and_mesh.fbx"))
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "blender_empty_and_mesh.glb"))
    scene, bar = build_skinned_bar()
    with open(os.path.join(folder, "blender_skinned_bar.json"), "w") as out:
        json.dump(evaluated_vertices(scene, bar), out, indent=1)
    bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "blender_skinned_bar.glb"))


main()
