"""What Python adds to a stereo frame of the tracker, measured in one process (docs/performance.md).

usage: PYTHONPATH=build/python python3 bench/python_overhead.py [--frames N] [--target T]

Renders N pairs of a toy moving slowly, then tracks them three times with the same seed (the same work):
from Python with RGBA arrays, with BGR arrays (OpenCV's layout, converted once per frame), and timed inside
the C++ tracker (TrackResult.compute_ms, the time spent in PhotoModelTracker::track()). Prints the
per-frame medians and the ratios: Python's overhead on the tracker's own time, and the BGR conversion's.
"""
import argparse
import statistics
import time

import numpy as np

import visp_photomodel as pm


def run(rig, model, pairs):
    tracker = pm.Tracker(rig, model, seed=1)
    wall, inside = [], []
    for left, right in pairs:
        t0 = time.perf_counter()
        r = tracker.track(left, right)
        wall.append(1e3 * (time.perf_counter() - t0))
        inside.append(r.compute_ms)
    return wall, inside


def main():
    parser = argparse.ArgumentParser(description="Python's overhead per stereo frame, against the tracker's own time")
    parser.add_argument("--frames", type=int, default=300, help="pairs tracked (default 300)")
    parser.add_argument("--target", default="C12", help="the lab's toy (default C12)")
    parser.add_argument("--rounds", type=int, default=3, help="each layout tracked this many times, alternately (default 3)")
    a = parser.parse_args()
    rig = pm.load_rig(pm.data_path("rig/pa10_stereo.json"))
    scene = pm.lab.Scene(a.target)
    model, _ = scene.make_model(rig)
    rgba = []
    for k in range(a.frames):
        hMo = np.eye(4)
        hMo[:3, 3] = [0.2e-3 * k, 0.0, 0.5]
        rgba.append(scene.render(rig, hMo, k))
    bgr = [(np.ascontiguousarray(l[..., 2::-1]), np.ascontiguousarray(r[..., 2::-1])) for l, r in rgba]
    skip = 30  # the first lock: not a steady frame
    over, conv, inside_all = [], [], []
    for _ in range(a.rounds):
        w_rgba, in_rgba = run(rig, model, rgba)
        w_bgr, in_bgr = run(rig, model, bgr)
        over += [w - i for w, i in zip(w_rgba[skip:], in_rgba[skip:])]
        conv += [(wb - ib) - (wr - ir) for wb, ib, wr, ir in zip(w_bgr[skip:], in_bgr[skip:], w_rgba[skip:], in_rgba[skip:])]
        inside_all += in_rgba[skip:]
    own = statistics.median(inside_all)
    print("frames %d x %d rounds; the tracker's own time (median) %.3f ms a stereo frame" % (a.frames - skip, a.rounds, own))
    print("Python's overhead, RGBA arrays: median %.4f ms = %.2f %% of it" % (statistics.median(over), 100 * statistics.median(over) / own))
    print("the BGR conversion (two 640 x 480 images): median %.4f ms = %.2f %% of it" % (statistics.median(conv), 100 * statistics.median(conv) / own))


if __name__ == "__main__":
    main()
