#pragma once
/*!
  \file ArmModel.h
  What the pass and the servo loop need to know of an arm: its forward kinematics, Jacobians and
  limits, for any joint values. ViSP's robots carry such a model themselves (vpViper850,
  vpAfma6, ...), but vpRobot does not expose it; an ArmModel wraps one (Viper850Model,
  Afma6Model) or is our own (Pa10Model).

  Frames: f the arm's base (reference) frame, e its flange (end-effector). Lengths in metres,
  revolute joints in radians, prismatic ones in metres.
*/
#include <initializer_list>
#include <string>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>

namespace pm::robot {

/*!
  Kinematics and limits of an arm (see ArmModel.h). Implementations are stateless: every query
  takes the joint values.
  \code
    const std::unique_ptr<pm::robot::ArmModel> arm = pm::robot::makeArmModel("viper850");
    const vpColVector q = arm->restJoints();
    const vpHomogeneousMatrix fMe = arm->fMe(q);   // the flange in the base frame
    const vpMatrix eJe = arm->eJe(q);              // 6 x dof, the flange's twist in its own frame
  \endcode
*/
class ArmModel
{
public:
  virtual ~ArmModel() = default;
  //! The arm's name as the programs' --robot takes it ("pa10", "viper850", "afma6").
  virtual std::string name() const = 0;
  //! How a person names it ("Mitsubishi PA-10-7C", ...).
  virtual std::string title() const = 0;
  //! Number of joints.
  virtual unsigned dof() const = 0;
  //! The flange's pose in the base frame at joints \e q. Throws pm::core::Error for a wrong size.
  virtual vpHomogeneousMatrix fMe(const vpColVector &q) const = 0;
  //! The Jacobian in the flange frame (6 x dof, rows vx vy vz wx wy wz of the flange in its own frame) at \e q.
  virtual vpMatrix eJe(const vpColVector &q) const = 0;
  //! The Jacobian in the base frame (6 x dof, the flange origin's velocity and the angular velocity in f): [fRe 0; 0 fRe] eJe.
  virtual vpMatrix fJe(const vpColVector &q) const;
  virtual vpColVector jointMin() const = 0; //!< lower joint limits (rad or m)
  virtual vpColVector jointMax() const = 0; //!< upper joint limits (rad or m)
  virtual vpColVector speedLimits() const = 0; //!< joint speed limits (rad/s or m/s)
  //! Acceleration limits (rad/s^2 or m/s^2) the commands are held to (pm::servo::SafeCommand); each arm says where its figures come from.
  virtual vpColVector accelerationLimits() const = 0;
  //! Whether joint \e i (from 0) slides (m) rather than turns (rad).
  virtual bool prismatic(unsigned i) const { return i >= dof(); }
  /*!
    The joints the lab starts from: the flange's z axis (along which the rig looks) horizontal
    along the base's x axis, elbow and wrist away from their singularities and limits, with room
    for the pass's tilts around a target 500 mm ahead.
  */
  virtual vpColVector restJoints() const = 0;
  //! Throws pm::core::Error naming the arm unless \e q has dof() finite values; \e what says whose values they are.
  void requireJoints(const vpColVector &q, const std::string &what = "joint values") const;
  //! "joint 3 (-12.5 deg, limits -170..170 deg)" for joint \e i (from 0) at \e q: in degrees, or mm for a prismatic one.
  std::string describeJoint(unsigned i, const vpColVector &q) const;
  //! The column vector of \e v.
  static vpColVector values(std::initializer_list<double> v);
  //! The column vector of \e deg, each d * pi / 180 (rad).
  static vpColVector degrees(std::initializer_list<double> deg);
};

//! [R 0; 0 R] J: the rows of a 6 x n Jacobian \e J (a translational and a rotational velocity) turned by \e R into another frame.
vpMatrix rotateJacobian(const vpRotationMatrix &R, const vpMatrix &J);

} // namespace pm::robot
