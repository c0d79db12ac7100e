//! pm-make-rig: writes a symmetric stereo rig, or its left camera alone (rig JSON + ViSP camera XML).
#include <cmath>
#include <iostream>
#include <vector>
#include <sstream>

#include "pm/app/App.h"
#include "pm/core/CameraRig.h"
#include "pm/core/Error.h"
#include "pm/core/StereoRig.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"

int main(int argc, char **argv)
{
  CLI::App app{"Writes a symmetric stereo rig: two identical cameras (pinhole, or with the lens of --distortion), the baseline along the hand's x "
               "axis, each toed in toward the hand's z axis. Defaults: the lab's PA-10 rig (Sony FCB-IX11A at "
               "640x480, 323 mm baseline, converging 500 mm ahead). With --cameras 1, that rig's left camera alone, where it sits on the hand.",
               "pm-make-rig"};
  app.option_defaults()->always_capture_default();
  std::string out, name = "rig";
  double px = 754, py = 754, u0 = 320, v0 = 240, baselineMm = 323, convergeMm = 500, toeInDeg = NAN;
  unsigned width = 640, height = 480, cameras = 2;
  app.add_option("--out", out, "output folder (receives <name>.json and <name>_cameras.xml)")->required();
  app.add_option("--name", name, "file name stem");
  app.add_option("--px", px, "focal length along x (px)");
  app.add_option("--py", py, "focal length along y (px)");
  app.add_option("--u0", u0, "principal point u0 (px)");
  app.add_option("--v0", v0, "principal point v0 (px)");
  app.add_option("--width", width, "image width (px)")->check(CLI::Range(1u, 100000u));
  app.add_option("--height", height, "image height (px)")->check(CLI::Range(1u, 100000u));
  app.add_option("--baseline-mm", baselineMm, "distance between the optical centres (mm)")->check(CLI::PositiveNumber);
  auto *conv = app.add_option("--converge-mm", convergeMm,
                              "toe both cameras in so that a point this far ahead of the hand is at each image centre");
  app.add_option("--toe-in-deg", toeInDeg, "toe-in angle of each camera instead (0: parallel cameras)")
      ->excludes(conv)
      ->check(CLI::Range(-45.0, 45.0));
  std::vector<double> lens;
  app.add_option("--distortion", lens, "both cameras' lens distortion, OpenCV's k1 k2 p1 p2 [k3 ...] (the rig then "
                                       "also gets <name>_left.yml and <name>_right.yml)")->expected(4, 14);
  app.add_option("--cameras", cameras, "2: the stereo rig; 1: its left camera alone (a one-camera rig)")->check(CLI::IsMember({1u, 2u}));
  bool quiet = false;
  app.add_flag("--quiet", quiet, "print nothing on success");

  return pm::app::run(app, argc, argv, [&] {
    vpCameraParameters cam;
    cam.initPersProjWithoutDistortion(px, py, u0, v0);
    const double toe = std::isnan(toeInDeg) ? pm::core::StereoRig::toeInFor(baselineMm * 1e-3, convergeMm * 1e-3)
                                            : toeInDeg * M_PI / 180.0;
    if (std::isnan(toeInDeg) && !(convergeMm > 0))
      throw pm::core::Error("--converge-mm must be positive");
    pm::core::StereoRig stereo = pm::core::StereoRig::symmetric(cam, width, height, baselineMm * 1e-3, toe);
    stereo.left.distortion.coefficients = stereo.right.distortion.coefficients = lens;
    const pm::core::CameraRig rig = cameras == 1 ? pm::core::CameraRig(std::vector<pm::core::PinholeCamera>{stereo.left}) : pm::core::CameraRig(stereo);
    rig.validate();
    pm::io::StagedFiles files(out); // creates the folder
    const std::string json = files.finalPath(name + ".json");
    std::ostringstream desc;
    if (cameras == 1)
      desc << "one camera: the left of a symmetric rig of baseline " << baselineMm << " mm, toed in by " << toe * 180 / M_PI << " deg";
    else
      desc << "symmetric rig: baseline " << baselineMm << " mm, each camera toed in by " << toe * 180 / M_PI << " deg";
    pm::io::saveRig(rig, json, name + "_cameras.xml", desc.str());
    if (!quiet)
      std::cout << "wrote " << json << " (" << desc.str() << ")" << std::endl;
    return 0;
  });
}
