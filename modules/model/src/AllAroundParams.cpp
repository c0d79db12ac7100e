#include "pm/model/AllAroundParams.h"

#include <string>

#include "pm/core/Error.h"

namespace pm::model {

namespace {

void check(bool ok, const char *what)
{
  if (!ok)
    throw core::Error(std::string("all-around model parameter ") + what);
}

} // namespace

void HullCarvingParams::validate() const
{
  check(minViews >= 2 && minViews <= 1000, "minimum views must lie in [2, 1000]");
  check(finestMm > 0.1 && finestMm <= 20, "finest cell must lie in (0.1, 20] mm");
  check(coarsestMm >= finestMm && coarsestMm <= 200, "coarsest cell must lie in [finest, 200] mm");
  check(outlierCarveFraction > 0 && outlierCarveFraction <= 1, "outlier carve fraction must lie in (0, 1]");
}

void HullSurfaceParams::validate() const
{
  outline.validate();
  check(visibilityTolMm > 0 && visibilityTolMm <= 50, "visibility tolerance must lie in (0, 50] mm");
}

void SurfaceColourParams::validate() const
{
  check(minSaturation >= 0 && minSaturation < 1, "minimum saturation must lie in [0, 1)");
  check(minValue >= 0 && minValue < 1, "minimum value must lie in [0, 1)");
  check(minHueFromBackgroundDeg >= 0 && minHueFromBackgroundDeg < 180, "minimum hue from background must lie in [0, 180)");
  check(maxHueSpreadDeg > 0 && maxHueSpreadDeg <= 180, "maximum hue spread must lie in (0, 180]");
}

void ViewpointSamplingParams::validate() const
{
  check(count >= 1 && count <= 5000, "viewpoints must lie in [1, 5000]");
  check(capDeg > 0 && capDeg <= 180, "cap must lie in (0, 180] deg");
  check(nIn >= 8 && nIn <= 20000, "S_in points per viewpoint must lie in [8, 20000]");
  check(nOut >= 8 && nOut <= 20000, "S_out points per viewpoint must lie in [8, 20000]");
  check(stripGapPx >= 1 && stripGapPx <= 100, "strip gap must lie in [1, 100] px");
  check(stripWidthPx >= 0 && stripWidthPx <= 100, "strip width must lie in [0, 100] px");
  check(stripRows >= 1 && stripRows <= 10, "strip rows must lie in [1, 10]");
  check(inMinInsidePx >= 0 && inMinInsidePx <= 50, "S_in's distance inside the outline must lie in [0, 50] px");
  check(blurInsideGain >= 0 && blurInsideGain <= 10, "S_in's distance per pixel of blur must lie in [0, 10]");
  check(sharpEdgeWidthPx > 0 && sharpEdgeWidthPx <= 5 && blurDeadZonePx >= 0 && blurDeadZonePx <= 5,
        "a sharp camera's outline width must lie in (0, 5] px and the blur ignored in [0, 5] px");
  check(nContour >= 8 && nContour <= 20000, "outline points per viewpoint must lie in [8, 20000]");
}

void AllAroundParams::validate() const
{
  silhouette.validate();
  fusion.validate();
  check(backdropHueDeg < 360, "the backdrop's hue must lie in [0, 360) degrees (negative: background images)");
  carving.validate();
  surface.validate();
  colour.validate();
  viewpoints.validate();
}

} // namespace pm::model
