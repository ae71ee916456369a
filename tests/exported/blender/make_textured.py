# Writes textured.glb, textured.fbx (the image embedded) and textured.dae
# (the image beside it, textured_checker.png) beside this file: a 2 x 2 x 2
# cube whose six faces show an 8 x 8 checker of red and cream, each face
# the whole image, as Blender's own exporters write them. Run with Debian's
# blender (3.4); its glTF exporter needs python3-numpy:
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_textured.py
import os

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
STEM = os.path.join(HERE, "textured")
PNG = STEM + "_checker.png"

bpy.ops.wm.read_factory_settings(use_empty=True)

# The COLLADA exporter names the file after the image.
image = bpy.data.images.new("textured_checker", 8, 8, alpha=False)
pixels = []
for y in range(8):
    for x in range(8):
        red = (x + y) % 2 == 0
        pixels += [0.8, 0.1, 0.1, 1.0] if red else [0.95, 0.9, 0.75, 1.0]
image.pixels = pixels
image.filepath_raw = PNG
image.file_format = 'PNG'
image.save()

bpy.ops.mesh.primitive_cube_add(size=2, location=(0, 0, 0))
cube = bpy.context.active_object
cube.name = "Box"
material = bpy.data.materials.new("Checker")
material.use_nodes = True
nodes = material.node_tree.nodes
texture = nodes.new("ShaderNodeTexImage")
texture.image = image
texture.interpolation = 'Closest'
material.node_tree.links.new(texture.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
cube.data.materials.append(material)

bpy.ops.export_scene.gltf(filepath=STEM + ".glb", export_format='GLB', export_yup=True, export_materials='EXPORT')
bpy.ops.export_scene.fbx(filepath=STEM + ".fbx", object_types={'MESH'}, path_mode='COPY', embed_textures=True)
print("COLLADA export:", bpy.ops.wm.collada_export(filepath=STEM + ".dae", selected=False, triangulate=True))
