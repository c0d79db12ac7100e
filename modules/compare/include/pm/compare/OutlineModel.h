#pragma once
/*!
  \file OutlineModel.h
  What ViSP's own trackers are given of the target: its outline, taken from the photo-model's
  region (the same single photo our tracker uses), as a planar polygon in the model frame
  (z = 0, the toy's base plane, where the toy's rounded edge meets the backdrop). It becomes a
  one-face .cao model for vpMbGenericTracker, and a template zone for vpTemplateTracker.
*/
#include <array>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoint.h>

#include "pm/core/PhotoModel.h"

namespace pm::compare {

/*!
  The outer contour of \e region (255 inside, the photo-model's region) simplified to within
  \e tolerancePx (OpenCV's findContours and approxPolyDP), in the model frame of \e model
  (metres, z = 0), in the order in which a camera in front of the model sees it turn
  counter-clockwise (ViSP's rule for a face's visible side). Throws pm::core::Error for an empty region.
*/
std::vector<vpPoint> outlinePolygon(const vpImage<unsigned char> &region, const core::PhotoModel &model, double tolerancePx = 1.5);

//! The .cao text (ViSP's model format, version 1) of one planar face bounded by \e polygon.
std::string caoText(const std::vector<vpPoint> &polygon, const std::string &comment);
//! A ViSP .cao model of points (model frame, metres) and faces (indices into them, each a polygon), in ViSP's "V1" text format.
std::string caoText(const std::vector<std::array<double, 3>> &pointsM, const std::vector<std::vector<std::size_t>> &faces,
                    const std::string &comment);

//! Where the polygon's vertices project in a camera at cMm (pixels, (i, j) = (v, u)).
std::vector<std::pair<double, double>> projectPolygon(const std::vector<vpPoint> &polygon, const vpHomogeneousMatrix &cMm,
                                                      const vpCameraParameters &cam);

} // namespace pm::compare
