"""The second renderer's images beside the lab's: for each scene of the set, the first view of its pass
and a frame of its sequence, our rasterizer's (left) and Cycles' (right), in one JPEG.

    python3 scripts/cycles/contact.py SET_DIR OUT.jpg [SCENE ...]

(Debian's python3 with python3-opencv and numpy; SET_DIR as scripts/render-cycles.sh fills it.)
"""
import os
import sys

import cv2
import numpy as np


def main():
    if len(sys.argv) < 3 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(sys.argv) > 1 and sys.argv[1] in ("-h", "--help") else 2)
    root, out = sys.argv[1], sys.argv[2]
    scenes = sys.argv[3:] or sorted(d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "sequence", "truth.csv")))
    rows = []
    for s in scenes:
        d = os.path.join(root, s)
        pics = []
        for lab, cyc in (("lab_views/left_00.png", "views/left_00.png"), ("lab_sequence/left_0060.png", "sequence/left_0060.png")):
            a, b = cv2.imread(os.path.join(d, lab)), cv2.imread(os.path.join(d, cyc))
            if a is None or b is None:
                sys.exit("error: %s is not rendered (no %s or %s)" % (d, lab, cyc))
            pics += [a, b]
        row = np.hstack([cv2.resize(p, (320, 240), interpolation=cv2.INTER_AREA) for p in pics])
        cv2.putText(row, s, (6, 18), cv2.FONT_HERSHEY_SIMPLEX, 0.55, (255, 255, 255), 1, cv2.LINE_AA)
        rows.append(row)
    if not rows:
        sys.exit("error: no rendered scene in %s" % root)
    img = np.vstack(rows)
    for i, label in enumerate(("pass, ours", "pass, Cycles", "sequence, ours", "sequence, Cycles")):
        cv2.putText(img, label, (320 * i + 6, 236), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1, cv2.LINE_AA)
    if not cv2.imwrite(out, img, [cv2.IMWRITE_JPEG_QUALITY, 85]):
        sys.exit("error: cannot write %s" % out)


if __name__ == "__main__":
    main()
