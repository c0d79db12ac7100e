#pragma once
/*!
  \file Overlay.h
  Pictures of photo-models for people: the sampled points drawn on the photo, and the model
  alone (S_in in its hues, S_out in white) on grey, like Fig. 4 (c), (d) of the paper.
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoFitness.h"

namespace pm::app {

//! The photo with the region outline (yellow), S_in (green), S_out (red) and the origin (cross).
vpImage<vpRGBa> drawModelOnPhoto(const vpImage<vpRGBa> &photo, const vpImage<unsigned char> &region, const PhotoModel &m);
//! The model alone: S_in points in their own hue, S_out points white, on dark grey.
vpImage<vpRGBa> drawModel(const PhotoModel &m);
/*!
  The model projected at a pose, each point coloured by how it scored (Eqs. 8, 9): S_in on the
  target green, on background yellow, elsewhere grey; S_out on background blue, on the target red.
*/
vpImage<vpRGBa> drawPointScores(const vpImage<vpRGBa> &image, const std::vector<PointScore> &scores,
                                const std::string &label);
/*!
  The relief the rig measured: the photo in grey, each matched region pixel coloured by its depth
  in the hand frame (\e depthMm, NaN where unmatched; red near, blue far over [near, far]), the
  S_in points kept (white) and dropped (black), and a colour bar with the depths in mm.
*/
vpImage<vpRGBa> drawDepth(const vpImage<vpRGBa> &photo, const vpImage<float> &depthMm, const PhotoModel &m,
                          const std::vector<ModelPoint> &dropped, double nearMm, double farMm);
//! Writes \e text at (row, col) with ViSP's font, in \e color.
void drawLabel(vpImage<vpRGBa> &I, const std::string &text, int row, int col, const vpRGBa &color);
//! Places \e b to the right of \e a.
vpImage<vpRGBa> sideBySide(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b);

} // namespace pm::app
