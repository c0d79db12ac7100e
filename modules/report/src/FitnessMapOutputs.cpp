#include "pm/report/FitnessMapOutputs.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/HeatMap.h"
#include "pm/report/Overlay.h"

namespace pm::report {

namespace {

const char *kVarNames[6] = {"x [mm]", "y [mm]", "z [mm]", "eps1", "eps2", "eps3"};
const char *kVarShort[6] = {"x", "y", "z", "e1", "e2", "e3"};

Grid2D toGrid(const core::FitnessMap &m)
{
  Grid2D g;
  g.xName = kVarNames[m.spec.a];
  g.yName = kVarNames[m.spec.b];
  g.x0 = m.spec.loA;
  g.y0 = m.spec.loB;
  g.dx = g.dy = m.spec.step;
  g.nx = m.nA;
  g.ny = m.nB;
  g.values = m.values;
  return g;
}

nlohmann::json countsJson(const core::FitnessCounts &c)
{
  return nlohmann::json{{"in_match", c.inMatch},   {"in_background", c.inBackground},   {"in_other", c.inOther}, {"in_off", c.inOff},
                        {"out_background", c.outBackground}, {"out_other", c.outOther}, {"out_off", c.outOff}};
}

} // namespace

const GridResult &FitnessMapsResult::grid(const std::string &name) const
{
  for (const GridResult &g : grids)
    if (g.name == name)
      return g;
  throw core::Error("no fitness map '" + name + "'");
}

FitnessMapsResult writeFitnessMaps(const std::string &dir, const core::StereoFitness &fit, std::size_t modelPoints, const core::Phi &truth,
                                   const std::vector<core::FitnessMapSpec> &specs, const std::string &source,
                                   const core::CameraImages &images, const std::function<void()> &onMap)
{
  io::StagedFiles files(dir);
  FitnessMapsResult r;
  r.modelPoints = modelPoints;
  nlohmann::json grids;
  std::ostringstream report;
  for (const auto &s : specs) {
    // The variables not on the grid are held at the truth (the model's true pose).
    const core::FitnessMap m = core::computeFitnessMap(fit, truth, s);
    r.seconds += m.seconds;
    const std::string name = std::string(kVarShort[s.a]) + kVarShort[s.b];
    const double ta = truth[s.a], tb = truth[s.b], ea = m.peakA - ta, eb = m.peakB - tb;
    core::Phi peak = truth;
    peak[s.a] = m.peakA;
    peak[s.b] = m.peakB;
    const double reproj = fit.reprojectionRms(peak, truth);
    r.grids.push_back({name, m.peakA, m.peakB, ea, eb, reproj, m.maxFitness, m.seconds});
    grids[name] = {{"variables", {kVarShort[s.a], kVarShort[s.b]}},
                   {"peak", {m.peakA, m.peakB}},
                   {"peak_fitness", m.maxFitness},
                   {"argmax", {m.argmaxA, m.argmaxB}},
                   {"top_cells", m.topCells},
                   {"truth", {ta, tb}},
                   {"error_to_truth", {ea, eb}},
                   {"peak_reprojection_px", reproj},
                   {"evaluations", m.values.size()},
                   {"time_s", m.seconds}};
    std::ofstream csv(files.stage("map_" + name + ".csv"));
    csv << kVarShort[s.a] << "," << kVarShort[s.b] << ",fitness\n" << std::setprecision(10);
    for (int j = 0; j < m.nB; ++j)
      for (int i = 0; i < m.nA; ++i)
        csv << m.coordA(i) << "," << m.coordB(j) << "," << m.at(i, j) << "\n";
    if (!csv)
      throw core::Error("cannot write " + files.finalPath("map_" + name + ".csv"));
    std::ostringstream title;
    title << std::setprecision(3) << "F over " << kVarShort[s.a] << "-" << kVarShort[s.b] << ", max " << m.maxFitness;
    io::writeImage(drawHeatMap(toGrid(m), title.str(),
                               {{ta, tb, "truth", vpRGBa(255, 255, 255), true}, {m.peakA, m.peakB, "peak", vpRGBa(230, 30, 30), false}}),
                   files.stage("map_" + name + ".png"));
    const int prec = s.a < 3 ? 1 : 3;
    report << std::fixed << std::setprecision(prec) << "  " << std::setw(4) << name << ": peak (" << m.peakA << ", " << m.peakB
           << "), error to truth (" << ea << ", " << eb << "), " << std::setprecision(2) << reproj << " px, max F "
           << std::setprecision(3) << m.maxFitness << ", " << std::setprecision(2) << m.seconds << " s\n";
    if (onMap)
      onMap();
  }
  const core::FitnessDetail atTruth = fit.evaluateDetail(truth);
  r.fitnessAtTruth = atTruth.fitness;
  std::vector<std::vector<core::PointScore>> scores;
  nlohmann::json counts; // a pair's "left" and "right"; other rigs' "camera_0", "camera_1", ...
  const std::vector<std::string> names = cameraLabels(images.size(), "");
  for (std::size_t k = 0; k < images.size(); ++k) {
    scores.push_back(fit.pointScores(truth, static_cast<int>(k)));
    std::string key = names[k];
    std::replace(key.begin(), key.end(), ' ', '_');
    counts[key] = countsJson(atTruth.counts[k]);
  }
  io::writeImage(drawCameras(images, scores, cameraLabels(images.size(), "model at the truth, ")), files.stage("truth_overlay.png"));
  const nlohmann::json summary{{"source", source},
                               {"truth", {truth.x, truth.y, truth.z, truth.e1, truth.e2, truth.e3}},
                               {"model_points", modelPoints},
                               {"fitness_at_truth", atTruth.fitness},
                               {"counts_at_truth", counts},
                               {"kernel", fit.kernelName()},
                               {"grids", grids},
                               {"time_s", r.seconds}};
  r.summaryJson = summary.dump(2) + "\n";
  io::writeTextFile(files.stage("summary.json"), r.summaryJson);
  files.commit();
  r.text = report.str();
  return r;
}

} // namespace pm::report
