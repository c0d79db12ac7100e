//! pm-calibrate-rig: a stereo rig's intrinsics, lens distortion and extrinsics from chessboard pairs
//! (OpenCV's calibration), written as the project's rig file with a ViSP XML and OpenCV YAML.
#include <filesystem>
#include <iostream>
#include <optional>

#include "pm/app/App.h"
#include "pm/report/CalibrationOutputs.h"
#include "pm/app/Patterns.h"
#include "pm/app/Progress.h"
#include "pm/calib/RigCalibration.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main(int argc, char **argv)
{
  CLI::App app{"Calibrates a stereo rig from image pairs of a chessboard or an AprilTag board: each camera's intrinsics and lens distortion "
               "(cv::calibrateCamera, k1 k2 p1 p2 k3), then the right camera's pose in the left one "
               "(cv::stereoCalibrate). Pairs whose board is not whole in both images, or blurred, are rejected with the "
               "reason. Writes rig.json (the hand frame midway between the cameras, axes halfway between theirs), "
               "cameras.xml (ViSP), rig_left.yml / rig_right.yml (OpenCV, exact), coverage.png (every corner, residuals "
               "as red arrows) and summary.json. --simulate N renders N pairs through a known rig with distortion and "
               "reports how well it is recovered.",
               "pm-calibrate-rig"};
  app.option_defaults()->always_capture_default();
  std::vector<std::string> leftFiles, rightFiles;
  std::string out, boardText, trueRigPath, patternKind = "chessboard";
  int simulate = 0;
  double arrowGain = 20;
  bool quiet = false;
  pm::calib::RigCalibrationParams params;
  pm::lab::SimulatedCalibrationParams simParams;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  auto *optL = app.add_option("--left", leftFiles, "left images: files in pair order (e.g. data/left*.jpg), or a printf pattern (e.g. L_%02d.png, from 0)");
  auto *optR = app.add_option("--right", rightFiles, "right images, the same way");
  auto *optSim = app.add_option("--simulate", simulate, "lab: render N chessboard pairs through a known rig with distortion")
                     ->check(CLI::Range(3, 1000));
  optL->needs(optR)->excludes(optSim);
  optR->needs(optL);
  app.add_option("--true-rig", trueRigPath, "simulation: the rig that takes the pictures (default: the lab's rig with "
                                            "the lens of --true-distortion)")->needs(optSim);
  app.add_option("--true-distortion", simParams.distortion.coefficients,
                 "simulation: both cameras' lens, OpenCV's k1 k2 p1 p2 k3 (ignored with --true-rig)")
      ->expected(5)->needs(optSim);
  app.add_option("--pattern", patternKind, "chessboard (OpenCV's corner finder) or tags (an AprilTag 36h11 board, "
                                           "vpDetectorAprilTag; a board seen in part still counts)")
      ->check(CLI::IsMember({"tags", "chessboard"}));
  app.add_option("--board", boardText, "the pattern's layout, in the rig's unit (mm). chessboard: inner_rows,inner_cols,square "
                                       "(default 6,9,20; one count odd, the other even); tags: rows,cols,tag_size,pitch "
                                       "(default 3,3,40,55)");
  app.add_option("--min-pairs", params.minPairs, "usable pairs needed")->check(CLI::Range(3, 100000));
  app.add_option("--max-edge-width-px", params.maxEdgeWidthPx, "reject a view whose board edges are wider (blurred; "
                                                                "cv::estimateChessboardSharpness)")->check(CLI::PositiveNumber);
  app.add_option("--noise", simParams.noiseSigma, "simulation: sensor noise (grey levels)")->check(CLI::Range(0.0, 100.0));
  app.add_option("--seed", simParams.seed, "simulation: seed of the noise and the board's poses");
  app.add_option("--arrow-gain", arrowGain, "coverage.png: residual arrows drawn this many times longer")->check(CLI::PositiveNumber);
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    if (!simulate && leftFiles.empty())
      throw CLI::ValidationError("--left/--right or --simulate", "one of them is needed");
    leftFiles = pm::app::imageFiles(leftFiles);
    rightFiles = pm::app::imageFiles(rightFiles);
    if (leftFiles.size() != rightFiles.size())
      throw CLI::ValidationError("--left/--right", std::to_string(leftFiles.size()) + " left images but " +
                                                       std::to_string(rightFiles.size()) + " right ones");
    const std::unique_ptr<pm::calib::Pattern> pattern = pm::app::makePattern(patternKind, boardText);
    const pm::calib::Pattern &board = *pattern;

    std::vector<pm::calib::StereoImagePair> pairs;
    std::optional<pm::core::StereoRig> truth;
    std::string source;
    if (simulate) {
      truth = trueRigPath.empty() ? pm::lab::labRigWithLens(simParams.distortion) : pm::io::loadRig(trueRigPath);
      pm::app::Progress progress("rendering", static_cast<std::size_t>(simulate), quiet);
      pairs = pm::lab::renderCalibrationPairs(*truth, board, simulate, simParams, [&] { progress.step(); });
      progress.finish();
      source = "simulation, " + std::to_string(simulate) + " pairs";
    } else {
      pm::app::Progress progress("reading", leftFiles.size(), quiet);
      for (std::size_t i = 0; i < leftFiles.size(); ++i) {
        pm::calib::StereoImagePair p;
        p.name = std::filesystem::path(leftFiles[i]).filename().string() + " + " +
                 std::filesystem::path(rightFiles[i]).filename().string();
        p.left = pm::io::readColorImage(leftFiles[i]);
        p.right = pm::io::readColorImage(rightFiles[i]);
        pairs.push_back(std::move(p));
        progress.step();
      }
      progress.finish();
      source = std::to_string(pairs.size()) + " image pairs";
    }
    pm::report::RigCalibrationOutputs o;
    o.source = source;
    o.board = board.describe();
    o.calibration = pm::calib::calibrateRig(pairs, board, params);
    o.truth = truth;
    o.arrowGain = arrowGain;
    pm::report::writeRigCalibration(out, o);
    if (!quiet)
      std::cout << pm::report::describeRigCalibration(o, out) << std::flush;
    return 0;
  });
}
