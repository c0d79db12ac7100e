#pragma once
/*!
  \file PhotoModel.h
  The photo-model of the paper (Sec. 3.2, Fig. 4): points sampled inside the target's
  outline (S_in, each with the photo's hue there) and a strip of points enveloping it
  (S_out), all on the model plane z = 0 of the model frame M.

  A point sampled at pixel (u, v) of a photo taken at distance d by a camera of focal
  lengths px, py becomes M_r = ((u - cu) d / px, (v - cv) d / py, 0) in millimetres, where
  (cu, cv) is the centroid of the target region: the model frame's origin is the region's
  centroid (our choice, SPEC.md section 3).
*/
#include <string>
#include <vector>

namespace pm {

struct ModelPoint
{
  float x = 0, y = 0, z = 0; //!< position in the model frame (mm)
  float hue = 0;             //!< photo hue in degrees (S_in); background hue for S_out
  float u = 0, v = 0;        //!< where it was sampled in the photo (px)
};

struct PhotoModel
{
  double distanceMm = 0;           //!< photo distance d
  double px = 0, py = 0;           //!< photo camera focal lengths (px)
  double u0 = 0, v0 = 0;           //!< photo camera principal point (px)
  unsigned photoWidth = 0, photoHeight = 0;
  double centroidU = 0, centroidV = 0; //!< target region centroid in the photo (px): the model origin
  float backgroundHue = 0;         //!< H_B, circular mean hue of the background photo (deg)
  float targetHue = 0;             //!< circular mean hue of S_in (deg), for reports
  std::vector<ModelPoint> inner;   //!< S_in
  std::vector<ModelPoint> outer;   //!< S_out

  std::size_t size() const { return inner.size() + outer.size(); }
  /*!
    Throws pm::Error if the model cannot be used: S_in empty, a non-finite coordinate or
    hue outside [0, 360), a non-positive distance or focal length. \e source names the
    file or the origin for the message.
  */
  void validate(const std::string &source) const;
};

} // namespace pm
