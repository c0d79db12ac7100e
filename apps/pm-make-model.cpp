//! pm-make-model: builds a photo-model (Fig. 4 of the paper) from two photos or from the simulator.
#include <chrono>
#include <iostream>

#include "pm/app/App.h"
#include "pm/app/Progress.h"
#include "pm/lab/SilhouetteTruth.h"
#include "pm/trust/PassCalibration.h"
#include "pm/app/Options.h"
#include "pm/report/ModelOutputs.h"
#include "pm/report/AllAroundOutputs.h"
#include "pm/capture/VideoCaptureSource.h"
#include "pm/core/Error.h"
#include "pm/io/CameraFile.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/LabPass.h"
#include "pm/lab/ModelMaking.h"
#include "pm/lab/SurfaceTruth.h"
#include "pm/lab/TrustCache.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassRig.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ArmPassPlan.h"
#include "pm/robot/SteppedArm.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

namespace {

//! pm-make-model's options.
struct Options
{
  std::string out, target = "C12", background, photo, texture, intrinsics, cameraName = "left";
  std::string leftBg, rightBg, leftPhoto, rightPhoto, leftSource, rightSource;
  long backgroundFrame = 0, photoFrame = -1;
  bool stereo = false, flat = false, quiet = false, allAround = false;
  pm::model::StereoModelParams smp;
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  double distanceMm = 500, widthMm = 150, depthMm = 20, viewTurnDeg = 0;
  pm::model::PhotoModelParams mp;
  pm::sim::SceneParams sp;
  std::string viewsDir, robotName = "pa10";
  pm::model::PassPlan plan;
  pm::model::AllAroundParams ap;
  bool noTrustCalibration = false;
};

//! The options of the flat model's photos, the stereo model's pairs (files or live) and the simulator's targets; returns those the all-around options exclude.
std::vector<CLI::Option *> addPhotoOptions(CLI::App &app, Options &o)
{
  auto *optTarget = app.add_option("--target", o.target, "simulated target C01..C12 or R1..R3 (used when no photos are given)");
  auto *optBg = app.add_option("--background", o.background, "photo of the background alone (PNG/JPEG)");
  auto *optPhoto = app.add_option("--photo", o.photo, "photo of the target on that background (PNG/JPEG)");
  optBg->needs(optPhoto);
  optPhoto->needs(optBg);
  auto *optTex = app.add_option("--texture", o.texture, "simulate a target from this image (PNG/JPEG, alpha = outline)");
  optTex->excludes(optBg)->excludes(optTarget);
  optTarget->excludes(optBg);
  auto *optLB = app.add_option("--left-background", o.leftBg, "stereo: the left camera's photo of the background alone");
  auto *optRB = app.add_option("--right-background", o.rightBg, "stereo: the right camera's photo of the background alone");
  auto *optLP = app.add_option("--left-photo", o.leftPhoto, "stereo: the left camera's photo of the target (same hand pose)");
  auto *optRP = app.add_option("--right-photo", o.rightPhoto, "stereo: the right camera's photo of the target");
  for (auto *a : {optLB, optRB, optLP, optRP}) {
    for (auto *q : {optLB, optRB, optLP, optRP})
      if (q != a)
        a->needs(q);
    a->excludes(optBg)->excludes(optTarget)->excludes(optTex);
  }
  auto *optLS = app.add_option("--left-source", o.leftSource, "stereo, live: the left camera through OpenCV's VideoCapture "
                                                             "(device index, V4L2 path, video file or GStreamer pipeline)");
  auto *optRS = app.add_option("--right-source", o.rightSource, "stereo, live: the right camera, the same way");
  app.add_option("--background-frame", o.backgroundFrame, "live: the pair (counted from 0) that shows the backdrop alone")
      ->check(CLI::Range(0L, 100000000L))->needs(optLS);
  app.add_option("--photo-frame", o.photoFrame, "live: the pair that shows the target (later than the background's; "
                                                "without it, on a terminal, press Enter when the target is in place)")
      ->check(CLI::Range(0L, 100000000L))->needs(optLS);
  optLS->needs(optRS)->excludes(optLB)->excludes(optTarget)->excludes(optTex);
  optRS->needs(optLS);
  auto *optStereo = app.add_flag("--stereo", o.stereo, "simulator: the stereo model (the rig's two cameras, depth per point)");
  auto *optFlat = app.add_flag("--flat", o.flat, "simulator: the paper's flat model (two photos face-on) instead of the all-around one");
  optFlat->excludes(optStereo)->excludes(optTex)->excludes(optBg)->excludes(optLB)->excludes(optLS);
  app.add_flag("--right-view", o.smp.rightView, "stereo: add the right camera's own view (S_in and S_out sampled in the "
               "right photo, scored in the right camera; a version 3 model file)");
  app.add_option("--view-turn-deg", o.viewTurnDeg, "simulator, --stereo: four further photo pairs with the hand turned by "
                 "this about its x and y axes around the toy (a multi-view model; 0: one pair)")
      ->check(CLI::Range(0.0, 45.0));
  optStereo->excludes(optBg);
  return {optBg, optTex, optLB, optLS, optStereo, optFlat, optTarget};
}

void addPhotoModelOptions(CLI::App &app, Options &o)
{
  app.add_option("--backdrop-mm", o.smp.backdropMm, "stereo: the backdrop's distance from the left camera (0: measured "
                 "from the background pair; give it for a plain backdrop)")->check(CLI::NonNegativeNumber);
  app.add_option("--max-relief-mm", o.smp.maxReliefMm, "stereo: search depths this far in front of the backdrop")
      ->check(CLI::Range(1.0, 2000.0));
  app.add_option("--min-matched", o.smp.minMatchedFraction, "stereo: refuse the model when fewer S_in points match")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--width-mm", o.widthMm, "with --texture: the image's physical width (mm)")->check(CLI::PositiveNumber);
  app.add_option("--depth-mm", o.depthMm, "with --texture: relief of the default dome (mm, 0 = flat)")->check(CLI::NonNegativeNumber);
  app.add_option("--distance-mm", o.distanceMm, "distance from the camera to the target when the photo was taken (mm)")
      ->check(CLI::PositiveNumber);
  auto *optXml = app.add_option("--intrinsics", o.intrinsics, "intrinsics file of the photo camera (photos mode): ViSP XML, OpenCV YAML/XML or ROS camera_info; its lens distortion is corrected");
  app.add_option("--camera-name", o.cameraName, "camera name in --intrinsics")->needs(optXml);
  app.add_option("--rig", o.rigPath, "rig file: a stereo rig, or for --all-around and --views one camera or more (one camera: each view's "
                 "second image after a side step of the hand, docs/camera-rigs.md); its first camera takes the photos when --intrinsics is not given");
  pm::app::addModelOptions(app, o.mp);
  pm::app::addSceneOptions(app, o.sp);
  app.add_flag("--quiet", o.quiet, "print nothing on success");
}

//! The all-around model's options; \e others: the options it excludes (addPhotoOptions'), the last one --target.
void addAllAroundOptions(CLI::App &app, Options &o, const std::vector<CLI::Option *> &others)
{
  auto *optViews = app.add_option("--views", o.viewsDir, "all-around: a pass of the hand around the target, as a views folder "
                                  "(left_%02d.png, right_%02d.png, background_left_%02d.png, background_right_%02d.png, "
                                  "pose_fPh_%02d.yaml for k = 0, 1, ...), taken by --rig");
  auto *optAA = app.add_flag("--all-around", o.allAround, "simulator: the arm (--robot) walks the rig around --target (a pass of "
                             "--pass-views hand poses), the all-around model is built from it and the pass kept in OUT/views "
                             "(the default for --target; kept for older command lines)");
  pm::app::addRobotOption(app, o.robotName);
  app.add_option("--pass-views", o.plan.views, "all-around, simulator: hand poses of the pass")->check(CLI::Range(6, 200));
  app.add_option("--pass-rings-deg", o.plan.ringsDeg, "all-around, simulator: the pass's rings, their angles from the rest axis (deg; "
                 "the views spread over them in proportion to the angle)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 80.0));
  app.add_option("--backdrop-hue", o.ap.backdropHueDeg, "all-around: a plain backdrop of this hue (deg) replaces the "
                 "background images (none needed in --views; the lab makes no second pass)")->check(CLI::Range(0.0, 359.999));
  app.add_option("--viewpoints", o.ap.viewpoints.count, "all-around: viewing directions of the model (K)")->check(CLI::Range(1, 5000));
  app.add_option("--min-inside-px", o.ap.viewpoints.inMinInsidePx, "all-around: the model's S_in points at least this far inside each viewpoint's outline through a sharp camera (px; raised by the blur the pass's photos show, docs/model-outline.md)")->check(CLI::Range(0.0, 50.0));
  app.add_flag("--no-trust-calibration", o.noTrustCalibration, "all-around: the model's trust not calibrated from its pass (the "
               "shipped confidence and sigmas; faster). By default the pass's views, each held out of a model built without it, "
               "teach the confidence what right poses read through this camera (trust_tries.csv, docs/trust.md)");
  app.add_flag("--refine-outlines", o.ap.surface.refineOutlines, "all-around: the outlines to a fraction of a pixel (sub-pixel "
               "silhouettes, the surface moved onto every view's outline; docs/model-outline.md)");
  for (auto *a : {optViews, optAA})
    for (std::size_t k = 0; k + 1 < others.size(); ++k)
      a->excludes(others[k]);
  optViews->excludes(optAA)->excludes(others.back());
}

//! The model's trust calibrated from its own pass (pm::trust, through the test suite's cache when PM_LAB_CACHE is set); returns the tries as a table (trust_tries.csv).
std::string calibrate(const Options &o, const pm::core::CameraRig &rig, const std::vector<pm::model::PassView> &pass, pm::model::AllAroundBuild &b,
                      const pm::model::PassMeasurements &measured)
{
  if (o.noTrustCalibration)
    return "";
  pm::app::Progress progress("calibrating trust", pm::trust::calibrationSteps(pass.size()), o.quiet);
  const pm::lab::LabTrust t = pm::lab::calibrateLabTrust(rig, pass, o.ap, measured, b.model, [&] { progress.step(); });
  progress.finish();
  b.model.trust = t.trust;
  if (!t.trust.measured && !o.quiet)
    std::cerr << "note: trust not calibrated from the pass: " << t.why << " (the shipped confidence is used)" << std::endl;
  return t.triesCsv;
}

//! trust_tries.csv when the trust was calibrated.
std::vector<std::pair<std::string, std::string>> moreFiles(const std::string &tries)
{
  if (tries.empty())
    return {};
  return {{"trust_tries.csv", tries}};
}

//! The all-around model from a views folder, or from the lab's pass (then checked against the toy).
int makeAllAround(const Options &o)
{
  const pm::core::CameraRig cameras = pm::io::loadCameraRig(o.rigPath); // the tracker's rig: the trust is calibrated through it
  const pm::core::StereoRig rig = pm::model::passRig(cameras);          // the pass's pairs (one camera: after the side step)
  if (!o.viewsDir.empty()) {
    const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder(o.viewsDir, rig, o.ap.carving.minViews, o.ap.backdropHueDeg < 0);
    const std::string source = "views " + o.viewsDir;
    pm::model::PassMeasurements measured;
    pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass, o.ap, measured);
    const std::string tries = calibrate(o, cameras, pass, b, measured);
    pm::report::writeAllAroundModel(b, pass, rig, o.out, source, false, "", moreFiles(tries));
    if (!o.quiet)
      std::cout << pm::report::describeAllAroundModel(b, source, o.out, false) << "  " << pm::trust::describe(b.model.trust) << "\n" << std::flush;
    return 0;
  }
  // The lab: the arm's pass, the model, and the model checked against the toy (the renderer's truth).
  const pm::sim::TargetShape shape = pm::sim::makeTarget(o.target);
  const pm::sim::Scene scene(shape, o.sp);
  pm::robot::SteppedArm arm(pm::robot::makeArmModel(o.robotName));
  const pm::lab::LabPass lp = pm::lab::runLabPass(scene, rig, o.plan, arm, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), o.ap.backdropHueDeg < 0);
  const std::string source = "simulator, target " + shape.info.code + " (" + shape.info.name + "), " + arm.model().title() + " pass";
  if (!o.quiet)
    for (const pm::model::PassDirection &d : lp.leftOut)
      std::cout << "pass: " << pm::robot::describeLeftOut(d, arm.model().title()) << "\n";
  pm::model::PassMeasurements measured;
  pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, lp.views, o.ap, measured);
  const std::string tries = calibrate(o, cameras, lp.views, b, measured);
  const pm::lab::SurfaceTruth truth = pm::lab::checkSurface(scene, b, lp.fMo.inverse() * b.fMm, rig.left.cam);
  const std::string silhouettes = pm::lab::checkSilhouettes(scene, lp.views, lp.fMo, b, rig).text;
  pm::report::writeAllAroundModel(b, lp.views, rig, o.out, source, true, pm::lab::surfaceTruthJson(truth), moreFiles(tries));
  if (!o.quiet)
    std::cout << pm::report::describeAllAroundModel(b, source, o.out, true) << silhouettes << truth.text << "  " << pm::trust::describe(b.model.trust) << "\n"
              << std::flush;
  return 0;
}

