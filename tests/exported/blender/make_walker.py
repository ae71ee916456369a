# Writes walker.glb beside this file: a small low-poly humanoid "walker"
# (one mesh object of about 1.8 units, three materials Skin / Shirt /
# Trousers) skinned with automatic weights to a 13-bone armature, with two
# armature actions, as Blender's own glTF exporter writes them. Run with
# Debian's blender (3.4); its glTF exporter needs python3-numpy:
#   blender -b --python-exit-code 1 --python tests/exported/blender/make_walker.py
#
# The character stands on the ground (the soles at Z = 0 in Blender, y = 0
# in the Y-up glTF) and faces -Y in Blender, +Z in the glTF; its left (.L
# bones) is +X. Bones: hips (the root) -> spine -> head; spine ->
# upper_arm.L/R -> forearm.L/R; hips -> thigh.L/R -> shin.L/R -> foot.L/R.
# Every bone's local X axis is Blender's +X, so a positive rotation about it
# swings a limb backwards (towards +Y).
#
# Two actions, 24 fps, each alone on an NLA track of its own name, so the
# glTF exporter writes two animations, "Walk" and "Idle":
#   Walk  frames 0..24 (1 s), keyed at every frame, frame 24 = frame 0: the
#         thighs swing +-22 deg and the arms +-15 deg in opposition, the
#         knee of the swinging leg bends up to 45 deg,
#         the feet stay level but for a 10 deg heel rise at push-off, the
#         spine twists +-4 deg (the head twists back). No root motion:
#         the character walks in place. The only translation is the hips'
#         bob, which is measured here, not guessed: the pose is first keyed
#         with the hips at rest, the lowest point of the deformed mesh is
#         read at every frame, and the hips are keyed down by that much, so
#         the lowest point of the mesh is at Z = 0 in every frame (one foot
#         planted, both at the changes of step). The table is printed.
#   Idle  frames 0..48 (2 s): one breath (the spine scales 1 -> 1.015 -> 1
#         and leans back 1.5 deg) and a head turn 0 -> +20 -> 0 -> -20 -> 0
#         deg about the vertical; every other bone keyed at rest.
# The exporter orders the animations by name: "Idle" is animation 0, "Walk" 1.
#
# The same character in Blender's other formats, for the format twins:
#   walker.fbx       both takes (Walk, Idle), baked at every frame
#   walker.dae       COLLADA, the active action only (Walk, bones sampled as
#                    matrices at every frame)
#   walker_rest.obj  the rest pose with its materials (Y up), and
#   walker_rest.stl, walker_rest.ply  positions and faces only (Z up, as
#                    Blender writes them: upload with ?up=z)
#   walker_walk_0_25.obj  the mesh at Walk frame 6 (0.25 s) from Blender's
#                    own armature deform, Y up, positions only
# Reruns are not byte-identical: Blender's split normals of the smooth parts
# vary in the last bit and the Skin primitive's triangles come in another
# order; the geometry, weights and keys are the same.
# As in make_rigged.py the actions start at frame 0 because Blender 3.4's
# glTF exporter writes a key's time as frame / fps.
import math
import os

import addon_utils
import bmesh
import bpy
from mathutils import Matrix, Vector

FPS = 24
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "walker.glb")

bpy.ops.wm.read_factory_settings(use_empty=True)
for obj in list(bpy.data.objects):  # an empty scene, whatever the start-up file
    bpy.data.objects.remove(obj, do_unlink=True)
scene = bpy.context.scene
scene.render.fps = FPS
scene.render.fps_base = 1.0
scene.frame_start = 0
scene.frame_end = 24

# --- the body: primitives built into one bmesh = one mesh object ------------
SKIN, SHIRT, TROUSERS = 0, 1, 2
SEGMENTS = 8
bm = bmesh.new()
parts = {}  # part name -> set of its vertices, for the weight checks


def new_faces(before):
    return [f for f in bm.faces if f not in before]


def tube(name, rings, material):
    """A closed tube of SEGMENTS-gon horizontal rings, each (cx, cy, z, rx, ry)."""
    before = set(bm.faces)
    loops = []
    for cx, cy, z, rx, ry in rings:
        loop = []
        for i in range(SEGMENTS):
            a = 2 * math.pi * (i + 0.5) / SEGMENTS
            loop.append(bm.verts.new((cx + rx * math.cos(a), cy + ry * math.sin(a), z)))
        loops.append(loop)
    for r in range(len(loops) - 1):
        for i in range(SEGMENTS):
            j = (i + 1) % SEGMENTS
            bm.faces.new((loops[r][i], loops[r][j], loops[r + 1][j], loops[r + 1][i]))
    bm.faces.new(list(reversed(loops[0])))  # bottom cap, facing -Z
    bm.faces.new(loops[-1])                 # top cap, facing +Z
    faces = new_faces(before)
    for f in faces:
        f.material_index = material(f) if callable(material) else material
    parts[name] = {v for f in faces for v in f.verts}


