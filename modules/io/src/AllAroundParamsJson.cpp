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

} // namespace

std::string allAroundParamsToJson(const model::AllAroundParams &p)
{
  const nlohmann::json j = {{"silhouette", silhouetteJson(p.silhouette)},
                            {"backdrop_hue_deg", p.backdropHueDeg},
                            {"min_views", p.minViews},
                            {"coarsest_mm", p.coarsestMm},
                            {"finest_mm", p.finestMm},
                            {"outlier_carve_fraction", p.outlierCarveFraction},
                            {"visibility_tol_mm", p.visibilityTolMm},
                            {"fusion", fusionJson(p.fusion)},
                            {"refine_outlines", p.refineOutlines},
                            {"outline", outlineJson(p.outline)},
                            {"refine_depth_mm", p.refineDepthMm},
                            {"refine_min_score", p.refineMinScore},
                            {"refine_min_gain", p.refineMinGain},
                            {"min_saturation", p.minSaturation},
                            {"min_value", p.minValue},
                            {"min_hue_from_background_deg", p.minHueFromBackgroundDeg},
                            {"max_hue_spread_deg", p.maxHueSpreadDeg},
                            {"viewpoints", p.viewpoints},
                            {"cap_deg", p.capDeg},
                            {"n_in", p.nIn},
                            {"in_min_inside_px", p.inMinInsidePx},
                            {"blur_inside_gain", p.blurInsideGain},
                            {"sharp_edge_width_px", p.sharpEdgeWidthPx},
                            {"blur_dead_zone_px", p.blurDeadZonePx},
                            {"n_out", p.nOut},
                            {"strip_gap_px", p.stripGapPx},
                            {"strip_width_px", p.stripWidthPx},
                            {"strip_rows", p.stripRows},
                            {"n_contour", p.nContour},
                            {"pass_landings", p.passLandings}};
  return j.dump();
}

} // namespace pm::io
