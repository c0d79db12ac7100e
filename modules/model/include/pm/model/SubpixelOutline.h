#pragma once
/*!
  \file SubpixelOutline.h
  A silhouette's signed distance to a fraction of a pixel: the binary mask puts the
  outline on a pixel border, up to half a pixel from the image's own edge, and the hull, the least
  of every view's distance, keeps the innermost of those errors. A pixel the outline crosses holds
  a mixture of the target's colour and the background's: its share of the target (alpha) and the
  outline's direction give where the outline passes inside it, exactly for a straight outline over
  a pixel that integrates its area (a camera's pixel, the lab's supersampled one), at the middle
  of a symmetric blur. The mixture is read perpendicular to the background's colour, so a cast
  shadow (the background darker, its colour kept) counts as background.

  \code
      cv::Mat sd = pm::model::hull::subpixelSignedDistance(mask, view.left, &view.backgroundLeft);
      // sd(y, x): px, positive inside; its zero level is the photo's outline, to a tenth of a pixel
  \endcode
*/
#include <opencv2/core.hpp>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model::hull {

/*!
  Where a straight outline crosses a pixel of unit side: the signed distance (px, positive when the
  pixel's centre is inside) of the outline from the centre, from the share \e alpha of the pixel's
  area on the inside and the outline's outward normal (\e nx, \e ny), any length but not zero.
*/
double edgeDistanceFromCoverage(double alpha, double nx, double ny);

/*!
  The signed distance (CV_32F, px, positive inside) of the silhouette \e mask (255 inside) in
  \e photo, its zero level moved to the image's own outline: each pixel next to the mask's border
  reads its share of target colour (the target's colour a pixel and a half inside the outline,
  darkened as much again as it darkens from two and a half pixels in, as a rounded target turning
  from the light does; against \e background at the pixel, or two pixels outside when \e background
  is null: a plain backdrop) and the pixels around it are placed from there; elsewhere the mask's
  distance, with its border's half pixel taken off. Where target and background have the same colour
  the mask's border stays. Throws pm::core::Error when the images are not of one size.
*/
cv::Mat subpixelSignedDistance(const vpImage<unsigned char> &mask, const vpImage<vpRGBa> &photo,
                               const vpImage<vpRGBa> *background);

} // namespace pm::model::hull
