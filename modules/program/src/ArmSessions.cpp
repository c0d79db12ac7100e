#include "pm/program/ArmSessions.h"

#include <atomic>
#include <cstdio>
#include <csignal>
#include <cmath>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "pm/capture/VideoCaptureSource.h"
#include "pm/core/Error.h"
#include "pm/hand/HandLoop.h"
#include "pm/hand/HandPass.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/PoseFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/ArmCameraSource.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"

namespace pm::program {

namespace {

//! The cameras: live, or the lab's renderer on the arm's hand (the scene is kept in \e scene).
struct Cameras
{
  std::unique_ptr<sim::Scene> scene;
  std::unique_ptr<capture::StereoSource> source;
  lab::ArmCameraSource *simulated = nullptr; //!< source, when it is the lab's
};

Cameras openCameras(const CameraOptions &o, const core::StereoRig &rig, robot::Arm &arm,
                    std::function<vpHomogeneousMatrix(double)> h0MoAt, long maxPairs)
{
  Cameras c;
  if (o.simulate.empty()) {
    capture::VideoCaptureParams vp;
    vp.maxPairs = maxPairs;
    c.source = std::make_unique<capture::VideoCaptureSource>(o.left, o.right, vp);
    return c;
  }
  sim::SceneParams sp;
  sp.distractor = false;
  c.scene = std::make_unique<sim::Scene>(sim::makeTarget(o.simulate), sp);
  const vpHomogeneousMatrix fMh0 = arm.fMh();
  auto source = std::make_unique<lab::ArmCameraSource>(
      *c.scene, rig, arm, [fMh0, h0MoAt](double t) { return fMh0 * h0MoAt(t); }, o.fps, maxPairs);
  c.simulated = source.get();
  c.source = std::move(source);
  return c;
}

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) { g_interrupted = true; }

//! Ctrl-C ends the servo's loop (the arm then stops) instead of the program, while it lives.
class InterruptScope
{
public:
  InterruptScope() : m_previous(std::signal(SIGINT, onInterrupt)) { g_interrupted = false; }
  ~InterruptScope() { std::signal(SIGINT, m_previous); }
  InterruptScope(const InterruptScope &) = delete;
  InterruptScope &operator=(const InterruptScope &) = delete;

private:
  void (*m_previous)(int);
};

std::string fixed(double v, int decimals)
{
  char s[48];
  std::snprintf(s, sizeof s, "%.*f", decimals, v);
  return s;
}

std::string poseText(const vpHomogeneousMatrix &M)
{
  const vpTranslationVector t = M.getTranslationVector();
  char s[96];
  std::snprintf(s, sizeof s, "(%.1f, %.1f, %.1f) mm, %.1f deg", 1e3 * t[0], 1e3 * t[1], 1e3 * t[2],
                M.getThetaUVector().getTheta() * 180 / M_PI);
  return s;
}

} // namespace

void runPassSession(robot::Arm &arm, const CameraOptions &cameras, const PassOptions &pass, std::ostream &out)
{
  const core::StereoRig rig = io::loadRig(cameras.rig);
  const bool live = cameras.simulate.empty();
  if (live && pass.backgrounds && !isatty(STDIN_FILENO))
    throw core::Error("the pass's backgrounds need someone at a terminal to remove the target (or --no-backgrounds)");
  const vpHomogeneousMatrix h0Mo(0, 0, 1e-3 * cameras.distanceMm, 0, 0, 0);
  Cameras c = openCameras(cameras, rig, arm, [h0Mo](double) { return h0Mo; }, 0);
  model::PassPlan plan;
  plan.views = pass.count;
  plan.distanceMm = cameras.distanceMm;
  hand::PassRecording rec;
  rec.settlePairs = pass.settlePairs;
  rec.backgrounds = pass.backgrounds;
  rec.ask = [&](const std::string &what) {
    if (c.simulated) {
      out << "\n" << what << " (simulated: the target is removed)" << std::endl;
      c.simulated->setTargetPresent(false);
      return;
    }
    out << "\n" << what << std::flush;
    std::string line;
    std::getline(std::cin, line);
  };
  rec.note = [&](const std::string &what) { out << "pass: " << what << std::endl; };
  InterruptScope ctrlC; // Ctrl-C ends the pass at the next stop, the arm stopped and nothing written
  rec.progress = [&](std::size_t done, std::size_t total) {
    if (!pass.quiet)
      out << "\rpass: " << done << "/" << total << " pairs" << (done == total ? "\n" : "") << std::flush;
    if (g_interrupted) {
      arm.stop();
      throw core::Error("the pass was interrupted (Ctrl-C) after " + std::to_string(done) + " of " + std::to_string(total) +
                  " pairs: the arm is stopped where it was, nothing written");
    }
  };
  const std::vector<model::PassView> views = hand::recordPass(arm, *c.source, plan, rec);
  io::saveViewsFolder(views, pass.views);
  out << "wrote " << views.size() << " views of the " << arm.model().title() << "'s pass to " << pass.views << " ("
      << c.source->describe() << "); next: pm-make-model --views " << pass.views << " --rig " << cameras.rig << " --out MODEL"
      << std::endl;
}

