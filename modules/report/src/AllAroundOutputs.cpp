#include "pm/report/AllAroundOutputs.h"

#include <algorithm>
#include <array>
#include <filesystem>

#include <nlohmann/json.hpp>

#include <opencv2/imgproc.hpp>

#include "pm/core/UndistortMap.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/PlyFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/ViewsFolder.h"
#include "pm/report/SurfaceDrawing.h"

namespace pm::report {

namespace {

cv::Mat asMat(vpImage<vpRGBa> &I) { return cv::Mat(static_cast<int>(I.getHeight()), static_cast<int>(I.getWidth()), CV_8UC4, I.bitmap); }

//! \e tile (RGBA) scaled into the sheet at (x, y) with size (w, h).
void paste(vpImage<vpRGBa> &sheet, vpImage<vpRGBa> &tile, int x, int y, int w, int h)
{
  cv::Mat dst = asMat(sheet)(cv::Rect(x, y, w, h));
  cv::resize(asMat(tile), dst, cv::Size(w, h), 0, 0, cv::INTER_AREA);
}

void outline(vpImage<vpRGBa> &I, const vpImage<unsigned char> &mask, const cv::Scalar &colour)
{
  cv::Mat m(static_cast<int>(mask.getHeight()), static_cast<int>(mask.getWidth()), CV_8U, const_cast<unsigned char *>(mask.bitmap));
  cv::Mat closed;
  cv::morphologyEx(m, closed, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(closed, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  cv::Mat im = asMat(I);
  cv::drawContours(im, contours, -1, colour, 2);
}

//! The left camera of view \e k in the model frame, and its photo in the ideal image.
vpHomogeneousMatrix leftInModel(const model::AllAroundBuild &b, const model::PassView &v, const core::StereoRig &rig)
{
  return b.fMm.inverse() * v.fMh * rig.left.hMc;
}

} // namespace

void writeAllAroundPictures(const model::AllAroundBuild &b, const std::vector<model::PassView> &pass, const core::StereoRig &rig, io::StagedFiles &out)
{
  io::writeTextFile(out.stage("model.ply"), io::plyText(b.surface, &b.mesh));
  const unsigned w = rig.left.width, h = rig.left.height;
  const int tw = 320, th = static_cast<int>(320.0 * h / w);
  std::unique_ptr<core::UndistortMap> und;
  if (!rig.left.distortion.isNone())
    und = std::make_unique<core::UndistortMap>(rig.left);
  // Contact sheet: 8 views (evenly over the pass), photo | model.
  const std::size_t n = std::min<std::size_t>(8, pass.size());
  vpImage<vpRGBa> sheet(static_cast<unsigned>(th * ((n + 1) / 2)), static_cast<unsigned>(4 * tw), vpRGBa(40, 40, 40));
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = j * pass.size() / n;
    vpImage<vpRGBa> photo = und ? und->undistorted(pass[k].left) : pass[k].left;
    vpImage<vpRGBa> model = drawSurface(b.surface, leftInModel(b, pass[k], rig), rig.left.cam, w, h);
    cv::putText(asMat(photo), pass[k].name, cv::Point(10, 30), cv::FONT_HERSHEY_SIMPLEX, 1.0, cv::Scalar(255, 255, 255, 255), 2);
    cv::putText(asMat(model), "model", cv::Point(10, 30), cv::FONT_HERSHEY_SIMPLEX, 1.0, cv::Scalar(255, 255, 255, 255), 2);
    const int x = static_cast<int>(j % 2) * 2 * tw, y = static_cast<int>(j / 2) * th;
    paste(sheet, photo, x, y, tw, th);
    paste(sheet, model, x + tw, y, tw, th);
  }
  io::writeImage(sheet, out.stage("contact.png"));
  // Silhouettes: every view's left photo, its silhouette (green) and the hull's outline (red).
  const std::size_t cols = 4, rows = (pass.size() + cols - 1) / cols;
  vpImage<vpRGBa> sil(static_cast<unsigned>(th * rows), static_cast<unsigned>(tw * cols), vpRGBa(40, 40, 40));
  for (std::size_t k = 0; k < pass.size(); ++k) {
    vpImage<vpRGBa> photo = und ? und->undistorted(pass[k].left) : pass[k].left;
    vpImage<unsigned char> hull;
    drawSurface(b.surface, leftInModel(b, pass[k], rig), rig.left.cam, w, h, &hull);
    if (2 * k < b.silhouettes.size())
      outline(photo, b.silhouettes[2 * k], cv::Scalar(0, 255, 0, 255));
    outline(photo, hull, cv::Scalar(255, 0, 0, 255));
    cv::putText(asMat(photo), pass[k].name, cv::Point(10, 30), cv::FONT_HERSHEY_SIMPLEX, 1.0, cv::Scalar(255, 255, 255, 255), 2);
    paste(sil, photo, static_cast<int>(k % cols) * tw, static_cast<int>(k / cols) * th, tw, th);
  }
  io::writeImage(sil, out.stage("silhouettes.png"));
}

std::string writeAllAroundModel(const model::AllAroundBuild &b, const std::vector<model::PassView> &pass, const core::StereoRig &rig,
                                const std::string &dir, const std::string &source, bool keepViews, const std::string &truthJson,
                                const std::vector<std::pair<std::string, std::string>> &moreFiles)
{
  io::StagedFiles out(dir);
  io::savePhotoModel(b.model, out.stage("model.json"));
  writeAllAroundPictures(b, pass, rig, out);
  nlohmann::json fMo = nlohmann::json::array();
  for (unsigned r = 0; r < 4; ++r)
    fMo.push_back({b.fMm[r][0], b.fMm[r][1], b.fMm[r][2], b.fMm[r][3]});
  std::size_t nPoints = b.model.size();
  for (const core::ModelView &v : b.model.views)
    nPoints += v.inner.size() + v.outer.size();
  // The model's own error at its pass views (the precise stage from each view's known pose): rms per axis of the model frame.
  const std::array<double, 6> rms = core::rmsOffsets(b.model.passLandings);
  const nlohmann::json landings{
      {"n", b.model.passLandings.size()}, {"rms_mm", {rms[0], rms[1], rms[2]}}, {"rms_deg", {rms[3], rms[4], rms[5]}}};
  nlohmann::json summary{{"source", source},
                               {"kind", "all-around"},
                               {"fMo", fMo},
                               {"n_views", b.nViews},
                               {"n_views_used", b.nViewsUsed},
                               {"views_left_out", b.leftOut},
                               {"n_surface_points", b.surface.size()},
                               {"n_viewpoints", b.model.views.size() + 1},
                               {"n_model_points", nPoints},
                               {"n_in", b.model.inner.size()},
                               {"n_out", b.model.outer.size()},
                               {"hull_volume_cm3", b.hullVolumeCm3},
                               {"surface_volume_cm3", b.surfaceVolumeCm3},
                               {"n_mesh_triangles", b.mesh.triangles.size()},
                               {"fusion_carved_cells", b.fusionCarvedCells},
                               {"matched_target_px", b.matchedTargetPx},
                               {"matched_backdrop_px", b.matchedBackdropPx},
                               {"outline_residual_before_px", b.outlineResidualBeforePx},
                               {"outline_residual_px", b.outlineResidualPx},
                               {"outline_residual_rms_px", b.outlineResidualRmsPx},
                               {"pass_landings", landings},
                               {"n_contour_points", b.model.contour.size()},
                               {"cell_mm", b.cellMm},
                               {"n_highlight_points", b.nHighlight},
                               {"n_highlight_samples", b.nHighlightSamples},
                               {"shadow_px", b.shadowPx},
                               {"edge_width_px", b.edgeWidthPx},
                               {"s_in_min_inside_px", b.minInsidePx},
                               {"background_hue_deg", b.model.backgroundHue},
                               {"distance_mm", b.model.distanceMm},
                               {"build_s", b.buildS}};
  if (!truthJson.empty())
    summary["truth"] = nlohmann::json::parse(truthJson);
  if (b.model.trust.measured)
    summary["trust_calibration"] = nlohmann::json::parse(io::trustCalibrationToJson(b.model.trust));
  for (const auto &[name, content] : moreFiles)
    io::writeTextFile(out.stage(name), content);
  const std::string text = summary.dump(2) + "\n";
  io::writeTextFile(out.stage("summary.json"), text);
  out.commit();
  if (keepViews) // after the model: a failure here leaves the model, never half a folder of views
    io::saveViewsFolder(pass, (std::filesystem::path(dir) / "views").string());
  return text;
}

} // namespace pm::report