def box(name, lo, hi, material):
    before = set(bm.faces)
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    size = [b - a for a, b in zip(lo, hi)]
    matrix = Matrix.Translation(centre) @ Matrix.Diagonal((*size, 1.0))
    bmesh.ops.create_cube(bm, size=1.0, matrix=matrix)
    faces = new_faces(before)
    for f in faces:
        f.material_index = material
    parts[name] = {v for f in faces for v in f.verts}


def sphere(name, centre, radius, z_scale, material):
    before = set(bm.faces)
    matrix = Matrix.Translation(centre) @ Matrix.Diagonal((radius, radius, radius * z_scale, 1.0))
    bmesh.ops.create_uvsphere(bm, u_segments=10, v_segments=7, radius=1.0, matrix=matrix)
    faces = new_faces(before)
    for f in faces:
        f.material_index = material
    parts[name] = {v for f in faces for v in f.verts}


def lerp(a, b, t):
    return a + (b - a) * t


for side, sx in (("L", 1.0), ("R", -1.0)):
    # leg: ankle (inside the foot) to the top of the thigh (inside the pelvis)
    zs = [0.05, 0.14, 0.23, 0.32, 0.42, 0.52, 0.62, 0.72, 0.82, 0.92, 1.00]
    tube("leg." + side,
         [(sx * 0.10, 0.0, z, lerp(0.050, 0.078, z), lerp(0.050, 0.078, z)) for z in zs],
         TROUSERS)
    # foot: a shoe box, toes towards -Y (forward)
    box("foot." + side, (sx * 0.10 - 0.06, -0.19, 0.0), (sx * 0.10 + 0.06, 0.06, 0.08), TROUSERS)
    # arm: shoulder to wrist, hanging a little away from the body
    arm_rings = []
    for k in range(8):
        t = k / 7
        arm_rings.append((sx * lerp(0.255, 0.285, t), 0.0, lerp(1.43, 0.85, t),
                          lerp(0.056, 0.042, t), lerp(0.056, 0.042, t)))
    tube("arm." + side, list(reversed(arm_rings)), SHIRT)
    box("hand." + side, (sx * 0.285 - 0.035, -0.045, 0.75), (sx * 0.285 + 0.035, 0.045, 0.86), SKIN)

# torso: pelvis (trousers) up to the shoulders (shirt)
torso_rings = [(0.0, 0.0, 0.86, 0.170, 0.105), (0.0, 0.0, 0.96, 0.175, 0.105),
               (0.0, 0.0, 1.06, 0.165, 0.100), (0.0, 0.0, 1.16, 0.165, 0.100),
               (0.0, 0.0, 1.26, 0.175, 0.105), (0.0, 0.0, 1.36, 0.190, 0.110),
               (0.0, 0.0, 1.44, 0.160, 0.095)]
tube("torso", torso_rings,
     lambda f: TROUSERS if f.calc_center_median().z < 1.0 else SHIRT)
tube("neck", [(0.0, 0.0, z, 0.048, 0.048) for z in (1.42, 1.48, 1.56)], SKIN)
sphere("head", (0.0, 0.0, 1.665), 0.12, 1.12, SKIN)
box("nose", (-0.018, -0.142, 1.625), (0.018, -0.105, 1.665), SKIN)

for f in bm.faces:
    f.smooth = True
bm.normal_update()
mesh = bpy.data.meshes.new("Walker")
bm.to_mesh(mesh)
part_indices = {name: sorted(v.index for v in verts) for name, verts in parts.items()}
bm.free()
mesh.use_auto_smooth = True  # smooth tubes and head, sharp box edges
mesh.auto_smooth_angle = math.radians(50)
body = bpy.data.objects.new("Walker", mesh)
scene.collection.objects.link(body)

for name, colour in (("Skin", (0.93, 0.70, 0.55, 1.0)),
                     ("Shirt", (0.15, 0.45, 0.80, 1.0)),
                     ("Trousers", (0.25, 0.22, 0.20, 1.0))):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = colour
    material.diffuse_color = colour
    mesh.materials.append(material)

