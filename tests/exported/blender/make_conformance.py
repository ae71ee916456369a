# Writes the rig conformance set beside this file (tests/conformance/ poses
# each with toond and with three.js): small skinned tubes, each made to
# exercise one thing a rig can do, as Blender 3.4's exporters write them.
# Run with Debian's blender (its glTF exporter needs python3-numpy):
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_conformance.py
#
# Every case is a tube (a ring of `sides` vertices every so often along
# its bones, n-gon caps, smooth) skinned to an armature, with one action
# "Move" over frames 1..25 at 24 fps (Blender's factory start frame, so the
# glTF's keys run from 1/24 s and the FBX take from 0). Each writes
# conf_NAME.glb (glTF exporter: factory settings unless the case says
# otherwise), conf_NAME.fbx (FBX exporter, factory settings) and
# conf_NAME.dae (COLLADA, bones sampled at every frame) unless the case
# says why not, and conf_NAME_f09.obj: the mesh Blender deforms itself at
# frame 9, Y up like the glTF, to judge by when toond and three.js
# disagree.
#
#   tentacle      4 connected bones off every axis, rolled 0, 30, -60 and
#                 90 degrees, each turning about its X and Z at once.
#   turned        a 3-bone chain whose armature object is turned (20, -35,
#                 50 degrees), moved and scaled 0.7, object transform kept.
#   stretched     the chain in an armature object scaled (1, 2, 0.5) and
#                 turned 30 degrees about Z: bending bones shear the tube.
#   parented      the chain's armature object under an empty ("Carrier":
#                 moved, turned 40 degrees, scaled 1.3) under another
#                 ("Stage": turned 15 degrees about X, scaled 0.8).
#   offset_mesh   the skinned mesh object has a transform of its own under
#                 its armature (moved, turned 25 degrees about Z, scaled
#                 1.2), set after skinning: glTF ignores a skinned node's
#                 transform, so the exporter must carry it in the bind.
#   branches      a Y of five bones (Trunk, then Left1-Left2 and
#                 Right1-Right2) made in a scrambled order, so the skin
#                 lists its joints in another order than the nodes.
#   eight         an 8-bone chain whose every vertex is weighted to all
#                 eight bones (a smooth falloff along the tube), exported
#                 with all influences (JOINTS_0/1, WEIGHTS_0/1). glTF only:
#                 FBX and COLLADA readers keep four (toond's helper the
#                 strongest four renormalised, three.js's loaders four
#                 without renormalising), so those twins compare nothing.
#   cubic         Bezier keys (quaternion rotations, locations, scales)
#                 exported unsampled: CUBICSPLINE samplers.
#   step          constant-interpolation keys exported unsampled: STEP.
#   constant      linear keys exported unsampled, where one bone's track
#                 holds one value at every key and another bone has a
#                 single key (exported as STEP).
#   scale_keys    bones keyed in scale, uniform on the middle bone and not
#                 uniform on the tip, beside rotations.
#   morph_skin    two shape keys (a bulge and a squash) animated with the
#                 bones, in one clip. glTF and FBX: the COLLADA reader of
#                 toond's helper cannot read a skinned mesh with shape keys
#                 (tests/conformance/cases.json, rigged.dae).
#
# What Blender's own exporters get wrong, as seen against its OBJ at frame
# 9 (toond and three.js agree with each other on every one of these
# files): the COLLADA files of an armature object with a transform of its
# own (turned, stretched, parented) bind the skin where their joints do not
# put it at rest, so even at frame 1 the skin is 0.4-1.8 m from where it
# was bound, and 1-4 m off Blender's mesh at frame 9; and
# conf_constant.dae holds only the one bone whose keys change (B2), a clip
# of a single channel that toond's helper (assimp 5.2) cannot convert.
#
# Blender's glTF exporter never gives a skinned mesh's node a transform of
# its own (offset_mesh comes out with the mesh object's transform baked
# into the vertices), so one file is not Blender's alone:
#   conf_skinned_node_moved.glb  conf_turned.glb with its skinned node
#                 "Tube" moved, turned and scaled by this script. glTF
#                 places a skinned mesh by its joints and ignores that
#                 transform: it must pose as conf_turned.glb does.
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Euler, Matrix, Vector

