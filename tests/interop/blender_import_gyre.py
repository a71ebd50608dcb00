# Does Blender import Gyre's exports as Gyre plays them? For each project and format (FBX, glb or
# Collada):
# `gyre-cli export` writes the file, `gyre-cli bake` gives every object's pose relative to its parent
# at each frame and key time (the times the export samples), and Blender's default importer for the
# format (bpy.ops.import_scene.fbx or .gltf, default settings) reads it. At every baked time the
# object's transform relative to its parent in Blender must match the bake: orientation within 0.01°,
# position within 1e-4 units, scale 1 (one Gyre unit is one Blender metre). The geometry must stand
# where Gyre puts it: at the first, the last and some baked times between, every vertex of the
# project's mesh, posed by the bake, must have a vertex of Blender's mesh within 1e-4. Each action
# must end at the last baked time (the clip's full length).
#
# FBX: the file names Blender's own axes (Z up, like Gyre's world), so the importer turns nothing and
# an object's frame in Blender is its frame in Gyre. The scene's frame rate must be the project's.
#
# glb: glTF is Y-up, so Gyre writes its top-level poses turned by yUpToZUp()⁻¹ (src/io/up_axis.h,
# turnZUpToYUp in src/io/scene_export.cpp), children and meshes as they are. Blender's glTF importer
# changes the basis of everything back to Z-up with C = +90° about X (Y becomes Z, Z becomes -Y):
# every node's local transform L becomes C·L·C⁻¹ and every mesh's vertices v become C·v
# (set_convert_functions in io_scene_gltf2/blender/imp/gltf2_blender_gltf.py). So a top-level object
# gets C·(C⁻¹·P)·C⁻¹ = P·C⁻¹ and a vertex lands at P·C⁻¹·C·v = P·v, where Gyre puts it: the object's
# Gyre frame in Blender is its matrix_world·C, and the test compares that (relative to the parent's,
# likewise) with the bake. The file's root node (GyreScene, the identity) becomes an empty that is
# every top-level object's parent. glTF stores no frame rate: the importer puts time t at frame
# t × scene.render.fps (Blender's default 24 fps, time 0 at frame 0), and the test evaluates Blender
# at that (sub)frame. The importer reads the file's float32 times and interpolates quaternion keys
# linearly; at the baked times (the file's keys) that is the key itself.
#
# Collada: Gyre writes it Y-up (Assimp's writer says Y_UP), its top-level poses turned by C⁻¹ as for
# glTF. Blender 3.4's Collada importer (bpy.ops.wm.collada_import, default settings) reads the nodes'
# matrices as they are and ignores <up_axis>: a top-level object's matrix_world is C⁻¹·P and its
# mesh is as Gyre's, so the object's Gyre frame is C·matrix_world (C on the left, unlike glTF's change
# of basis), and relative to its parent nothing changes. The visual scene (GyreScene) is no object.
# Collada stores no frame rate either: the importer keys time t at frame t × 24 (time 0 at frame 0),
# linearly, each baked matrix as location, rotation_quaternion and scale keys.
#
# glb-spline: glb again, from a copy of the project whose fits are removed, so that every hermite
# track is Gyre's spline through its keys, which Gyre writes as a CUBICSPLINE rotation sampler, and
# its positions, cubic as a squad track's are, as a CUBICSPLINE translation sampler
# (src/io/gltf_scene_writer.h); the file must hold those. Blender 3.4 makes
# each CUBICSPLINE key a Bézier key with handles a third of the span along the tangents, the same
# cubic, and normalises the quaternion: the baked times between the spline's keys check that.
#
# Empties: an object the project marks "empty" must be an EMPTY in Blender (FBX: a Null Model with a
# Null NodeAttribute; glTF: a node without a mesh), and its motion is checked as every object's. A
# scene file given in place of a project (Blender's Empty carrying a mesh, make_fixtures.py) is first
# imported with `gyre-cli import`, and that project must hold at least one Empty.
#
# Run it with Blender 3.4 (Debian's `blender`), from the top of the source tree:
#   blender -b --factory-startup --python tests/interop/blender_import_gyre.py -- \
#       fbx build/src/cli/gyre-cli resources/samples/*.gyre
# (glb, glb-spline or dae in place of fbx for those). It prints one line per project and exits with status 1 if any
# check fails. Objects whose name another object shares, or that bears the glTF root's name, are
# skipped (gyre-cli bake selects objects by name, and the export renames them).
#
# One limit of Blender 3.4's FBX importer shows here, not of the file: it places keys at the frame
# rate rounded to an integer (so a 12.5 fps project plays 4% fast; integer rates are exact).

