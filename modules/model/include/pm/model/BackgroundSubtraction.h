#pragma once
/*!
  \file BackgroundSubtraction.h
  The one background subtraction of the model builders: where a photo differs from the photo of the
  same view with the target removed. The all-around model's silhouettes (Silhouette.h) and the flat
  and stereo models' target regions (PhotoModelBuilder.h) both start from it, each cleaning it its own way.

  A pixel differs when its chromaticity (r, g, b divided by their sum) moved by more than
  \e chromaTol, or its brightness changed by a ratio outside [\e darkRatio, \e brightRatio]. A cast
  shadow dims the backdrop and keeps its chromaticity: a pixel darker than the background by a
  ratio in [\e darkRatio, 1) with its chromaticity kept is shadow, not target. White and grey
  parts of a target differ from a coloured backdrop in chromaticity, and from a grey one in
  brightness upward (a shadow never brightens).

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
  double chromaTol = 0.035;   //!< chromaticity change (each of r, g over r + g + b) that marks the target
  double darkRatio = 0.35;    //!< darker than this ratio of the background: the target (a shadow keeps more light)
  double brightRatio = 1.12;  //!< brighter than this ratio: the target (no shadow brightens)
  double minBrightness = 30;  //!< a background darker than this (mean of r, g, b) has no chromaticity to compare: brightness alone decides

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

/*!
  CV_8U, 255 where \e photo differs from \e background as the target does, 0 elsewhere (no cleaning);
  \e shadowPx (when given): the pixels that changed but were taken for shadow. The images must be
  of the same size (the caller checks, naming them).
*/
cv::Mat subtractBackground(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background, const BackgroundParams &params,
                           int *shadowPx = nullptr);

} // namespace pm::model