void runServoSession(robot::Arm &arm, const CameraOptions &cameras, const ServoOptions &servo, std::ostream &out)
{
  const core::StereoRig rig = io::loadRig(cameras.rig);
  const core::PhotoModel model = io::loadPhotoModel(servo.model);
  servo::ServoParams sp;
  if (!servo.desired.empty())
    sp.hdMo = io::readPoseYaml(servo.desired);
  // --simulate: the target moves in front of the hand (50 mm across, 40 mm up and 60 mm nearer, back).
  const double d = cameras.distanceMm;
  const sim::Trajectory steps({{0, 0, d, 0, 0, 0}, {50, 0, d, 0, 0, 0}, {50, -40, d - 60, 0, 0, 0}, {0, 0, d, 0, 0, 0}}, 1.5, 1.5);
  const long maxPairs = servo.durationS > 0 ? static_cast<long>(std::floor(servo.durationS * cameras.fps)) + 1 : 0;
  Cameras c = openCameras(cameras, rig, arm, [&steps](double t) { return core::toHomogeneousMatrix(steps.at(t)); }, maxPairs);
  hand::HandLoop loop(rig, model, tracker::TrackerParams(), sp, hand::GuardParams(), *c.source, arm, cameras.fps);
  if (servo.desired.empty())
    loop.keepWhereFound();
  InterruptScope ctrlC;
  hand::HandFrame f;
  long pairs = 0, servoed = 0;
  vpHomogeneousMatrix hMoTrue, hMoTaken; // --simulate: the truth now, and when the pose to keep was taken
  bool taken = false;
  double nextReport = 0;
  while (!g_interrupted) {
    if (c.simulated)
      hMoTrue = c.simulated->hMo();
    if (!loop.step(f))
      break;
    ++pairs;
    servoed += f.command.servoing ? 1 : 0;
    if (f.tookDesired) {
      hMoTaken = hMoTrue;
      taken = true;
      out << "t " << fixed(f.timeS, 2) << " s: the target found, kept at " << poseText(loop.desired()) << std::endl;
    }
    if (!servo.quiet && f.timeS >= nextReport) {
      out << "t " << fixed(f.timeS, 2) << " s: " << (f.command.servoing ? "servoing" : "held") << ", estimate "
          << poseText(f.track.hMo) << ", confidence " << fixed(f.track.confidence, 3) << std::endl;
      nextReport += 1.0;
    }
  }
  arm.stop();
  out << pairs << " pairs, " << servoed << " servoed" << (g_interrupted ? " (stopped by Ctrl-C)" : "") << "; the arm is stopped ("
      << c.source->describe() << ")" << std::endl;
  if (c.simulated && taken) {
    const vpHomogeneousMatrix e = hMoTaken.inverse() * c.simulated->hMo();
    out << "simulated: the target in the hand at the end against where it was kept (truth): "
        << fixed(1e3 * e.getTranslationVector().frobeniusNorm(), 2) << " mm, " << fixed(e.getThetaUVector().getTheta() * 180 / M_PI, 2)
        << " deg" << std::endl;
  }
}

} // namespace pm::program
