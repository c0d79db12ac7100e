#include <cstdio>
#include <filesystem>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "pm/io/CameraFile.h"
#include "pm/io/RigFile.h"

namespace pmpy {

void bindRig(py::module_ &m)
{
  using pm::core::PinholeCamera;
  using pm::core::StereoRig;
  py::class_<PinholeCamera>(m, "Camera", "A camera: its intrinsics, image size, lens and where it sits on the hand (pm::core::PinholeCamera).")
      .def_readonly("name", &PinholeCamera::name, "'left' or 'right' on a rig")
      .def_readonly("width", &PinholeCamera::width, "image width (px)")
      .def_readonly("height", &PinholeCamera::height, "image height (px)")
      .def_property_readonly("px", [](const PinholeCamera &c) { return c.cam.get_px(); }, "focal length along u (px)")
      .def_property_readonly("py", [](const PinholeCamera &c) { return c.cam.get_py(); }, "focal length along v (px)")
      .def_property_readonly("u0", [](const PinholeCamera &c) { return c.cam.get_u0(); }, "principal point, column (px)")
      .def_property_readonly("v0", [](const PinholeCamera &c) { return c.cam.get_v0(); }, "principal point, row (px)")
      .def_property_readonly("distortion", [](const PinholeCamera &c) { return c.distortion.coefficients; },
                             "the lens's coefficients in OpenCV's order (k1, k2, p1, p2[, k3...]); empty: a pinhole camera")
      .def_property_readonly("hMc", [](const PinholeCamera &c) { return toArray(c.hMc); }, "the camera in the hand frame (4 x 4, metres)")
      .def("__repr__", [](const PinholeCamera &c) {
        char s[160];
        std::snprintf(s, sizeof s, "<Camera %s %ux%u, px %.1f, %s>", c.name.c_str(), c.width, c.height, c.cam.get_px(),
                      c.distortion.coefficients.empty() ? "pinhole" : "a lens");
        return std::string(s);
      });

  py::class_<StereoRig>(m, "StereoRig", "The two cameras on the robot's hand (pm::core::StereoRig); load_rig() reads one.")
      .def_readonly("left", &StereoRig::left, "the left camera (camera 0)")
      .def_readonly("right", &StereoRig::right, "the right camera (camera 1)")
      .def_property_readonly("baseline_mm", [](const StereoRig &r) { return 1e3 * r.baseline(); }, "distance between the optical centres (mm)")
      .def(
          "save",
          [](const StereoRig &r, const std::string &path, const std::string &xml, const std::string &description) {
            const std::string x = xml.empty() ? std::filesystem::path(path).stem().string() + ".xml" : xml;
            pm::io::saveRig(r, path, x, description);
          },
          py::arg("path"), py::arg("xml_name") = "", py::arg("description") = "",
          "Writes the rig JSON and its intrinsics XML (xml_name, relative to the JSON's folder; default: the JSON's stem + '.xml'). "
          "Nothing is left half-written.")
      .def("__repr__", [](const StereoRig &r) {
        char s[120];
        std::snprintf(s, sizeof s, "<StereoRig %ux%u, baseline %.1f mm>", r.left.width, r.left.height, 1e3 * r.baseline());
        return std::string(s);
      });

  using pm::core::CameraRig;
  py::class_<CameraRig>(m, "CameraRig",
                        "The cameras on the robot's hand, one to four (pm::core::CameraRig): camera k is rig[k] (a stereo rig: 0 left, 1 "
                        "right); load_camera_rig() reads one, and a StereoRig is taken wherever a CameraRig is.")
      .def(py::init<const StereoRig &>(), py::arg("stereo"), "The stereo rig's two cameras: 0 left, 1 right.")
      .def(py::init([](const std::vector<PinholeCamera> &cams) {
             CameraRig r(cams);
             r.validate();
             return r;
           }),
           py::arg("cameras"), "The rig of these cameras, in this order (one to four). Raises Error for none or more than four.")
      .def("__len__", &CameraRig::size)
      .def(
          "__getitem__",
          [](const CameraRig &r, std::size_t k) {
            if (k >= r.size())
              throw py::index_error("camera " + std::to_string(k) + " of a rig of " + std::to_string(r.size()));
            return r[k];
          },
          py::arg("k"))
      .def_property_readonly("cameras", [](const CameraRig &r) { return r.cameras; }, "the cameras, camera k at [k]")
      .def("__repr__", [](const CameraRig &r) {
        return "<CameraRig of " + std::to_string(r.size()) + (r.size() == 1 ? " camera>" : " cameras>");
      });
  py::implicitly_convertible<StereoRig, CameraRig>();

  m.def("load_camera_rig", &pm::io::loadCameraRig, py::arg("path"),
        "Reads a rig file of one to four cameras (data/rig/pa10_mono.json: one). Raises Error naming the file and what is wrong.");
  m.def("load_rig", &pm::io::loadRig, py::arg("path"),
        "Reads a stereo rig file (rig.json, as pm-calibrate-rig writes it). Raises Error naming the file and what is wrong.");
  m.def(
      "read_camera_file",
      [](const std::string &path, const std::string &name, unsigned w, unsigned h) { return pm::io::readCameraFile(path, name, w, h).camera; },
      py::arg("path"), py::arg("name") = "", py::arg("width") = 0, py::arg("height") = 0,
      "Reads one camera: a ViSP XML (name selects the camera), an OpenCV or a ROS YAML; width and height (0: any) the image size it must have.");
  m.def("write_camera_file", &pm::io::writeOpenCvCameraFile, py::arg("camera"), py::arg("path"),
        "Writes the camera as an OpenCV YAML file (read back by read_camera_file()).");
}

} // namespace pmpy