FIRST, LAST = 1, 25
OBJ_FRAME = 9
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from rig_parts import empty_scene as scene_of_frames, skin, smooth_tube, write_deformed_obj  # noqa: E402


def empty_scene():
    return scene_of_frames(FIRST, LAST)


def link(obj):
    bpy.context.scene.collection.objects.link(obj)
    return obj


def armature(bones, matrix=Matrix.Identity(4), name="Armature"):
    """An armature object placed by `matrix` (its transform, not applied)
    with `bones`: (name, head, tail, parent or None, roll in degrees), made
    in the order given; connected where a bone's head is its parent's tail."""
    data = bpy.data.armatures.new(name)
    rig = link(bpy.data.objects.new(name, data))
    rig.matrix_world = matrix
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='EDIT')
    made = {}
    for bone_name, head, tail, _, roll in bones:
        bone = data.edit_bones.new(bone_name)
        bone.head = head
        bone.tail = tail
        bone.roll = math.radians(roll)
        made[bone_name] = bone
    for bone_name, head, _, parent, _ in bones:
        if parent is not None:
            made[bone_name].parent = made[parent]
            made[bone_name].use_connect = (Vector(head) - made[parent].tail).length < 1e-9
    bpy.ops.object.mode_set(mode='OBJECT')
    bpy.context.view_layer.update()
    return rig


def tube(name, path, radius, sides, rings_per_segment, matrix=Matrix.Identity(4)):
    """A smooth tube along the polyline `path` (points in the armature's
    space), rings carried along it without twisting, put into the world by
    `matrix` (the armature object's). Returns the mesh object."""
    points = [Vector(p) for p in path]
    centres, tangents = [], []
    for s in range(len(points) - 1):
        a, b = points[s], points[s + 1]
        for k in range(rings_per_segment + (1 if s == len(points) - 2 else 0)):
            centres.append(a.lerp(b, k / rings_per_segment))
            tangents.append((b - a).normalized())
    normal = tangents[0].orthogonal().normalized()
    rings = []
    for centre, tangent in zip(centres, tangents):
        normal = (normal - tangent * normal.dot(tangent)).normalized()
        binormal = tangent.cross(normal)
        rings.append([matrix @ (centre + radius * (math.cos(2 * math.pi * i / sides) * normal +
                                                   math.sin(2 * math.pi * i / sides) * binormal))
                      for i in range(sides)])
    return smooth_tube(name, rings)


def new_action(rig, name="Move"):
    rig.animation_data_create()
    action = bpy.data.actions.new(name)
    rig.animation_data.action = action
    return action


def key(rig, frame, bone, path, value, interpolation=None):
    pb = rig.pose.bones[bone]
    if path == "rotation_euler":
        pb.rotation_mode = 'XYZ'
        value = tuple(math.radians(v) for v in value)
    elif path == "rotation_quaternion":
        pb.rotation_mode = 'QUATERNION'
        value = Euler(tuple(math.radians(v) for v in value), 'XYZ').to_quaternion()
    setattr(pb, path, value)
    pb.keyframe_insert(data_path=path, frame=frame, group=bone)
    if interpolation:
        for fc in rig.animation_data.action.fcurves:
            if fc.data_path == 'pose.bones["%s"].%s' % (bone, path):
                for kp in fc.keyframe_points:
                    kp.interpolation = interpolation


def chain(n, length, direction=(0, 0, 1)):
    """n connected bones B0..B(n-1) from the origin along `direction`."""
    d = Vector(direction).normalized() * length
    return [("B%d" % k, tuple(d * k), tuple(d * (k + 1)), "B%d" % (k - 1) if k else None, 0.0) for k in range(n)]


def chain_path(bones):
    return [bones[0][1]] + [b[2] for b in bones]


def export(stem, body, gltf=None, fbx=True, dae=True):
    scene = bpy.context.scene
    scene.frame_set(FIRST)
    path = os.path.join(HERE, "conf_" + stem)
    bpy.ops.export_scene.gltf(filepath=path + ".glb", **(gltf or {}))
    written = [path + ".glb"]
    if fbx:
        bpy.ops.export_scene.fbx(filepath=path + ".fbx")
        written.append(path + ".fbx")
    if dae:
        bpy.ops.wm.collada_export(filepath=path + ".dae", include_armatures=True, include_animations=True,
                                  export_animation_type_selection='sample', sampling_rate=1,
                                  triangulate=True)
        written.append(path + ".dae")
    write_deformed_obj(body, "%s_f%02d.obj" % (path, OBJ_FRAME), OBJ_FRAME)
    for f in written:
        print("wrote", f, os.path.getsize(f), "bytes")


