# Writes the two rigs of issue 43 beside this file, each as Blender 3.4's
# glTF and FBX exporters write them with their factory settings, with
# Blender's own deformed mesh (the evaluated mesh, armature applied) as OBJ
# at three frames of the clip. Run with Debian's blender (its glTF exporter
# needs python3-numpy):
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_bending_rigs.py
#
#   bending_arm   A smooth cylinder (radius 0.25, 3 m along Blender's Z, 24
#                 rings of 24 vertices, n-gon caps) skinned with automatic
#                 weights to three connected bones Base, Middle, Tip (0-1,
#                 1-2, 2-3 m, roll 0: each bone's X is Blender's X). One
#                 action "Bend", Euler XYZ keys at frames 1, 7, 13, 19, 25
#                 (Blender's default Bezier keys): Middle 0, 35, 0, -35, 0
#                 degrees about its X, Tip 1.4 times that (0, 49, 0, -49, 0).
#   turned_limb   The same kind of arm (radius 0.2, 24 rings of 24) whose
#                 armature object is turned 90 degrees about Y and scaled
#                 1.5, the object transform not applied: the bones are 0-1,
#                 1-2, 2-3 m along the armature's Z, which the turn takes to
#                 the world's +X and the scale makes 0-4.5 m (the tube is
#                 0.3 m thick in the world). Action "Bend": Middle 0, 40, 0,
#                 -40, 0 degrees and Tip 0, 55, 0, -55, 0 degrees about
#                 their X at the same frames.
#
# Each writes NAME.glb (glTF exporter, factory settings but for the file
# path), NAME.fbx (FBX exporter, factory settings: leaf bones added, the
# take baked at every frame) and NAME_fNN.obj, the evaluated mesh at frames
# 7 and 19 (the peaks of the bend) and 10 (between the keys 7 and 13), Y up
# like the glTF, positions and triangles only.
#
# Times: the scene runs frames 1..25 at 24 fps. Blender's glTF exporter
# writes frame F at F / 24 s (the clip's first key is at 1/24 s), its FBX
# exporter starts the take at 0 (frame F at (F - 1) / 24 s).
import math
import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from rig_parts import empty_scene, skin, smooth_tube, write_deformed_obj  # noqa: E402

KEY_FRAMES = (1, 7, 13, 19, 25)
BEND = (0.0, 1.0, 0.0, -1.0, 0.0)  # the shape of the bend over the key frames
OBJ_FRAMES = (7, 10, 19)


def cylinder(name, radius, length, rings, sides, place):
    """A smooth tube of `rings` rings of `sides` vertices along its Z from 0
    to `length`, with n-gon caps; place(x, y, z) gives a point's world
    position."""
    rings_of_points = []
    for r in range(rings):
        z = length * r / (rings - 1)
        rings_of_points.append([place(radius * math.cos(2 * math.pi * i / sides),
                                      radius * math.sin(2 * math.pi * i / sides), z) for i in range(sides)])
    return smooth_tube(name, rings_of_points)


def chain(rotation, scale):
    """An armature object (turned by `rotation`, Euler XYZ radians, scaled
    by `scale`) with Base, Middle, Tip connected along its Z, 1 m each."""
    data = bpy.data.armatures.new("Armature")
    rig = bpy.data.objects.new("Armature", data)
    bpy.context.scene.collection.objects.link(rig)
    rig.rotation_euler = rotation
    rig.scale = (scale, scale, scale)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='EDIT')
    parent = None
    for k, name in enumerate(("Base", "Middle", "Tip")):
        bone = data.edit_bones.new(name)
        bone.head = (0, 0, k)
        bone.tail = (0, 0, k + 1)
        bone.roll = 0.0
        if parent is not None:
            bone.parent = parent
            bone.use_connect = True
        parent = bone
    bpy.ops.object.mode_set(mode='OBJECT')
    return rig


def key_bend(rig, middle_deg, tip_deg):
    rig.animation_data_create()
    action = bpy.data.actions.new("Bend")
    rig.animation_data.action = action
    for pb in rig.pose.bones:
        pb.rotation_mode = 'XYZ'
    for frame, shape in zip(KEY_FRAMES, BEND):
        for bone, degrees in (("Middle", middle_deg), ("Tip", tip_deg)):
            pb = rig.pose.bones[bone]
            pb.rotation_euler = (math.radians(degrees * shape), 0.0, 0.0)
            pb.keyframe_insert(data_path="rotation_euler", frame=frame, group=bone)
    return action


def export(stem, body):
    scene = bpy.context.scene
    scene.frame_set(KEY_FRAMES[0])
    path = os.path.join(HERE, stem)
    bpy.ops.export_scene.gltf(filepath=path + ".glb")
    bpy.ops.export_scene.fbx(filepath=path + ".fbx")
    for frame in OBJ_FRAMES:
        write_deformed_obj(body, "%s_f%02d.obj" % (path, frame), frame)
    for suffix in (".glb", ".fbx"):
        print("wrote", path + suffix, os.path.getsize(path + suffix), "bytes")


def bending_arm():
    empty_scene(KEY_FRAMES[0], KEY_FRAMES[-1])
    body = cylinder("Arm", 0.25, 3.0, 24, 24, lambda x, y, z: (x, y, z))
    rig = chain((0.0, 0.0, 0.0), 1.0)
    skin(body, rig)
    key_bend(rig, 35.0, 35.0 * 1.4)
    export("bending_arm", body)


def turned_limb():
    empty_scene(KEY_FRAMES[0], KEY_FRAMES[-1])
    # The armature's turn (90 degrees about Y) takes its (x, y, z) to the
    # world's (z, y, -x); its scale makes the 3 m chain 4.5 m long.
    scale = 1.5
    body = cylinder("Limb", 0.2 * scale, 3.0 * scale, 24, 24, lambda x, y, z: (z, y, -x))
    rig = chain((0.0, math.radians(90.0), 0.0), scale)
    skin(body, rig)
    key_bend(rig, 40.0, 55.0)
    export("turned_limb", body)


bending_arm()
turned_limb()
