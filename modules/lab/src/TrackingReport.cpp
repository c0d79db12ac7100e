#include "pm/lab/TrackingReport.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/core/Statistics.h"
#include "pm/lab/Convergence.h"
#include "pm/lab/RunSummary.h"

#include <visp3/core/vpRotationMatrix.h>
#include <visp3/core/vpThetaUVector.h>

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
    throw core::Error("reportTracking: no frame");
  TrackingReport r;
  Convergence conv(std::max(1L, std::lround(fps)));
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const TrackedFrame &f = frames[k];
    const bool within = f.haveTruth ? core::translationDistanceMm(f.result.phi, f.truth) <= kConvergedMm &&
                                          core::rotationDistanceDeg(f.result.phi, f.truth) <= kConvergedDeg
                                    : f.result.state == tracker::TrackState::Tracking;
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
  double mm2 = 0, deg2 = 0;
  std::size_t nTruth = 0;
  for (std::size_t k = from; k < frames.size(); ++k)
    if (frames[k].haveTruth) {
      const double mm = core::translationDistanceMm(frames[k].result.phi, frames[k].truth), deg = core::rotationDistanceDeg(frames[k].result.phi, frames[k].truth);
      mm2 += mm * mm, deg2 += deg * deg, ++nTruth;
      r.positionMaxMm = std::max(r.positionMaxMm, mm);
      r.rotationMaxDeg = std::max(r.rotationMaxDeg, deg);
    }
  if (nTruth > 0) {
    r.positionRmsMm = std::sqrt(mm2 / static_cast<double>(nTruth));
    r.rotationRmsDeg = std::sqrt(deg2 / static_cast<double>(nTruth));
  }
  std::vector<double> ms;
  ms.reserve(frames.size());
  double evals = 0;
  for (const TrackedFrame &f : frames) {
    ms.push_back(f.result.computeMs);
    evals += static_cast<double>(f.result.evaluations);
    ++r.states[toString(f.result.state)];
    r.preciseFrames += f.result.precise ? 1 : 0;
    r.trustedFrames += f.result.trusted ? 1 : 0;
    if (!f.result.trusted)
      ++r.heldBy[f.result.heldBy ? f.result.heldBy : "confidence"];
    if (f.haveTruth) {
      const double mm = core::translationDistanceMm(f.result.phi, f.truth), deg = core::rotationDistanceDeg(f.result.phi, f.truth);
      const bool right = mm <= kRightMm && deg <= kRightDeg, wrong = mm > kWrongMm || deg > kWrongDeg;
      r.rightFrames += right;
      r.rightTrusted += right && f.result.trusted;
      r.wrongFrames += wrong;
      r.wrongTrusted += wrong && f.result.trusted;
      if (f.result.trusted) {
        r.trustedMaxMm = std::max(r.trustedMaxMm, mm);
        r.trustedMaxDeg = std::max(r.trustedMaxDeg, deg);
      }
    }
  }
  // The reported 1-sigma against the true errors, along and about the hand's axes.
  std::array<long, 6> within{};
  for (std::size_t k = from; k < frames.size(); ++k) {
    const TrackedFrame &f = frames[k];
    if (!f.haveTruth || !f.result.uncertainty.known || f.result.state != tracker::TrackState::Tracking)
      continue;
    const std::array<double, 6> e = handFrameErrors(f.result.phi, f.truth);
    for (std::size_t a = 0; a < 6; ++a)
      within[a] += std::fabs(e[a]) <= (a < 3 ? f.result.uncertainty.sigmaMm[a] : f.result.uncertainty.sigmaDeg[a - 3]);
    ++r.sigmaFrames;
  }
  for (std::size_t a = 0; a < 6 && r.sigmaFrames > 0; ++a)
    r.withinSigma[a] = static_cast<double>(within[a]) / static_cast<double>(r.sigmaFrames);
  double sum = 0;
  for (double v : ms)
    sum += v;
  r.meanMs = sum / static_cast<double>(ms.size());
  r.p99Ms = core::percentile(ms, 0.99);
  r.meanEvaluations = evals / static_cast<double>(frames.size());
  return r;
}

