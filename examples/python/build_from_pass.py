"""An all-around photo-model from a pass of the hand given as arrays (docs/tutorial-python.md): the images as your
cameras gave them and the hand's poses as your robot reports them.

usage: PYTHONPATH=build/python python3 examples/python/build_from_pass.py VIEWS_FOLDER RIG OUT_MODEL
(here the arrays are read from a views folder, e.g. the one pm-make-model --target C12 writes)
"""
import os
import sys

import cv2
import numpy as np

import visp_photomodel as pm


def hand_pose(path: str) -> np.ndarray:
    """A vpPoseVector YAML (tx, ty, tz and theta-u, metres and radians) as a 4 x 4 matrix."""
    values = [float(line.split("[")[1].split("]")[0]) for line in open(path) if line.strip().startswith("- [")]
    fMh = np.eye(4)
    fMh[:3, :3], _ = cv2.Rodrigues(np.array(values[3:6]))
    fMh[:3, 3] = values[:3]
    return fMh


folder, rig_file, out = sys.argv[1:4]
rig = pm.load_rig(rig_file)
views = []
k = 0
while os.path.exists(os.path.join(folder, "left_%02d.png" % k)):
    image = lambda stem: cv2.imread(os.path.join(folder, "%s_%02d.png" % (stem, k)))  # BGR, as OpenCV reads it
    views.append(pm.PassView(image("left"), image("right"), hand_pose(os.path.join(folder, "pose_fPh_%02d.yaml" % k)),
                             background_left=image("background_left"), background_right=image("background_right"),
                             name="view %02d" % k))
    k += 1
try:
    model = pm.build_model(rig, views)
except pm.Error as e:
    sys.exit("error: %s" % e)
model.save(out)
print("%d views: %s, written to %s" % (len(views), model, out))
