# Pieces the rig-writing scripts here share (make_bending_rigs.py,
# make_conformance.py): an empty scene at 24 fps, a smooth tube from its
# rings, skinning by bone heat, and Blender's own deformed mesh as OBJ.
# Imported by those scripts from their folder; not run on its own.
import bmesh
import bpy


def empty_scene(first, last, fps=24):
    """Blender's factory settings without a single object, running frames
    first..last at `fps`."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    for obj in list(bpy.data.objects):  # whatever the start-up file holds
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    scene.render.fps = fps
    scene.render.fps_base = 1.0
    scene.frame_start = first
    scene.frame_end = last
    return scene


def smooth_tube(name, rings):
    """A mesh object of quads between consecutive rings (each a list of
    world points, all of one length), closed by an n-gon at each end,
    smooth-shaded, linked to the scene."""
    bm = bmesh.new()
    loops = [[bm.verts.new(p) for p in ring] for ring in rings]
    sides = len(loops[0])
    for r in range(len(loops) - 1):
        for i in range(sides):
            j = (i + 1) % sides
            bm.faces.new((loops[r][i], loops[r][j], loops[r + 1][j], loops[r + 1][i]))
    bm.faces.new(list(reversed(loops[0])))
    bm.faces.new(loops[-1])
    for f in bm.faces:
        f.smooth = True
    bm.normal_update()
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def skin(body, rig, automatic=True):
    """Parents `body` to armature `rig` with bone-heat weights (every vertex
    must get one), or with empty vertex groups named after the bones."""
    bpy.ops.object.select_all(action='DESELECT')
    body.select_set(True)
    rig.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.parent_set(type='ARMATURE_AUTO' if automatic else 'ARMATURE_NAME')
    if automatic:
        unweighted = [v.index for v in body.data.vertices if not any(g.weight > 1e-4 for g in v.groups)]
        assert not unweighted, unweighted


def write_deformed_obj(body, path, frame):
    """The mesh of `body` as Blender deforms it at `frame` (modifiers
    applied), Y up like the glTF, positions and triangles only."""
    scene = bpy.context.scene
    bpy.ops.object.select_all(action='DESELECT')
    body.select_set(True)
    bpy.context.view_layer.objects.active = body
    scene.frame_set(frame)
    bpy.context.view_layer.update()
    bpy.ops.export_scene.obj(filepath=path, use_selection=True, use_mesh_modifiers=True, use_triangles=True,
                             use_normals=False, use_uvs=False, use_materials=False, use_animation=False)
