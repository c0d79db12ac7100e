//! pm-calibrate-rig: a stereo rig's intrinsics, lens distortion and extrinsics from chessboard pairs
//! (OpenCV's calibration), or one camera's intrinsics, lens and pose on the hand (OpenCV's
//! calibration, ViSP's hand-eye), written as the project's rig file with a ViSP XML and OpenCV YAML.
#include <filesystem>
#include <iostream>
#include <optional>

#include <visp3/core/vpPoseVector.h>

#include "pm/app/App.h"
#include "pm/app/Patterns.h"
#include "pm/app/Progress.h"
#include "pm/calib/CameraCalibration.h"
#include "pm/calib/HandEye.h"
#include "pm/calib/RigCalibration.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PoseFile.h"
#include "pm/io/RigFile.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/report/CalibrationOutputs.h"

namespace {

struct Options
{
  std::vector<std::string> leftFiles, rightFiles, imageFiles, handPoseFiles;
  std::vector<double> hMc;
  std::string out, boardText, trueRigPath, patternKind = "chessboard";
  int simulate = 0, cameras = 2;
  double arrowGain = 20;
  bool quiet = false;
  pm::calib::RigCalibrationParams params;
  pm::lab::SimulatedCalibrationParams simParams;
  bool oneCamera() const { return !imageFiles.empty() || (simulate && cameras == 1); }
};

void addOptions(CLI::App &app, Options &o)
{
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  auto *optL = app.add_option("--left", o.leftFiles, "left images: files in pair order (e.g. data/left*.jpg), or a printf pattern (e.g. L_%02d.png, from 0)");
  auto *optR = app.add_option("--right", o.rightFiles, "right images, the same way");
  auto *optI = app.add_option("--camera-images", o.imageFiles, "one camera: its images, files in order or a printf pattern (e.g. C_%02d.png, from 0)");
  auto *optP = app.add_option("--hand-poses", o.handPoseFiles, "one camera: the hand's pose in the robot's base frame at each image (vpPoseVector YAML, "
                                                               "as ViSP's hand-eye tutorial writes them), files or a printf pattern "
                                                               "(e.g. pose_fPe_%d.yaml): the camera's pose on the hand by vpHandEyeCalibration");
  auto *optH = app.add_option("--hMc", o.hMc, "one camera: its pose on the hand, given: x y z (m) and theta-u (rad), as a vpPoseVector")->expected(6);
  auto *optSim = app.add_option("--simulate", o.simulate, "lab: render N chessboard pairs (or views, --cameras 1) through a known rig with distortion")
                     ->check(CLI::Range(3, 1000));
  auto *optC = app.add_option("--cameras", o.cameras, "simulation: 2 (a stereo rig) or 1 (its left camera alone, on a robot that moves it: "
                                                      "the views' hand poses give its pose on the hand)")
                   ->check(CLI::Range(1, 2))->needs(optSim);
  optL->needs(optR)->excludes(optSim)->excludes(optI);
  optR->needs(optL);
  optI->excludes(optSim);
  optP->needs(optI)->excludes(optH);
  optH->needs(optI);
  (void)optC;
  app.add_option("--true-rig", o.trueRigPath, "simulation: the rig that takes the pictures (default: the lab's rig with "
                                              "the lens of --true-distortion)")->needs(optSim);
  app.add_option("--true-distortion", o.simParams.distortion.coefficients,
                 "simulation: both cameras' lens, OpenCV's k1 k2 p1 p2 k3 (ignored with --true-rig)")
      ->expected(5)->needs(optSim);
  app.add_option("--pattern", o.patternKind, "chessboard (OpenCV's corner finder) or tags (an AprilTag 36h11 board, "
                                             "vpDetectorAprilTag; a board seen in part still counts)")
      ->check(CLI::IsMember({"tags", "chessboard"}));
  app.add_option("--board", o.boardText, "the pattern's layout, in the rig's unit (mm). chessboard: inner_rows,inner_cols,square "
                                         "(default 6,9,20; one count odd, the other even); tags: rows,cols,tag_size,pitch "
                                         "(default 3,3,40,55)");
  app.add_option("--min-pairs", o.params.minPairs, "usable pairs (or views, one camera) needed")->check(CLI::Range(3, 100000));
  app.add_option("--max-edge-width-px", o.params.maxEdgeWidthPx, "reject a view whose board edges are wider (blurred; "
                                                                  "cv::estimateChessboardSharpness)")->check(CLI::PositiveNumber);
  app.add_option("--noise", o.simParams.noiseSigma, "simulation: sensor noise (grey levels)")->check(CLI::Range(0.0, 100.0));
  app.add_option("--seed", o.simParams.seed, "simulation: seed of the noise and the board's poses");
  app.add_option("--arrow-gain", o.arrowGain, "coverage.png: residual arrows drawn this many times longer")->check(CLI::PositiveNumber);
  app.add_flag("--quiet", o.quiet, "no progress, no summary on stdout");
}

//! The stereo rig from --left/--right or --simulate.
void calibrateStereo(Options &o, const pm::calib::Pattern &board)
{
  o.leftFiles = pm::app::imageFiles(o.leftFiles);
  o.rightFiles = pm::app::imageFiles(o.rightFiles);
  if (o.leftFiles.size() != o.rightFiles.size())
    throw CLI::ValidationError("--left/--right", std::to_string(o.leftFiles.size()) + " left images but " +
                                                     std::to_string(o.rightFiles.size()) + " right ones");
  std::vector<pm::calib::StereoImagePair> pairs;
  std::optional<pm::core::StereoRig> truth;
  std::string source;
  if (o.simulate) {
    truth = o.trueRigPath.empty() ? pm::lab::labRigWithLens(o.simParams.distortion) : pm::io::loadRig(o.trueRigPath);
    pm::app::Progress progress("rendering", static_cast<std::size_t>(o.simulate), o.quiet);
    pairs = pm::lab::renderCalibrationPairs(*truth, board, o.simulate, o.simParams, [&] { progress.step(); });
    progress.finish();
    source = "simulation, " + std::to_string(o.simulate) + " pairs";
  } else {
    pm::app::Progress progress("reading", o.leftFiles.size(), o.quiet);
    for (std::size_t i = 0; i < o.leftFiles.size(); ++i) {
      pm::calib::StereoImagePair p;
      p.name = std::filesystem::path(o.leftFiles[i]).filename().string() + " + " + std::filesystem::path(o.rightFiles[i]).filename().string();
      p.left = pm::io::readColorImage(o.leftFiles[i]);
      p.right = pm::io::readColorImage(o.rightFiles[i]);
      pairs.push_back(std::move(p));
      progress.step();
    }
    progress.finish();
    source = std::to_string(pairs.size()) + " image pairs";
  }
  pm::report::RigCalibrationOutputs r;
  r.source = source;
  r.board = board.describe();
  r.calibration = pm::calib::calibrateRig(pairs, board, o.params);
  r.truth = truth;
  r.arrowGain = o.arrowGain;
  pm::report::writeRigCalibration(o.out, r);
  if (!o.quiet)
    std::cout << pm::report::describeRigCalibration(r, o.out) << std::flush;
}

//! The images (and hand poses) of one camera: read from --camera-images / --hand-poses, or rendered (--simulate --cameras 1).
pm::lab::CalibrationPass oneCameraViews(Options &o, const pm::calib::Pattern &board, std::optional<pm::core::PinholeCamera> &truth)
{
  pm::lab::CalibrationPass pass;
  if (o.simulate) {
    truth = o.trueRigPath.empty() ? pm::lab::labRigWithLens(o.simParams.distortion).left : pm::io::loadCameraRig(o.trueRigPath).cameras.front();
    pm::app::Progress progress("rendering", static_cast<std::size_t>(o.simulate), o.quiet);
    pass = pm::lab::renderCalibrationViews(*truth, board, o.simulate, o.simParams, [&] { progress.step(); });
    progress.finish();
    return pass;
  }
  o.imageFiles = pm::app::imageFiles(o.imageFiles);
  if (!o.handPoseFiles.empty()) {
    o.handPoseFiles = pm::app::imageFiles(o.handPoseFiles);
    if (o.handPoseFiles.size() != o.imageFiles.size())
      throw CLI::ValidationError("--camera-images/--hand-poses", std::to_string(o.imageFiles.size()) + " images but " +
                                                              std::to_string(o.handPoseFiles.size()) + " hand poses (one per image)");
  }
  pm::app::Progress progress("reading", o.imageFiles.size(), o.quiet);
  for (std::size_t i = 0; i < o.imageFiles.size(); ++i) {
    pm::calib::CalibrationView v;
    v.name = std::filesystem::path(o.imageFiles[i]).filename().string();
    v.image = pm::io::readColorImage(o.imageFiles[i]);
    pass.views.push_back(std::move(v));
    if (!o.handPoseFiles.empty())
      pass.fMh.push_back(pm::io::readPoseYaml(o.handPoseFiles[i]));
    progress.step();
  }
  progress.finish();
  return pass;
}

//! One camera: its intrinsics and lens, and its pose on the hand by hand-eye (hand poses) or given (--hMc).
void calibrateOneCamera(Options &o, const pm::calib::Pattern &board)
{
  if (!o.simulate && o.handPoseFiles.empty() && o.hMc.empty())
    throw CLI::ValidationError("--camera-images", "one camera needs its pose on the hand: --hand-poses (one per image, for a hand-eye "
                                           "calibration) or --hMc");
  pm::report::CameraCalibrationOutputs r;
  const pm::lab::CalibrationPass pass = oneCameraViews(o, board, r.truth);
  r.source = (o.simulate ? "simulation, " : "") + std::to_string(pass.views.size()) + (o.simulate ? " views" : " images");
  r.board = board.describe();
  pm::calib::CameraCalibrationParams cp;
  cp.minViews = o.params.minPairs;
  cp.maxEdgeWidthPx = o.params.maxEdgeWidthPx;
  r.calibration = pm::calib::calibrateCamera(pass.views, board, cp);
  if (!o.hMc.empty()) {
    r.calibration.camera.hMc = vpHomogeneousMatrix(vpPoseVector(o.hMc[0], o.hMc[1], o.hMc[2], o.hMc[3], o.hMc[4], o.hMc[5]));
    r.poseOnHand = "given";
  } else {
    std::vector<vpHomogeneousMatrix> cMo, fMh;
    for (std::size_t i = 0; i < pass.views.size(); ++i)
      if (r.calibration.views[i].used) {
        cMo.push_back(r.calibration.views[i].cMo);
        fMh.push_back(pass.fMh[i]);
      }
    r.handEye = pm::calib::solveHandEye(cMo, fMh);
    r.calibration.camera.hMc = r.handEye->hMc;
    r.poseOnHand = "hand-eye from " + std::to_string(fMh.size()) + " hand poses";
  }
  r.arrowGain = o.arrowGain;
  pm::report::writeCameraCalibration(o.out, r);
  if (!o.quiet)
    std::cout << pm::report::describeCameraCalibration(r, o.out) << std::flush;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Calibrates a rig from images of a chessboard or an AprilTag board. A stereo rig (--left, --right): each camera's "
               "intrinsics and lens distortion (cv::calibrateCamera, k1 k2 p1 p2 k3), then the right camera's pose in the left one "
               "(cv::stereoCalibrate); rig.json's hand frame lies midway between the cameras, axes halfway between theirs. One "
               "camera (--camera-images): its intrinsics and lens, and its pose on the hand, from the robot's hand poses at each image "
               "(--hand-poses, vpHandEyeCalibration) or given (--hMc). Views whose board is not whole, or blurred, are rejected "
               "with the reason. Writes rig.json, cameras.xml (ViSP), rig_<camera>.yml (OpenCV, exact), coverage.png (every "
               "corner, residuals as red arrows) and summary.json. --simulate N renders N pairs (or views) through a known rig "
               "with distortion and reports how well it is recovered.",
               "pm-calibrate-rig"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);
  return pm::app::run(app, argc, argv, [&] {
    if (!o.simulate && o.leftFiles.empty() && o.imageFiles.empty())
      throw CLI::ValidationError("--left/--right, --camera-images or --simulate", "one of them is needed");
    const std::unique_ptr<pm::calib::Pattern> pattern = pm::app::makePattern(o.patternKind, o.boardText);
    if (o.oneCamera())
      calibrateOneCamera(o, *pattern);
    else
      calibrateStereo(o, *pattern);
    return 0;
  });
}
