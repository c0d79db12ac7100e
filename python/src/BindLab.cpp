#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "ServoLoop.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/TargetCatalog.h"

namespace pmpy {

void bindLab(py::module_ &lab)
{
  using pm::sim::Scene;
  py::class_<Scene>(lab, "Scene", "The lab's scene of one toy of the catalogue (pm::sim::Scene): what the rig's cameras see for a pose of the toy.")
      .def(py::init([](const std::string &target, std::uint64_t seed) {
             pm::sim::SceneParams sp;
             sp.seed = seed;
             return std::make_unique<Scene>(pm::sim::makeTarget(target), sp);
           }),
           py::arg("target") = "C12", py::arg("seed") = 1,
           "target: C01..C12 (the paper's sea creatures) or R1..R3 (box, head, tower); seed: the cameras' noise. Raises Error "
           "for an unknown target.")
      .def(
          "render",
          [](const Scene &s, const pm::core::StereoRig &rig, const py::array_t<double, py::array::c_style | py::array::forcecast> &hMo,
             std::uint64_t frame) {
            const vpHomogeneousMatrix M = toMatrix(hMo, "hMo");
            pm::sim::StereoImages im;
            {
              py::gil_scoped_release free;
              im = s.renderStereo(rig, M, frame);
            }
            return py::make_tuple(toArray(im.left), toArray(im.right));
          },
          py::arg("rig"), py::arg("hMo"), py::arg("frame") = 0,
          "The stereo pair (left, right: H x W x 4 RGBA uint8) of the toy at hMo in the hand frame (4 x 4, metres); frame: the "
          "frame number (the noise changes with it).")
      .def(
          "make_model",
          [](const Scene &s, const pm::core::StereoRig &rig, const std::string &arm) {
            pm::lab::LabModelChoice c;
            c.arm = arm;
            pm::sim::SimulatedPhotoModel m;
            {
              py::gil_scoped_release free;
              m = pm::lab::makeLabModel(s, rig, c);
            }
            return py::make_tuple(m.build.model, toArray(m.oMm));
          },
          py::arg("rig"), py::arg("arm") = "pa10",
          "The toy's all-around model as a user makes it: the arm ('pa10', 'viper850', 'afma6') walks the rig around it. "
          "Returns (model, oMm): oMm, the model frame in the toy's (ground truth: hMm = hMo @ oMm).");

  using pm::lab::LoopFrame;
  py::class_<LoopFrame>(lab, "ServoFrame", "What one step of the servo loop did (pm::lab::LoopFrame).")
      .def_readonly("t", &LoopFrame::t, "time of the frame (s)")
      .def_readonly("moving", &LoopFrame::moving, "the TC-robot moves the target")
      .def_property_readonly("true_pose", [](const LoopFrame &f) { return toArray(f.hMmTrue); }, "the model in the hand frame, true (4 x 4, m)")
      .def_property_readonly("used_pose", [](const LoopFrame &f) { return toArray(f.hMmUsed); }, "the pose the servo used (4 x 4, m)")
      .def_readonly("result", &LoopFrame::track, "the tracker's TrackResult")
      .def_readonly("servoing", &LoopFrame::servoing, "the servo ran on the estimate (else the arm was being stopped)")
      .def_readonly("error_mm", &LoopFrame::translationErrorMm, "the hand against where it should be: translation (mm)")
      .def_readonly("error_deg", &LoopFrame::rotationErrorDeg, "... and rotation (deg)")
      .def_readonly("estimate_error_mm", &LoopFrame::estimateErrorMm, "the tracker's estimate against the truth (mm)")
      .def_readonly("estimate_error_deg", &LoopFrame::estimateErrorDeg, "... (deg)")
      .def_property_readonly("servoed_on_wrong_pose", [](const LoopFrame &f) { return f.servoing && f.wrongUsed(); },
                             "the servo ran on a pose over 20 mm or 5 deg off (never, so far)")
      .def_property_readonly("joints", [](const LoopFrame &f) { return std::vector<double>(f.q.data, f.q.data + f.q.size()); },
                             "the arm's joints after the frame (rad or m)");

  py::class_<ServoLoop>(lab, "ServoLoop",
                        "The main job, frame by frame: the TC-robot moves the toy through Table 2's steps, the arm servoes on the "
                        "tracker's pose (pm::lab::ClosedLoop). The toy's model is made first by the arm's pass (a few seconds).\n\n"
                        "    loop = lab.ServoLoop('C12', rig, seed=1)\n"
                        "    frame = loop.step(); left, right = loop.images()")
      .def(py::init([](const std::string &target, const pm::core::StereoRig &rig, const std::string &trajectory, int steps, long seed, long gaSeed,
                       const std::string &arm) {
             if (steps < 0 || seed < 0 || gaSeed < 0)
               throw py::value_error("steps, seed and ga_seed: numbers >= 0 are needed");
             py::gil_scoped_release free;
             return std::make_unique<ServoLoop>(target, rig, trajectory, steps, seed, gaSeed, arm);
           }),
           py::arg("target"), py::arg("rig"), py::arg("trajectory"), py::arg("steps") = 0, py::arg("seed") = 1, py::arg("ga_seed") = 1,
           py::arg("arm") = "pa10",
           "target: a catalogue code; rig: the stereo rig; trajectory: the waypoints file (data_path('trajectories/table2.csv')); "
           "steps: its first N (0: all); seed: the cameras' noise; ga_seed: RM-GA's; arm: 'pa10', 'viper850' or 'afma6'. The "
           "same as pm-servo --target T --seed S --ga-seed G --robot A.")
      .def(
          "step",
          [](ServoLoop &l) {
            py::gil_scoped_release free;
            return l.step();
          },
          "One camera frame: images, estimate, command, the arm moved to the next frame. Returns a ServoFrame.")
      .def(
          "images",
          [](const ServoLoop &l) {
            py::tuple out(l.images().size());
            for (std::size_t k = 0; k < l.images().size(); ++k)
              out[k] = toArray(l.images()[k]);
            return out;
          },
          "The images of the last step(), one per camera (a stereo rig: left, right), H x W x 4 RGBA uint8 copies.")
      .def_property_readonly("model", [](const ServoLoop &l) { return l.model().build.model; }, "the toy's photo-model the pass made")
      .def_property_readonly("time", &ServoLoop::time, "the time of the next step()'s frame (s)")
      .def_property_readonly("duration", &ServoLoop::duration, "the trajectory's duration (s): step() until then");
}

} // namespace pmpy
