#include "pm/lab/RunSummary.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

namespace pm::lab {

namespace {
//! The nearest the target came and how well it was seen there (a grasp approach's end).
nlohmann::json nearestJson(const RunLog &log)
{
  const ErrorStats e = log.estimateNearest();
  return {{"distance_mm", log.nearestMm()},
          {"estimate_frames", e.frames},
          {"estimate_rms_mm", e.rmsMm()},
          {"estimate_max_mm", e.maxMm},
          {"estimate_rms_deg", e.rmsDeg()},
          {"estimate_max_deg", e.maxDeg},
          {"over", "the tracked frames whose target stood within 10 mm of the nearest distance (the true pose's z)"}};
}

//! The tracker's own estimate against the truth, or why there is none (0.00 mm would read as perfect).
std::string estimateText(const ErrorStats &e)
{
  if (e.frames == 0)
    return "not measured (it is measured over the tracked frames from the loop's convergence on, and the loop never converged)";
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << "rms " << e.rmsMm() << " mm and " << e.rmsDeg() << " deg, max " << e.maxMm << " mm and "
      << e.maxDeg << " deg";
  return out.str();
}
} // namespace

std::string runSummaryJson(const RunLog &log, const RunInfo &info)
{
  const ErrorStats &rest = log.atRest(), &moving = log.moving();
  nlohmann::json tenths = nlohmann::json::array();
  for (const auto &s : log.tenths())
    tenths.push_back({{"frames", s.frames}, {"rms_error_mm", s.rmsMm()}, {"max_error_mm", s.maxMm}, {"rms_rotation_error_deg", s.rmsDeg()},
                      {"max_rotation_error_deg", s.maxDeg}});
  nlohmann::json memory = nlohmann::json::array();
  for (double m : info.memoryMb)
    memory.push_back(std::isfinite(m) ? nlohmann::json(m) : nlohmann::json());
  const nlohmann::json summary{
      {"robot", info.arm},
      {"target", info.targetCode},
      {"trajectory", info.trajectory},
      {"oracle", info.oracle},
      {"frames", log.frames()},
      {"converged_after_s", log.converged() ? nlohmann::json(log.convergedAfterS()) : nlohmann::json()},
      {"rms_error_mm", {{"at_rest", rest.rmsMm()}, {"moving", moving.rmsMm()}}},
      {"max_error_mm", {{"at_rest", rest.maxMm}, {"moving", moving.maxMm}}},
      {"rms_rotation_error_deg", {{"at_rest", rest.rmsDeg()}, {"moving", moving.rmsDeg()}}},
      {"max_rotation_error_deg", {{"at_rest", rest.maxDeg}, {"moving", moving.maxDeg}}},
      {"by_tenth_of_the_run", tenths},
      {"resident_memory_mb", memory},
      {"joint_limit_violations", info.jointLimitViolations},
      {"frames_servoed", log.framesServoed()},
      {"frames_held", log.framesHeld()},
      {"held_by", log.heldBy()},
      {"frames_servoed_on_wrong_pose", log.framesServoedOnWrongPose()},
      {"frames_servoed_on_wrong_raw_estimate", log.framesServoedOnWrongRawEstimate()},
      {"wrong_pose", "the pose the servo used (the filtered estimate) more than 20 mm or 5 deg from the truth; "
                     "raw estimate: the tracker's own, before the filter"},
      {"estimate_error", {{"rms_mm", log.estimate().rmsMm()}, {"max_mm", log.estimate().maxMm}, {"rms_deg", log.estimate().rmsDeg()},
                          {"max_deg", log.estimate().maxDeg}, {"frames", log.estimate().frames},
                          {"over", "the tracker's own estimate, tracked frames from convergence on (none when frames is 0: the loop never converged)"}}},
      {"nearest", nearestJson(log)},
      {"frames_precise", log.framesPrecise()},
      {"visible_share", {{"min", log.minVisibleShare()}, {"frames_partly_hidden", log.framesPartlyHidden()},
                         {"over", "the share of the model's points on the images not found hidden (the lower camera's), at the estimate"}}},
      {"max_joint_speed_fraction", log.maxJointSpeedFraction()},
      {"mean_frame_ms", log.meanComputeMs()},
      {"overlays", info.overlays},
      {"video", info.video}};
  return summary.dump(2) + "\n";
}

std::string heldByText(const std::map<std::string, long> &heldBy)
{
  std::vector<std::pair<long, std::string>> v;
  for (const auto &[why, n] : heldBy)
    v.emplace_back(n, why);
  std::sort(v.begin(), v.end(), [](const auto &a, const auto &b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
  std::ostringstream out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out << (i ? ", " : "") << v[i].second << " " << v[i].first;
  return v.empty() ? "none" : out.str();
}

std::string runSummaryText(const RunLog &log, const RunInfo &info)
{
  const ErrorStats &rest = log.atRest(), &moving = log.moving();
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << info.arm << " following " << info.targetCode << " (" << info.targetName << "), "
      << info.trajectory << ", " << (info.oracle ? "oracle pose" : "photo-model tracker") << ", " << log.frames() << " frames\n";
  if (log.converged())
    out << "  converged after " << log.convergedAfterS() << " s\n";
  else
    out << "  never within 10 mm and 2 deg for 1 s\n";
  out << "  relative pose error at rest: rms " << rest.rmsMm() << " mm, max " << rest.maxMm << " mm; rotation rms " << rest.rmsDeg()
      << " deg, max " << rest.maxDeg << " deg\n"
      << "  while moving: rms " << moving.rmsMm() << " mm, max " << moving.maxMm << " mm; rotation rms " << moving.rmsDeg()
      << " deg, max " << moving.maxDeg << " deg\n"
      << "  the tracker's estimate: " << estimateText(log.estimate()) << "; the precise stage gave " << log.framesPrecise() << " of "
      << log.frames() << " frames\n"
      << "  joint limit violations " << info.jointLimitViolations << ", tracker " << log.meanComputeMs() << " ms per frame\n"
      << "  servoed on " << log.framesServoed() << " frames ("
      << 100.0 * static_cast<double>(log.framesServoed()) / static_cast<double>(std::max(1L, log.frames())) << " %), held on "
      << log.framesHeld() << " (" << heldByText(log.heldBy()) << "), servoed on a wrong pose on " << log.framesServoedOnWrongPose()
      << " (the raw estimate wrong on " << log.framesServoedOnWrongRawEstimate() << ")\n"
      << "  by tenth of the run, rms error (mm):";
  for (const auto &t : log.tenths())
    out << " " << t.rmsMm();
  out << "\n  by tenth of the run, resident memory (MB):";
  for (double m : info.memoryMb)
    out << " " << std::setprecision(1) << m;
  out << std::setprecision(2) << "\n";
  return out.str();
}

} // namespace pm::lab
