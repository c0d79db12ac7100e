#pragma once
/*!
  \file PbvsServo.h
  Position-based visual servoing of the eye-in-hand robot with ViSP's vpServo
  (EYEINHAND_L_cVe_eJe): the features are vpFeatureTranslation(cdMc) and vpFeatureThetaU(cdRc)
  built from the estimated pose of the target in the hand frame hMo and the desired one hdMo
  (the paper's [0, 0, 500 mm, 0, 0, 0]), with cdMc = hdMo * hMo^-1; desired features zero,
  interaction matrix CURRENT, an adaptive gain (vpAdaptiveGain), and the joint-limit avoidance of
  vpServo as a secondary task. The target moves, so a feed-forward term follows its estimated
  velocity (a finite difference of its pose in the base frame, smoothed).

  Fail-safe: a pose that is not valid (NaN, not rigid) never reaches vpServo; stop() commands
  zero velocity and forgets the target's motion.
*/
#include <memory>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>
#include <visp3/visual_features/vpFeatureThetaU.h>
#include <visp3/visual_features/vpFeatureTranslation.h>
#include <visp3/vs/vpServo.h>

namespace pm {

struct ServoParams
{
  vpHomogeneousMatrix hdMo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); //!< desired pose of the target in the hand frame (not {...}: that is ViSP's 12-value list)
  double gainAtZero = 4.0;       //!< vpAdaptiveGain: gain for a small error (1/s)
  double gainAtInfinity = 1.5;   //!< ... for a large error
  double gainSlopeAtZero = 30.0;
  bool feedForward = true;       //!< follow the target's estimated velocity (translation) ...
  bool feedForwardRotation = true; //!< ... and angular velocity
  double feedForwardSmoothing = 0.5; //!< exponential smoothing of that velocity (0: none, < 1)
  bool jointLimitAvoidance = true;
  double maxHandSpeed = 1.0;     //!< the command is scaled down so that the hand moves at most this fast (m/s) ...
  double maxHandRotation = 2.0;  //!< ... and turns at most this fast (rad/s)

  void validate() const;
};

class PbvsServo
{
public:
  explicit PbvsServo(const ServoParams &params = ServoParams());
  PbvsServo(const PbvsServo &) = delete; // vpServo keeps raw pointers to our features
  PbvsServo &operator=(const PbvsServo &) = delete;

  /*!
    Joint velocities for the current estimate hMo (hand frame), the robot's flange pose fMe, its
    Jacobian eJe, joints q and limits. \e dt is the time since the previous call (for the
    feed-forward). \e targetTwist, when given, is the target's twist (v, w) in the base frame (e.g.
    from a PoseFilter) and replaces the finite difference. Throws pm::Error if hMo is not a valid pose.
  */
  vpColVector computeJointVelocity(const vpHomogeneousMatrix &hMo, const vpHomogeneousMatrix &fMe, const vpMatrix &eJe,
                                   const vpColVector &q, const vpColVector &qmin, const vpColVector &qmax, double dt,
                                   const vpColVector *targetTwist = nullptr);
  //! Zero velocity; the feed-forward forgets the target's motion.
  vpColVector stop(unsigned dof);
  //! Translation (m) and rotation (rad) of the last servo error cdMc.
  double translationError() const { return m_tErr; }
  double rotationError() const { return m_rErr; }
  const ServoParams &params() const { return m_params; }

private:
  ServoParams m_params;
  vpServo m_task;
  vpFeatureTranslation m_t{vpFeatureTranslation::cdMc};
  vpFeatureThetaU m_tu{vpFeatureThetaU::cdRc};
  bool m_havePrev = false;
  vpHomogeneousMatrix m_prevFMo;
  vpColVector m_vObj; //!< smoothed target twist in the base frame (v, w)
  double m_tErr = 0, m_rErr = 0;
};

} // namespace pm
