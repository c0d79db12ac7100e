#pragma once
/*!
  \file RmGaUpdate.h
  What the tracker's parts ask of RM-GA's population at the end of a frame, as a value: the lock
  verifier's switch (a new population around the better pose), the precise stage's pose (joins the
  population), the lock state's restart (the target lost) or scatter (a first lock plainly wrong,
  its basin avoided for a while),
  and the anchor (the last trusted pose). PoseSearch::apply() applies them in that order, in one
  place; no part changes RM-GA itself.

  \code
    pm::tracker::RmGaUpdate u;
    u.reseed = pm::tracker::RmGaUpdate::Reseed{betterPose, 0.02};
    u.anchor = trustedPose;
    search.apply(u);
  \endcode
*/
#include <optional>

#include "pm/core/Pose.h"

namespace pm::tracker {

//! Changes to RM-GA's population asked for by a frame (see the file's description).
struct RmGaUpdate
{
  //! A new population around \e pose, spread over \e spread of each range (rmga::RmGa::seedAround).
  struct Reseed
  {
    core::Phi pose;     //!< the centre
    double spread = 0;  //!< fraction of each range
  };
  //! A pose found by other means, with its fitness on this frame (rmga::RmGa::inject).
  struct Inject
  {
    core::Phi pose;     //!< the pose
    double fitness = 0; //!< F there
  };
  /*!
    Searching again: none; a restart around the best (the target lost); a scatter away from it, the
    best avoided for a while (a lock refused or dropped as plainly wrong: SearchParams::avoidFrames).
  */
  enum class Restart { None, AroundBest, AwayFromBest };

  std::optional<Reseed> reseed;          //!< the verifier moved the tracker to a better pose
  std::optional<Inject> inject;          //!< the precise stage's pose
  Restart restart = Restart::None;       //!< the lock state's
  std::optional<core::Phi> anchor;       //!< a trusted pose: the restarts' anchor
};

} // namespace pm::tracker
