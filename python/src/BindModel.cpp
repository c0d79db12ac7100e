#include <optional>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/model/AllAroundModelBuilder.h"

namespace pmpy {

namespace {

pm::model::AllAroundParams buildParams(std::optional<double> backdropHueDeg, bool refineOutlines)
{
  pm::model::AllAroundParams p;
  if (backdropHueDeg) {
    if (!(*backdropHueDeg >= 0 && *backdropHueDeg < 360))
      throw py::value_error("backdrop_hue_deg: a hue in [0, 360) deg is needed");
    p.backdropHueDeg = *backdropHueDeg;
  }
  p.surface.refineOutlines = refineOutlines;
  return p;
}

pm::core::PhotoModel build(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &views, const pm::model::AllAroundParams &p)
{
  py::gil_scoped_release free;
  return pm::model::buildAllAroundModel(rig, views, p).model;
}

py::array_t<float> pointsOf(const std::vector<pm::core::ModelPoint> &points)
{
  py::array_t<float> a({static_cast<py::ssize_t>(points.size()), py::ssize_t(4)});
  auto r = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    const pm::core::ModelPoint &p = points[static_cast<std::size_t>(i)];
    r(i, 0) = p.x;
    r(i, 1) = p.y;
    r(i, 2) = p.z;
    r(i, 3) = p.hue;
  }
  return a;
}

} // namespace

void bindModel(py::module_ &m)
{
  using pm::core::PhotoModel;
  py::class_<PhotoModel>(m, "PhotoModel",
                         "A photo-model (pm::core::PhotoModel): the target's hue sampled inside its outline (S_in) and a strip of "
                         "background around it (S_out), from each of its viewpoints. load_model() reads one, build_model() makes one.")
      .def_property_readonly("viewpoints", [](const PhotoModel &pm) { return pm.views.size() + 1; }, "viewing directions it holds")
      .def_property_readonly("inner_points", [](const PhotoModel &pm) { return pm.inner.size(); }, "S_in points of its first view")
      .def_property_readonly("outer_points", [](const PhotoModel &pm) { return pm.outer.size(); }, "S_out points of its first view")
      .def_property_readonly("inner", [](const PhotoModel &pm) { return pointsOf(pm.inner); },
                             "S_in of its first view: an N x 4 float32 array, x, y, z (mm, the model frame) and hue (deg)")
      .def_property_readonly("outer", [](const PhotoModel &pm) { return pointsOf(pm.outer); }, "S_out of its first view, the same way")
      .def_property_readonly("all_around", &PhotoModel::isAllAround, "made from a pass around the target (else flat or stereo)")
      .def_property_readonly("has_outlines", &PhotoModel::hasContours, "it holds outlines: the tracker's precise stage runs")
      .def_readonly("background_hue_deg", &PhotoModel::backgroundHue, "the background's hue in its photos (deg)")
      .def_readonly("target_hue_deg", &PhotoModel::targetHue, "the target's mean hue (deg)")
      .def("save", &pm::io::savePhotoModel, py::arg("path"), "Writes model.json (the current version). Nothing is left half-written.")
      .def(
          "to_json", [](const PhotoModel &model) { return pm::io::photoModelToJson(model); }, "The model as the text of model.json.")
      .def("__repr__", [](const PhotoModel &pm) {
        return "<PhotoModel " + std::string(pm.isAllAround() ? "all-around" : "flat or stereo") + ", " + std::to_string(pm.views.size() + 1) +
               " viewpoints, " + std::to_string(pm.inner.size()) + " S_in points>";
      });
  m.def("load_model", &pm::io::loadPhotoModel, py::arg("path"),
        "Reads model.json (pm-make-model writes it). Raises Error naming the file and what is wrong (a model of another version says so).");

  using pm::model::PassView;
  py::class_<PassView>(m, "PassView", "One stop of the hand's pass around the target: a stereo pair, the same pair with the target removed, and the hand's pose.")
      .def(py::init([](const py::array &left, const py::array &right, const py::array_t<double, py::array::c_style | py::array::forcecast> &fMh,
                       const std::optional<py::array> &bgLeft, const std::optional<py::array> &bgRight, const std::string &name) {
             PassView v;
             v.left = toImage(left, "left image");
             v.right = toImage(right, "right image");
             if (bgLeft.has_value() != bgRight.has_value())
               throw py::value_error("background_left and background_right: both or neither");
             if (bgLeft) {
               v.backgroundLeft = toImage(*bgLeft, "background_left");
               v.backgroundRight = toImage(*bgRight, "background_right");
             }
             v.fMh = toMatrix(fMh, "fMh");
             v.name = name;
             return v;
           }),
           py::arg("left"), py::arg("right"), py::arg("fMh"), py::arg("background_left") = py::none(), py::arg("background_right") = py::none(),
           py::arg("name") = "view",
           "left, right: uint8 images (H x W x 3 BGR or H x W x 4 RGBA); fMh: the hand in a fixed world frame (4 x 4, metres, "
           "from the robot); the backgrounds: the same pose, the target removed (not needed with build_model(backdrop_hue_deg=...)).")
      .def_readonly("name", &PassView::name)
      .def_property_readonly("fMh", [](const PassView &v) { return toArray(v.fMh); }, "the hand in the world frame (4 x 4, metres)")
      .def_property_readonly("left", [](const PassView &v) { return toArray(v.left); }, "the left photo (a copy, H x W x 4 RGBA)")
      .def_property_readonly("right", [](const PassView &v) { return toArray(v.right); }, "the right photo (a copy, H x W x 4 RGBA)");

  m.def(
      "build_model", [](const pm::core::StereoRig &rig, const std::vector<PassView> &views, std::optional<double> hue, bool refine) {
        return build(rig, views, buildParams(hue, refine));
      },
      py::arg("rig"), py::arg("views"), py::arg("backdrop_hue_deg") = py::none(), py::arg("refine_outlines") = false,
      "The all-around photo-model from a pass of the hand (a list of PassView, at least 6): silhouettes, carving, surface, "
      "viewpoints (pm::model::buildAllAroundModel; a few seconds, the GIL released). backdrop_hue_deg: a plain backdrop of "
      "that hue (no background images needed). Raises Error naming the view and what is wrong.");
  m.def(
      "build_model_from_folder",
      [](const pm::core::StereoRig &rig, const std::string &folder, std::optional<double> hue, bool refine) {
        const pm::model::AllAroundParams p = buildParams(hue, refine);
        return build(rig, pm::io::loadViewsFolder(folder, rig, p.carving.minViews, p.backdropHueDeg < 0), p);
      },
      py::arg("rig"), py::arg("folder"), py::arg("backdrop_hue_deg") = py::none(), py::arg("refine_outlines") = false,
      "The same from a views folder (left_NN.png, right_NN.png, background_*_NN.png, pose_fPh_NN.yaml), as pm-make-model --views does.");
}

} // namespace pmpy
