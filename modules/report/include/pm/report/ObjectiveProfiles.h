#pragma once
/*!
  \file ObjectiveProfiles.h
  The hue fitness and the precise stage's objective along turns about each axis through the true
  pose (pm-fitness-map --profiles): where each peaks, and how sharply. The fitness of Eqs. (8)-(11)
  is flat over degrees in rotation near its peak; the outline's objective is not. Writes
  profiles.png (a panel per axis, both curves scaled to [0, 1], 1 the best of each) and
  profiles.csv.

  \code
      const pm::report::ProfileResult r = pm::report::writeObjectiveProfiles(files, fitness, precise, truth, 6.0, 0.25);
      std::cout << "F peaks " << r.axes[0].fitnessPeakDeg << " deg off the truth about x\n";
  \endcode
*/
#include <array>
#include <string>

#include "pm/core/Pose.h"
#include "pm/core/StereoFitness.h"
#include "pm/io/StagedFiles.h"
#include "pm/precise/PreciseStage.h"

namespace pm::report {

//! One axis's profiles: where each objective is best along it, and the span of the fitness's plateau.
struct AxisProfile
{
  double fitnessPeakDeg = 0;   //!< the turn (deg) where F is highest
  double objectivePeakDeg = 0; //!< the turn where the precise stage's objective is lowest
  double plateauDeg = 0;       //!< the span of turns (deg) whose F is at least F(truth)
};

//! What writeObjectiveProfiles() found.
struct ProfileResult
{
  std::array<AxisProfile, 3> axes{}; //!< about the hand's x, y and z axes through the model's origin
  std::string text;                  //!< a few lines for the terminal
};

/*!
  The profiles of \e fitness (its images set) and of \e precise (its images set) along turns of
  -rangeDeg..rangeDeg by \e stepDeg about each of the hand's axes through \e truth's origin; staged in
  \e files as profiles.png and profiles.csv.
  \code
  pm::io::StagedFiles files("out");
  const pm::report::ProfileResult r = pm::report::writeObjectiveProfiles(files, fitness, precise, truth, 6.0, 0.25);
  files.commit();
  \endcode
*/
ProfileResult writeObjectiveProfiles(io::StagedFiles &files, const core::StereoFitness &fitness, precise::PreciseStage &precise, const core::Phi &truth,
                                     double rangeDeg, double stepDeg);

} // namespace pm::report
