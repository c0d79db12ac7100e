//! pm-fitness-map: the fitness-distribution experiment of the paper (Sec. 5, Figs. 10, 11).
#include <cstdio>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/report/FitnessMapOutputs.h"
#include "pm/report/ObjectiveProfiles.h"
#include "pm/app/Options.h"
#include "pm/app/Progress.h"
#include "pm/app/RigImages.h"
#include "pm/core/Error.h"
#include "pm/core/StereoFitness.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/lab/StillPair.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

//! pm-fitness-map's options.
struct Options
{
  std::string out, target = "C04", left, right, modelPath, pose = "0,0,500,0,0,0";
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  std::vector<std::string> images; // --camera-images: one per camera of the rig
  bool quiet = false, profiles = false, allTargets = false;
  pm::app::LabModelChoice lab;
  pm::sim::SceneParams sp;
  pm::core::FitnessParams fp;
  double posStep = 1, epsStep = 0.01, reliefScale = 1;
};

void addOptions(CLI::App &app, Options &o)
{
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", o.target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  auto *optL = app.add_option("--left", o.left, "left image of a user's stereo pair");
  auto *optR = app.add_option("--right", o.right, "right image of a user's stereo pair");
  auto *optI = app.add_option("--camera-images", o.images, "a user's still frame of any rig: one image per camera of --rig, in its order");
  auto *optM = app.add_option("--model", o.modelPath, "photo-model file (with --left/--right or --camera-images)");
  optL->needs(optR)->needs(optM)->excludes(optTarget)->excludes(optI);
  optR->needs(optL);
  optI->needs(optM)->excludes(optTarget);
  app.add_option("--pose", o.pose, "reference pose x,y,z,eps1,eps2,eps3: where the simulated toy is, or the truth of the "
                                   "user's images; the variables not on a grid are held there");
  app.add_option("--rig", o.rigPath, "rig file: a stereo rig, or one to four cameras");
  app.add_option("--pos-step", o.posStep, "grid step of x, y, z (mm)")->check(CLI::Range(0.1, 50.0));
  app.add_option("--eps-step", o.epsStep, "grid step of eps (quaternion vector)")->check(CLI::Range(0.001, 0.1));
  pm::app::addLabModelOptions(app, o.lab);
  app.add_option("--relief-scale", o.reliefScale, "simulator: scale of the toy's relief (0: flat)")->check(CLI::Range(0.0, 3.0));
  pm::app::addModelOptions(app, o.lab.photo);
  pm::app::addSceneOptions(app, o.sp);
  pm::app::addFitnessOptions(app, o.fp);
  app.add_flag("--quiet", o.quiet, "no progress, no summary on stdout");
  app.add_flag("--profiles", o.profiles, "also the hue fitness and the precise stage's objective along turns of +-6 deg about "
                                         "each axis at the reference pose (an all-around model): profiles.png, profiles.csv");
  app.add_flag("--all-targets", o.allTargets, "run the 12 simulated targets, each into DIR/<code>/, and write the table "
                                              "peaks.md / peaks.csv of their peak errors")
      ->excludes(optTarget)
      ->excludes(optL)
      ->excludes(optI);
}

//! A user's images (\e code empty; the reference pose their truth) or the simulator's of lab target \e code at \e ref, one per camera of \e rig.
pm::lab::StillPair loadPair(const Options &o, const std::string &code, const pm::core::Phi &ref, const pm::core::CameraRig &rig)
{
  if (code.empty()) {
    const std::vector<std::string> files = pm::app::stillImagesFor(rig, o.images, o.left, o.right);
    pm::lab::StillPair p = pm::lab::loadStillPair(files, o.modelPath);
    pm::lab::requireSameSize(p, files);
    p.truth = ref;
    return p;
  }
  pm::sim::TargetShape shape = pm::sim::makeTarget(code);
  shape.scaleRelief(o.reliefScale);
  return pm::lab::renderStillPair(shape, ref, rig, o.sp, o.lab);
}

