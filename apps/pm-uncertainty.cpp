//! pm-uncertainty: is the tracker's reported 1-sigma uncertainty honest? (and, with --fit, its scales and floors)
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Progress.h"
#include "pm/compare/UncertaintyCalibration.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/TimePlot.h"

namespace {

//! "C12:1" as a run (the toy, RM-GA's seed).
pm::compare::UncertaintyRun parseRun(const std::string &s, long budget)
{
  const auto colon = s.find(':');
  pm::compare::UncertaintyRun r;
  r.target = s.substr(0, colon);
  try {
    if (colon != std::string::npos)
      r.seed = std::stoull(s.substr(colon + 1));
  } catch (const std::exception &) {
    throw pm::core::Error("run '" + s + "': expected TOY:SEED (e.g. C12:1)");
  }
  r.budget = budget;
  return r;
}

const char *kAxes[6] = {"x (mm)", "y (mm)", "z (mm)", "about x (deg)", "about y (deg)", "about z (deg)"};

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Measures whether the tracker's reported uncertainty (1-sigma per axis of the hand frame, mm and deg; "
               "TrackResult::uncertainty) is honest: random 6-DoF runs (600 frames at random poses, the all-around model, "
               "the precise stage) of chosen toys and RM-GA seeds; on each frame whose pose is the precise stage's, the "
               "true error per axis against the reported sigma. Of an honest sigma about 68 % of the errors fall within "
               "it. --fit fits the scales and floors (pm::UncertaintyModel) on --fit-runs and checks them on every run. "
               "Writes samples.csv, calibration.png (share within m sigma against m) and summary.json.",
               "pm-uncertainty"};
  app.option_defaults()->always_capture_default();
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  std::vector<std::string> fitRuns{"C12:1", "R2:1"}, checkRuns{"C12:2", "R2:2", "C08:1", "R1:1"};
  long budget = 1900;
  bool fit = false, quiet = false;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  app.add_option("--rig", rigPath, "stereo rig file");
  app.add_option("--fit-runs", fitRuns, "runs the fit is made on, TOY:SEED")->delimiter(',');
  app.add_option("--check-runs", checkRuns, "further runs it is checked on, TOY:SEED")->delimiter(',');
  app.add_option("--budget-evals", budget, "fitness evaluations per frame")->check(CLI::Range(100L, 100000000L));
  app.add_flag("--fit", fit, "fit the scales and floors on --fit-runs (else: measure the shipped ones)");
  app.add_flag("--quiet", quiet, "no progress, no table on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::core::StereoRig rig = pm::io::loadRig(rigPath);
    std::vector<pm::compare::UncertaintyRun> runs;
    for (const auto &s : fitRuns)
      runs.push_back(parseRun(s, budget));
    for (const auto &s : checkRuns)
      runs.push_back(parseRun(s, budget));
    pm::io::StagedFiles files(out);
    pm::app::Progress progress("random 6-DoF runs", 600 * runs.size(), quiet);
    std::vector<std::vector<pm::compare::UncertaintySample>> samples;
    for (const auto &r : runs)
      samples.push_back(pm::compare::collectUncertaintySamples(rig, r, [&] { progress.step(); }));
    progress.finish();
    pm::precise::UncertaintyModel model;
    if (fit)
      model = pm::compare::fitUncertainty({samples.begin(), samples.begin() + static_cast<long>(fitRuns.size())});

    std::ofstream csv(files.stage("samples.csv"));
    csv << "run,target,seed,frame,residual_px";
    for (const char *a : {"x", "y", "z", "rx", "ry", "rz"})
      csv << ",error_" << a << ",line_sigma_" << a << ",sigma_" << a;
    csv << "\n" << std::setprecision(6);
    nlohmann::json runsJson = nlohmann::json::array();
    std::vector<pm::report::Panel> panels(6);
    const vpRGBa colours[] = {vpRGBa(200, 40, 40), vpRGBa(40, 90, 200), vpRGBa(30, 150, 60), vpRGBa(190, 120, 0), vpRGBa(130, 50, 170), vpRGBa(0, 150, 160)};
    for (std::size_t a = 0; a < 6; ++a)
      panels[a] = {kAxes[a], "% within", {}, 0, {1.0}};
    for (std::size_t i = 0; i < runs.size(); ++i) {
      for (const auto &s : samples[i]) {
        const pm::precise::PoseUncertainty u = model.uncertainty(s.lineSigma, s.residualPx);
        csv << i << "," << runs[i].target << "," << runs[i].seed << "," << s.frame << "," << s.residualPx;
        for (std::size_t a = 0; a < 6; ++a)
          csv << "," << s.error[a] << "," << s.lineSigma[a] << "," << (a < 3 ? u.sigmaMm[a] : u.sigmaDeg[a - 3]);
        csv << "\n";
      }
      const std::string name = runs[i].target + ":" + std::to_string(runs[i].seed) + (i < fitRuns.size() ? " fit" : "");
      runsJson.push_back({{"name", name}, {"frames", samples[i].size()}, {"within_1_sigma", pm::compare::shareWithin(samples[i], model, 1.0)},
                          {"within_2_sigma", pm::compare::shareWithin(samples[i], model, 2.0)}});
      for (std::size_t a = 0; a < 6; ++a) {
        pm::report::Series c{name, colours[i % 6], {}, {}, false};
        for (int k = 0; k <= 30; ++k) {
          c.t.push_back(k / 10.0);
          c.y.push_back(100 * pm::compare::shareWithin(samples[i], model, k / 10.0)[a]);
        }
        panels[a].series.push_back(c);
      }
    }
    pm::report::Series gauss{"Gaussian", vpRGBa(0, 0, 0), {}, {}, false}; // drawn last: on top
    for (int k = 0; k <= 30; ++k) {
      gauss.t.push_back(k / 10.0);
      gauss.y.push_back(100 * std::erf(k / 10.0 / std::sqrt(2.0)));
    }
    for (auto &p : panels)
      p.series.push_back(gauss);
    csv.close();
    if (!csv)
      throw pm::core::Error("cannot write samples.csv");
    pm::io::writeImage(pm::report::drawTimePlots(panels, 3, "Share of true errors within m reported sigmas (black: a Gaussian, 68 % at m = 1)", "m (sigmas)", 560),
                       files.stage("calibration.png"));
    const nlohmann::json summary{{"model", {{"scale", model.scale}, {"floor", model.floor}, {"fitted", fit}}},
                                 {"axes", {"x mm", "y mm", "z mm", "about x deg", "about y deg", "about z deg"}},
                                 {"runs", runsJson}};
    pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
    files.commit();
    if (!quiet) {
      std::cout << std::fixed << std::setprecision(3) << (fit ? "fitted" : "shipped") << " scale " << nlohmann::json(model.scale).dump()
                << " floor " << nlohmann::json(model.floor).dump() << "\nwithin 1 sigma (x, y, z, about x, y, z):\n";
      for (const auto &r : runsJson)
        std::cout << "  " << std::setw(18) << std::left << r["name"].get<std::string>() << " " << r["within_1_sigma"].dump() << "\n";
      std::cout << "written to " << files.dir() << "/ (samples.csv, calibration.png, summary.json)" << std::endl;
    }
    return 0;
  });
}
