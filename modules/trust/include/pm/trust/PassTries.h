#pragma once
/*!
  \file PassTries.h
  The tracker tried on a held-out view of the pass, whose true pose the arm knows: started near the
  truth (where it lands is a right pose through this camera), and started where wrong poses lie on
  the same images (the poses the lock verifier and the confidence's competitors try: turned about
  the model's axis and the tilt mirrored; moved 40 mm along the hand's axes; tilted 15 deg; and a
  search from scratch, RM-GA's own optima). Each try is a few frames of the still pair from its
  start, as the tracker runs them; what it records is the last frame's cues, uncertainty and true
  error. Whether a try is right or wrong is read from its error (PassTry::right(), wrong()), not
  from its start: a start near a wrong optimum may come back to the truth.

  \code
    pm::tracker::PhotoModelTracker tracker(rig, fold.model);
    const vpHomogeneousMatrix hMm = pass[k].fMh.inverse() * fold.fMm;
    for (const pm::trust::PassTry &t : pm::trust::tryView(tracker, pass[k], hMm, pm::trust::TryParams(), k))
      std::cout << t.start << ": " << t.errorMm << " mm, " << t.errorDeg << " deg\n";
  \endcode
*/
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/model/PassView.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/TrackConfidence.h"

namespace pm::trust {

//! How each held-out view is tried (see PassTries.h).
struct TryParams
{
  int nearStarts = 3;      //!< starts near the truth (the first on it, the others within nearMm and nearDeg)
  double nearMm = 2;       //!< how far the near starts lie from the truth (mm, at most)
  double nearDeg = 1;      //!< ... and turned (deg, at most)
  int nearFrames = 3;      //!< frames tracked from a near start
  double shiftMm = 40;     //!< the starts moved along the hand's x, y and z, either way (mm)
  double tiltDeg = 15;     //!< the starts tilted about the hand's x and y, either way (deg)
  int wrongFrames = 1;     //!< frames tracked from a wrong start
  int searches = 1;        //!< searches from scratch (each its own RM-GA seed)
  int searchFrames = 12;   //!< frames a search runs
};

//! One try (see PassTries.h): where the tracker landed from a start, and what it read there.
struct PassTry
{
  std::size_t view = 0;     //!< the pass view it was tried on
  std::string start;        //!< "near", "turned 90 deg", "tilt mirrored", "moved +40 mm along x", "tilted -15 deg about y", "search"
  tracker::ConfidenceCues cues;          //!< the last frame's cues
  precise::PoseUncertainty uncertainty;  //!< the last frame's 1-sigma (unknown without the precise stage's pose)
  std::array<double, 6> error{};         //!< estimate less truth along the hand's x, y, z (mm), about them (deg)
  double errorMm = 0;       //!< the model origin's distance from its true place (mm)
  double errorDeg = 0;      //!< the rotation between the estimate and the truth (deg)
  std::array<double, 3> originMm{}; //!< the model origin's true place in the hand frame (mm)
  //! Right: within 5 mm and 2 deg (the right frames).
  bool right() const { return errorMm <= 5 && errorDeg <= 2; }
  //! Wrong: over 20 mm or 5 deg off (the confidence's wrong frames).
  bool wrong() const { return errorMm > 20 || errorDeg > 5; }
  //! Plainly wrong: twice as far (over 40 mm or 10 deg), not a near miss of a hard axis (a thin toy's roll).
  bool plainlyWrong() const { return errorMm > 40 || errorDeg > 10; }
};

/*!
  The tries on view \e view (its stereo pair) with the truth \e hMm (the model frame in the hand
  frame there), \e tracker built on a model that did not see that view. \e seed makes the near
  starts and the searches; the same seed, the same tries. The tracker is left in the state of the
  last try.
*/
std::vector<PassTry> tryView(tracker::PhotoModelTracker &tracker, const model::PassView &view, const vpHomogeneousMatrix &hMm,
                             const TryParams &params, std::uint64_t seed, std::size_t viewIndex = 0);

} // namespace pm::trust
