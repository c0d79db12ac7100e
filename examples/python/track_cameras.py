"""Two cameras read with OpenCV's VideoCapture, tracked (docs/tutorial-python.md).

usage: PYTHONPATH=build/python python3 examples/python/track_cameras.py LEFT RIGHT --rig RIG --model MODEL
LEFT, RIGHT: what cv2.VideoCapture opens: a device index (0, 1), a video file, an image pattern (L_%04d.png), a pipeline.
"""
import argparse
import sys

import cv2
import numpy as np

import visp_photomodel as pm


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("left", help="the left camera: a device index, a video file or an image pattern")
    parser.add_argument("right", help="the right camera, the same way")
    parser.add_argument("--rig", required=True, help="the stereo rig file (rig.json)")
    parser.add_argument("--model", required=True, help="the photo-model (model.json)")
    parser.add_argument("--frames", type=int, default=0, help="stop after this many pairs (0: when a camera ends)")
    args = parser.parse_args()
    try:
        rig, model = pm.load_rig(args.rig), pm.load_model(args.model)
        tracker = pm.Tracker(rig, model)
    except pm.Error as e:
        print("error:", e, file=sys.stderr)
        return 1
    opened = [cv2.VideoCapture(int(s) if s.isdigit() else s) for s in (args.left, args.right)]
    if not all(c.isOpened() for c in opened):
        print("error: cannot open the cameras", args.left, args.right, file=sys.stderr)
        return 1
    k = 0
    while args.frames == 0 or k < args.frames:
        ok_left, left = opened[0].read()   # H x W x 3 BGR uint8, as OpenCV gives it
        ok_right, right = opened[1].read()
        if not (ok_left and ok_right):
            break
        result = tracker.track(left, right)  # read once where the tracker first reads its pixels
        x, y, z = 1e3 * result.pose[:3, 3]
        print("frame %3d  %-9s  confidence %.3f  %s  model at %7.1f %7.1f %7.1f mm" % (
            k, result.state.name.lower(), result.confidence, "trusted" if result.trusted else "-------", x, y, z))
        k += 1
    print("%d pairs tracked" % k)
    return 0 if k > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
