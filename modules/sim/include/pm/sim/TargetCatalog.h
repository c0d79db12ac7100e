#pragma once
/*!
  \file TargetCatalog.h
  The 12 sea-creature toys of the paper's Fig. 8 (C01..C12), generated procedurally from a
  fixed seed: each is a union of rounded parts (body, fins, claws, arms...) with its own
  colours, patterns and relief, scaled to the sizes of Fig. 8. We read each "A x B x C cm" as
  the two extents of the outline seen from the camera and the depth toward it; which of the
  first two is horizontal is chosen to suit the creature (the seahorse stands upright).
*/
#include <string>
#include <vector>

#include "pm/sim/TargetShape.h"

namespace pm::sim {

//! The 12 targets: code, English name, nominal size (mm).
const std::vector<TargetInfo> &targetCatalog();
//! True if \e code names one of the 12 (C01..C12, case-insensitive).
bool isCatalogTarget(const std::string &code);
//! Generates a target. Throws pm::Error for an unknown code. Deterministic.
TargetShape makeTarget(const std::string &code, double texelMm = 0.25);

} // namespace pm::sim
