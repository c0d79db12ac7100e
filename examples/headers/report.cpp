// The usage examples of pm::report's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/report/AllAroundOutputs.h"
#include "pm/report/CalibrationOutputs.h"
#include "pm/report/DetectionOutputs.h"
#include "pm/report/FitnessMapOutputs.h"
#include "pm/report/LiveView.h"
#include "pm/report/ModelOutputs.h"
#include "pm/report/ObjectiveProfiles.h"
#include "pm/report/Overlay.h"
#include "pm/report/SurfaceDrawing.h"
#include "pm/report/TimePlot.h"

#include <cmath>
#include <iostream>
#include "pm/calib/BaselineCheck.h"
#include "pm/calib/RigCalibration.h"
#include "pm/calib/TagBoard.h"
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/precise/PreciseStage.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/StaticDetection.h"
#include "pm/calib/HandEye.h"
namespace pm_examples {

// AllAroundOutputs.h
void exampleAllAroundOutputs(const pm::model::AllAroundBuild &build, const std::vector<pm::model::PassView> &pass, const pm::core::StereoRig &rig)
{
  pm::io::StagedFiles out("model_dir");
  pm::report::writeAllAroundPictures(build, pass, rig, out);
  out.commit();
}

// SurfaceDrawing.h
void exampleSurfaceDrawing(const pm::model::AllAroundBuild &build, const vpHomogeneousMatrix &mMc, const pm::core::StereoRig &rig)
{
  const vpImage<vpRGBa> seen = pm::report::drawSurface(build.surface, mMc, rig.left.cam, 640, 480);
}

// CalibrationOutputs.h
void exampleCalibrationOutputs(const std::vector<pm::calib::StereoImagePair> &pairs, const pm::calib::TagBoard &board)
{
  pm::report::RigCalibrationOutputs o;
  o.source = std::to_string(pairs.size()) + " image pairs";
  o.board = board.describe();
  o.calibration = pm::calib::calibrateRig(pairs, board);
  pm::report::writeRigCalibration("rig", o);
  std::cout << pm::report::describeRigCalibration(o, "rig");
}

// CalibrationOutputs.h
void exampleCalibrationOutputs2(const pm::core::StereoRig &rig, const pm::calib::TagBoard &board)
{
  pm::calib::BaselineCheck check(rig, board);
  // ... check.add(left, right, name) for every pair
  pm::report::BaselineCheckOutputs o;
  o.source = "10 pairs";
  o.pattern = board.describe();
  o.rigPath = "rig.json";
  o.result = check.result();
  o.left = check.firstLeft();
  o.right = check.firstRight();
  pm::report::writeBaselineCheck("check", o);
  std::cout << pm::report::describeBaselineCheck(o);
}

// DetectionOutputs.h
void exampleDetectionOutputs(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  pm::tracker::PhotoModelTracker tracker(rig, model);
  tracker.initialize();
  pm::report::DetectionOutputs o;
  o.source = "my pair";
  o.detection = pm::tracker::detectStatic(tracker, {left, right}, pm::tracker::DetectionParams());
  pm::report::writeDetection("detect", o, tracker.fitness(), {left, right});
  std::cout << pm::report::describeDetection(o, "detect");
}

// FitnessMapOutputs.h
void exampleFitnessMapOutputs(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right,
                              const pm::core::Phi &truth)
{
  pm::core::StereoFitness fit(rig, model);
  const pm::core::CameraImages images(left, right); // a pair; CameraImages(image) for one camera
  fit.setImages(images.data());
  const pm::report::FitnessMapsResult r =
      pm::report::writeFitnessMaps("maps", fit, model.size(), truth, pm::core::paperFitnessMaps(), "my pair", images);
  std::cout << r.text;
}

// LiveView.h
void exampleLiveView(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR, const pm::core::Phi &phi)
{
  pm::core::StereoFitness fitness(rig, model);      // rig, model: pm/io/RigFile.h, pm/io/PhotoModelFile.h
  pm::report::LiveView view;
  view.open("pm-track");                      // false, said on stderr, when there is no X display
  fitness.setImages(IL, IR);                  // each new stereo pair, vpImage<vpRGBa>
  view.show(IL, IR, fitness.pointScores(phi, 0), fitness.pointScores(phi, 1), "tracking, F 0.91, 3.2 ms");
  if (view.isOpen())
    view.capture("screen.png");               // what the X server shows, read back from the window
}

// ModelOutputs.h
void exampleModelOutputs(const vpImage<vpRGBa> &bg, const vpImage<vpRGBa> &toy, const vpCameraParameters &cam)
{
  pm::report::ModelOutputs m;
  m.source = "photos bg.png + toy.png";
  m.build = pm::model::buildPhotoModel(bg, toy, cam, 500);
  m.photo = toy;
  m.background = bg;
  pm::report::writeModelOutputs("model", m, 0.5);
}

// ObjectiveProfiles.h
void exampleObjectiveProfiles(const pm::core::StereoFitness &fitness, pm::precise::PreciseStage &precise, const pm::core::Phi &truth)
{
  pm::io::StagedFiles files("out");
  const pm::report::ProfileResult r = pm::report::writeObjectiveProfiles(files, fitness, precise, truth, 6.0, 0.25);
  files.commit();
}

// Overlay.h
void exampleOverlay(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR, const pm::core::Phi &phi)
{
  pm::core::StereoFitness fitness(rig, model);        // rig, model: pm/io/RigFile.h, pm/io/PhotoModelFile.h
  fitness.setImages(IL, IR);                    // the stereo pair, vpImage<vpRGBa>
  const vpImage<vpRGBa> both = pm::report::sideBySide(
      pm::report::drawPointScores(IL, fitness.pointScores(phi, 0), "model at phi, left"),
      pm::report::drawPointScores(IR, fitness.pointScores(phi, 1), "right"));
  pm::io::writeImage(both, "scores.png");       // pm/io/ImageFile.h
}

// Overlay.h
void exampleOverlay2(const pm::tracker::PhotoModelTracker &tracker, const vpImage<vpRGBa> &IL)
{
  const pm::precise::PreciseStage &stage = *tracker.preciseStage();
  vpImage<vpRGBa> left = IL;
  pm::report::drawCorrespondenceLines(left, stage.lines(0));
}

// TimePlot.h
void exampleTimePlot()
{
  pm::report::Series error;
  error.name = "x error";
  error.color = vpRGBa(220, 40, 40);
  for (int k = 0; k <= 100; ++k) {
    error.t.push_back(0.1 * k);                    // s
    error.y.push_back(5.0 * std::exp(-0.05 * k));  // mm
  }
  pm::report::Panel panel;
  panel.title = "position error";
  panel.yLabel = "mm";
  panel.series.push_back(error);
  panel.band = 1.0;                                // the +-1 mm tolerance, shaded
  panel.marks.push_back(3.2);                      // converged at 3.2 s: a dotted line
  const vpImage<vpRGBa> figure = pm::report::drawTimePlots({panel}, 1, "pm-servo run"); // 520 x 336 px
  pm::io::writeImage(figure, "errors.png");        // pm/io/ImageFile.h
}

// ObjectiveProfiles.h
void exampleObjectiveProfilesFile(pm::io::StagedFiles &files, const pm::core::StereoFitness &fitness, pm::precise::PreciseStage &precise,
                                  const pm::core::Phi &truth)
{
  const pm::report::ProfileResult r = pm::report::writeObjectiveProfiles(files, fitness, precise, truth, 6.0, 0.25);
  std::cout << "F peaks " << r.axes[0].fitnessPeakDeg << " deg off the truth about x\n";
}

// CalibrationOutputs.h
void exampleCalibrationOutputs3(const std::vector<pm::calib::CalibrationView> &views, const pm::calib::ChessBoard &board,
                                const std::vector<vpHomogeneousMatrix> &cMo, const std::vector<vpHomogeneousMatrix> &fMh)
{
  pm::report::CameraCalibrationOutputs o;
  o.source = std::to_string(views.size()) + " images";
  o.board = board.describe();
  o.calibration = pm::calib::calibrateCamera(views, board);
  o.handEye = pm::calib::solveHandEye(cMo, fMh); // cMo from o.calibration.views, fMh from the robot
  o.calibration.camera.hMc = o.handEye->hMc;
  o.poseOnHand = "hand-eye from " + std::to_string(fMh.size()) + " hand poses";
  pm::report::writeCameraCalibration("rig", o);
  std::cout << pm::report::describeCameraCalibration(o, "rig");
}

// Overlay.h
void exampleOverlay3(const std::vector<vpImage<vpRGBa>> &images, const pm::core::StereoFitness &fitness, const pm::core::Phi &phi)
{
  const vpImage<vpRGBa> all = pm::report::drawCameras(pm::core::CameraImages::of(images),
                                                      {fitness.pointScores(phi, 0)}, pm::report::cameraLabels(images.size(), "found, "));
}

} // namespace pm_examples
