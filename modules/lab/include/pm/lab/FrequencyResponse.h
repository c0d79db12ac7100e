#pragma once
/*!
  \file FrequencyResponse.h
  The frequency response of the visual servo (pm-servo --freq-sweep): the TC-robot moves the
  target along one axis by sines of increasing frequency, and the hand's motion along that axis
  is compared with the target's over the last three periods (a least-squares fit of a sine at
  the known frequency): gain (hand / target amplitude) and phase lag of the hand.
*/
#include <functional>
#include <utility>
#include <vector>

#include "pm/lab/ClosedLoop.h"

namespace pm::lab {

//! One frequency of the sweep.
struct BodePoint
{
  double frequencyHz = 0; //!< the sine's frequency (Hz)
  double amplitude = 0;   //!< its amplitude (mm, or unitless on an eps axis), reduced where the TC-robot's limits require
  double gain = 0;        //!< the hand's amplitude over the target's
  double phaseLagDeg = 0; //!< how far the hand lags the target (deg, in [-180, 180])
};

//! The sweep's settings.
struct SweepParams
{
  std::vector<double> frequenciesHz{0.1, 0.2, 0.3, 0.5, 0.7, 1.0}; //!< the sines, in order (Hz)
  int axis = 0;               //!< 0..5: x, y, z, eps1, eps2, eps3 of the target in the hand frame
  double amplitude = 50;      //!< the largest amplitude (mm, or unitless on an eps axis)
  double maxVelocity = 0;     //!< the TC-robot's velocity limit (units of the axis per s; must be positive)
  double maxAcceleration = 0; //!< its acceleration limit (units per s^2; must be positive)
};

/*!
  Amplitude and phase (rad) of the component at \e frequencyHz of the samples (\e t in s, \e y):
  the least-squares fit of a sin + b cos + c, amplitude hypot(a, b), phase atan2(b, a).
*/
std::pair<double, double> sinusoidFit(const std::vector<double> &t, const std::vector<double> &y, double frequencyHz);

/*!
  Runs the closed loop once per frequency (a fade-in period, then three periods, the target
  around [0, 0, 500, 0, 0, 0]) and measures the hand's response. \e onFrequency, if given, is
  called after each. Throws pm::core::Error as ClosedLoop.

  \code
    pm::lab::SweepParams sw;
    sw.maxVelocity = 250;
    sw.maxAcceleration = 1000;
    for (const pm::lab::BodePoint &p : pm::lab::frequencyResponse(rig, scene, model, tp, servo, lp, sw))
      std::cout << p.frequencyHz << " Hz: gain " << p.gain << ", lag " << p.phaseLagDeg << " deg\n";
  \endcode
*/
std::vector<BodePoint> frequencyResponse(const core::CameraRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model,
                                         const tracker::TrackerParams &tp, const servo::ServoParams &servo, const LoopParams &lp,
                                         const SweepParams &sweep, const std::function<void()> &onFrequency = {});

} // namespace pm::lab