//! One experiment: the four maps of one frame of the rig and model (and its profiles), into \e dir.
pm::report::FitnessMapsResult mapOne(const Options &o, const pm::core::CameraRig &rig, const pm::core::Phi &ref, const std::string &code,
                                     const std::string &dir, bool silent)
{
  const pm::lab::StillPair p = loadPair(o, code, ref, rig);
  pm::core::StereoFitness fit(rig, p.model, o.fp);
  const pm::core::CameraImages images = p.view();
  fit.setImages(images.data());
  const std::vector<pm::core::FitnessMapSpec> specs = pm::core::paperFitnessMaps(o.posStep, o.epsStep);
  pm::app::Progress progress("fitness maps", specs.size(), silent);
  const pm::report::FitnessMapsResult r =
      pm::report::writeFitnessMaps(dir, fit, p.model.size(), p.truth, specs, p.source, images, [&] { progress.step(); });
  progress.finish();
  if (o.profiles && p.model.hasContours()) { // beside the maps, in the same folder
    pm::precise::PreciseStage precise(rig, p.model);
    precise.setImages(images);
    pm::io::StagedFiles more(dir);
    const pm::report::ProfileResult pr = pm::report::writeObjectiveProfiles(more, fit, precise, p.truth, 6.0, 0.25);
    more.commit();
    if (!silent)
      std::cout << "profiles along turns at the reference pose:\n" << pr.text;
  } else if (o.profiles) {
    throw pm::core::Error("--profiles needs a model with outlines (an all-around model, version 5)");
  }
  if (!silent)
    std::cout << "fitness maps of " << p.source << " (" << p.model.size() << " model points)\n"
              << r.text << "  all four in " << std::setprecision(2) << r.seconds << " s, written to " << dir << "/" << std::endl;
  return r;
}

//! --all-targets: the maps of the 12 targets, and a table of their peak errors.
int mapAll(const Options &o, const pm::core::CameraRig &rig, const pm::core::Phi &ref)
{
  pm::io::StagedFiles files(o.out);
  std::ostringstream md, csv;
  md << "| target | points | F(truth) | x | y (x-y) | y (y-z) | z | eps1 | eps2 (e1-e2) | eps2 (e2-e3) | eps3 | maps s |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "target,points,fitness_at_truth,dx,dy_xy,dy_yz,dz,de1,de2_e1e2,de2_e2e3,de3,time_s\n";
  nlohmann::json all = nlohmann::json::array();
  pm::app::Progress progress("targets", pm::sim::targetCatalog().size(), o.quiet);
  for (const auto &info : pm::sim::targetCatalog()) {
    const pm::report::FitnessMapsResult s = mapOne(o, rig, ref, info.code, files.dir() + "/" + info.code, true);
    auto e = [&](const char *grid, int k) { return k == 0 ? s.grid(grid).errorA : s.grid(grid).errorB; };
    char row[512];
    std::snprintf(row, sizeof row, "| %s %s | %d | %.3f | %+.1f | %+.1f | %+.1f | %+.1f | %+.3f | %+.3f | %+.3f | %+.3f | %.2f |\n",
                  info.code.c_str(), info.name.c_str(), static_cast<int>(s.modelPoints), s.fitnessAtTruth, e("xy", 0), e("xy", 1),
                  e("yz", 0), e("yz", 1), e("e1e2", 0), e("e1e2", 1), e("e2e3", 0), e("e2e3", 1), s.seconds);
    md << row;
    std::snprintf(row, sizeof row, "%s,%d,%.4f,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f\n", info.code.c_str(),
                  static_cast<int>(s.modelPoints), s.fitnessAtTruth, e("xy", 0), e("xy", 1), e("yz", 0), e("yz", 1), e("e1e2", 0),
                  e("e1e2", 1), e("e2e3", 0), e("e2e3", 1), s.seconds);
    csv << row;
    all.push_back({{"target", info.code}, {"summary", nlohmann::json::parse(s.summaryJson)}});
    progress.step();
  }
  progress.finish();
  pm::io::writeTextFile(files.stage("peaks.md"), md.str());
  pm::io::writeTextFile(files.stage("peaks.csv"), csv.str());
  pm::io::writeTextFile(files.stage("summary.json"), nlohmann::json{{"targets", all}}.dump(2) + "\n");
  files.commit();
  if (!o.quiet)
    std::cout << "peak errors (peak - truth; mm and quaternion vector) of the 12 targets:\n" << md.str() << std::flush;
  return 0;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"The fitness-distribution experiment of the paper (Sec. 5, Figs. 10, 11): the stereo fitness F on four "
               "2-D grids, x-y and y-z (1 mm steps over x, y in [-180, 180], z in [320, 680]) and eps1-eps2, eps2-eps3 "
               "(0.01 steps over [-0.37, 0.37]), the other variables held at the reference pose. Works on the simulator "
               "(--target) or on a user's images (--left, --right or --camera-images, --rig, --model): the rig's "
               "cameras, one or more. Writes a CSV and a PNG heat map "
               "per grid and summary.json.",
               "pm-fitness-map"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);

  return pm::app::run(app, argc, argv, [&] {
    const auto v = pm::app::parseNumbers(o.pose, 6, "--pose");
    const pm::core::Phi ref{v[0], v[1], v[2], v[3], v[4], v[5]};
    const pm::core::CameraRig rig = pm::io::loadCameraRig(o.rigPath);
    if (o.allTargets)
      return mapAll(o, rig, ref);
    const bool userImages = !o.left.empty() || !o.images.empty();
    mapOne(o, rig, ref, userImages ? std::string() : o.target, o.out, o.quiet);
    return 0;
  });
}
