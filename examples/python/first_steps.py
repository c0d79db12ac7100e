"""visp-photomodel from Python, first steps (docs/tutorial-python.md): a rig, a photo-model, the tracker on NumPy images.

usage: PYTHONPATH=build/python python3 examples/python/first_steps.py
"""
import numpy as np

import visp_photomodel as pm

# The rig: two cameras on the hand, 323 mm apart (a rig.json as pm-calibrate-rig writes it).
rig = pm.load_rig(pm.data_path("rig/pa10_stereo.json"))
print(rig, rig.left)

# The lab's crab, and its all-around model as the arm's pass makes it (pm-make-model --target C12).
scene = pm.lab.Scene("C12")
model, oMm = scene.make_model(rig)
model.save("c12_model.json")
print(model)

# The tracker, started with no pose: it finds the crab by itself, then follows it.
tracker = pm.Tracker(rig, model)
for k in range(60):
    hMo = np.eye(4)
    hMo[:3, 3] = [0.001 * k, 0.0, 0.5]      # the crab 500 mm ahead, sliding 1 mm a frame
    left, right = scene.render(rig, hMo, k)  # H x W x 4 RGBA uint8, as ViSP holds images
    result = tracker.track(left, right)

print(result.state.name.lower(), "confidence %.3f" % result.confidence, "trusted" if result.trusted else "not trusted")
hMm_true = hMo @ oMm                         # where the model truly is (the lab knows)
error_mm = 1e3 * np.linalg.norm(result.pose[:3, 3] - hMm_true[:3, 3])
print("pose (m):\n", np.round(result.pose, 4))
print("error %.2f mm; 1-sigma x y z (mm) %.2f %.2f %.2f, about them (deg) %.2f %.2f %.2f" % (error_mm, *result.sigma))
