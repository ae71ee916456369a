# Writes walker_clips.fbx beside this file: the walker's two actions (Walk,
# Idle) on its armature alone, no mesh, as Mixamo-style animation files come
# for a character exported once with its mesh (walker.fbx beside it, made by
# make_walker.py). Blender imports walker.fbx and exports the armature only:
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_walker_clips.py
import os

import bpy

here = os.path.dirname(os.path.abspath(__file__))
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.fbx(filepath=os.path.join(here, "walker.fbx"))
bpy.ops.export_scene.fbx(
    filepath=os.path.join(here, "walker_clips.fbx"),
    object_types={"ARMATURE"},
    add_leaf_bones=False,
    bake_anim=True,
    bake_anim_use_all_actions=True,
    bake_anim_use_nla_strips=False,
)
