#include "pm/report/CalibrationOutputs.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>
#include <visp3/core/vpImageDraw.h>

#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/Overlay.h"

namespace pm::report {

namespace {

nlohmann::json cameraJson(const core::PinholeCamera &c)
{
  return {{"px", c.cam.get_px()}, {"py", c.cam.get_py()}, {"u0", c.cam.get_u0()}, {"v0", c.cam.get_v0()},
          {"distortion", c.distortion.coefficients}, {"image_width", c.width}, {"image_height", c.height}};
}

nlohmann::json summaryJson(const RigCalibrationOutputs &o)
{
  const calib::RigCalibration &c = o.calibration;
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
  nlohmann::json s{{"source", o.source},
                   {"board", o.board},
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
  if (o.truth) {
    const calib::CalibrationErrors e = calib::compareRigs(c.rig, *o.truth);
    s["truth"] = {{"baseline_error_mm", e.baselineErrorMm},
                  {"translation_error_mm", e.translationErrorMm},
                  {"rotation_error_deg", e.rotationErrorDeg},
                  {"reprojection_error_rms_px", {e.reprojectionRmsPx[0], e.reprojectionRmsPx[1]}}};
  }
  return s;
}

//! The report's files (written by \e writeReport) and the rig's. The rig's (saveRig names them after
//! rig.json) go to a hidden folder first and join the report only when everything is written: no
//! half-written output.
void writeWithRig(const std::string &dir, const core::CameraRig &rig, const std::string &description,
                  const std::function<void(io::StagedFiles &)> &writeReport)
{
  io::StagedFiles files(dir);
  const std::filesystem::path hidden = std::filesystem::path(files.dir()) / ".partial-rig";
  std::error_code ec;
  std::filesystem::remove_all(hidden, ec);
  std::filesystem::create_directories(hidden);
  try {
    io::saveRig(rig, (hidden / "rig.json").string(), "cameras.xml", description);
    writeReport(files);
    files.commit();
    for (const auto &e : std::filesystem::directory_iterator(hidden))
      std::filesystem::rename(e.path(), std::filesystem::path(files.dir()) / e.path().filename());
  } catch (...) {
    std::filesystem::remove_all(hidden, ec);
    throw;
  }
  std::filesystem::remove_all(hidden, ec);
}

} // namespace

std::string writeRigCalibration(const std::string &dir, const RigCalibrationOutputs &o)
{
  const calib::RigCalibration &c = o.calibration;
  const std::string text = summaryJson(o).dump(2) + "\n";
  writeWithRig(dir, c.rig, "calibrated by pm-calibrate-rig from " + o.source, [&](io::StagedFiles &files) {
    vpImage<vpRGBa> coverage = calib::coverageImage(c, o.arrowGain);
    std::ostringstream legend;
    legend << "left: corners found (a colour per view), residuals x" << o.arrowGain << " (red)";
    drawLabel(coverage, legend.str(), 8, 8, vpRGBa(255, 255, 255));
    drawLabel(coverage, "right", 8, static_cast<int>(c.rig.left.width) + 16, vpRGBa(255, 255, 255));
    io::writeImage(coverage, files.stage("coverage.png"));
    io::writeTextFile(files.stage("summary.json"), text);
  });
  return text;
}

std::string describeRigCalibration(const RigCalibrationOutputs &o, const std::string &dir)
{
  const calib::RigCalibration &c = o.calibration;
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << "stereo rig calibration (" << o.board << "; " << o.source << ": "
      << c.pairsUsed << " pairs for the stereo pose, views " << c.viewsUsed[0] << " left and " << c.viewsUsed[1]
      << " right for the lenses)\n  rms: left " << c.rmsLeftPx << " px, right " << c.rmsRightPx << " px, stereo "
      << c.rmsStereoPx << " px\n  baseline " << c.baselineMm << ", " << c.rotationDeg
      << " deg between the cameras\n  left lens: " << c.rig.left.distortion.describe()
      << "\n  right lens: " << c.rig.right.distortion.describe() << "\n";
  for (int k = 0; k < 2; ++k)
    if (c.k3Fixed[k])
      out << "  " << (k ? "right" : "left") << " lens: k3 held at 0 (with it free the model folded the image: "
          << "add views with the board near the image's edges)\n";
  for (const auto &p : c.pairs)
    if (!p.used)
      out << "  " << p.name << " not in the stereo pose"
          << (p.usedBy[0] ? " (its left view calibrates the left lens)" : p.usedBy[1] ? " (its right view calibrates the right lens)" : "")
          << ": " << p.reason << "\n";
  if (o.truth) {
    const calib::CalibrationErrors e = calib::compareRigs(c.rig, *o.truth);
    out << "  against the true rig: baseline " << e.baselineErrorMm << " mm, translation " << e.translationErrorMm
        << " mm, rotation " << e.rotationErrorDeg << " deg; reprojection of the true rig's lens: "
        << e.reprojectionRmsPx[0] << " / " << e.reprojectionRmsPx[1] << " px rms\n";
  }
  out << "  written to " << dir << "/ (rig.json, cameras.xml, rig_left.yml, rig_right.yml, coverage.png, summary.json)\n";
  return out.str();
}

namespace {

nlohmann::json poseJson(const vpHomogeneousMatrix &M)
{
  const vpPoseVector p(M);
  return {p[0], p[1], p[2], p[3], p[4], p[5]};
}

nlohmann::json cameraSummaryJson(const CameraCalibrationOutputs &o)
{
  const calib::CameraCalibration &c = o.calibration;
  nlohmann::json views = nlohmann::json::array();
  for (const calib::ViewReport &v : c.views) {
    nlohmann::json j{{"name", v.name}, {"used", v.used}, {"edge_width_px", v.edgeWidthPx}};
    if (v.used)
      j["rms_px"] = v.rmsPx;
    else
      j["reason"] = v.reason;
    views.push_back(j);
  }
  nlohmann::json camera = cameraJson(c.camera);
  camera["hMc"] = poseJson(c.camera.hMc);
  nlohmann::json s{{"source", o.source},     {"board", o.board},         {"cameras", 1},
                   {"rms_px", c.rmsPx},      {"views_used", c.viewsUsed}, {"views_rejected", static_cast<int>(c.views.size()) - c.viewsUsed},
                   {"k3_fixed", c.k3Fixed},  {"camera", camera},          {"pose_on_hand", o.poseOnHand},
                   {"views", views}};
  if (o.handEye)
    s["hand_eye"] = {{"views", o.handEye->views}, {"board_spread_mm", o.handEye->spreadMm}, {"board_spread_deg", o.handEye->spreadDeg}};
  if (o.truth) {
    const calib::CameraErrors e = calib::compareCameras(c.camera, *o.truth);
    s["truth"] = {{"reprojection_error_rms_px", e.reprojectionRmsPx},
                  {"hMc_translation_error_mm", e.translationErrorMm},
                  {"hMc_rotation_error_deg", e.rotationErrorDeg}};
  }
  return s;
}

} // namespace

std::string writeCameraCalibration(const std::string &dir, const CameraCalibrationOutputs &o)
{
  const calib::CameraCalibration &c = o.calibration;
  const std::string text = cameraSummaryJson(o).dump(2) + "\n";
  writeWithRig(dir, core::CameraRig(std::vector<core::PinholeCamera>{c.camera}),
               "one camera calibrated by pm-calibrate-rig from " + o.source + "; its pose on the hand: " + o.poseOnHand,
               [&](io::StagedFiles &files) {
                 vpImage<vpRGBa> coverage = calib::coverageImage(c, o.arrowGain);
                 std::ostringstream legend;
                 legend << "corners found (a colour per view), residuals x" << o.arrowGain << " (red)";
                 drawLabel(coverage, legend.str(), 8, 8, vpRGBa(255, 255, 255));
                 io::writeImage(coverage, files.stage("coverage.png"));
                 io::writeTextFile(files.stage("summary.json"), text);
               });
  return text;
}

std::string describeCameraCalibration(const CameraCalibrationOutputs &o, const std::string &dir)
{
  const calib::CameraCalibration &c = o.calibration;
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << "one-camera calibration (" << o.board << "; " << o.source << ": " << c.viewsUsed
      << " views used)\n  rms " << c.rmsPx << " px; lens: " << c.camera.distortion.describe() << "\n";
  if (c.k3Fixed)
    out << "  k3 held at 0 (with it free the model folded the image: add views with the board near the image's edges)\n";
  const vpPoseVector p(c.camera.hMc);
  out << std::setprecision(2) << "  pose on the hand (" << o.poseOnHand << "): " << p[0] * 1e3 << ", " << p[1] * 1e3 << ", " << p[2] * 1e3
      << " mm; theta-u " << p[3] * 180 / M_PI << ", " << p[4] * 180 / M_PI << ", " << p[5] * 180 / M_PI << " deg\n";
  if (o.handEye)
    out << "  hand-eye check: the board's place in the world from each of " << o.handEye->views << " views agrees within "
        << o.handEye->spreadMm << " mm / " << o.handEye->spreadDeg << " deg rms\n";
  for (const calib::ViewReport &v : c.views)
    if (!v.used)
      out << "  " << v.name << " left out: " << v.reason << "\n";
  if (o.truth) {
    const calib::CameraErrors e = calib::compareCameras(c.camera, *o.truth);
    out << std::setprecision(4) << "  against the true camera: reprojection of its lens " << e.reprojectionRmsPx
        << " px rms; pose on the hand " << e.translationErrorMm << " mm, " << e.rotationErrorDeg << " deg\n";
  }
  out << "  written to " << dir << "/ (rig.json, cameras.xml, rig_camera.yml, coverage.png, summary.json)\n";
  return out.str();
}

bool BaselineCheckOutputs::agrees() const
{
  return std::fabs(result.baselineErrorMm) <= toleranceMm && result.translationErrorMm <= toleranceMm &&
         result.rotationErrorDeg <= toleranceDeg;
}

bool BaselineCheckOutputs::handEyeAgrees() const
{
  bool ok = true;
  if (handEyePoses > 0)
    for (const HandEyeAgreement &c : handEye)
      ok = ok && c.translationErrorMm <= handEyeToleranceMm && c.rotationErrorDeg <= handEyeToleranceDeg;
  return ok;
}

std::string writeBaselineCheck(const std::string &dir, const BaselineCheckOutputs &o)
{
  const calib::BaselineResult &r = o.result;
  io::StagedFiles files(dir);
  vpImage<vpRGBa> L = o.left, R = o.right;
  for (const auto &c : o.cornersLeft)
    vpImageDraw::drawCross(L, c, 9, vpColor::green, 2);
  for (const auto &c : o.cornersRight)
    vpImageDraw::drawCross(R, c, 9, vpColor::green, 2);
  drawLabel(L, "corners found, left", 8, 8, vpRGBa(255, 255, 255));
  drawLabel(R, "right", 8, 8, vpRGBa(255, 255, 255));
  io::writeImage(sideBySide(L, R), files.stage("detections.png"));
  nlohmann::json s{{"source", o.source},
                   {"pattern", o.pattern},
                   {"rig", o.rigPath},
                   {"baseline_mm", r.baselineMm},
                   {"baseline_error_mm", r.baselineErrorMm},
                   {"translation_error_mm", r.translationErrorMm},
                   {"rotation_error_deg", r.rotationErrorDeg},
                   {"n_pairs_used", r.pairsUsed},
                   {"n_pairs_rejected", r.pairsRejected},
                   {"spread_mm", r.spreadMm},
                   {"spread_deg", r.spreadDeg},
                   {"reprojection_rms_px", r.reprojectionRmsPx},
                   {"tolerance_mm", o.toleranceMm},
                   {"tolerance_deg", o.toleranceDeg},
                   {"agrees", o.agrees()}};
  if (o.handEyePoses > 0) {
    for (int k = 0; k < 2; ++k)
      s["hand_eye"][k ? "right" : "left"] = {{"translation_error_mm", o.handEye[k].translationErrorMm},
                                             {"rotation_error_deg", o.handEye[k].rotationErrorDeg},
                                             {"poses", o.handEyePoses}};
    s["hand_eye_agrees"] = o.handEyeAgrees();
  }
  const std::string text = s.dump(2) + "\n";
  io::writeTextFile(files.stage("summary.json"), text);
  files.commit();
  return text;
}

std::string describeBaselineCheck(const BaselineCheckOutputs &o)
{
  const calib::BaselineResult &r = o.result;
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "stereo rig check (" << o.pattern << "; " << o.source << ", " << r.pairsUsed
      << " pairs used, " << r.pairsRejected << " rejected)\n  baseline " << r.baselineMm << " mm (rig file: "
      << r.baselineMm - r.baselineErrorMm << " mm, difference " << r.baselineErrorMm << " mm; translation "
      << r.translationErrorMm << " mm), rotation difference " << r.rotationErrorDeg << " deg\n  spread " << r.spreadMm
      << " mm, " << r.spreadDeg << " deg; reprojection " << r.reprojectionRmsPx << " px\n  "
      << (o.agrees() ? "the rig file agrees" : "THE RIG FILE DOES NOT AGREE") << " (tolerances " << o.toleranceMm
      << " mm, " << o.toleranceDeg << " deg)\n";
  if (o.handEyePoses > 0)
    for (int k = 0; k < 2; ++k)
      out << "  hand-eye, " << (k ? "right" : "left") << " camera: hMc differs from the rig file by "
          << o.handEye[k].translationErrorMm << " mm, " << o.handEye[k].rotationErrorDeg << " deg (" << o.handEyePoses
          << " poses)\n";
  return out.str();
}

} // namespace pm::report
