#pragma once
/*!
  \file BackgroundSubtraction.h
  The one background subtraction of the model builders: where a photo differs from the photo of the
  same view with the target removed. The all-around model's silhouettes (Silhouette.h) and the flat
  and stereo models' target regions (PhotoModelBuilder.h) both start from it, each cleaning it its own way.

  A cast shadow dims the backdrop along its own colour: the photo's pixel P lies near the line a B
  (0 <= a <= 1) through the background's pixel B. A pixel is the target when it lies farther from that
  line than the sensor's noise and a share of the light allow (colourTolGrey + colourTolShare |a B|:
  another colour, however dark), when it is brighter than the background by more than brightRatio (no
  shadow brightens), or darker than darkRatio of it (black, not a shadow: a soft light's umbra keeps
  more). A shadow's penumbra, and the umbra where the toy rests, keep the backdrop's colour and stay
  background, however dark (a chromaticity test reads a dark pixel's noise as colour, and took an area
  light's umbra for the target: on a second renderer's crab, 13 % of its area added). What this cannot
  tell: a part of the target of the backdrop's own colour, darker than it, reads as shadow (a hue
  method cannot use such a part either).

  \code
    int shadow = 0;
    const cv::Mat target = pm::model::subtractBackground(photo, background, pm::model::BackgroundParams(), &shadow);
    std::cout << cv::countNonZero(target) << " target pixels, " << shadow << " shadow pixels\n";
  \endcode
*/
#include <opencv2/core.hpp>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model {

//! The per-pixel test of subtractBackground() (see the file's description); validate() checks it.
struct BackgroundParams
{
  double colourTolGrey = 10;  //!< a photo pixel farther than this from the background's shadow line is the target (grey levels: the noise)
  double colourTolShare = 0.06; //!< ... plus this share of the dimmed background's length (light bounced off the toy tints its shadow)
  double darkRatio = 0.08;    //!< darker than this ratio of the background: the target (black; a soft light's umbra keeps more)
  double brightRatio = 1.12;  //!< brighter than this ratio: the target (no shadow brightens)

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

/*!
  CV_8U, 255 where \e photo differs from \e background as the target does, 0 elsewhere (no cleaning);
  \e shadowPx (when given): the pixels that changed but were taken for shadow (darker than
  1 / brightRatio of the background along its colour); \e changed (when given): CV_8U, 255 where the
  photo is the target or such a shadow (a background of another view changes most of the image's
  border, mostly in brightness). The images must be of the same size (the caller checks, naming them).
*/
cv::Mat subtractBackground(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background, const BackgroundParams &params,
                           int *shadowPx = nullptr, cv::Mat *changed = nullptr);

} // namespace pm::model
