# Writes rigged.gltf (+ rigged.bin), rigged.fbx, rigged.dae and
# rigged_pose_bend_0_5.obj beside this file: a "bendy arm", a 0.4 x 0.4 x 2
# box column (9 rings of 8 vertices) skinned with automatic weights to a
# 3-bone chain Root -> Mid -> Tip, with one shape key "Bulge" (the middle
# ring pushed 0.2 outward), as Blender's own exporters write them. Run with
# Debian's blender (3.4); its glTF exporter needs python3-numpy:
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_rigged.py
#
# Two armature actions, 24 fps:
#   Bend  frames 0..24 (1 s): Mid rotates 0 -> 60 -> 0 deg about its X, Tip
#         0 -> 45 -> 0 deg about its Z, Root moves 0 -> 0.1 -> 0 along its Z;
#         the shape key Bulge goes 0 -> 1 -> 0 in the same clip.
#   Twist frames 0..12 (0.5 s): Root rotates 0 -> 90 deg about the column.
# Each action sits alone on an NLA track of its own name (the Bulge action
# on a shape-key NLA track also named "Bend"), so the glTF exporter writes
# two animations, "Bend" and "Twist", the Bulge weights merged into "Bend",
# and the FBX exporter two takes of the same names (Bulge only in Bend).
# The COLLADA exporter writes only the active action (Bend, bones sampled as
# matrices) and no shape-key animation: its include_all_actions does nothing
# in 3.4, so rigged.dae has no Twist.
#
# The actions start at frame 0 because Blender 3.4's glTF exporter writes a
# key's time as frame / fps (not (frame - frame_start) / fps): frame 0 makes
# the first key time 0, so a clip's time and glTF's absolute time agree.
# rigged_pose_bend_0_5.obj is the mesh (armature + shape key applied) at
# frame 12 of Bend = time 0.5 s in the glTF clip "Bend", Y up like the glTF.
import math
import os

import bmesh
import bpy

FPS = 24
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "rigged")

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = FPS
scene.render.fps_base = 1.0
scene.frame_start = 0
scene.frame_end = 24

# --- the mesh: 9 square rings of 8 vertices (corners + edge middles) ------
HALF, HEIGHT, RINGS = 0.2, 2.0, 9
ring_xy = [(-1, -1), (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0)]
mesh = bpy.data.meshes.new("Arm")
bm = bmesh.new()
rings = []
for r in range(RINGS):
    z = HEIGHT * r / (RINGS - 1)
    rings.append([bm.verts.new((x * HALF, y * HALF, z)) for x, y in ring_xy])
n = len(ring_xy)
for r in range(RINGS - 1):
    for i in range(n):
        j = (i + 1) % n
        bm.faces.new((rings[r][i], rings[r][j], rings[r + 1][j], rings[r + 1][i]))
bm.faces.new(list(reversed(rings[0])))  # bottom cap, facing -Z
bm.faces.new(rings[-1])                 # top cap, facing +Z
bm.normal_update()
bm.to_mesh(mesh)
bm.free()
arm_obj = bpy.data.objects.new("Arm", mesh)
scene.collection.objects.link(arm_obj)

material = bpy.data.materials.new("ArmColour")
material.use_nodes = True
material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.8, 0.3, 0.1, 1.0)
material.diffuse_color = (0.8, 0.3, 0.1, 1.0)
mesh.materials.append(material)

# --- the armature: Root, Mid, Tip along +Z ---------------------------------
arm_data = bpy.data.armatures.new("Armature")
rig = bpy.data.objects.new("Armature", arm_data)
scene.collection.objects.link(rig)
bpy.context.view_layer.objects.active = rig
bpy.ops.object.mode_set(mode='EDIT')
parent = None
for k, name in enumerate(("Root", "Mid", "Tip")):
    bone = arm_data.edit_bones.new(name)
    bone.head = (0, 0, HEIGHT * k / 3)
    bone.tail = (0, 0, HEIGHT * (k + 1) / 3)
    bone.roll = 0.0
    if parent is not None:
        bone.parent = parent
        bone.use_connect = True
    parent = bone
bpy.ops.object.mode_set(mode='OBJECT')

# Parent with automatic (bone heat) weights: select the mesh, then the rig
# as the active object.
bpy.ops.object.select_all(action='DESELECT')
arm_obj.select_set(True)
rig.select_set(True)
bpy.context.view_layer.objects.active = rig
bpy.ops.object.parent_set(type='ARMATURE_AUTO')

# --- the shape key: the middle ring (z = 1) pushed 0.2 outward ----------
arm_obj.shape_key_add(name="Basis", from_mix=False)
bulge = arm_obj.shape_key_add(name="Bulge", from_mix=False)
mid_ring = RINGS // 2
for i, v in enumerate(mesh.vertices):
    if abs(v.co.z - HEIGHT * mid_ring / (RINGS - 1)) < 1e-6:
        x, y = v.co.x, v.co.y
        d = math.hypot(x, y)
        bulge.data[i].co = (x + 0.2 * x / d, y + 0.2 * y / d, v.co.z)