import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import warnings

import bpy
from bpy_extras.io_utils import axis_conversion
from mathutils import Matrix, Quaternion, Vector
from mathutils.kdtree import KDTree

ANGLE_TOLERANCE_DEGREES = 0.01
POSITION_TOLERANCE = 1e-4
SCALE_TOLERANCE = 1e-5
GEOMETRY_CHECKS = 10  # baked times at which the meshes' vertices are compared
GLTF_ROOT_NAME = "GyreScene"  # kRootName in src/io/scene_export.cpp


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) < 3 or args[0] not in ("fbx", "glb", "glb-spline", "dae"):
        sys.exit("usage: blender -b --factory-startup --python blender_import_gyre.py -- fbx|glb|glb-spline|dae "
                 "GYRE_CLI PROJECT.gyre|SCENE...")
    return args[0], args[1], args[2:]


class Fbx:
    """Blender's FBX importer: the file's frame rate, Z up as Gyre, time 0 at frame 1."""
    name = "fbx"
    basis = Matrix.Identity(4)  # from an object's frame in Gyre to its frame in Blender
    world_turn = Matrix.Identity(4)  # from Blender's world to Gyre's
    root = None  # the name of an object the importer makes above the top-level ones
    frame_of_time_0 = 1.0

    @staticmethod
    def load(path):
        bpy.ops.import_scene.fbx(filepath=path)

    @staticmethod
    def check_scene(scene, fps, problems):
        blender_fps = scene.render.fps / scene.render.fps_base
        if abs(blender_fps - fps) > 1e-6 * fps:
            problems.append("frame rate %g, not %g" % (blender_fps, fps))
        # Blender 3.4's importer places the keys at time × render.fps, the frame rate rounded to an
        # integer (fps_base carries the rest): at 12.5 fps the keys land at 12 frames a second.
        if scene.render.fps != fps:
            problems.append("keys placed at %d frames a second, so the motion plays at %g times its speed"
                            % (scene.render.fps, blender_fps / scene.render.fps))
        # The importer turns the file's axes into Blender's at the top level. Gyre's FBX names
        # Blender's own axes (UpAxis Z, FrontAxis -Y, which io_scene_fbx calls up "Z", forward "Y"),
        # so this is the identity: the scene stands as it does in Gyre.
        to_blender = axis_conversion(from_forward="Y", from_up="Z").to_4x4()
        if to_blender != Matrix.Identity(4):
            problems.append("the importer's axis conversion is not the identity")
        return "%g fps" % blender_fps


class Glb:
    """Blender's glTF importer: Y up turned to Z up by a change of basis, keys at time × 24 fps."""
    name = "glb"
    basis = Matrix.Rotation(math.radians(90.0), 4, "X")  # C: glTF's Y up to Blender's Z up
    world_turn = Matrix.Identity(4)
    root = GLTF_ROOT_NAME
    frame_of_time_0 = 0.0

    @staticmethod
    def load(path):
        # Debian's Blender 3.4 glTF importer uses numpy.bool, which numpy 1.24 removed.
        import numpy
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FutureWarning)  # numpy 1.24 warns on the look-up
            if not hasattr(numpy, "bool"):
                numpy.bool = bool
        bpy.ops.import_scene.gltf(filepath=path)

    @staticmethod
    def check_scene(scene, fps, problems):
        # glTF stores no frame rate: the importer keeps the scene's (24) and keys at time × that.
        return "keys at %d fps (glTF stores no frame rate)" % scene.render.fps


class GlbSpline(Glb):
    """glb from the project without its fits: hermite tracks as CUBICSPLINE samplers."""
    name = "glb-spline"
    without_fits = True


