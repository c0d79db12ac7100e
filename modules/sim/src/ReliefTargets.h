#pragma once
/*!
  \file ReliefTargets.h
  The relief targets R1..R3 (private to the catalogue): bodies a flat photo-model cannot fake (steep
  sides, an outline above the backdrop, a nearest point off the centre), built on the grid directly.
*/
#include <functional>
#include <vector>

#include "pm/sim/TargetShape.h"

namespace pm::sim::catalog {

//! R1..R3's makers (from the texel size, mm), in the catalogue's order.
const std::vector<std::function<TargetShape(double)>> &reliefBuilders();

} // namespace pm::sim::catalog
