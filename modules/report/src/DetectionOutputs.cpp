#include "pm/report/DetectionOutputs.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/Overlay.h"

namespace pm::report {

namespace {
nlohmann::json phiJson(const core::Phi &p) { return {p.x, p.y, p.z, p.e1, p.e2, p.e3}; }
} // namespace

PoseErrors poseErrors(const core::Phi &a, const core::Phi &b)
{
  PoseErrors e;
  e.positionMm = core::translationDistanceMm(a, b);
  e.orientation = std::max({std::fabs(a.e1 - b.e1), std::fabs(a.e2 - b.e2), std::fabs(a.e3 - b.e3)});
  e.rotationDeg = core::rotationDistanceDeg(a, b);
  return e;
}

std::string writeDetection(const std::string &dir, const DetectionOutputs &o, const core::StereoFitness &fitness,
                           const core::CameraImages &images)
{
  const tracker::Detection &d = o.detection;
  const tracker::TrackResult &best = d.best;
  io::StagedFiles files(dir);
  std::vector<std::vector<core::PointScore>> scores;
  for (std::size_t k = 0; k < images.size(); ++k)
    scores.push_back(fitness.pointScores(best.phi, static_cast<int>(k)));
  io::writeImage(drawCameras(images, scores, cameraLabels(images.size(), "detection, ")), files.stage("detection.png"));
  nlohmann::json s{{"source", o.source},
                   {"pose", phiJson(best.phi)},
                   {"fitness", best.fitness},
                   {"quality", best.quality},
                   {"state", toString(best.state)},
                   {"time_s", d.convergedS},
                   {"total_time_s", d.totalS},
                   {"evaluations", d.evaluations},
                   {"total_evaluations", d.totalEvaluations},
                   {"frames", d.frames},
                   {"budget", o.budget}};
  if (o.haveTruth) {
    const PoseErrors e = poseErrors(best.phi, o.truth), ep = poseErrors(best.phi, o.peak);
    const core::Phi &t = o.truth;
    s["truth"] = phiJson(t);
    s["position_error_mm"] = e.positionMm;
    s["orientation_error"] = e.orientation;
    s["rotation_error_deg"] = e.rotationDeg;
    s["error_vector"] = {best.phi.x - t.x, best.phi.y - t.y, best.phi.z - t.z, best.phi.e1 - t.e1, best.phi.e2 - t.e2, best.phi.e3 - t.e3};
    s["fitness_peak"] = phiJson(o.peak);
    s["fitness_at_peak"] = o.fitnessAtPeak;
    s["position_error_to_peak_mm"] = ep.positionMm;
    s["orientation_error_to_peak"] = ep.orientation;
  }
  const std::string text = s.dump(2) + "\n";
  io::writeTextFile(files.stage("summary.json"), text);
  files.commit();
  return text;
}

std::string describeDetection(const DetectionOutputs &o, const std::string &dir)
{
  const tracker::TrackResult &b = o.detection.best;
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << "detected in " << o.source << "\n  pose [" << b.phi.x << ", " << b.phi.y << ", " << b.phi.z
      << ", " << std::setprecision(4) << b.phi.e1 << ", " << b.phi.e2 << ", " << b.phi.e3 << "], F = " << b.fitness << " ("
      << toString(b.state) << ")\n";
  if (o.haveTruth) {
    const PoseErrors e = poseErrors(b.phi, o.truth), ep = poseErrors(b.phi, o.peak);
    out << std::setprecision(2) << "  error to the truth " << e.positionMm << " mm, " << std::setprecision(4) << e.orientation
        << " in eps (" << std::setprecision(2) << e.rotationDeg << " deg); to the fitness peak " << ep.positionMm << " mm, "
        << std::setprecision(4) << ep.orientation << "\n";
  }
  out << std::setprecision(3) << "  converged after " << o.detection.convergedS << " s (" << o.detection.evaluations
      << " evaluations), written to " << dir << "/\n";
  return out.str();
}

} // namespace pm::report
