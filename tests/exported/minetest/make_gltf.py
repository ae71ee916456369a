# Writes character_blender.glb, Blender's glTF of Minetest's player model,
# from the character.blend that Debian's minetest-data ships beside the
# character.b3d exported from it (README.md says how to get both):
#   blender -b PATH/character.blend --python-exit-code 1 --python make_gltf.py -- OUT_DIR
# Blender 3.4's own exporter, default options but for the texture (the
# .blend's image is character.png; the B3D names none).
import os
import sys

import bpy

out_dir = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.path.dirname(os.path.abspath(__file__))
bpy.ops.export_scene.gltf(
    filepath=os.path.join(out_dir, "character_blender.glb"),
    export_format="GLB",
    export_animations=True,
    export_frame_range=False,
    export_force_sampling=True,
    export_image_format="NONE",
    use_selection=False,
)
