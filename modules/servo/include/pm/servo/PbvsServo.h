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

namespace pm::servo {

/*!
  Settings of PbvsServo: the desired pose, vpAdaptiveGain's three parameters, the feed-forward,
  the joint-limit avoidance and the hand's speed limits. validate() checks them; the PbvsServo
  constructor calls it.
*/
struct ServoParams
{
  vpHomogeneousMatrix hdMo = vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); //!< desired pose of the target in the hand frame, metres (not {...}: that is ViSP's 12-value list)
  double gainAtZero = 4.0;       //!< vpAdaptiveGain: gain for a small error (1/s)
  double gainAtInfinity = 1.5;   //!< ... for a large error
  double gainSlopeAtZero = 30.0; //!< vpAdaptiveGain: slope of the gain against the error's norm at zero error
  bool feedForward = true;       //!< follow the target's estimated velocity (translation) ...
  bool feedForwardRotation = true; //!< ... and angular velocity
  double feedForwardSmoothing = 0.5; //!< exponential smoothing of the finite-difference velocity (0: none, < 1); a given twist is not smoothed
  bool jointLimitAvoidance = true; //!< add vpServo::secondaryTaskJointLimitAvoidance() to the command
  double maxHandSpeed = 1.0;     //!< the command is scaled down so that the hand moves at most this fast (m/s) ...
  double maxHandRotation = 2.0;  //!< ... and turns at most this fast (rad/s)

  /*!
    Throws pm::core::Error unless hdMo is a rigid transformation, 0 < gainAtInfinity <= gainAtZero,
    gainSlopeAtZero > 0, the hand's speed limits are positive and 0 <= feedForwardSmoothing < 1.
  */
  void validate() const;
};

/*!
  Position-based visual servo of the eye-in-hand arm (the law is in PbvsServo.h): one call of
  computeJointVelocity() per camera frame turns the estimated pose of the target in the hand frame
  into joint velocities (rad/s). The hand frame is the flange frame (cVe is the identity). Not
  copyable: its vpServo keeps pointers to the features held in this object.

  \code
    pm::sim::RobotPA10 robot;
    robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
    pm::servo::PbvsServo servo; // default ServoParams: the target held 0.5 m ahead of the hand
    const double dt = 1.0 / 30;
    vpMatrix eJe;
    robot.get_eJe(eJe);
    // hMo: the target's estimated pose in the hand frame (metres), e.g. a pm::tracker::TrackResult's.
    const vpColVector qdot = servo.computeJointVelocity(hMo, robot.fMe(), eJe, robot.q(), robot.jointMin(),
                                                        robot.jointMax(), dt);
    robot.setVelocity(vpRobot::JOINT_STATE, qdot);
    robot.step(dt);
  \endcode
*/
class PbvsServo
{
public:
  //! Sets up the vpServo task from \e params. Throws pm::core::Error if ServoParams::validate() does.
  explicit PbvsServo(const ServoParams &params = ServoParams());
  PbvsServo(const PbvsServo &) = delete; // vpServo keeps raw pointers to our features
  PbvsServo &operator=(const PbvsServo &) = delete;

  /*!
    Joint velocities for the current estimate hMo (hand frame), the robot's flange pose fMe, its
    Jacobian eJe, joints q and limits (rad). \e dt is the time since the previous call (s, for the
    feed-forward; none when dt <= 0). \e targetTwist, when given, is the target's twist (v in m/s,
    w in rad/s) in the base frame (e.g. from a PoseFilter) and replaces the finite difference.
    Returns one velocity per joint (rad/s), scaled down as a whole to ServoParams::maxHandSpeed and
    ServoParams::maxHandRotation. Throws pm::core::Error if hMo is not a valid pose, \e targetTwist has
    not 6 components, or the law gives a non-finite velocity.
  */
  vpColVector computeJointVelocity(const vpHomogeneousMatrix &hMo, const vpHomogeneousMatrix &fMe, const vpMatrix &eJe,
                                   const vpColVector &q, const vpColVector &qmin, const vpColVector &qmax, double dt,
                                   const vpColVector *targetTwist = nullptr);
  /*!
    Keeps the target at \e hdMo from the next call on (a grasp approach closing in), the
    feed-forward's memory of the target's motion kept. Throws pm::core::Error unless \e hdMo is a
    rigid transformation.
  */
  void setDesired(const vpHomogeneousMatrix &hdMo);
  //! Zero velocity for \e dof joints; the feed-forward forgets the target's motion.
  vpColVector stop(unsigned dof);
  //! Norm of the translation of the last servo error cdMc (m).
  double translationError() const { return m_tErr; }
  //! Angle of the rotation of the last servo error cdMc (rad).
  double rotationError() const { return m_rErr; }
  //! The settings given to the constructor.
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

} // namespace pm::servo
