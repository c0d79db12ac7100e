#pragma once
/*!
  \file TargetTexels.h
  What the lab's targets are drawn on (private to the target catalogue): a target's grid of texels
  sized to its nominal outline plus a margin, and a texel's colour given in HSV.
*/
#include <cstddef>

#include "pm/sim/TargetShape.h"

namespace pm::sim::catalog {

//! A colour: hue (deg), saturation and value (in [0, 1]).
struct Hsv3
{
  double h, s, v;
};

/*!
  An empty target of \e info: texels of \e texelMm over its nominal width and height plus \e marginMm
  on every side, the origin at the grid's centre; colour, signed distance and height all zero (and
  the underside's height with \e underside).
*/
TargetShape targetGrid(const TargetInfo &info, double texelMm, double marginMm, bool underside);

//! Writes colour \e c into texel \e k of \e s (8-bit RGB, core::hsvToRgb()).
void setTexel(TargetShape &s, std::size_t k, const Hsv3 &c);

} // namespace pm::sim::catalog