std::array<double, 6> handFrameErrors(const core::Phi &estimate, const core::Phi &truth)
{
  const vpHomogeneousMatrix hMe = core::toHomogeneousMatrix(estimate), hMt = core::toHomogeneousMatrix(truth);
  vpRotationMatrix Re, Rt;
  hMe.extract(Re);
  hMt.extract(Rt);
  const vpThetaUVector tu(Re * Rt.t());
  return {estimate.x - truth.x, estimate.y - truth.y, estimate.z - truth.z, tu[0] * 180 / M_PI, tu[1] * 180 / M_PI, tu[2] * 180 / M_PI};
}

void writeFramesCsv(std::ostream &out, const std::vector<TrackedFrame> &frames)
{
  out << "t,true_x,true_y,true_z,true_e1,true_e2,true_e3,est_x,est_y,est_z,est_e1,est_e2,est_e3,err_x,err_y,err_z,"
         "err_e1,err_e2,err_e3,fitness,quality,state,evaluations,generations,compute_ms,moving,confidence,trusted,held_by,visible_share,background_hue_deg"
      << uncertaintyCsvHeader() << cuesCsvHeader() << stepsCsvHeader() << "\n";
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
        << f.result.evaluations << "," << f.result.generations << "," << f.result.computeMs << "," << (f.moving ? 1 : 0) << ","
        << f.result.confidence << "," << (f.result.trusted ? 1 : 0) << "," << (f.result.heldBy ? f.result.heldBy : "") << ","
        << f.result.visibleShare << "," << f.result.backgroundHueDeg;
    writeUncertaintyCells(out, f.result.uncertainty);
    writeCueCells(out, f.result.cues);
    writeStepCells(out, f.result.steps);
    out << "\n";
  }
  if (!out)
    throw core::Error("cannot write the frames' table");
}

std::string cuesCsvHeader()
{
  std::string h;
  for (const char *n : tracker::ConfidenceCues::featureNames())
    h += std::string(",cue_") + n;
  return h;
}

void writeCueCells(std::ostream &out, const tracker::ConfidenceCues &c)
{
  for (double x : c.features())
    out << "," << x;
}

const char *uncertaintyCsvHeader() { return ",sigma_x_mm,sigma_y_mm,sigma_z_mm,sigma_rx_deg,sigma_ry_deg,sigma_rz_deg"; }

std::string stepsCsvHeader()
{
  std::string h;
  for (const char *n : tracker::StepTimes::names())
    h += std::string(",step_") + n + "_ms";
  return h;
}

void writeStepCells(std::ostream &out, const tracker::StepTimes &s)
{
  for (double ms : s.values())
    out << "," << ms;
}

void writeUncertaintyCells(std::ostream &out, const precise::PoseUncertainty &u)
{
  for (std::size_t i = 0; i < 6; ++i) {
    out << ",";
    if (u.known)
      out << (i < 3 ? u.sigmaMm[i] : u.sigmaDeg[i - 3]);
  }
}

