#include <cstdio>
#include <optional>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "Tracker.h"

namespace pmpy {

void bindTracker(py::module_ &m)
{
  using pm::tracker::TrackResult;
  using pm::tracker::TrackState;
  py::enum_<TrackState>(m, "TrackState", "The tracker's state: SEARCHING (no lock yet), TRACKING (locked), LOST (the lock lost).")
      .value("SEARCHING", TrackState::Searching)
      .value("TRACKING", TrackState::Tracking)
      .value("LOST", TrackState::Lost);
  py::class_<TrackResult>(m, "TrackResult", "What the tracker says about a frame (pm::tracker::TrackResult).")
      .def_property_readonly("pose", [](const TrackResult &r) { return toArray(r.hMo); }, "hMo: the model in the hand frame (4 x 4, metres)")
      .def_property_readonly(
          "phi", [](const TrackResult &r) { return py::make_tuple(r.phi.x, r.phi.y, r.phi.z, r.phi.e1, r.phi.e2, r.phi.e3); },
          "the same pose as the programs write it: x, y, z (mm) and the quaternion's vector e1, e2, e3")
      .def_readonly("state", &TrackResult::state, "TrackState: SEARCHING, TRACKING or LOST")
      .def_readonly("fitness", &TrackResult::fitness, "F, the stereo fitness at the pose")
      .def_readonly("quality", &TrackResult::quality, "q, the normalised fitness")
      .def_readonly("confidence", &TrackResult::confidence, "in (0, 1): how likely the pose is within 2 cm and 5 deg")
      .def_readonly("verified", &TrackResult::verified, "the lock survived its challenger search")
      .def_readonly("trusted", &TrackResult::trusted, "tracking, verified and confident: a pose a robot may act on")
      .def_readonly("visible_share", &TrackResult::visibleShare, "share of the model's points not found hidden (1: nothing hidden)")
      .def_readonly("precise", &TrackResult::precise, "the precise stage's pose is the frame's")
      .def_property_readonly(
          "sigma",
          [](const TrackResult &r) -> py::object {
            if (!r.uncertainty.known)
              return py::none();
            const auto &u = r.uncertainty;
            return py::make_tuple(u.sigmaMm[0], u.sigmaMm[1], u.sigmaMm[2], u.sigmaDeg[0], u.sigmaDeg[1], u.sigmaDeg[2]);
          },
          "the pose's 1-sigma along the hand's x, y, z (mm) and about them (deg), or None where it is not known (no precise stage)")
      .def_readonly("evaluations", &TrackResult::evaluations, "RM-GA's work this frame (whole evaluations)")
      .def_readonly("compute_ms", &TrackResult::computeMs, "time spent in the tracker (ms)")
      .def_property_readonly(
          "steps_ms",
          [](const TrackResult &r) {
            py::dict d;
            const auto v = r.steps.values();
            for (std::size_t k = 0; k < v.size(); ++k)
              d[pm::tracker::StepTimes::names()[k]] = v[k];
            return d;
          },
          "where compute_ms went, step by step (ms): plan, search, challenge, refine, measure, judge, apply")
      .def("__repr__", [](const TrackResult &r) {
        char s[120];
        std::snprintf(s, sizeof s, "<TrackResult %s, confidence %.3f%s>", pm::tracker::toString(r.state), r.confidence, r.trusted ? ", trusted" : "");
        return std::string(s);
      });

  py::class_<Tracker>(m, "Tracker",
                      "The photo-model tracker (pm::tracker::PhotoModelTracker): a stereo pair in, the pose of the model in the hand frame out, "
                      "with its state, confidence, trust and uncertainty. It starts searching from scratch. One thread at a time per "
                      "tracker (it releases the GIL while it tracks: other threads run, but must not call the same tracker).\n\n"
                      "    tracker = Tracker(rig, model)\n"
                      "    result = tracker.track(left, right)   # uint8, H x W x 3 BGR or H x W x 4 RGBA\n"
                      "    if result.trusted: act_on(result.pose)")
      .def(py::init([](const pm::core::CameraRig &rig, const pm::core::PhotoModel &model, const std::string &config, std::optional<long> seed,
                       std::optional<long> budget, std::optional<py::dict> params) {
             if ((seed && *seed < 0) || (budget && *budget < 0))
               throw py::value_error(seed && *seed < 0 ? "seed: a number >= 0 is needed" : "budget_evaluations: a number >= 0 is needed");
             std::string keys;
             if (params) // the configuration's one key list, as a file holds it (pm::tracker::trackerParamsFromJson)
               keys = py::module_::import("json").attr("dumps")(*params).cast<std::string>();
             return std::make_unique<Tracker>(rig, model, config, keys, seed.value_or(-1), budget.value_or(-1));
           }),
           py::arg("rig"), py::arg("model"), py::arg("config") = "", py::arg("seed") = py::none(), py::arg("budget_evaluations") = py::none(),
           py::arg("params") = py::none(),
           "config: a tracker configuration file (pm-track --config's; empty: the defaults every program uses); params: its "
           "keys as a dict, over the file's or the defaults (e.g. {'search': {'budget_evaluations': 400}}: the keys of "
           "docs/file-formats.md); seed: RM-GA's seed; budget_evaluations: the frame's search budget in evaluations (0: the "
           "wall-time budget). Raises Error if the rig, the model or the configuration is invalid (an unknown key named), or "
           "the model does not fit the rig.")
      .def("initialize", [](Tracker &t) { t.tracker().initialize(); }, "Searches from scratch (state: searching).")
      .def(
          "init_from_pose", [](Tracker &t, const py::array_t<double, py::array::c_style | py::array::forcecast> &hMo) { t.tracker().initFromPose(toMatrix(hMo, "hMo")); },
          py::arg("hMo"), "Starts from a known pose (4 x 4, metres; state: tracking).")
      .def("track", py::overload_cast<const std::vector<py::array> &>(&Tracker::track), py::arg("images"),
           "One frame of a rig of any number of cameras: a list of one image per camera, in the rig's order, each as track(left, "
           "right) takes them. Raises Error for another number of images.")
      .def("track", py::overload_cast<const py::array &, const py::array &>(&Tracker::track), py::arg("left"), py::arg("right"),
           "One stereo frame: uint8 C-contiguous arrays, H x W x 3 BGR (OpenCV) or H x W x 4 RGBA (ViSP; read where it lies, no "
           "copy), of the rig's image size. The GIL is released while it runs. Returns a TrackResult. Raises TypeError for "
           "another dtype, ValueError for another shape or a non-contiguous array, Error for another image size.")
      .def(
          "apply_hand_motion",
          [](Tracker &t, const py::array_t<double, py::array::c_style | py::array::forcecast> &h) { t.tracker().applyHandMotion(toMatrix(h, "hNowMhPrev")); },
          py::arg("hNowMhPrev"),
          "The hand moved since the last frame: hNowMhPrev is the previous hand frame seen from the current one (4 x 4, metres, "
          "from the robot's odometry).")
      .def_property_readonly("pose", [](const Tracker &t) { return toArray(t.tracker().getPose()); }, "hMo of the last frame (4 x 4, metres)")
      .def_property_readonly("state", [](const Tracker &t) { return t.tracker().getState(); }, "the state after the last frame (TrackState)")
      .def_property_readonly("last_result", [](const Tracker &t) { return t.tracker().lastResult(); }, "what the last track() returned")
      .def_property_readonly(
          "_pixels_read", // a test hook (the tests read where track() read the pixels), not the API
          [](const Tracker &t) {
            py::tuple out(t.pixelsRead().size());
            for (std::size_t k = 0; k < t.pixelsRead().size(); ++k)
              out[k] = reinterpret_cast<std::uintptr_t>(t.pixelsRead()[k]);
            return out;
          },
          "the addresses of the pixels the last track() read, camera by camera: an RGBA array's own buffer (no copy), or the "
          "one buffer a BGR array is converted into (kept from frame to frame)")
      .def_property_readonly("has_precise_stage", [](const Tracker &t) { return t.tracker().hasPreciseStage(); },
                             "the precise stage runs (a model with outlines): the results carry a sigma");
}

} // namespace pmpy
