"""Two image sequences of the lab's crab, as two cameras would record them (for track_cameras.py without a rig at hand).

usage: PYTHONPATH=build/python python3 examples/python/record_lab_cameras.py FOLDER [FRAMES]
writes FOLDER/L_0000.png, R_0000.png, ...: the crab 500 mm ahead, sliding 1 mm a frame (its model: first_steps.py's)
"""
import os
import sys

import numpy as np

import visp_photomodel as pm

folder = sys.argv[1]
frames = int(sys.argv[2]) if len(sys.argv) > 2 else 45
os.makedirs(folder, exist_ok=True)
rig = pm.load_rig(pm.data_path("rig/pa10_stereo.json"))
scene = pm.lab.Scene("C12", seed=2)
for k in range(frames):
    hMo = np.eye(4)
    hMo[:3, 3] = [0.0, 0.001 * k, 0.5]
    left, right = scene.render(rig, hMo, k)
    pm.write_image(left, os.path.join(folder, "L_%04d.png" % k))
    pm.write_image(right, os.path.join(folder, "R_%04d.png" % k))
print("wrote %d pairs to %s" % (frames, folder))
