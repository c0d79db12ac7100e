#pragma once
/*!
  \file TargetCatalog.h
  The 12 sea-creature toys of the paper's Fig. 8 (C01..C12), generated procedurally from a
  fixed seed: each is a union of rounded parts (body, fins, claws, arms...) with its own
  colours, patterns and relief, scaled to the sizes of Fig. 8. We read each "A x B x C cm" as
  the two extents of the outline seen from the camera and the depth toward it; which of the
  first two is horizontal is chosen to suit the creature (the seahorse stands upright).

  Besides them, three relief targets (R1..R3) that a flat photo-model cannot fake, lit by default
  by a light fixed in the scene with cast shadows (pm::sim::ShadowMode::Auto):
  - R1 poster box, 140 x 100 x 30 mm: steep cardboard sides, a colourful landscape print on its
    flat front face;
  - R2 head on a stand, 120 x 150 x 55 mm: its outline 18 mm above the backdrop (a closed body
    with an underside, TargetShape::base, on a stand of 40 mm), turned so that its nearest point
    (the nose) is off the centre, with a brow ridge, cheeks and a chin; skin, freckles, hair;
  - R3 pagoda tower, 70 x 90 x 110 mm: three tiers of steep walls and tiled roofs and a spire.
*/
#include <string>
#include <vector>

#include "pm/sim/TargetShape.h"

namespace pm::sim {

/*!
  The 12 targets: code, English name, nominal size (mm).
  \code
  for (const pm::sim::TargetInfo &t : pm::sim::labTargetCatalog())
    std::cout << t.code << " " << t.name << ": " << t.widthMm << " x " << t.heightMm << " x " << t.depthMm << " mm\n";
  pm::sim::TargetShape crab = pm::sim::makeTarget("c12");       // case-insensitive
  crab.scaleRelief(0.5);                                        // half as thick
  const pm::sim::Mesh mesh = pm::sim::buildTargetMesh(crab);    // what the renderer draws
  const bool shadows = pm::sim::isReliefTarget(crab.info.code); // false: a sea creature
  \endcode
*/
const std::vector<TargetInfo> &targetCatalog();
/*!
  The relief targets: R1 poster box, R2 head on a stand, R3 pagoda tower (code, name, nominal size
  in mm: outline extents and the depth toward the camera). Kept apart from targetCatalog(), which
  stays the 12 of Fig. 8.
*/
const std::vector<TargetInfo> &reliefTargetCatalog();
//! All the lab's targets: C01..C12 then R1..R3 (what pm-detect --all-targets measures).
const std::vector<TargetInfo> &labTargetCatalog();
//! True if \e code names a catalogue target: C01..C12 or R1..R3, case-insensitive.
bool isCatalogTarget(const std::string &code);
//! True if \e code names one of the relief targets R1..R3 (case-insensitive).
bool isReliefTarget(const std::string &code);
//! Generates a target (C01..C12, R1..R3). Throws pm::core::Error for an unknown code. Deterministic.
TargetShape makeTarget(const std::string &code, double texelMm = 0.25);

} // namespace pm::sim