# --- the armature -------------------------------------------------------------
BONES = [  # name, head, tail, parent, connected
    ("hips", (0, 0, 0.92), (0, 0, 1.06), None, False),
    ("spine", (0, 0, 1.06), (0, 0, 1.42), "hips", True),
    ("head", (0, 0, 1.42), (0, 0, 1.80), "spine", True),
]
for side, sx in (("L", 1.0), ("R", -1.0)):
    BONES += [
        ("upper_arm." + side, (sx * 0.255, 0, 1.42), (sx * 0.27, 0, 1.13), "spine", False),
        ("forearm." + side, (sx * 0.27, 0, 1.13), (sx * 0.285, 0, 0.78), "upper_arm." + side, True),
        ("thigh." + side, (sx * 0.10, 0, 0.94), (sx * 0.10, 0, 0.51), "hips", False),
        ("shin." + side, (sx * 0.10, 0, 0.51), (sx * 0.10, 0, 0.08), "thigh." + side, True),
        ("foot." + side, (sx * 0.10, 0, 0.08), (sx * 0.10, -0.17, 0.04), "shin." + side, True),
    ]

arm_data = bpy.data.armatures.new("Armature")
rig = bpy.data.objects.new("Armature", arm_data)
scene.collection.objects.link(rig)
bpy.context.view_layer.objects.active = rig
bpy.ops.object.mode_set(mode='EDIT')
for name, head, tail, parent, connected in BONES:
    bone = arm_data.edit_bones.new(name)
    bone.head = head
    bone.tail = tail
    # Roll so that the bone's X axis is Blender's +X: Z = X x Y.
    bone.align_roll(Vector((1, 0, 0)).cross(Vector(tail) - Vector(head)))
    if parent is not None:
        bone.parent = arm_data.edit_bones[parent]
        bone.use_connect = connected
bpy.ops.object.mode_set(mode='OBJECT')
for bone in arm_data.bones:
    x_axis = bone.matrix_local.col[0].xyz
    assert x_axis.dot(Vector((1, 0, 0))) > 0.99, (bone.name, x_axis)

# Parent with automatic (bone heat) weights: select the mesh, then the rig
# as the active object.
bpy.ops.object.select_all(action='DESELECT')
body.select_set(True)
rig.select_set(True)
bpy.context.view_layer.objects.active = rig
bpy.ops.object.parent_set(type='ARMATURE_AUTO')

# Every vertex must have weights; a part whose vertices bone heat missed gets
# the bone that part belongs to, explicitly.
PART_BONE = {"torso": "spine", "neck": "head", "head": "head", "nose": "head"}
for side in ("L", "R"):
    PART_BONE.update({"foot." + side: "foot." + side, "hand." + side: "forearm." + side,
                      "arm." + side: "upper_arm." + side, "leg." + side: "thigh." + side})
group_names = {g.index: g.name for g in body.vertex_groups}
unweighted = [v.index for v in mesh.vertices if not any(g.weight > 1e-4 for g in v.groups)]
print("vertices without weights after ARMATURE_AUTO:", len(unweighted), "of", len(mesh.vertices))
if unweighted:
    missing = set(unweighted)
    for name, indices in part_indices.items():
        fix = [i for i in indices if i in missing]
        if fix:
            body.vertex_groups[PART_BONE[name]].add(fix, 1.0, 'REPLACE')
            print("  weighted", len(fix), "vertices of", name, "to", PART_BONE[name])
unweighted = [v.index for v in mesh.vertices if not any(g.weight > 1e-4 for g in v.groups)]
assert not unweighted, unweighted
print("dominant bone per part:")
for name, indices in part_indices.items():
    totals = {}
    for i in indices:
        for g in mesh.vertices[i].groups:
            totals[group_names[g.group]] = totals.get(group_names[g.group], 0.0) + g.weight
    ranked = sorted(totals.items(), key=lambda kv: -kv[1])[:3]
    print("  %-8s %s" % (name, ", ".join("%s %.0f%%" % (b, 100 * w / sum(totals.values()))
                                          for b, w in ranked)))

# --- the actions --------------------------------------------------------------
for pb in rig.pose.bones:
    pb.rotation_mode = 'XYZ'


def reset_pose():
    for pb in rig.pose.bones:
        pb.location = (0, 0, 0)
        pb.rotation_euler = (0, 0, 0)
        pb.scale = (1, 1, 1)


def key_all(frame):
    for pb in rig.pose.bones:
        for path in ("location", "rotation_euler", "scale"):
            pb.keyframe_insert(data_path=path, frame=frame, group=pb.name)


