# Imports a BVH with Blender's own importer and prints every bone's world head position at every
# frame, one "POS <bvh frame> <bone> <x> <y> <z>" line each, for bvh_blender_test.cpp to compare
# with fapcast's forward kinematics. Usage:
#   blender -b --factory-startup --python tests/data/bvh/blender_import_check.py -- FILE.bvh
import sys

import bpy

# Debian's Blender 3.4.1 runs its BVH importer on Python 3.11, which no longer accepts the 'rU'
# file mode the importer passes to open(): every import fails with "invalid mode: 'rU'" before
# reading a byte. Give the importer an open() that drops the obsolete 'U' flag.
from io_anim_bvh import import_bvh

_builtin_open = open


def _open_without_u(file, mode="r", *args, **kwargs):
    return _builtin_open(file, mode.replace("U", ""), *args, **kwargs)


import_bvh.open = _open_without_u

path = sys.argv[sys.argv.index("--") + 1]
# axis_forward='Y', axis_up='Z' is Blender's own frame: no axis conversion, so positions compare
# 1:1 with the file's. frame_start=1: BVH frame k is scene frame k + 1.
bpy.ops.import_anim.bvh(filepath=path, axis_forward='Y', axis_up='Z', frame_start=1,
                        use_fps_scale=False, update_scene_fps=True, update_scene_duration=True)
arm = bpy.context.object
scene = bpy.context.scene
print("IMPORTED", arm.name, len(arm.pose.bones), "bones", "frames", scene.frame_start, scene.frame_end,
      "fps", scene.render.fps / scene.render.fps_base)
action = arm.animation_data.action
first, last = (int(round(v)) for v in action.frame_range)
for frame in range(first, last + 1):
    scene.frame_set(frame)
    for bone in arm.pose.bones:
        p = arm.matrix_world @ bone.head
        print("POS", frame - 1, bone.name, "%.6f %.6f %.6f" % (p.x, p.y, p.z))
