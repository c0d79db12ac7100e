#pragma once
/*!
  \file ConfidenceFit.h
  Fitting the tracker's confidence for one kind of photo-model on a labelled set
  (pm-confidence --fit): a logistic model over the features that kind weighs
  (ConfidenceModel::featuresUsed), cross-validated by run, then its bias placed so that the
  tracker's threshold (0.95) is the operating point where at most a given share of the wrong
  frames is trusted (trusted: tracking, verified and confident).

  \code
    const pm::compare::ConfidenceStudy s = pm::compare::runConfidenceStudy(rig, params);
    const pm::compare::ConfidenceFit f = pm::compare::fitConfidence(s, pm::tracker::ConfidenceKind::AllAround, 0.001);
    std::cout << "cross-validated AUROC " << f.aurocCrossValidated << "\n";
    pm::tracker::TrackerParams p;
    p.judgement.confidence = f.model; // kind Custom: used as it is
  \endcode
*/
#include <cstddef>
#include <string>

#include "pm/compare/ConfidenceStudy.h"
#include "pm/tracker/TrackConfidence.h"

namespace pm::compare {

//! What fitConfidence() found.
struct ConfidenceFit
{
  tracker::ConfidenceModel model;            //!< the fitted coefficients (kind: the one asked), threshold 0.95 at the operating point
  double aurocCrossValidated = 0;   //!< AUROC of the frames each scored by the model fitted on the other fold of runs
  double auroc = 0;                 //!< AUROC of the frames scored by \e model
  double operatingThreshold = 0;    //!< the threshold of the unshifted fit at the operating point
  std::size_t trustedRight = 0;     //!< right frames \e model would trust (tracking, verified, confidence >= 0.95)
  std::size_t trustedWrong = 0;     //!< wrong frames it would trust
  int iterations = 0;               //!< Newton steps of the fit
  //! The runs through one camera left out of the fit (fitConfidence()'s \e heldOut), scored by \e model.
  struct HeldOut
  {
    std::string variation;          //!< the camera (ConfidencePass::variation; empty: none held out)
    std::size_t runs = 0;           //!< its runs
    std::size_t frames = 0;         //!< their frames
    std::size_t wrong = 0;          //!< the wrong ones among them
    std::size_t trustedRight = 0;   //!< right frames \e model trusts
    std::size_t trustedWrong = 0;   //!< wrong frames it trusts
    double auroc = 1;               //!< AUROC of their frames (1 when they are all right or all wrong)
    double worstRunTrustedShare = 1; //!< the lowest share of a run's right frames trusted (runs with right frames)
  };
  HeldOut heldOut; //!< the held-out runs' figures (variation empty: none held out)
};

/*!
  Fits the confidence of \e kind (Flat, Stereo or AllAround) on \e study; its operating point is the
  lowest threshold at which at most \e maxFalseAccept of the wrong frames are trusted. The figures
  are those of the frames as the runs tracked them (the fitted confidence, had it been the
  tracker's, might have changed its re-verifications: run the study again with it to know).
  With \e heldOut (a camera among the study's variations), the runs through it are left out of the
  fit and scored by its model afterwards (ConfidenceFit::heldOut): how the confidence does on a
  camera it was not fitted on.
  Throws pm::core::Error for an empty set, a set of one class, the kind Auto or Custom, or a held-out
  camera no run was filmed through.
*/
ConfidenceFit fitConfidence(const ConfidenceStudy &study, tracker::ConfidenceKind kind, double maxFalseAccept,
                            const std::string &heldOut = "");

} // namespace pm::compare
