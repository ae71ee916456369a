# Writes part.obj, part.stl and part.ply beside this file: one object (a
# 2-unit cube with a cylinder of 48 sides on top), positions and faces
# only, as Blender's own exporters write them. Run with Debian's blender:
#   blender -b --python tests/exported/blender/make.py
# Blender is Z-up: its OBJ exporter turns the object Y-up, its STL and PLY
# exporters keep Z up (upload those with ?up=z).
import os

import addon_utils
import bpy

for module in ("io_mesh_stl", "io_mesh_ply"):
    addon_utils.enable(module, default_set=True)
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.mesh.primitive_cube_add(size=2, location=(0, 0, 0))
bpy.ops.mesh.primitive_cylinder_add(vertices=48, radius=0.5, depth=1.0, location=(0, 0, 1.5))
bpy.ops.object.select_all(action='SELECT')
bpy.ops.object.join()
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "part")
bpy.ops.export_mesh.stl(filepath=out + ".stl", ascii=False)
bpy.ops.export_mesh.ply(filepath=out + ".ply", use_normals=False, use_uv_coords=False, use_colors=False)
bpy.ops.export_scene.obj(filepath=out + ".obj", use_normals=False, use_materials=False)
