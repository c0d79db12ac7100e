#include "pm/io/AllAroundParamsJson.h"

#include <nlohmann/json.hpp>

namespace pm::io {

namespace {

nlohmann::json silhouetteJson(const model::SilhouetteParams &s)
{
  const model::BackgroundParams &b = s.background;
  return {{"background",
           {{"colour_tol_grey", b.colourTolGrey}, {"colour_tol_share", b.colourTolShare}, {"dark_ratio", b.darkRatio},
            {"bright_ratio", b.brightRatio}}},
          {"clean_radius_px", s.cleanRadiusPx},
          {"min_region_fraction", s.minRegionFraction},
          {"max_image_fraction", s.maxImageFraction},
          {"backdrop_hue_tol_deg", s.backdropHueTolDeg},
          {"backdrop_min_saturation", s.backdropMinSaturation},
          {"backdrop_min_value", s.backdropMinValue}};
}

nlohmann::json fusionJson(const model::FusionParams &f)
{
  return {{"enabled", f.enabled},
          {"truncation_mm", f.truncationMm},
          {"backdrop_margin_mm", f.backdropMarginMm},
          {"block_px", f.blockPx},
          {"max_disparity_spread_px", f.maxDisparitySpreadPx},
          {"erode_px", f.erodePx},
          {"edge_ramp_px", f.edgeRampPx},
          {"outline_margin_px", f.outlineMarginPx},
          {"grazing_cos", f.grazingCos},
          {"backdrop_search_mm", f.backdropSearchMm},
          {"fast_matching", f.fastMatching},
          {"min_texture", f.minTexture},
          {"uniqueness_percent", f.uniquenessPercent}};
}

nlohmann::json outlineJson(const model::OutlineRefinementParams &o)
{
  return {{"rounds", o.rounds},       {"max_residual_px", o.maxResidualPx}, {"gain", o.gain},
          {"max_step_mm", o.maxStepMm}, {"smoothness", o.smoothness},        {"stay", o.stay},
          {"smooth_iterations", o.smoothIterations}};
}

nlohmann::json carvingJson(const model::HullCarvingParams &c)
{
  return {{"min_views", c.minViews}, {"coarsest_mm", c.coarsestMm}, {"finest_mm", c.finestMm}, {"outlier_carve_fraction", c.outlierCarveFraction}};
}

nlohmann::json surfaceJson(const model::HullSurfaceParams &s)
{
  return {{"visibility_tol_mm", s.visibilityTolMm}, {"refine_outlines", s.refineOutlines}, {"outline", outlineJson(s.outline)}};
}

nlohmann::json colourJson(const model::SurfaceColourParams &c)
{
  return {{"min_saturation", c.minSaturation},
          {"min_value", c.minValue},
          {"min_hue_from_background_deg", c.minHueFromBackgroundDeg},
          {"max_hue_spread_deg", c.maxHueSpreadDeg}};
}

nlohmann::json viewpointsJson(const model::ViewpointSamplingParams &v)
{
  return {{"count", v.count},
          {"cap_deg", v.capDeg},
          {"n_in", v.nIn},
          {"in_min_inside_px", v.inMinInsidePx},
          {"blur_inside_gain", v.blurInsideGain},
          {"sharp_edge_width_px", v.sharpEdgeWidthPx},
          {"blur_dead_zone_px", v.blurDeadZonePx},
          {"n_out", v.nOut},
          {"strip_gap_px", v.stripGapPx},
          {"strip_width_px", v.stripWidthPx},
          {"strip_rows", v.stripRows},
          {"n_contour", v.nContour}};
}

} // namespace

std::string allAroundParamsToJson(const model::AllAroundParams &p)
{
  const nlohmann::json j = {{"silhouette", silhouetteJson(p.silhouette)},
                            {"backdrop_hue_deg", p.backdropHueDeg},
                            {"carving", carvingJson(p.carving)},
                            {"fusion", fusionJson(p.fusion)},
                            {"surface", surfaceJson(p.surface)},
                            {"colour", colourJson(p.colour)},
                            {"viewpoints", viewpointsJson(p.viewpoints)},
                            {"pass_landings", p.passLandings}};
  return j.dump();
}

} // namespace pm::io