def bend_chain(rig, bones, axes, degrees, frames=(1, 9, 17, 25), shape=(0.0, 1.0, -0.6, 0.0), path="rotation_euler"):
    """Keys every bone but the first turning by `degrees` (per bone) about
    `axes` (per bone, a weight per Euler axis) with the bend's `shape`."""
    for frame, s in zip(frames, shape):
        for (name, *_), axis, d in zip(bones[1:], axes, degrees):
            key(rig, frame, name, path, tuple(a * d * s for a in axis))


def case_tentacle():
    empty_scene()
    heads = [(0, 0, 0), (0.5, 0.4, 0.6), (0.9, 0.9, 1.1), (1.2, 1.5, 1.5), (1.3, 2.1, 1.8)]
    rolls = [0.0, 30.0, -60.0, 90.0]
    bones = [("T%d" % k, heads[k], heads[k + 1], "T%d" % (k - 1) if k else None, rolls[k]) for k in range(4)]
    rig = armature(bones)
    body = tube("Tentacle", heads, 0.12, 10, 6)
    skin(body, rig)
    new_action(rig)
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.7, 0.0)):
        for k, (name, *_) in enumerate(bones):
            key(rig, frame, name, "rotation_euler", (25 * s * (1 + 0.2 * k), 0.0, -18 * s))
    export("tentacle", body)


def placed_chain(matrix, radius=0.15):
    bones = chain(3, 0.7)
    rig = armature(bones, matrix)
    body = tube("Tube", chain_path(bones), radius, 10, 5, matrix)
    skin(body, rig)
    new_action(rig)
    bend_chain(rig, bones, ((1, 0, 0), (1, 0, 0.5)), (40.0, 55.0))
    return rig, body


def case_turned():
    empty_scene()
    matrix = Matrix.LocRotScale(Vector((0.3, -0.2, 0.5)), Euler(tuple(map(math.radians, (20, -35, 50)))),
                                Vector((0.7, 0.7, 0.7)))
    _, body = placed_chain(matrix)
    export("turned", body)


def case_stretched():
    empty_scene()
    matrix = Matrix.LocRotScale(Vector((0, 0, 0)), Euler((0, 0, math.radians(30))), Vector((1.0, 2.0, 0.5)))
    _, body = placed_chain(matrix)
    export("stretched", body)


def case_parented():
    empty_scene()
    stage = link(bpy.data.objects.new("Stage", None))
    stage.matrix_world = Matrix.LocRotScale(Vector((0, 0.5, 0)), Euler((math.radians(15), 0, 0)),
                                            Vector((0.8, 0.8, 0.8)))
    carrier = link(bpy.data.objects.new("Carrier", None))
    carrier.parent = stage
    carrier.matrix_basis = Matrix.LocRotScale(Vector((1.0, 0, 0.5)), Euler((0, 0, math.radians(40))),
                                              Vector((1.3, 1.3, 1.3)))
    bpy.context.view_layer.update()
    bones = chain(3, 0.7)
    rig = armature(bones)
    rig.parent = carrier
    rig.matrix_basis = Matrix.Identity(4)
    bpy.context.view_layer.update()
    body = tube("Tube", chain_path(bones), 0.15, 10, 5, rig.matrix_world)
    skin(body, rig)
    new_action(rig)
    bend_chain(rig, bones, ((1, 0, 0), (0, 0, 1)), (40.0, 50.0))
    export("parented", body)


def case_offset_mesh():
    empty_scene()
    bones = chain(3, 0.7)
    rig = armature(bones)
    body = tube("Tube", chain_path(bones), 0.15, 10, 5)
    skin(body, rig)
    body.matrix_basis = Matrix.LocRotScale(Vector((0.1, 0, 0)), Euler((0, 0, math.radians(25))),
                                           Vector((1.2, 1.2, 1.2))) @ body.matrix_basis
    new_action(rig)
    bend_chain(rig, bones, ((1, 0, 0), (1, 0, 0)), (40.0, 50.0))
    export("offset_mesh", body)


