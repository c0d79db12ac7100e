"""The main job from Python, frame by frame (docs/tutorial-python.md): the PA-10 keeps the crab 500 mm ahead while the
TC-robot moves it through Table 2's first steps.

usage: PYTHONPATH=build/python python3 examples/python/servo_loop.py [SECONDS]
"""
import sys

import visp_photomodel as pm

seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 6.0
rig = pm.load_rig(pm.data_path("rig/pa10_stereo.json"))
loop = pm.lab.ServoLoop("C12", rig, pm.data_path("trajectories/table2.csv"), steps=2, seed=1, ga_seed=1)
servoed = wrong = 0
while loop.time <= min(seconds, loop.duration):
    frame = loop.step()
    servoed += frame.servoing
    wrong += frame.servoed_on_wrong_pose
    if round(frame.t * 30) % 30 == 0:  # once a second
        print("t %4.1f s  %-9s  hand off by %6.2f mm %5.2f deg  estimate off by %5.2f mm %5.2f deg" % (
            frame.t, frame.result.state.name.lower(), frame.error_mm, frame.error_deg, frame.estimate_error_mm, frame.estimate_error_deg))
left, right = loop.images()
pm.write_image(left, "servo_last_left.png")
print("servoed on %d frames, %d on a wrong pose; the last left image in servo_last_left.png" % (servoed, wrong))