std::string trackingSummaryJson(const TrackingReport &report, const TrackingRunInfo &info)
{
  const auto &names = TrackingReport::names();
  const capture::SourceStats &st = info.stats;
  nlohmann::json errors;
  for (std::size_t i = 0; i < 6 && report.haveTruth; ++i)
    errors[names[i]] = {{"rms_error", report.errors[i].rms},
                        {"max_abs_error", report.errors[i].max},
                        {"max_abs_error_moving", report.errors[i].maxMoving},
                        {"max_abs_error_at_rest", report.errors[i].maxAtRest},
                        {"goal", report.errors[i].goal}};
  nlohmann::json summary{{"source", info.source},
                         {"frames", info.frames},
                         {"unreadable_frames", st.skipped},
                         {"unreadable", std::vector<std::string>(st.problems.begin(), st.problems.begin() + st.skipped)},
                         {"fps", info.fps},
                         {"converged_after_s", report.convergedFrame >= 0 ? nlohmann::json(report.convergedS) : nlohmann::json()},
                         {"errors", errors},
                         {"errors_over", report.convergedFrame >= 0 ? "frames after convergence" : "all frames (never converged)"},
                         {"goals_met", report.goalsMet},
                         {"position_error_mm", {{"rms", report.positionRmsMm}, {"max", report.positionMaxMm}}},
                         {"rotation_error_deg", {{"rms", report.rotationRmsDeg}, {"max", report.rotationMaxDeg}}},
                         {"precise_frames", report.preciseFrames},
                         {"trusted_frames", report.trustedFrames},
                         {"held_by", report.heldBy},
                         {"right_frames", {{"n", report.rightFrames}, {"trusted", report.rightTrusted},
                                           {"over", "estimates within 5 mm and 2 deg of the truth"}}},
                         {"wrong_frames", {{"n", report.wrongFrames}, {"trusted", report.wrongTrusted},
                                           {"over", "estimates more than 20 mm or 5 deg from the truth"}}},
                         {"trusted_error_max", {{"mm", report.trustedMaxMm}, {"deg", report.trustedMaxDeg},
                                                {"over", "the trusted frames, each its own maximum"}}},
                         {"within_sigma", {{"share", report.withinSigma}, {"frames", report.sigmaFrames},
                                           {"axes", "along the hand's x, y, z, about them; tracked frames after convergence"}}},
                         {"mean_frame_ms", report.meanMs},
                         {"p99_frame_ms", report.p99Ms},
                         {"mean_evaluations_per_frame", report.meanEvaluations},
                         {"states", report.states},
                         {"tracker", nlohmann::json::parse(info.trackerJson)}};
  if (info.live)
    summary["capture"] = {{"pairs", st.pairs},
                          {"frames_read", {st.framesRead[0], st.framesRead[1]}},
                          {"unpaired", {st.unpaired[0], st.unpaired[1]}},
                          {"largest_skew_ms", st.maxSkewMs},
                          {"notes", st.problems}};
  return summary.dump(2) + "\n";
}

std::string trackingSummaryText(const TrackingReport &report, const TrackingRunInfo &info)
{
  const auto &names = TrackingReport::names();
  std::ostringstream out;
  out << std::fixed << "tracked " << info.frames << " frames of " << info.source << "\n";
  if (report.convergedFrame >= 0)
    out << std::setprecision(2) << "  converged after " << report.convergedS << " s\n";
  else
    out << std::setprecision(0) << "  never converged (within " << kConvergedMm << " mm and " << kConvergedDeg << " deg for 1 s)\n";
  for (std::size_t i = 0; i < 6 && report.haveTruth; ++i)
    out << std::setprecision(i < 3 ? 2 : 4) << "  " << std::setw(4) << names[i] << ": rms " << report.errors[i].rms << ", max "
        << report.errors[i].max << " (goal " << report.errors[i].goal << ")\n";
  if (report.haveTruth)
    out << std::setprecision(2) << "  pose error: rms " << report.positionRmsMm << " mm and " << report.rotationRmsDeg << " deg, max "
        << report.positionMaxMm << " mm and " << report.rotationMaxDeg << " deg\n";
  out << "  precise stage: " << report.preciseFrames << " of " << info.frames << " frames\n";
  out << "  trusted on " << report.trustedFrames << " frames, held on " << static_cast<long>(info.frames) - report.trustedFrames << " ("
      << heldByText(report.heldBy) << ")\n";
  if (report.haveTruth) {
    out << std::setprecision(1) << "  right estimates (within 5 mm and 2 deg) " << report.rightFrames << ", trusted "
        << report.rightTrusted << " (" << 100.0 * static_cast<double>(report.rightTrusted) / static_cast<double>(std::max(1L, report.rightFrames))
        << " %); wrong (over 20 mm or 5 deg) " << report.wrongFrames << ", trusted " << report.wrongTrusted << "\n";
    if (report.trustedFrames > 0)
      out << "  the trusted frames at most " << report.trustedMaxMm << " mm and " << report.trustedMaxDeg << " deg from the truth\n";
    if (report.sigmaFrames > 0) {
      out << std::setprecision(0) << "  true errors within 1 sigma (x, y, z, about x, y, z):";
      for (double w : report.withinSigma)
        out << " " << 100 * w << " %";
      out << " over " << report.sigmaFrames << " frames\n";
    }
  }
  out << std::setprecision(2) << "  compute per frame: mean " << report.meanMs << " ms, p99 " << report.p99Ms << " ms (" << info.budget
      << " budget)\n";
  return out.str();
}

} // namespace pm::lab
