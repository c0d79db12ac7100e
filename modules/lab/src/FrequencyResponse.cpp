#include "pm/lab/FrequencyResponse.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpMatrix.h>

#include "pm/core/Error.h"

namespace pm::lab {

std::pair<double, double> sinusoidFit(const std::vector<double> &t, const std::vector<double> &y, double frequencyHz)
{
  double s[3][3] = {{0}}, b[3] = {0};
  for (std::size_t k = 0; k < t.size() && k < y.size(); ++k) {
    const double r[3] = {std::sin(2 * M_PI * frequencyHz * t[k]), std::cos(2 * M_PI * frequencyHz * t[k]), 1.0};
    for (int i = 0; i < 3; ++i) {
      b[i] += r[i] * y[k];
      for (int j = 0; j < 3; ++j)
        s[i][j] += r[i] * r[j];
    }
  }
  vpMatrix A(3, 3);
  vpColVector B(3);
  for (unsigned i = 0; i < 3; ++i) {
    B[i] = b[i];
    for (unsigned j = 0; j < 3; ++j)
      A[i][j] = s[i][j];
  }
  const vpColVector x = A.pseudoInverse() * B;
  return {std::hypot(x[0], x[1]), std::atan2(x[1], x[0])};
}

std::vector<BodePoint> frequencyResponse(const core::CameraRig &rig, const sim::Scene &scene, const sim::SimulatedPhotoModel &model,
                                         const tracker::TrackerParams &tp, const servo::ServoParams &servo, const LoopParams &lp,
                                         const SweepParams &sweep, const std::function<void()> &onFrequency)
{
  if (sweep.axis < 0 || sweep.axis > 5 || !(sweep.maxVelocity > 0) || !(sweep.maxAcceleration > 0) || !(sweep.amplitude > 0))
    throw core::Error("frequency response: the axis must be 0..5 and the amplitude and the TC-robot's limits positive");
  const core::Phi phi0{0, 0, 500, 0, 0, 0};
  const std::size_t ax = static_cast<std::size_t>(sweep.axis);
  std::vector<BodePoint> points;
  for (double f : sweep.frequenciesHz) {
    if (!(f > 0))
      throw core::Error("frequency response: the frequencies must be positive");
    const double seconds = 1.0 / f + 3.0 / f; // the fade-in period, then three periods
    // The amplitude, reduced where the TC-robot's velocity or acceleration limit requires it.
    const double w = 2 * M_PI * f;
    const double amp = std::min({sweep.amplitude, 0.999 * sweep.maxVelocity / w, 0.999 * sweep.maxAcceleration / (w * w)});
    ClosedLoop loop(rig, scene, model, tp, servo, lp, [&](const vpHomogeneousMatrix &wMh0) {
      return std::make_unique<sim::TcRobot>(wMh0, phi0, sweep.axis, amp, f, sweep.maxVelocity, sweep.maxAcceleration);
    });
    // The hand's motion along the axis in h0 against the target's, over the last three periods:
    // the hand follows if the relative pose stays constant, hand motion = target motion - relative error.
    std::vector<double> t, yt, yh;
    const long n = static_cast<long>(std::floor(seconds * lp.fps)) + 1;
    for (long k = 0; k < n; ++k) {
      const LoopFrame fr = loop.step();
      if (fr.t < 1.0 / f)
        continue;
      const core::Phi rel = core::fromHomogeneousMatrix(fr.hMmTrue);
      const double targetMotion = amp * std::sin(2 * M_PI * f * fr.t);
      t.push_back(fr.t);
      yt.push_back(targetMotion);
      yh.push_back(targetMotion - (rel[ax] - phi0[ax]));
    }
    const auto [at, pt] = sinusoidFit(t, yt, f);
    const auto [ah, ph] = sinusoidFit(t, yh, f);
    double lag = (pt - ph) * 180 / M_PI;
    while (lag > 180)
      lag -= 360;
    while (lag < -180)
      lag += 360;
    points.push_back({f, amp, ah / at, lag});
    if (onFrequency)
      onFrequency();
  }
  return points;
}

} // namespace pm::lab