# --- the actions -------------------------------------------------------------
for pb in rig.pose.bones:
    pb.rotation_mode = 'XYZ'


def key(bone, path, frame, value, index):
    pb = rig.pose.bones[bone]
    getattr(pb, path)[index] = value
    pb.keyframe_insert(data_path=path, index=index, frame=frame, group=bone)


def reset_pose():
    for pb in rig.pose.bones:
        pb.location = (0, 0, 0)
        pb.rotation_euler = (0, 0, 0)
        pb.scale = (1, 1, 1)


rig.animation_data_create()

bend = bpy.data.actions.new("Bend")
rig.animation_data.action = bend
for frame, t in ((0, 0.0), (12, 1.0), (24, 0.0)):
    key("Mid", "rotation_euler", frame, math.radians(60) * t, 0)   # about X
    key("Tip", "rotation_euler", frame, math.radians(45) * t, 2)   # about Z
    key("Root", "location", frame, 0.1 * t, 2)                     # along bone Z

reset_pose()
twist = bpy.data.actions.new("Twist")
rig.animation_data.action = twist
for frame, t in ((0, 0.0), (12, 1.0)):
    key("Root", "rotation_euler", frame, math.radians(90) * t, 1)  # bone Y = column
for action in (twist,):
    for fc in action.fcurves:
        for kp in fc.keyframe_points:
            kp.interpolation = 'LINEAR'
rig.animation_data.action = None
reset_pose()

keys = mesh.shape_keys
keys.animation_data_create()
bulge_action = bpy.data.actions.new("BendBulge")
keys.animation_data.action = bulge_action
for frame, t in ((0, 0.0), (12, 1.0), (24, 0.0)):
    bulge.value = t
    bulge.keyframe_insert(data_path="value", frame=frame)
keys.animation_data.action = None
bulge.value = 0.0


def push_to_track(anim_data, action, name, start):
    track = anim_data.nla_tracks.new()
    track.name = name
    strip = track.strips.new(action.name, start, action)
    strip.name = action.name
    return track


push_to_track(rig.animation_data, bend, "Bend", 0)
# Twist's strip sits at frame 100 so that the FBX exporter, which bakes each
# rig strip alone over the strip's frames, does not see the Bulge strip (a
# shape-key strip, which it never mutes) in the Twist take. The glTF
# exporter uses each action's own frames 0..12 and ignores this placement.
push_to_track(rig.animation_data, twist, "Twist", 100)
push_to_track(keys.animation_data, bulge_action, "Bend", 0).strips[0].extrapolation = 'NOTHING'
for action in (bend, twist, bulge_action):
    action.use_fake_user = True

# --- exports -----------------------------------------------------------------
scene.frame_set(0)
bpy.ops.object.select_all(action='SELECT')
bpy.ops.export_scene.gltf(
    filepath=OUT + ".gltf",
    export_format='GLTF_SEPARATE',
    export_yup=True,
    export_texcoords=False,
    export_animations=True,
    export_nla_strips=True,
    export_anim_single_armature=False,
    export_force_sampling=True,
    export_frame_range=False,
    export_skins=True,
    export_morph=True,
    export_morph_normal=False,
    export_materials='EXPORT',
)

bpy.ops.export_scene.fbx(
    filepath=OUT + ".fbx",
    object_types={'ARMATURE', 'MESH'},
    add_leaf_bones=False,
    bake_anim=True,
    bake_anim_use_all_bones=True,
    bake_anim_use_nla_strips=True,
    bake_anim_use_all_actions=False,
    bake_anim_force_startend_keying=True,
    use_armature_deform_only=True,
    path_mode='STRIP',
)

# The pose for the tests: clip Bend (armature action + Bulge) at frame 12,
# i.e. glTF time 12 / 24 = 0.5 s.
rig.animation_data.use_nla = False
rig.animation_data.action = bend
keys.animation_data.use_nla = False
keys.animation_data.action = bulge_action

try:
    result = bpy.ops.wm.collada_export(
        filepath=OUT + ".dae",
        selected=False,
        include_armatures=True,
        include_shapekeys=True,
        include_animations=True,
        include_all_actions=True,
        export_animation_type_selection='sample',
        sampling_rate=1,
        triangulate=True,
    )
    print("COLLADA export:", result)
except Exception as error:  # the COLLADA exporter is optional in builds
    print("COLLADA export failed:", error)

scene.frame_set(12)
bpy.context.view_layer.update()
bpy.ops.object.select_all(action='DESELECT')
arm_obj.select_set(True)
bpy.context.view_layer.objects.active = arm_obj
bpy.ops.export_scene.obj(
    filepath=OUT + "_pose_bend_0_5.obj",
    use_selection=True,
    use_mesh_modifiers=True,
    use_triangles=True,
    use_normals=False,
    use_uvs=False,
    use_materials=False,
    use_animation=False,
)