//! The stereo model from the rig's two pairs, files or live.
pm::report::ModelOutputs makeStereo(const Options &o)
{
  const pm::core::StereoRig rig = pm::io::loadRig(o.rigPath);
  pm::capture::ModelPairs pairs;
  std::string left = o.leftPhoto, right = o.rightPhoto;
  if (!o.leftSource.empty()) {
    pm::capture::VideoCaptureSource src(o.leftSource, o.rightSource);
    pairs = pm::capture::grabModelPairs(src, o.backgroundFrame, o.photoFrame);
    left = o.leftSource;
    right = o.rightSource;
  } else {
    pairs.background.right = pm::io::readColorImage(o.rightBg);
    pairs.photo.right = pm::io::readColorImage(o.rightPhoto);
    pairs.background.left = pm::io::readColorImage(o.leftBg);
    pairs.photo.left = pm::io::readColorImage(o.leftPhoto);
  }
  pm::model::StereoModelParams smp = o.smp;
  smp.photo = o.mp;
  return pm::lab::stereoModelFromPhotos(rig, pairs, smp, "stereo photos " + left + " + " + right);
}

//! The paper's flat model from its two photos, through the lens of --intrinsics (else the rig's left camera).
pm::report::ModelOutputs makeFlat(const Options &o)
{
  vpImage<vpRGBa> bg = pm::io::readColorImage(o.background), tg = pm::io::readColorImage(o.photo);
  pm::core::PinholeCamera cam;
  if (o.intrinsics.empty()) {
    cam = pm::io::loadRig(o.rigPath).left;
  } else if (bg.getWidth() == tg.getWidth() && bg.getHeight() == tg.getHeight()) { // else flatModelFromPhotos says so
    cam = pm::io::readCameraFile(o.intrinsics, o.cameraName, bg.getWidth(), bg.getHeight()).camera;
  }
  return pm::lab::flatModelFromPhotos(std::move(bg), std::move(tg), cam, o.distanceMm, o.mp, o.background, o.photo);
}