def case_branches():
    empty_scene()
    trunk = ("Trunk", (0, 0, 0), (0, 0, 0.8), None, 0.0)
    left1 = ("Left1", (0, 0, 0.8), (-0.5, 0, 1.3), "Trunk", 0.0)
    left2 = ("Left2", (-0.5, 0, 1.3), (-0.8, 0, 1.9), "Left1", 20.0)
    right1 = ("Right1", (0, 0, 0.8), (0.5, 0, 1.3), "Trunk", 0.0)
    right2 = ("Right2", (0.5, 0, 1.3), (0.8, 0.1, 1.9), "Right1", -35.0)
    rig = armature([right2, left1, trunk, right1, left2])
    left = tube("Left", [trunk[1], trunk[2], left1[2], left2[2]], 0.1, 8, 4)
    right = tube("Right", [right1[1], right1[2], right2[2]], 0.1, 8, 4)
    bpy.ops.object.select_all(action='DESELECT')
    left.select_set(True)
    right.select_set(True)
    bpy.context.view_layer.objects.active = left
    bpy.ops.object.join()
    body = left
    body.name = "Branches"
    skin(body, rig)
    new_action(rig)
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.6, 0.0)):
        key(rig, frame, "Trunk", "rotation_euler", (0, 20 * s, 0))
        key(rig, frame, "Left1", "rotation_euler", (30 * s, 0, 15 * s))
        key(rig, frame, "Left2", "rotation_euler", (-40 * s, 0, 0))
        key(rig, frame, "Right1", "rotation_euler", (0, 0, -35 * s))
        key(rig, frame, "Right2", "rotation_euler", (45 * s, 10 * s, 0))
    export("branches", body)


def case_eight():
    empty_scene()
    bones = chain(8, 0.25)
    rig = armature(bones)
    body = tube("Tube", chain_path(bones), 0.12, 8, 2)
    skin(body, rig, automatic=False)
    # Every vertex weighted to all eight bones, most to the nearest: a
    # smooth falloff along the tube, normalised.
    groups = [body.vertex_groups[name] for name, *_ in bones]
    for v in body.data.vertices:
        z = v.co.z
        raw = [math.exp(-((z - 0.25 * (k + 0.5)) / 0.45) ** 2) for k in range(8)]
        total = sum(raw)
        for group, w in zip(groups, raw):
            group.add([v.index], w / total, 'REPLACE')
    for v in body.data.vertices:
        assert len([g for g in v.groups if g.weight > 0]) == 8
    new_action(rig)
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.6, 0.0)):
        for k, (name, *_) in enumerate(bones[1:]):
            key(rig, frame, name, "rotation_euler", (14 * s, 6 * s * (-1) ** k, 0))
    export("eight", body, gltf={"export_all_influences": True}, fbx=False, dae=False)


def chain_case(stem, keys, gltf):
    """The 3-bone chain keyed by keys(rig), exported with `gltf` options."""
    empty_scene()
    bones = chain(3, 0.7)
    rig = armature(bones)
    body = tube("Tube", chain_path(bones), 0.15, 10, 5)
    skin(body, rig)
    new_action(rig)
    keys(rig)
    export(stem, body, gltf=gltf)


# Locations are keyed on the root bone: Blender ignores the location of a
# bone connected to its parent, but its glTF exporter writes such keys as
# they are when it does not sample (the file then moves the bone where
# Blender's own deform does not).
def keys_cubic(rig):
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.6, 0.0)):
        key(rig, frame, "B1", "rotation_quaternion", (40 * s, 10 * s, 0), 'BEZIER')
        key(rig, frame, "B2", "rotation_quaternion", (50 * s, 0, 20 * s), 'BEZIER')
        key(rig, frame, "B0", "location", (0.05 * s, 0, 0.1 * s), 'BEZIER')
        key(rig, frame, "B1", "scale", (1 + 0.2 * s, 1 + 0.2 * s, 1 + 0.2 * s), 'BEZIER')


def keys_step(rig):
    for frame, s in zip((1, 7, 13, 19, 25), (0.0, 1.0, 0.4, -0.6, 0.0)):
        key(rig, frame, "B1", "rotation_quaternion", (40 * s, 0, 0), 'CONSTANT')
        key(rig, frame, "B2", "rotation_quaternion", (0, 0, 50 * s), 'CONSTANT')
        key(rig, frame, "B0", "location", (0, 0.1 * s, 0), 'CONSTANT')


