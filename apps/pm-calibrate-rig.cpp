//! pm-calibrate-rig: a stereo rig's intrinsics, lens distortion and extrinsics from chessboard pairs
//! (OpenCV's calibration), written as the project's rig file with a ViSP XML and OpenCV YAML.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/report/Overlay.h"
#include "pm/app/Patterns.h"
#include "pm/app/Progress.h"
#include "pm/calib/RigCalibration.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"

namespace {

nlohmann::json cameraJson(const pm::RigCamera &c)
{
  return {{"px", c.cam.get_px()}, {"py", c.cam.get_py()}, {"u0", c.cam.get_u0()}, {"v0", c.cam.get_v0()},
          {"distortion", c.distortion.coefficients}, {"image_width", c.width}, {"image_height", c.height}};
}

} // namespace

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
    std::optional<pm::StereoRig> truth;
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
    const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board, params);

    nlohmann::json views = nlohmann::json::array();
    for (const auto &p : c.pairs) {
      nlohmann::json v{{"name", p.name}, {"used", p.used}, {"views_used", {p.usedBy[0], p.usedBy[1]}},
                       {"edge_width_px", {p.edgeWidthPx[0], p.edgeWidthPx[1]}}};
      if (p.used)
        v["rms_px"] = {p.rmsPx[0], p.rmsPx[1]};
      else
        v["reason"] = p.reason;
      views.push_back(v);
    }
    nlohmann::json summary{{"source", source},
                           {"board", board.describe()},
                           {"rms_left_px", c.rmsLeftPx},
                           {"rms_right_px", c.rmsRightPx},
                           {"rms_stereo_px", c.rmsStereoPx},
                           {"baseline", c.baselineMm},
                           {"rotation_between_cameras_deg", c.rotationDeg},
                           {"pairs_used", c.pairsUsed},
                           {"views_used", {c.viewsUsed[0], c.viewsUsed[1]}},
                           {"k3_fixed", {c.k3Fixed[0], c.k3Fixed[1]}},
                           {"pairs_rejected", static_cast<int>(c.pairs.size()) - c.pairsUsed},
                           {"left", cameraJson(c.rig.left)},
                           {"right", cameraJson(c.rig.right)},
                           {"pairs", views}};
    pm::lab::CalibrationErrors err;
    if (truth) {
      err = pm::lab::compareRigs(c.rig, *truth);
      summary["truth"] = {{"baseline_error_mm", err.baselineErrorMm},
                          {"translation_error_mm", err.translationErrorMm},
                          {"rotation_error_deg", err.rotationErrorDeg},
                          {"reprojection_error_rms_px", {err.reprojectionRmsPx[0], err.reprojectionRmsPx[1]}}};
    }
    pm::io::StagedFiles files(out);
    // The rig's files (saveRig names them after rig.json) go to a hidden folder first and join the
    // report only when everything is written: no half-written output.
    const std::filesystem::path hidden = std::filesystem::path(files.dir()) / ".partial-rig";
    std::error_code ec;
    std::filesystem::remove_all(hidden, ec);
    std::filesystem::create_directories(hidden);
    try {
      pm::io::saveRig(c.rig, (hidden / "rig.json").string(), "cameras.xml", "calibrated by pm-calibrate-rig from " + source);
      vpImage<vpRGBa> coverage = pm::calib::coverageImage(c, arrowGain);
      std::ostringstream legend;
      legend << "left: corners found (a colour per view), residuals x" << arrowGain << " (red)";
      pm::report::drawLabel(coverage, legend.str(), 8, 8, vpRGBa(255, 255, 255));
      pm::report::drawLabel(coverage, "right", 8, static_cast<int>(c.rig.left.width) + 16, vpRGBa(255, 255, 255));
      pm::io::writeImage(coverage, files.stage("coverage.png"));
      pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
      files.commit();
      for (const auto &e : std::filesystem::directory_iterator(hidden))
        std::filesystem::rename(e.path(), std::filesystem::path(files.dir()) / e.path().filename());
    } catch (...) {
      std::filesystem::remove_all(hidden, ec);
      throw;
    }
    std::filesystem::remove_all(hidden, ec);
    if (!quiet) {
      std::cout << std::fixed << std::setprecision(4) << "stereo rig calibration (" << board.describe() << "; " << source
                << ": " << c.pairsUsed << " pairs for the stereo pose, views " << c.viewsUsed[0] << " left and "
                << c.viewsUsed[1] << " right for the lenses)\n  rms: left " << c.rmsLeftPx << " px, right " << c.rmsRightPx << " px, stereo "
                << c.rmsStereoPx << " px\n  baseline " << c.baselineMm << ", " << c.rotationDeg
                << " deg between the cameras\n  left lens: " << c.rig.left.distortion.describe()
                << "\n  right lens: " << c.rig.right.distortion.describe() << "\n";
      for (int k = 0; k < 2; ++k)
        if (c.k3Fixed[k])
          std::cout << "  " << (k ? "right" : "left") << " lens: k3 held at 0 (with it free the model folded the image: "
                    << "add views with the board near the image's edges)\n";
      for (const auto &p : c.pairs)
        if (!p.used)
          std::cout << "  " << p.name << " not in the stereo pose"
                    << (p.usedBy[0] ? " (its left view calibrates the left lens)" : p.usedBy[1] ? " (its right view calibrates the right lens)" : "")
                    << ": " << p.reason << "\n";
      if (truth)
        std::cout << "  against the true rig: baseline " << err.baselineErrorMm << " mm, translation "
                  << err.translationErrorMm << " mm, rotation " << err.rotationErrorDeg
                  << " deg; reprojection of the true rig's lens: " << err.reprojectionRmsPx[0] << " / "
                  << err.reprojectionRmsPx[1] << " px rms\n";
      std::cout << "  written to " << out << "/ (rig.json, cameras.xml, rig_left.yml, rig_right.yml, coverage.png, summary.json)"
                << std::endl;
    }
    return 0;
  });
}
