#include "pm/report/ModelOutputs.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/Overlay.h"

namespace pm::report {

ModelFigures writeModelOutputs(const std::string &dir, const ModelOutputs &o, double seconds)
{
  const core::PhotoModel &m = o.build.model;
  const bool hasDepth = m.hasDepth();
  io::StagedFiles files(dir);
  io::savePhotoModel(m, files.stage("model.json"));
  io::writeImage(drawModelOnPhoto(o.photo, o.build.region, m), files.stage("overlay.png"));
  io::writeImage(drawModel(m), files.stage("model.png"));
  if (hasDepth)
    io::writeImage(drawDepth(o.photo, o.depth, m, o.dropped, m.depthRangeMm[0], m.depthRangeMm[1]), files.stage("depth.png"));
  if (o.writePhotos) {
    io::writeImage(o.background, files.stage("photo_background.png"));
    io::writeImage(o.photo, files.stage("photo_target.png"));
  }
  const double offX = (m.centroidU - m.u0) * m.distanceMm / m.px, offY = (m.centroidV - m.v0) * m.distanceMm / m.py;
  ModelFigures f;
  for (unsigned i = 0; i < o.build.region.getSize(); ++i)
    f.regionAreaPx += o.build.region.bitmap[i] ? 1u : 0u;
  nlohmann::json summary{{"source", o.source},
                         {"kind", hasDepth ? "stereo" : "flat"},
                         {"n_in", m.inner.size()},
                         {"n_out", m.outer.size()},
                         {"background_hue_deg", m.backgroundHue},
                         {"target_hue_deg", m.targetHue},
                         {"distance_mm", m.distanceMm},
                         {"centroid_px", {m.centroidU, m.centroidV}},
                         {"region_area_px", f.regionAreaPx},
                         {"model_origin_offset_mm", {offX, offY}},
                         {"step_px", o.stepPx},
                         {"time_s", seconds}};
  if (hasDepth) {
    summary.erase("model_origin_offset_mm");
    summary["model_origin_in_hand_mm"] = {m.originInHandMm[0], m.originInHandMm[1], m.originInHandMm[2]};
    summary["depth_range_mm"] = {m.depthRangeMm[0], m.depthRangeMm[1]};
    summary["n_in_dropped"] = m.nInDropped;
    summary["backdrop_mm"] = o.backdropMm;
  }
  io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
  files.commit();
  return f;
}

std::string describeModel(const ModelOutputs &o, const ModelFigures &figures, const std::string &dir, double seconds)
{
  const core::PhotoModel &m = o.build.model;
  const bool hasDepth = m.hasDepth();
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "photo-model of " << o.source << "\n"
      << "  S_in " << m.inner.size() << " points, S_out " << m.outer.size() << " points, region " << figures.regionAreaPx << " px\n"
      << "  background hue " << m.backgroundHue << " deg, target hue " << m.targetHue << " deg\n"
      << (hasDepth ? "  relief " + std::to_string(static_cast<int>(std::lround(m.depthRangeMm[0]))) + " to " +
                         std::to_string(static_cast<int>(std::lround(m.depthRangeMm[1]))) + " mm in the hand frame, origin at z " +
                         std::to_string(static_cast<int>(std::lround(m.originInHandMm[2]))) + " mm, " +
                         std::to_string(m.nInDropped) + " S_in points without a reliable match dropped\n"
                   : std::string())
      << "  written to " << dir << "/ (model.json, overlay.png, model.png, " << (hasDepth ? "depth.png, " : "")
      << (o.writePhotos ? "photo_background.png, photo_target.png, " : "") << "summary.json) in "
      << std::setprecision(2) << seconds << " s\n";
  return out.str();
}

std::string describeAllAroundModel(const model::AllAroundBuild &b, const std::string &source, const std::string &dir, bool withViews)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "all-around photo-model of " << source << "\n"
      << "  " << b.nViewsUsed << " of " << b.nViews << " views used, hull " << b.hullVolumeCm3 << " cm3 as carved, "
      << b.surfaceVolumeCm3 << " cm3 after the views' stereo pairs (" << b.surface.size() << " surface points, "
      << b.mesh.triangles.size() << " triangles, " << b.cellMm << " mm cells)\n"
      << "  " << b.model.views.size() + 1 << " viewpoints, " << b.model.inner.size() << " S_in and " << b.model.outer.size()
      << " S_out points and " << b.model.contour.size() << " outline points from the first\n";
  if (b.edgeWidthPx > 0)
    out << std::setprecision(2) << "  the camera's outline rises over " << b.edgeWidthPx << " px (25-75 %): S_in at least " << b.minInsidePx
        << " px inside it\n"
        << std::setprecision(1);
  for (const std::string &s : b.leftOut)
    out << "  left out: " << s << "\n";
  if (!b.model.passLandings.empty()) {
    const std::array<double, 6> r = core::rmsOffsets(b.model.passLandings);
    out << std::setprecision(2) << "  its own error at " << b.model.passLandings.size()
        << " pass views (the precise stage from the poses the arm knew), rms along x, y, z: " << r[0] << ", " << r[1] << ", " << r[2]
        << " mm; about them: " << r[3] << ", " << r[4] << ", " << r[5] << " deg\n";
  }
  out << "  written to " << dir << "/ (model.json, model.ply, contact.png, silhouettes.png, summary.json"
      << (withViews ? ", views/" : "") << ") in " << std::setprecision(2) << b.buildS << " s\n";
  return out.str();
}

} // namespace pm::report
