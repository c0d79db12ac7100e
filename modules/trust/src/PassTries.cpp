#include "pm/trust/PassTries.h"

#include <cmath>
#include <random>
#include <sstream>

#include <visp3/core/vpRotationMatrix.h>
#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Pose.h"
#include "pm/model/PassRig.h"

namespace pm::trust {

namespace {

//! \e tracker's last frame measured against the truth \e hMm.
PassTry record(const tracker::TrackResult &r, const vpHomogeneousMatrix &hMm, std::size_t view, const std::string &start)
{
  PassTry t;
  t.view = view;
  t.start = start;
  t.cues = r.cues;
  t.uncertainty = r.uncertainty;
  vpRotationMatrix Re, Rt;
  r.hMo.extract(Re);
  hMm.extract(Rt);
  const vpThetaUVector tu(Re * Rt.t()); // about the hand's axes
  for (unsigned i = 0; i < 3; ++i) {
    t.originMm[i] = 1e3 * hMm[i][3];
    t.error[i] = 1e3 * (r.hMo[i][3] - hMm[i][3]);
    t.error[3 + i] = tu[i] * 180.0 / M_PI;
  }
  t.errorMm = std::sqrt(t.error[0] * t.error[0] + t.error[1] * t.error[1] + t.error[2] * t.error[2]);
  t.errorDeg = std::sqrt(tu.sumSquare()) * 180.0 / M_PI;
  return t;
}

//! From \e start, \e frames frames of the view's still pair; the last one recorded.
PassTry tryFrom(tracker::PhotoModelTracker &tracker, const model::PassView &v, const vpHomogeneousMatrix &hMm, const vpHomogeneousMatrix &start,
                int frames, std::size_t view, const std::string &name)
{
  tracker.initFromPose(start);
  tracker::TrackResult r;
  for (int f = 0; f < frames; ++f)
    r = tracker.track(model::viewImages(v, static_cast<std::size_t>(tracker.cameraCount())));
  return record(r, hMm, view, name);
}

} // namespace

std::vector<PassTry> tryView(tracker::PhotoModelTracker &tracker, const model::PassView &v, const vpHomogeneousMatrix &hMm,
                             const TryParams &p, std::uint64_t seed, std::size_t view)
{
  std::vector<PassTry> out;
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double deg = M_PI / 180.0;
  // Near the truth: where the tracker lands from there is a right pose through this camera.
  for (int k = 0; k < p.nearStarts; ++k) {
    vpHomogeneousMatrix start = hMm;
    if (k > 0) {
      const double a = p.nearDeg * deg / std::sqrt(3.0);
      const vpHomogeneousMatrix d(p.nearMm * 1e-3 * unit(rng) / std::sqrt(3.0), p.nearMm * 1e-3 * unit(rng) / std::sqrt(3.0),
                                  p.nearMm * 1e-3 * unit(rng) / std::sqrt(3.0), a * unit(rng), a * unit(rng), a * unit(rng));
      start = d * hMm;
    }
    out.push_back(tryFrom(tracker, v, hMm, start, p.nearFrames, view, "near"));
  }
  // The competitors of the confidence and the verifier: turned about the model's own z axis, the tilt mirrored.
  for (int a : {-135, -90, -45, 45, 90, 135, 180})
    out.push_back(tryFrom(tracker, v, hMm, hMm * vpHomogeneousMatrix(0, 0, 0, 0, 0, a * deg), p.wrongFrames, view,
                          "turned " + std::to_string(a) + " deg"));
  {
    core::Phi m = core::fromHomogeneousMatrix(hMm);
    m.e1 = -m.e1;
    m.e2 = -m.e2;
    out.push_back(tryFrom(tracker, v, hMm, core::toHomogeneousMatrix(m), p.wrongFrames, view, "tilt mirrored"));
  }
  // Moved along and tilted about the hand's axes, past 20 mm and 5 deg.
  const char *axis[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    for (int s : {-1, 1}) {
      double t[3] = {0, 0, 0};
      t[i] = s * p.shiftMm * 1e-3;
      std::ostringstream name;
      name << "moved " << (s > 0 ? "+" : "-") << p.shiftMm << " mm along " << axis[i];
      out.push_back(tryFrom(tracker, v, hMm, vpHomogeneousMatrix(t[0], t[1], t[2], 0, 0, 0) * hMm, p.wrongFrames, view, name.str()));
    }
  for (int i = 0; i < 2; ++i)
    for (int s : {-1, 1}) {
      double r[3] = {0, 0, 0};
      r[i] = s * p.tiltDeg * deg;
      // Turned about the hand's axis through the model's origin: the origin stays where it is.
      const vpHomogeneousMatrix R(0, 0, 0, r[0], r[1], r[2]);
      vpHomogeneousMatrix start = R * hMm;
      for (unsigned k = 0; k < 3; ++k)
        start[k][3] = hMm[k][3];
      std::ostringstream name;
      name << "tilted " << (s > 0 ? "+" : "-") << p.tiltDeg << " deg about " << axis[i];
      out.push_back(tryFrom(tracker, v, hMm, start, p.wrongFrames, view, name.str()));
    }
  // RM-GA's own optima: a search from scratch.
  for (int k = 0; k < p.searches; ++k) {
    tracker.initialize();
    tracker::TrackResult r;
    for (int f = 0; f < p.searchFrames; ++f)
      r = tracker.track(model::viewImages(v, static_cast<std::size_t>(tracker.cameraCount())));
    out.push_back(record(r, hMm, view, "search"));
  }
  return out;
}

} // namespace pm::trust