def lowest_z(*part_names):
    """The lowest and highest Z of the deformed mesh, then the lowest Z of
    each part named."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = body.evaluated_get(depsgraph)
    deformed = evaluated.to_mesh()
    world = evaluated.matrix_world
    z = [(world @ v.co).z for v in deformed.vertices]
    evaluated.to_mesh_clear()
    return (min(z), max(z)) + tuple(min(z[i] for i in part_indices[p]) for p in part_names)


rad = math.radians
THIGH, ARM, ELBOW, TWIST = rad(22), rad(15), rad(10), rad(4)
KNEE_STANCE, KNEE_SWING, KNEE_PEAK = rad(5), rad(45), 0.4  # peak at 40% of the swing
HEEL = rad(10)  # heel rise (toes down) at the end of the stance, gone early in the swing


def smoothstep(x):
    x = min(1.0, max(0.0, x))
    return x * x * (3 - 2 * x)


def walk_pose(frame):
    """Rotations about each bone's X (= Blender X): positive swings back.

    Each leg's phase q runs 0..1 over the cycle: it swings forward (knee
    bent) over q 0..0.5 and stands over q 0.5..1 (the right leg swings over
    frames 0..12, the left over 12..24). The foot is kept level, except
    that its heel rises late in the stance (the toes push off), so the
    trailing leg, not the swinging one, holds the ground until the other
    foot lands at the change of step: the hips' bob is then a smooth rise
    and fall, no bump."""
    pose = {}
    for side, offset in (("L", 0.5), ("R", 0.0)):
        q = (frame / 24 + offset) % 1.0
        thigh = THIGH * math.cos(2 * math.pi * q)  # back at q = 0, forward at 0.5
        if q < 0.5:  # swing
            u = 2 * q
            if u < KNEE_PEAK:
                bend = math.sin(math.pi * u / (2 * KNEE_PEAK))
            else:
                bend = math.cos(math.pi / 2 * (u - KNEE_PEAK) / (1 - KNEE_PEAK))
            knee = KNEE_STANCE + (KNEE_SWING - KNEE_STANCE) * bend
            heel = HEEL * (1 - smoothstep(u / 0.3))
        else:  # stance
            v = 2 * q - 1
            knee = KNEE_STANCE
            heel = HEEL * smoothstep((v - 0.5) / 0.4)
        pose["thigh." + side] = (thigh, 0, 0)
        pose["shin." + side] = (knee, 0, 0)
        pose["foot." + side] = (heel - (thigh + knee), 0, 0)
        arm = -ARM * math.cos(2 * math.pi * q)  # opposite the leg of its side
        pose["upper_arm." + side] = (arm, 0, 0)
        pose["forearm." + side] = (-ELBOW * (1 + max(0.0, math.cos(2 * math.pi * q))), 0, 0)
    c = math.cos(2 * math.pi * frame / 24)
    pose["spine"] = (0, TWIST * c, 0)   # the left shoulder back with the left arm
    pose["head"] = (0, -TWIST * c, 0)   # the head keeps looking ahead
    return pose


rig.animation_data_create()
reset_pose()
walk = bpy.data.actions.new("Walk")
rig.animation_data.action = walk
for frame in range(25):
    reset_pose()
    for name, rotation in walk_pose(frame).items():
        rig.pose.bones[name].rotation_euler = rotation
    key_all(frame)

# The hips' bob: the lowest point of the mesh, hips at rest, frame by frame;
# the hips (Y axis = Blender Z) go down by that much.
bob = []
for frame in range(25):
    scene.frame_set(frame)
    bob.append(-lowest_z()[0])
bob[24] = bob[0]  # the same pose; keep the loop exact
fcurve = walk.fcurves.find('pose.bones["hips"].location', index=1)
for frame, kp in enumerate(sorted(fcurve.keyframe_points, key=lambda k: k.co[0])):
    kp.co[1] = bob[frame]
    kp.handle_left[1] = kp.handle_right[1] = bob[frame]
for fc in walk.fcurves:
    for kp in fc.keyframe_points:
        kp.interpolation = 'LINEAR'
    fc.update()

print("Walk: frame, hips bob, lowest Z, highest Z of the deformed mesh, lowest Z of foot.L, foot.R")
lows = []
for frame in range(25):
    scene.frame_set(frame)
    low, top, left, right = lowest_z("foot.L", "foot.R")
    lows.append(low)
    print("  %2d  %+.4f  %+.5f  %.4f  %.4f  %.4f" % (frame, bob[frame], low, top, left, right))
print("Walk: lowest Z ranges %.5f .. %.5f (spread %.5f); bob spread %.4f"
      % (min(lows), max(lows), max(lows) - min(lows), max(bob) - min(bob)))
assert max(abs(z) for z in lows) < 0.005, lows

rig.animation_data.action = None
reset_pose()
idle = bpy.data.actions.new("Idle")
rig.animation_data.action = idle
for frame, breath, turn in ((0, 0.0, 0.0), (12, 0.5, 1.0), (24, 1.0, 0.0),
                            (36, 0.5, -1.0), (48, 0.0, 0.0)):
    reset_pose()
    spine = rig.pose.bones["spine"]
    spine.scale = (1 + 0.015 * breath,) * 3
    spine.rotation_euler = (rad(1.5) * breath, 0, 0)   # leans back a little
    rig.pose.bones["head"].rotation_euler = (0, rad(20) * turn, 0)  # about the vertical
    key_all(frame)
print("Idle: frame, lowest Z, highest Z")
for frame in range(0, 49, 6):
    scene.frame_set(frame)
    print("  %2d  %+.5f  %.4f" % ((frame,) + lowest_z()))
rig.animation_data.action = None
reset_pose()


def push_to_track(anim_data, action, name, start):
    track = anim_data.nla_tracks.new()
    track.name = name
    strip = track.strips.new(action.name, start, action)
    strip.name = action.name
    return track


push_to_track(rig.animation_data, walk, "Walk", 0)
push_to_track(rig.animation_data, idle, "Idle", 100)  # the glTF exporter uses the action's own frames
for action in (walk, idle):
    action.use_fake_user = True

# --- export -------------------------------------------------------------------
scene.frame_set(0)
rig.animation_data.use_nla = False  # the rest pose in the file's nodes
bpy.context.view_layer.update()
print("rest: lowest Z %.5f, highest Z %.4f, %d triangles"
      % (lowest_z() + (sum(len(p.vertices) - 2 for p in mesh.polygons),)))
bpy.ops.object.select_all(action='SELECT')
bpy.ops.export_scene.gltf(
    filepath=OUT,
    export_format='GLB',
    export_yup=True,
    export_texcoords=False,
    export_normals=True,
    export_colors=False,
    export_animations=True,
    export_nla_strips=True,
    export_anim_single_armature=False,
    export_force_sampling=True,
    export_frame_range=False,
    export_skins=True,
    export_morph=False,
    export_materials='EXPORT',
)
print("wrote", OUT, os.path.getsize(OUT), "bytes")

STEM = os.path.join(HERE, "walker")
# The FBX exporter bakes each NLA strip as a take by playing the scene: the
# tracks must be live (with them off every take is the rest pose).
rig.animation_data.use_nla = True
bpy.ops.export_scene.fbx(
    filepath=STEM + ".fbx",
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
print("wrote", STEM + ".fbx", os.path.getsize(STEM + ".fbx"), "bytes")

rig.animation_data.use_nla = False
rig.animation_data.action = walk
print("COLLADA export:", bpy.ops.wm.collada_export(
    filepath=STEM + ".dae",
    selected=False,
    include_armatures=True,
    include_animations=True,
    include_all_actions=False,
    export_animation_type_selection='sample',
    sampling_rate=1,
    triangulate=True,
))

# The rest pose, and Walk at 0.25 s, from the deformed mesh.
for module in ("io_mesh_stl", "io_mesh_ply"):
    addon_utils.enable(module, default_set=True)
rig.animation_data.action = None
arm_data.pose_position = 'REST'  # the pose bones keep the last frame's values
scene.frame_set(0)
bpy.context.view_layer.update()
bpy.ops.object.select_all(action='DESELECT')
body.select_set(True)
bpy.context.view_layer.objects.active = body
bpy.ops.export_scene.obj(filepath=STEM + "_rest.obj", use_selection=True, use_mesh_modifiers=True,
                         use_triangles=True, use_normals=True, use_uvs=False, use_materials=True,
                         use_animation=False)
bpy.ops.export_mesh.stl(filepath=STEM + "_rest.stl", use_selection=True, ascii=False)
bpy.ops.export_mesh.ply(filepath=STEM + "_rest.ply", use_selection=True, use_normals=False,
                        use_uv_coords=False, use_colors=False)
arm_data.pose_position = 'POSE'
rig.animation_data.action = walk
scene.frame_set(6)
bpy.context.view_layer.update()
bpy.ops.export_scene.obj(filepath=STEM + "_walk_0_25.obj", use_selection=True, use_mesh_modifiers=True,
                         use_triangles=True, use_normals=False, use_uvs=False, use_materials=False,
                         use_animation=False)
