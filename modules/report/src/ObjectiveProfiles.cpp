#include "pm/report/ObjectiveProfiles.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "pm/io/ImageFile.h"
#include "pm/report/TimePlot.h"

namespace pm::report {

ProfileResult writeObjectiveProfiles(io::StagedFiles &files, const core::StereoFitness &fitness, precise::PreciseStage &precise, const core::Phi &truth,
                                     double rangeDeg, double stepDeg)
{
  ProfileResult res;
  std::ostringstream csv;
  csv << "axis,turn_deg,fitness,precise_objective\n" << std::setprecision(6);
  std::vector<Panel> panels;
  const char *names[3] = {"x", "y", "z"};
  const double fTruth = fitness.evaluate(truth);
  const int n = static_cast<int>(std::floor(rangeDeg / stepDeg));
  for (int axis = 0; axis < 3; ++axis) {
    Series f, o;
    f.name = "hue fitness F";
    f.color = vpRGBa(200, 60, 40);
    o.name = "precise stage";
    o.color = vpRGBa(40, 90, 200);
    double fMax = -1e300, oMin = 1e300;
    AxisProfile &ap = res.axes[static_cast<std::size_t>(axis)];
    double plateauLo = 1e9, plateauHi = -1e9;
    for (int k = -n; k <= n; ++k) {
      const double deg = k * stepDeg;
      double tw[6] = {0, 0, 0, 0, 0, 0};
      tw[3 + axis] = deg * M_PI / 180;
      const core::Phi p = core::applyTwist(truth, tw);
      const double F = fitness.evaluate(p), J = precise.objective(p);
      csv << names[axis] << "," << deg << "," << F << "," << J << "\n";
      f.t.push_back(deg), f.y.push_back(F);
      o.t.push_back(deg), o.y.push_back(J);
      if (F > fMax)
        fMax = F, ap.fitnessPeakDeg = deg;
      if (std::isfinite(J) && J < oMin)
        oMin = J, ap.objectivePeakDeg = deg;
      if (F >= fTruth)
        plateauLo = std::min(plateauLo, deg), plateauHi = std::max(plateauHi, deg);
    }
    ap.plateauDeg = plateauHi >= plateauLo ? plateauHi - plateauLo : 0;
    // Both on [0, 1], 1 the best: F over its range, the objective reversed.
    const double fMin = *std::min_element(f.y.begin(), f.y.end());
    double oMax = -1e300;
    for (double v : o.y)
      if (std::isfinite(v))
        oMax = std::max(oMax, v);
    for (double &v : f.y)
      v = fMax > fMin ? (v - fMin) / (fMax - fMin) : 1.0;
    for (double &v : o.y)
      v = std::isfinite(v) && oMax > oMin ? (oMax - v) / (oMax - oMin) : std::nan("");
    Panel panel;
    panel.title = std::string("about ") + names[axis] + " (1: best)";
    panel.yLabel = "";
    panel.series = {f, o};
    panel.marks = {0.0};
    panels.push_back(panel);
  }
  io::writeImage(drawTimePlots(panels, 3, "at the true pose (dotted): the hue fitness and the precise stage's objective", "turn [deg]", 480),
                 files.stage("profiles.png"));
  io::writeTextFile(files.stage("profiles.csv"), csv.str());
  std::ostringstream text;
  text << std::fixed << std::setprecision(2);
  for (int axis = 0; axis < 3; ++axis) {
    const AxisProfile &ap = res.axes[static_cast<std::size_t>(axis)];
    text << "  about " << names[axis] << ": F peaks at " << ap.fitnessPeakDeg << " deg (its plateau over F(truth) spans " << ap.plateauDeg
         << " deg), the precise stage's objective at " << ap.objectivePeakDeg << " deg\n";
  }
  res.text = text.str();
  return res;
}

} // namespace pm::report
