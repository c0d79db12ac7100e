#pragma once
/*!
  \file Clutter.h
  Clutter: three other toys of the catalogue standing around the target on its backdrop, as other
  objects stand near a target on a robot's table (SceneParams::clutter). One of them is the sea
  creature whose hue is nearest the target's (the hardest neighbour for a tracker that reads
  hue), the two others a green and a blue one; they stand to the left, to the right and below the
  target, 25 mm clear of its nominal outline, each a little turned.
*/
#include <string>
#include <vector>

#include "pm/sim/TargetShape.h"

namespace pm::sim {

//! One toy of the clutter: its catalogue code and its pose on the backdrop.
struct ClutterToy
{
  std::string code;            //!< a catalogue code (C01..C12)
  double poseMm[6] = {0, 0, 0, 0, 0, 0}; //!< its frame in the target's (x, y, z mm, eps1..3), the toy resting where the target's base rests
  bool similarHue = false;     //!< true for the one whose hue is nearest the target's
};

/*!
  The target's mean hue (degrees in [0, 360), core::rgbToHsv's hue): the
  circular mean over its outline of each texel's hue, weighted by its saturation.
*/
double meanHueDeg(const TargetShape &target);

/*!
  The clutter around \e target: three sea creatures other than it (the nearest in hue, then two
  of the green and blue ones), placed by their nominal sizes. Deterministic.
  \code
  const pm::sim::TargetShape crab = pm::sim::makeTarget("C12");
  for (const pm::sim::ClutterToy &t : pm::sim::clutterAround(crab))
    std::cout << t.code << " at x " << t.poseMm[0] << " y " << t.poseMm[1] << (t.similarHue ? " (similar hue)" : "") << "\n";
  \endcode
*/
std::vector<ClutterToy> clutterAround(const TargetShape &target);

} // namespace pm::sim
