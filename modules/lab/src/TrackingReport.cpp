#include "pm/lab/TrackingReport.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

#include "pm/core/Error.h"
#include "pm/core/Statistics.h"
#include "pm/lab/Convergence.h"

namespace pm::lab {

const std::array<const char *, 6> &TrackingReport::names()
{
  static const std::array<const char *, 6> n{"x", "y", "z", "eps1", "eps2", "eps3"};
  return n;
}

std::array<double, 6> table2Goals() { return {5, 5, 8, 0.02, 0.02, 0.02}; }

TrackingReport reportTracking(const std::vector<TrackedFrame> &frames, double fps, const std::array<double, 6> &goals)
{
  if (frames.empty())
    throw Error("reportTracking: no frame");
  TrackingReport r;
  Convergence conv(std::max(1L, std::lround(fps)));
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const TrackedFrame &f = frames[k];
    const bool within = f.haveTruth ? translationDistanceMm(f.result.phi, f.truth) <= kConvergedMm &&
                                          rotationDistanceDeg(f.result.phi, f.truth) <= kConvergedDeg
                                    : f.result.state == TrackState::Tracking;
    conv.add(static_cast<long>(k), f.t, within);
  }
  conv.finish();
  r.convergedFrame = conv.frame();
  r.convergedS = conv.time();

  const std::size_t from = r.convergedFrame < 0 ? 0 : static_cast<std::size_t>(r.convergedFrame);
  r.goalsMet = r.convergedFrame >= 0;
  for (std::size_t i = 0; i < 6; ++i) {
    AxisErrors &e = r.errors[i];
    e.goal = goals[i];
    double s2 = 0;
    for (std::size_t k = from; k < frames.size(); ++k)
      if (frames[k].haveTruth) {
        const double d = std::fabs(frames[k].result.phi[i] - frames[k].truth[i]);
        s2 += d * d;
        e.max = std::max(e.max, d);
        double &m = frames[k].moving ? e.maxMoving : e.maxAtRest;
        m = std::max(m, d);
        ++e.frames;
      }
    if (e.frames > 0) {
      r.haveTruth = true;
      e.rms = std::sqrt(s2 / static_cast<double>(e.frames));
      r.goalsMet = r.goalsMet && e.max <= e.goal;
    }
  }
  r.goalsMet = r.goalsMet && r.haveTruth; // nothing to meet them with otherwise
  std::vector<double> ms;
  ms.reserve(frames.size());
  double evals = 0;
  for (const TrackedFrame &f : frames) {
    ms.push_back(f.result.computeMs);
    evals += static_cast<double>(f.result.evaluations);
    ++r.states[toString(f.result.state)];
  }
  double sum = 0;
  for (double v : ms)
    sum += v;
  r.meanMs = sum / static_cast<double>(ms.size());
  r.p99Ms = percentile(ms, 0.99);
  r.meanEvaluations = evals / static_cast<double>(frames.size());
  return r;
}

void writeFramesCsv(std::ostream &out, const std::vector<TrackedFrame> &frames)
{
  out << "t,true_x,true_y,true_z,true_e1,true_e2,true_e3,est_x,est_y,est_z,est_e1,est_e2,est_e3,err_x,err_y,err_z,"
         "err_e1,err_e2,err_e3,fitness,quality,state,evaluations,generations,compute_ms,moving\n";
  out << std::setprecision(8);
  for (const TrackedFrame &f : frames) {
    out << f.t;
    for (std::size_t i = 0; i < 6; ++i)
      out << "," << (f.haveTruth ? f.truth[i] : NAN);
    for (std::size_t i = 0; i < 6; ++i)
      out << "," << f.result.phi[i];
    for (std::size_t i = 0; i < 6; ++i)
      out << "," << (f.haveTruth ? f.result.phi[i] - f.truth[i] : NAN);
    out << "," << f.result.fitness << "," << f.result.quality << "," << toString(f.result.state) << ","
        << f.result.evaluations << "," << f.result.generations << "," << f.result.computeMs << "," << (f.moving ? 1 : 0) << "\n";
  }
  if (!out)
    throw Error("cannot write the frames' table");
}

} // namespace pm::lab
