#include "pm/lab/RunFigures.h"

#include <cmath>

#include "pm/core/Error.h"
#include "pm/report/TimePlot.h"

namespace pm::lab {

namespace {

double convergedTime(const std::vector<TrackedFrame> &frames, const TrackingReport &report)
{
  return report.convergedFrame >= 0 ? frames[static_cast<std::size_t>(report.convergedFrame)].t : 0;
}

std::vector<double> runMarks(const RunLog &log)
{
  return log.converged() ? std::vector<double>{log.convergedAfterS()} : std::vector<double>{};
}

} // namespace

vpImage<vpRGBa> drawTrackingTrajectory(const std::vector<TrackedFrame> &frames, const TrackingReport &report,
                                       const std::string &source)
{
  const auto &names = TrackingReport::names();
  const std::vector<double> marks = report.convergedFrame >= 0 ? std::vector<double>{convergedTime(frames, report)} : std::vector<double>{};
  std::vector<report::Panel> panels;
  for (std::size_t i = 0; i < 6; ++i) {
    report::Series truthS{"truth", vpRGBa(40, 40, 40), {}, {}, true}, estS{"estimate", vpRGBa(220, 60, 40), {}, {}, false};
    for (const auto &f : frames) {
      estS.t.push_back(f.t);
      estS.y.push_back(f.result.phi[i]);
      if (f.haveTruth) {
        truthS.t.push_back(f.t);
        truthS.y.push_back(f.truth[i]);
      }
    }
    report::Panel a{std::string(names[i]), i < 3 ? "mm" : "", {}, 0, marks};
    if (!truthS.t.empty())
      a.series.push_back(truthS);
    a.series.push_back(estS);
    panels.push_back(a);
  }
  return report::drawTimePlots(panels, 2, "estimate (red) against truth (dashed), " + source);
}

vpImage<vpRGBa> drawTrackingErrors(const std::vector<TrackedFrame> &frames, const TrackingReport &report)
{
  if (!report.haveTruth)
    throw core::Error("drawTrackingErrors: the run has no truth");
  const auto &names = TrackingReport::names();
  const double tConverged = convergedTime(frames, report);
  std::vector<report::Panel> panels;
  for (std::size_t i = 0; i < 6; ++i) {
    // Errors after convergence (before, the random start dwarfs the scale).
    report::Series errS{"error", vpRGBa(40, 90, 200), {}, {}, false};
    for (const auto &f : frames)
      if (f.haveTruth && (report.convergedFrame < 0 || f.t >= tConverged)) {
        errS.t.push_back(f.t);
        errS.y.push_back(f.result.phi[i] - f.truth[i]);
      }
    panels.push_back({std::string("error of ") + names[i] + " after convergence", i < 3 ? "mm" : "", {errS}, report.errors[i].goal, {}});
  }
  return report::drawTimePlots(panels, 2, "errors after convergence; green band: the goal");
}

vpImage<vpRGBa> drawRunErrors(const RunLog &log, const std::string &title)
{
  const std::string every = log.framesPerSample() > 1 ? " (max of every " + std::to_string(log.framesPerSample()) + " frames)" : "";
  const std::vector<double> marks = runMarks(log);
  report::Series te{"translation", vpRGBa(40, 90, 200), {}, {}, false}, re{"rotation", vpRGBa(220, 60, 40), {}, {}, false};
  for (const auto &f : log.samples()) {
    te.t.push_back(f.t);
    te.y.push_back(f.translationErrorMm);
    re.t.push_back(f.t);
    re.y.push_back(f.rotationErrorDeg);
  }
  return report::drawTimePlots({{"relative pose error, translation (goal 10 mm moving, 2 mm at rest)" + every, "mm", {te}, 10, marks},
                                {"relative pose error, rotation (goal 2 deg moving, 0.5 deg at rest)" + every, "deg", {re}, 2, marks}},
                               1, title, "time [s]", 860);
}

vpImage<vpRGBa> drawRunRelativePose(const RunLog &log)
{
  const std::vector<double> marks = runMarks(log);
  std::vector<report::Panel> rel;
  for (std::size_t i = 0; i < 6; ++i) {
    report::Series a{"truth", vpRGBa(40, 40, 40), {}, {}, true}, b{"used by the servo", vpRGBa(220, 60, 40), {}, {}, false};
    for (const auto &f : log.samples()) {
      a.t.push_back(f.t);
      a.y.push_back(f.truth[i]);
      b.t.push_back(f.t);
      b.y.push_back(f.used[i]);
    }
    rel.push_back({std::string("target in the hand frame: ") + (i < 3 ? std::string(1, "xyz"[i]) : std::string("eps") + std::to_string(i - 2)),
                   i < 3 ? "mm" : "", {a, b}, 0, marks});
  }
  return report::drawTimePlots(rel, 2, "relative pose: estimate used by the servo against truth");
}

vpImage<vpRGBa> drawRunJoints(const RunLog &log, const robot::ArmModel &arm)
{
  std::vector<report::Series> js;
  const vpRGBa colors[7] = {vpRGBa(220, 60, 40), vpRGBa(40, 90, 200), vpRGBa(40, 160, 60), vpRGBa(160, 60, 200),
                            vpRGBa(230, 150, 20), vpRGBa(20, 170, 170), vpRGBa(90, 90, 90)};
  std::vector<report::Series> slides; // prismatic joints, in mm
  for (unsigned i = 0; i < arm.dof(); ++i) {
    report::Series s{"q" + std::to_string(i + 1), colors[i % 7], {}, {}, false};
    for (const auto &f : log.samples()) {
      s.t.push_back(f.t);
      s.y.push_back(i < f.q.size() ? f.q[i] * (arm.prismatic(i) ? 1e3 : 180 / M_PI) : NAN);
    }
    (arm.prismatic(i) ? slides : js).push_back(s);
  }
  std::vector<report::Panel> panels;
  if (!slides.empty())
    panels.push_back({arm.title() + " slides", "mm", slides, 0, runMarks(log)});
  panels.push_back({arm.title() + " joints", "deg", js, 0, runMarks(log)});
  return report::drawTimePlots(panels, 1, "joint trajectories");
}

} // namespace pm::lab