//! A flat or stereo model from the simulator's photos of a lab target or of --texture.
pm::report::ModelOutputs makeSimulated(const Options &o)
{
  const pm::core::StereoRig rig = pm::io::loadRig(o.rigPath);
  const pm::sim::TargetShape shape =
      o.texture.empty() ? pm::sim::makeTarget(o.target) : pm::sim::targetFromImage(pm::io::readColorImage(o.texture), o.widthMm, o.depthMm, o.texture);
  const std::string source = o.texture.empty() ? "simulator, target " + shape.info.code + " (" + shape.info.name + ")"
                                               : "simulator, texture " + o.texture;
  pm::model::StereoModelParams smp = o.smp;
  smp.photo = o.mp;
  return pm::lab::simulatedModel(pm::sim::Scene(shape, o.sp), rig, o.distanceMm, o.stereo, smp, o.viewTurnDeg, source);
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Builds a photo-model. All-around (the default, as in the lab programs): from a pass of the hand around the "
               "target, a views folder taken by --rig (--views), or the simulator's pass (--target); writes model.json, "
               "model.ply (the carved surface), contact.png (views beside the model seen from them), silhouettes.png and "
               "summary.json (and views/ in the lab). The paper's (Fig. 4), flat: a photo of the background alone and a "
               "photo of the target on it, taken by one camera at a known distance. Stereo (with depth): the rig's "
               "two cameras take the background pair, then the photo pair, from one hand pose (--left-background, "
               "--right-background, --left-photo, --right-photo, --rig); every point gets its relief by stereo "
               "matching and no distance is needed. Or from the simulator, which takes the photos of a lab target "
               "(--target --flat, --target --stereo) or of a user's image (--texture). Writes model.json, "
               "overlay.png (S_in and S_out on the photo), model.png, summary.json and, for a stereo model, "
               "depth.png (the relief); and, unless they are --background and --photo, the (left) photos it was made "
               "from (photo_background.png, photo_target.png).",
               "pm-make-model"};
  app.option_defaults()->always_capture_default();
  Options o;
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  const std::vector<CLI::Option *> photoOptions = addPhotoOptions(app, o);
  addPhotoModelOptions(app, o);
  addAllAroundOptions(app, o, photoOptions);

  return pm::app::run(app, argc, argv, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    // The simulator's default: the all-around model (the lab programs' too); --flat, --stereo and --texture the others.
    o.allAround = o.allAround || (o.viewsDir.empty() && o.background.empty() && o.leftBg.empty() && o.leftSource.empty() &&
                                  o.texture.empty() && !o.stereo && !o.flat);
    if (o.allAround || !o.viewsDir.empty())
      return makeAllAround(o);
    const pm::report::ModelOutputs m = !o.leftBg.empty() || !o.leftSource.empty() ? makeStereo(o)
                                       : !o.background.empty()                    ? makeFlat(o)
                                                                                  : makeSimulated(o);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const pm::report::ModelFigures fig = pm::report::writeModelOutputs(o.out, m, seconds);
    if (!o.quiet)
      std::cout << pm::report::describeModel(m, fig, o.out, seconds) << std::flush;
    return 0;
  });
}
