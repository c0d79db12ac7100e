//! pm-calib-baseline: checks the stereo rig's baseline and relative rotation with an AprilTag board
//! or a chessboard.
#include <iostream>
#include <memory>
#include <optional>
#include <random>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/CalibrationOutputs.h"
#include "pm/app/Patterns.h"
#include "pm/app/Progress.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/lab/SimulatedHandEye.h"
#include "pm/sim/Scene.h"


int main(int argc, char **argv)
{
  CLI::App app{"Checks the stereo rig against images of an AprilTag (36h11) board or a chessboard: the pattern's "
               "pose in each camera (vpDetectorAprilTag or OpenCV's corner finder, then vpPose on all its corners) "
               "gives cLMcR per pair; outliers are rejected and the rest averaged; the result is compared with the "
               "rig file. --simulate N renders the pattern at N poses "
               "seen by --true-rig (default: the lab's) with sensor noise. Exit status 0 when the rig agrees, 3 when "
               "it does not (baseline or rotation beyond the tolerances), 1 for errors.",
               "pm-calib-baseline"};
  app.option_defaults()->always_capture_default();
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json"), trueRigPath, boardText, patternKind = "tags";
  std::vector<std::string> leftImages, rightImages;
  int simulate = 0, firstFrame = 0, handEye = 0;
  double tolMm = 1.0, tolDeg = 0.3, handEyeTolMm = 3.0, handEyeTolDeg = 0.5, blurPx = 0.7;
  bool quiet = false;
  pm::sim::SceneParams sp;
  sp.supersampling = 3;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  app.add_option("--rig", rigPath, "the rig file to check");
  auto *optSim = app.add_option("--simulate", simulate, "render N stereo pairs of the board")->check(CLI::Range(1, 1000));
  app.add_option("--true-rig", trueRigPath, "simulation: the rig that takes the pictures (default: the lab's)")->needs(optSim);
  auto *optL = app.add_option("--left", leftImages, "left images: a printf pattern (e.g. L_%02d.png, from --first-frame), or files in pair order");
  auto *optR = app.add_option("--right", rightImages, "right images, the same way");
  optL->needs(optR)->excludes(optSim);
  optR->needs(optL);
  app.add_option("--hand-eye", handEye, "simulation: also move the PA-10 through M poses in front of a fixed board and "
                                       "estimate each camera's hMc with vpHandEyeCalibration")
      ->needs(optSim)
      ->check(CLI::Range(3, 1000));
  app.add_option("--first-frame", firstFrame, "with a pattern: index of the first image pair")->check(CLI::Range(0, 100000000));
  app.add_option("--pattern", patternKind, "tags: an AprilTag 36h11 board; chessboard: OpenCV's corner finder")
      ->check(CLI::IsMember({"tags", "chessboard"}));
  app.add_option("--board", boardText, "the pattern's layout. tags: rows,cols,tag_size_mm,pitch_mm (ids from 0, row by row; "
                                       "default 3,3,40,55); chessboard: inner_rows,inner_cols,square_mm (default 6,9,20)");
  app.add_option("--tolerance-mm", tolMm, "largest acceptable baseline / translation difference (mm)")->check(CLI::PositiveNumber);
  app.add_option("--tolerance-deg", tolDeg, "largest acceptable rotation difference (deg)")->check(CLI::PositiveNumber);
  app.add_option("--hand-eye-tolerance-mm", handEyeTolMm, "largest acceptable hMc translation difference (mm)")->check(CLI::PositiveNumber);
  app.add_option("--hand-eye-tolerance-deg", handEyeTolDeg, "largest acceptable hMc rotation difference (deg)")->check(CLI::PositiveNumber);
  app.add_option("--noise", sp.noiseSigma, "simulation: sensor noise (grey levels)")->check(CLI::Range(0.0, 100.0));
  app.add_option("--blur-px", blurPx, "simulation: Gaussian blur of the images (sigma, px; 0: none)")->check(CLI::Range(0.0, 10.0));
  app.add_option("--seed", sp.seed, "simulation: seed of the noise and the board's poses");
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    if (!simulate && leftImages.empty())
      throw CLI::ValidationError("--simulate or --left/--right", "one of them is needed");
    const std::unique_ptr<pm::calib::Pattern> pattern = pm::app::makePattern(patternKind, boardText);
    const pm::core::StereoRig rig = pm::io::loadRig(rigPath);
    pm::calib::BaselineCheck check(rig, *pattern);
    // Simulation (also the hand-eye check's): the rig that takes the pictures, the pattern printed flat.
    std::optional<pm::core::StereoRig> truthRig;
    std::optional<pm::sim::Scene> scene;
    if (simulate) {
      truthRig = pm::io::loadRig(trueRigPath.empty() ? pm::app::dataPath("rig/pa10_stereo.json") : trueRigPath);
      scene.emplace(pm::sim::flatPrint(pattern->render(8.0), pattern->widthMm(), "calibration pattern"), sp);
    }
    std::string source;
    if (simulate) {
      std::mt19937 rng(static_cast<std::uint32_t>(sp.seed));
      std::uniform_real_distribution<double> u(-1, 1);
      pm::app::Progress progress("rendering and detecting", static_cast<std::size_t>(simulate), quiet);
      for (int k = 0; k < simulate; ++k) {
        const pm::core::Phi p{20 * u(rng), 20 * u(rng), 500 + 40 * u(rng), 0.12 * u(rng), 0.12 * u(rng), 0.2 * u(rng)};
        const auto im = scene->renderStereo(*truthRig, pm::core::toHomogeneousMatrix(p), static_cast<std::uint64_t>(k));
        check.add(pm::lab::defocused(im.left, blurPx), pm::lab::defocused(im.right, blurPx), "simulated pair " + std::to_string(k));
        progress.step();
      }
      progress.finish();
      source = "simulation, " + std::to_string(simulate) + " pairs";
    } else {
      const std::vector<std::string> lf = pm::app::imageFiles(leftImages, firstFrame), rf = pm::app::imageFiles(rightImages, firstFrame);
      if (lf.size() != rf.size())
        throw pm::core::Error(std::to_string(lf.size()) + " left images but " + std::to_string(rf.size()) + " right ones (pairs are taken in order)");
      for (std::size_t i = 0; i < lf.size(); ++i)
        check.add(pm::io::readColorImage(lf[i]), pm::io::readColorImage(rf[i]),
                "pair " + std::to_string(pm::app::isImagePattern(leftImages) ? static_cast<long>(i) + firstFrame : static_cast<long>(i)));
      source = "images " + lf.front() + " + " + rf.front() + (lf.size() > 1 ? " and " + std::to_string(lf.size() - 1) + " more pairs" : "");
    }
    pm::report::BaselineCheckOutputs o;
    o.source = source;
    o.pattern = pattern->describe();
    o.rigPath = rigPath;
    o.result = check.result();
    o.toleranceMm = tolMm;
    o.toleranceDeg = tolDeg;
    o.left = check.firstLeft();
    o.right = check.firstRight();
    o.cornersLeft = check.firstLeftCorners();
    o.cornersRight = check.firstRightCorners();
    // Hand-eye: the PA-10 moves the rig around a board fixed in the world; each camera's board
    // poses and the flange poses give its hMc (vpHandEyeCalibration), compared with the rig file.
    if (handEye > 0) { // --hand-eye needs --simulate: truthRig and scene are set
      const pm::lab::HandEyeResult he = pm::lab::simulatedHandEye(*scene, *truthRig, rig, *pattern, handEye, sp.seed, blurPx);
      o.handEyePoses = he.poses;
      o.handEye[0] = {he.left.translationErrorMm, he.left.rotationErrorDeg};
      o.handEye[1] = {he.right.translationErrorMm, he.right.rotationErrorDeg};
      o.handEyeToleranceMm = handEyeTolMm;
      o.handEyeToleranceDeg = handEyeTolDeg;
    }
    pm::report::writeBaselineCheck(out, o);
    if (!quiet)
      std::cout << pm::report::describeBaselineCheck(o) << std::flush;
    return o.agrees() && o.handEyeAgrees() ? 0 : 3;
  }, {{"--left-images", "--left", {}}, {"--right-images", "--right", {}}});
}