def keys_constant(rig):
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.6, 0.0)):
        key(rig, frame, "B1", "rotation_quaternion", (30, 0, 10), 'LINEAR')  # one value throughout
        key(rig, frame, "B2", "rotation_quaternion", (45 * s, 0, 0), 'LINEAR')
    key(rig, 1, "B0", "location", (0.1, 0, 0.05), 'LINEAR')  # a single key


def keys_scale(rig):
    for frame, s in zip((1, 9, 17, 25), (0.0, 1.0, -0.6, 0.0)):
        u = 1 + 0.5 * s
        key(rig, frame, "B1", "scale", (u, u, u))
        key(rig, frame, "B1", "rotation_euler", (30 * s, 0, 0))
        key(rig, frame, "B2", "scale", (1 + 0.4 * s, 1 - 0.3 * s, 1 + 0.6 * s))
        key(rig, frame, "B2", "rotation_euler", (0, 0, 40 * s))


def case_morph_skin():
    empty_scene()
    bones = chain(3, 0.7)
    rig = armature(bones)
    body = tube("Tube", chain_path(bones), 0.15, 10, 5)
    skin(body, rig)
    body.shape_key_add(name="Basis", from_mix=False)
    bulge = body.shape_key_add(name="Bulge", from_mix=False)
    squash = body.shape_key_add(name="Squash", from_mix=False)
    for i, v in enumerate(body.data.vertices):
        x, y, z = v.co
        grow = 0.6 * math.exp(-((z - 1.05) / 0.2) ** 2)
        bulge.data[i].co = (x * (1 + grow), y * (1 + grow), z)
        fade = max(0.0, (z - 1.4) / 0.7)
        squash.data[i].co = (x * (1 + 0.8 * fade), y * (1 - 0.6 * fade), z)
    action = new_action(rig)
    bend_chain(rig, bones, ((1, 0, 0), (1, 0, 0)), (40.0, 50.0))
    keys = body.data.shape_keys
    keys.animation_data_create()
    weights = bpy.data.actions.new("MoveShapes")
    keys.animation_data.action = weights
    for frame, b, q in ((1, 0.0, 0.0), (9, 1.0, 0.3), (17, 0.2, 1.0), (25, 0.0, 0.0)):
        bulge.value, squash.value = b, q
        bulge.keyframe_insert(data_path="value", frame=frame)
        squash.keyframe_insert(data_path="value", frame=frame)
    # One glTF animation from both actions: NLA tracks of the same name.
    for data, act in ((rig.animation_data, action), (keys.animation_data, weights)):
        track = data.nla_tracks.new()
        track.name = "Move"
        track.strips.new(act.name, FIRST, act)
        data.action = None
        act.use_fake_user = True
    export("morph_skin", body, dae=False)


def glb_with(source, target, change):
    """Writes GLB `target`: GLB `source` with change(json) applied to its
    JSON chunk (the binary chunk as it was)."""
    with open(source, "rb") as f:
        data = f.read()
    length = struct.unpack_from("<I", data, 12)[0]
    gltf = json.loads(data[20:20 + length])
    binary = data[20 + length:]
    change(gltf)
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + binary
    with open(target, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)
    print("wrote", target, os.path.getsize(target), "bytes")


def move_skinned_node(gltf):
    node = next(n for n in gltf["nodes"] if n.get("skin") is not None)
    node["translation"] = [0.4, -0.3, 0.2]
    node["rotation"] = [0.0, 0.0, math.sin(math.radians(20)), math.cos(math.radians(20))]
    node["scale"] = [1.5, 0.5, 1.0]


case_tentacle()
case_turned()
case_stretched()
case_parented()
case_offset_mesh()
case_branches()
case_eight()
chain_case("cubic", keys_cubic, {"export_force_sampling": False})
chain_case("step", keys_step, {"export_force_sampling": False})
chain_case("constant", keys_constant, {"export_force_sampling": False})
chain_case("scale_keys", keys_scale, None)
case_morph_skin()
glb_with(os.path.join(HERE, "conf_turned.glb"), os.path.join(HERE, "conf_skinned_node_moved.glb"), move_skinned_node)