def cubic_spline_samplers(path):
    """How many samplers of a .glb's animations are CUBICSPLINE."""
    with open(path, "rb") as f:
        data = f.read()
    length, = struct.unpack_from("<I", data, 12)  # the JSON chunk's length, after the 12-byte header
    gltf = json.loads(data[20:20 + length])
    return sum(sampler.get("interpolation") == "CUBICSPLINE"
               for animation in gltf.get("animations", []) for sampler in animation["samplers"])


class Dae:
    """Blender's Collada importer: the file's Y-up world kept as it is, keys at time × 24 fps."""
    name = "dae"
    basis = Matrix.Identity(4)
    world_turn = Matrix.Rotation(math.radians(90.0), 4, "X")  # C: undoes Gyre's turn to Y up
    root = None
    frame_of_time_0 = 0.0

    @staticmethod
    def load(path):
        bpy.ops.wm.collada_import(filepath=path)

    @staticmethod
    def check_scene(scene, fps, problems):
        # Collada as Gyre writes it stores no frame rate: the importer keys at the scene's (24).
        return "keys at %d fps (the file stores no frame rate)" % scene.render.fps


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


def read_project(path):
    """A project (docs/file-format.md): version 3's JSON header, and each mesh's vertex positions,
    from the mesh blocks that come first after the header (float32 x, y, z per vertex, then normals
    and indices); or a version 1 or 2 project's JSON text and its meshes' positions."""
    with open(path, "rb") as f:
        data = f.read()
    if data.lstrip()[:1] == b"{":
        # Versions 1 and 2 are JSON text, their meshes' positions base64 float32 triples.
        document = json.loads(data.decode("utf-8"))
        positions = []
        for mesh in document.get("meshes", []):
            values = struct.unpack("<%df" % (len(base64.b64decode(mesh["positions"])) // 4),
                                   base64.b64decode(mesh["positions"]))
            positions.append([Vector(values[i:i + 3]) for i in range(0, len(values), 3)])
        return document, positions
    if data[:12] != b"gyre-project" or struct.unpack_from("<I", data, 12)[0] != 3:
        sys.exit("%s: not a Gyre project" % path)
    header_bytes = struct.unpack_from("<Q", data, 16)[0]
    document = json.loads(data[24:24 + header_bytes].decode("utf-8"))
    at = 24 + header_bytes
    positions = []
    for mesh in document["meshes"]:
        values = struct.unpack_from("<%df" % (3 * mesh["positions"]), data, at)
        positions.append([Vector(values[i:i + 3]) for i in range(0, len(values), 3)])
        at += 12 * (mesh["positions"] + mesh["normals"]) + 4 * mesh["indices"]
    return document, positions


def write_without_fits(path, document, out):
    """The version 3 project at `path`, whose header is `document`, with every fit taken off: the
    fitted curve and the keys the fit moved emptied, their blocks dropped (docs/file-format.md: the
    mesh blocks, the time lists, then each object's keys, its fitted curve and its keys before the
    fit)."""
    with open(path, "rb") as f:
        data = f.read()
    at = 24 + struct.unpack_from("<Q", data, 16)[0]
    for mesh in document["meshes"]:
        at += 12 * (mesh["positions"] + mesh["normals"]) + 4 * mesh["indices"]
    at += sum(8 * count for count in document["times"])
    blocks = [data[24 + struct.unpack_from("<Q", data, 16)[0]:at]]

    def key_bytes(layout):
        n = layout["count"]
        return 32 * n + (0 if layout["position"] is not None else 24 * n) + (0 if layout["constrained"] is not None else n)

    # No keys before a fit: a list of no times, after the others, so that no block moves.
    document["times"].append(0)
    for o in document["objects"]:
        keys = key_bytes(o["keyframes"])
        blocks.append(data[at:at + keys])
        at += keys + 72 * o["sketch"]["fittedCurve"]["count"] + key_bytes(o["sketch"]["keysBeforeFit"])
        o["sketch"]["fittedCurve"] = {"count": 0}
        o["sketch"]["keysBeforeFit"] = {"count": 0, "times": len(document["times"]) - 1, "position": None,
                                        "constrained": None}
    if at != len(data):
        sys.exit("%s: %d bytes after the blocks the header names" % (path, len(data) - at))
    header = json.dumps(document).encode("utf-8")
    with open(out, "wb") as f:
        f.write(data[:16] + struct.pack("<Q", len(header)) + header + b"".join(blocks))


def angle_between(a, b):
    """The angle of the rotation from a to b, degrees, in [0, 180]. Through atan2 of the difference's
    parts rather than acos of a dot product: mathutils works in single precision, where acos near 1
    cannot resolve angles below 0.04°."""
    d = a.normalized().conjugated() @ b.normalized()
    return math.degrees(2.0 * math.atan2(Vector((d.x, d.y, d.z)).length, abs(d.w)))


def geometry_error(obj, world_turn, positions, orientation_in_world, position_in_world):
    """How far the project's vertices, posed as Gyre poses them, lie from Blender's posed vertices,
    Blender's world turned into Gyre's by world_turn."""
    world = world_turn @ obj.matrix_world
    tree = KDTree(len(obj.data.vertices))
    for i, vertex in enumerate(obj.data.vertices):
        tree.insert(world @ vertex.co, i)
    tree.balance()
    return max(tree.find(orientation_in_world @ p + position_in_world)[2] for p in positions)


def check_project(kind, gyre_cli, project, folder):
    source = project
    imported_scene = not project.endswith(".gyre")
    if imported_scene:
        project = os.path.join(folder, "imported.gyre")
        subprocess.run([gyre_cli, "import", source, "-o", project], check=True)
    document, mesh_positions = read_project(project)
    fps = float(document["fps"])
    end = float(document["endTime"])
    # A glTF file starts at 0 s: Gyre moves a scene that starts earlier (prepareGltfTimes).
    shift = max(0.0, -float(document.get("startTime", 0.0))) if issubclass(kind, Glb) else 0.0
    names = [o["name"] for o in document["objects"]]
    parent_of = {o["id"]: o.get("parent") for o in document["objects"]}
    name_of = {o["id"]: o["name"] for o in document["objects"]}
    mesh_of = {o["id"]: o.get("mesh") for o in document["objects"]}

    empties = {o["name"] for o in document["objects"] if o.get("empty")}
    problems = []
    if imported_scene and not empties:
        problems.append("the imported scene holds no Empty")
    if getattr(kind, "without_fits", False):
        project = os.path.join(folder, "without-fits.gyre")
        write_without_fits(source, document, project)
    path = os.path.join(folder, "scene." + kind.name.split("-")[0])
    subprocess.run([gyre_cli, "export", project, "-o", path], check=True)
    if getattr(kind, "without_fits", False):
        moving = [o for o in document["objects"] if o["keyframes"]["count"] > 1]
        hermite = sum(o["interpolation"] == "hermite" for o in moving)
        squad = sum(o["interpolation"] == "squad" for o in moving)
        splines = 2 * hermite + squad  # a hermite track's rotation and translation, a squad track's translation
        if hermite == 0 or cubic_spline_samplers(path) != splines:
            problems.append("%d CUBICSPLINE samplers for %d hermite and %d squad tracks"
                            % (cubic_spline_samplers(path), hermite, squad))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    kind.load(path)
    scene = bpy.context.scene
    rate = kind.check_scene(scene, fps, problems)
    key_fps = scene.render.fps

    root = None
    if kind.root:
        root = bpy.data.objects.get(kind.root)
        if root is None or root.type != "EMPTY" or root.parent or root.animation_data:
            problems.append("the file's root '%s' is not an unmoving empty at the top" % kind.root)
            root = None
        elif not all(math.isclose(root.matrix_world[i][j], float(i == j), abs_tol=1e-6)
                     for i in range(4) for j in range(4)):
            problems.append("the file's root '%s' is not the identity" % kind.root)

    def gyre_frame(obj):
        """The object's frame as Gyre has it, from Blender's: its world matrix in Gyre's world, the
        basis the importer gave its mesh undone."""
        return kind.world_turn @ obj.matrix_world @ kind.basis

    worst_angle = worst_position = worst_scale = worst_vertex = 0.0
    for object_id, name in name_of.items():
        if names.count(name) > 1 or name == kind.root:
            continue
        obj = bpy.data.objects.get(name)
        if obj is None:
            problems.append("'%s' is missing" % name)
            continue
        parent_id = parent_of[object_id]
        expected_parent = name_of.get(parent_id) if parent_id else kind.root
        if (obj.parent.name if obj.parent else None) != expected_parent:
            problems.append("'%s' has parent %s, not %s" % (name, obj.parent and obj.parent.name, expected_parent))
        rows = baked_poses(gyre_cli, project, name, fps, folder)
        action = obj.animation_data.action if obj.animation_data else None
        # An object that never moves needs no action, and Blender's importers give it none; its
        # pose is still checked at every baked time below.
        moves = any(row[1] != rows[0][1] or row[2] != rows[0][2] for row in rows)
        if moves:
            last_frame = kind.frame_of_time_0 + (rows[-1][0] + shift) * key_fps
            if action is None or abs(action.frame_range[1] - last_frame) > 1e-3:
                problems.append("'%s' ends at frame %s, not %g" % (name, action and action.frame_range[1], last_frame))
        if name in empties and obj.type != "EMPTY":
            problems.append("'%s' is an Empty in Gyre and a %s in Blender" % (name, obj.type))
        mesh = mesh_of[object_id]
        positions = mesh_positions[mesh] if mesh is not None and obj.type == "MESH" else []
        if mesh is not None and obj.type != "MESH":
            problems.append("'%s' has no mesh" % name)
        geometry_rows = {round(i * (len(rows) - 1) / max(1, GEOMETRY_CHECKS - 1)) for i in range(GEOMETRY_CHECKS)}
        for row, (time, orientation, position) in enumerate(rows):
            frame = kind.frame_of_time_0 + (time + shift) * key_fps
            scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
            top_level = obj.parent is None or (root is not None and obj.parent == root)
            frame_of_parent = Matrix.Identity(4) if top_level else gyre_frame(obj.parent)
            location, rotation, scale = (frame_of_parent.inverted() @ gyre_frame(obj)).decompose()
            worst_angle = max(worst_angle, angle_between(rotation, orientation))
            worst_position = max(worst_position, (location - position).length)
            worst_scale = max(worst_scale, max(abs(s - 1.0) for s in scale))
            if positions and row in geometry_rows:
                # Gyre's world pose: the parent's, taken from Blender (checked above), then the bake.
                parent_rotation = frame_of_parent.to_quaternion()
                parent_location = frame_of_parent.to_translation()
                worst_vertex = max(worst_vertex, geometry_error(
                    obj, kind.world_turn, positions, parent_rotation @ orientation, parent_rotation @ position + parent_location))
    if worst_angle > ANGLE_TOLERANCE_DEGREES:
        problems.append("orientation off by %.6f°" % worst_angle)
    if worst_position > POSITION_TOLERANCE:
        problems.append("position off by %g" % worst_position)
    if worst_scale > SCALE_TOLERANCE:
        problems.append("scale off by %g" % worst_scale)
    if worst_vertex > POSITION_TOLERANCE:
        problems.append("vertices off by %g" % worst_vertex)
    print("%s %s: %d objects (%d Empties), %s, %g s; worst angle %.2e°, position %.1e, scale %.1e, vertex %.1e%s"
          % (kind.name, os.path.basename(source), len(names), len(empties), rate, end, worst_angle, worst_position,
             worst_scale, worst_vertex, "" if not problems else " -- FAILED: " + "; ".join(problems)))
    return not problems


def main():
    format_name, gyre_cli, projects = arguments()
    kind = {"fbx": Fbx, "glb": Glb, "glb-spline": GlbSpline, "dae": Dae}[format_name]
    passed = True
    with tempfile.TemporaryDirectory() as folder:
        for project in projects:
            passed = check_project(kind, gyre_cli, project, folder) and passed
    sys.exit(0 if passed else 1)


main()
