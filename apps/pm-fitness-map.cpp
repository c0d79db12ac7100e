//! pm-fitness-map: the fitness-distribution experiment of the paper (Sec. 5, Figs. 10, 11).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/report/HeatMap.h"
#include "pm/app/Options.h"
#include "pm/report/Overlay.h"
#include "pm/app/Progress.h"
#include "pm/core/Error.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/StereoFitness.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

const char *kVarNames[6] = {"x [mm]", "y [mm]", "z [mm]", "eps1", "eps2", "eps3"};
const char *kVarShort[6] = {"x", "y", "z", "e1", "e2", "e3"};

pm::report::Grid2D toGrid(const pm::FitnessMap &m)
{
  pm::report::Grid2D g;
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

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"The fitness-distribution experiment of the paper (Sec. 5, Figs. 10, 11): the stereo fitness F on four "
               "2-D grids, x-y and y-z (1 mm steps over x, y in [-180, 180], z in [320, 680]) and eps1-eps2, eps2-eps3 "
               "(0.01 steps over [-0.37, 0.37]), the other variables held at the reference pose. Works on the simulator "
               "(--target) or on a user's stereo pair (--left, --right, --rig, --model). Writes a CSV and a PNG heat map "
               "per grid and summary.json.",
               "pm-fitness-map"};
  app.option_defaults()->always_capture_default();
  std::string out, target = "C04", left, right, modelPath, pose = "0,0,500,0,0,0";
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  bool quiet = false;
  pm::app::LabModelChoice lab;
  pm::sim::SceneParams sp;
  pm::FitnessParams fp;
  double posStep = 1, epsStep = 0.01, reliefScale = 1;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  auto *optL = app.add_option("--left", left, "left image of a user's stereo pair");
  auto *optR = app.add_option("--right", right, "right image of a user's stereo pair");
  auto *optM = app.add_option("--model", modelPath, "photo-model file (with --left/--right)");
  optL->needs(optR)->needs(optM)->excludes(optTarget);
  optR->needs(optL);
  optM->needs(optL);
  app.add_option("--pose", pose, "reference pose x,y,z,eps1,eps2,eps3: where the simulated toy is, or the truth of the "
                                 "user's pair; the variables not on a grid are held there");
  app.add_option("--rig", rigPath, "stereo rig file");
  app.add_option("--pos-step", posStep, "grid step of x, y, z (mm)")->check(CLI::Range(0.1, 50.0));
  app.add_option("--eps-step", epsStep, "grid step of eps (quaternion vector)")->check(CLI::Range(0.001, 0.1));
  pm::app::addLabModelOptions(app, lab);
  app.add_option("--relief-scale", reliefScale, "simulator: scale of the toy's relief (0: flat)")->check(CLI::Range(0.0, 3.0));
  pm::app::addModelOptions(app, lab.photo);
  pm::app::addSceneOptions(app, sp);
  pm::app::addFitnessOptions(app, fp);
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");
  bool allTargets = false;
  app.add_flag("--all-targets", allTargets, "run the 12 simulated targets, each into DIR/<code>/, and write the table "
                                            "peaks.md / peaks.csv of their peak errors")
      ->excludes(optTarget)
      ->excludes(optL);

  return pm::app::run(app, argc, argv, [&] {
    const auto v = pm::app::parseNumbers(pose, 6, "--pose");
    const pm::Phi ref{v[0], v[1], v[2], v[3], v[4], v[5]};
    const vpHomogeneousMatrix hMo = pm::toHomogeneousMatrix(ref);
    const pm::StereoRig rig = pm::io::loadRig(rigPath);

    // One experiment: the four maps of one stereo pair and model, into \e dir.
    auto runOne = [&](const std::string &code, const std::string &dir, bool silent) {
      pm::PhotoModel model;
      vpImage<vpRGBa> IL, IR;
      pm::Phi truth = ref;
      std::string source;
      if (code.empty()) {
        IL = pm::io::readColorImage(left);
        IR = pm::io::readColorImage(right);
        if (IL.getWidth() != IR.getWidth() || IL.getHeight() != IR.getHeight())
          throw pm::Error("the left image '" + left + "' and the right image '" + right + "' differ in size (" +
                          std::to_string(IL.getWidth()) + "x" + std::to_string(IL.getHeight()) + " and " +
                          std::to_string(IR.getWidth()) + "x" + std::to_string(IR.getHeight()) + ")");
        model = pm::io::loadPhotoModel(modelPath);
        source = "stereo pair " + left + " + " + right + ", model " + modelPath;
      } else {
        pm::sim::TargetShape shape = pm::sim::makeTarget(code);
        shape.scaleRelief(reliefScale);
        const pm::sim::Scene scene(shape, sp);
        const pm::sim::SimulatedPhotoModel sm =
            pm::app::makeLabModel(scene, rig, lab);
        model = sm.build.model;
        truth = sm.truth(hMo);
        const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, 0);
        IL = im.left;
        IR = im.right;
        source = "simulator, target " + scene.target().info.code + " (" + scene.target().info.name + ")";
      }
      pm::StereoFitness fit(rig, model, fp);
      fit.setImages(IL, IR);

      pm::io::StagedFiles files(dir);
      nlohmann::json grids;
      const std::vector<pm::FitnessMapSpec> specs = pm::paperFitnessMaps(posStep, epsStep);
      pm::app::Progress progress("fitness maps", specs.size(), silent);
      double total = 0;
      std::ostringstream report;
      for (const auto &s : specs) {
        // The variables not on the grid are held at the truth (the model's true pose).
        const pm::FitnessMap m = pm::computeFitnessMap(fit, truth, s);
        total += m.seconds;
        const std::string name = std::string(kVarShort[s.a]) + kVarShort[s.b];
        const double ta = truth[s.a], tb = truth[s.b], ea = m.peakA - ta, eb = m.peakB - tb;
        pm::Phi peak = truth;
        peak[s.a] = m.peakA;
        peak[s.b] = m.peakB;
        const double reproj = fit.reprojectionRms(peak, truth);
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
          throw pm::Error("cannot write " + files.finalPath("map_" + name + ".csv"));
        std::ostringstream title;
        title << std::setprecision(3) << "F over " << kVarShort[s.a] << "-" << kVarShort[s.b] << ", max " << m.maxFitness;
        pm::io::writeImage(pm::report::drawHeatMap(toGrid(m), title.str(),
                                                {{ta, tb, "truth", vpRGBa(255, 255, 255), true},
                                                 {m.peakA, m.peakB, "peak", vpRGBa(230, 30, 30), false}}),
                           files.stage("map_" + name + ".png"));
        const int prec = s.a < 3 ? 1 : 3;
        report << std::fixed << std::setprecision(prec) << "  " << std::setw(4) << name << ": peak (" << m.peakA << ", "
               << m.peakB << "), error to truth (" << ea << ", " << eb << "), " << std::setprecision(2) << reproj
               << " px, max F " << std::setprecision(3) << m.maxFitness << ", " << std::setprecision(2) << m.seconds
               << " s\n";
        progress.step();
      }
      progress.finish();
      const pm::FitnessDetail atTruth = fit.evaluateDetail(truth);
      pm::io::writeImage(pm::report::sideBySide(pm::report::drawPointScores(IL, fit.pointScores(truth, 0), "model at the truth, left"),
                                             pm::report::drawPointScores(IR, fit.pointScores(truth, 1), "right")),
                         files.stage("truth_overlay.png"));
      auto countsJson = [](const pm::FitnessCounts &c) {
        return nlohmann::json{{"in_match", c.inMatch},         {"in_background", c.inBackground}, {"in_other", c.inOther},
                              {"in_off", c.inOff},             {"out_background", c.outBackground},
                              {"out_other", c.outOther},       {"out_off", c.outOff}};
      };
      const nlohmann::json summary{
          {"source", source},
          {"truth", {truth.x, truth.y, truth.z, truth.e1, truth.e2, truth.e3}},
          {"model_points", model.size()},
          {"fitness_at_truth", atTruth.fitness},
          {"counts_at_truth", {{"left", countsJson(atTruth.countsLeft)}, {"right", countsJson(atTruth.countsRight)}}},
          {"kernel", pm::StereoFitness::kernelName()},
          {"grids", grids},
          {"time_s", total}};
      pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
      files.commit();
      if (!silent)
        std::cout << "fitness maps of " << source << " (" << model.size() << " model points)\n"
                  << report.str() << "  all four in " << std::setprecision(2) << total << " s, written to "
                  << files.dir() << "/" << std::endl;
      return summary;
    };

    if (!allTargets) {
      runOne(left.empty() ? target : std::string(), out, quiet);
      return 0;
    }
    // All 12: a table of the peak errors.
    pm::io::StagedFiles files(out);
    std::ostringstream md, csv;
    md << "| target | points | F(truth) | x | y (x-y) | y (y-z) | z | eps1 | eps2 (e1-e2) | eps2 (e2-e3) | eps3 | maps s |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    csv << "target,points,fitness_at_truth,dx,dy_xy,dy_yz,dz,de1,de2_e1e2,de2_e2e3,de3,time_s\n";
    nlohmann::json all = nlohmann::json::array();
    pm::app::Progress progress("targets", pm::sim::targetCatalog().size(), quiet);
    for (const auto &info : pm::sim::targetCatalog()) {
      const nlohmann::json s = runOne(info.code, files.dir() + "/" + info.code, true);
      const auto &g = s.at("grids");
      auto e = [&](const char *grid, int k) { return g.at(grid).at("error_to_truth")[static_cast<std::size_t>(k)].get<double>(); };
      char row[512];
      std::snprintf(row, sizeof row, "| %s %s | %d | %.3f | %+.1f | %+.1f | %+.1f | %+.1f | %+.3f | %+.3f | %+.3f | %+.3f | %.2f |\n",
                    info.code.c_str(), info.name.c_str(), s.at("model_points").get<int>(), s.at("fitness_at_truth").get<double>(),
                    e("xy", 0), e("xy", 1), e("yz", 0), e("yz", 1), e("e1e2", 0), e("e1e2", 1), e("e2e3", 0),
                    e("e2e3", 1), s.at("time_s").get<double>());
      md << row;
      std::snprintf(row, sizeof row, "%s,%d,%.4f,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f\n", info.code.c_str(),
                    s.at("model_points").get<int>(), s.at("fitness_at_truth").get<double>(), e("xy", 0), e("xy", 1),
                    e("yz", 0), e("yz", 1), e("e1e2", 0), e("e1e2", 1), e("e2e3", 0), e("e2e3", 1), s.at("time_s").get<double>());
      csv << row;
      all.push_back({{"target", info.code}, {"summary", s}});
      progress.step();
    }
    progress.finish();
    pm::io::writeTextFile(files.stage("peaks.md"), md.str());
    pm::io::writeTextFile(files.stage("peaks.csv"), csv.str());
    pm::io::writeTextFile(files.stage("summary.json"), nlohmann::json{{"targets", all}}.dump(2) + "\n");
    files.commit();
    if (!quiet)
      std::cout << "peak errors (peak - truth; mm and quaternion vector) of the 12 targets:\n" << md.str() << std::flush;
    return 0;
  });
}
