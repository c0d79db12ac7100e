//! pm-servo: the PA-10 follows the moving target by position-based visual servoing (the main job).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/PlotUtil.h"
#include "pm/app/Progress.h"
#include "pm/report/TimePlot.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PoseTableFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/FrequencyResponse.h"
#include "pm/lab/LoopTable.h"
#include "pm/lab/RunFigures.h"
#include "pm/lab/RunRecorder.h"
#include "pm/lab/RunSummary.h"
#include "pm/lab/RunLog.h"
#include "pm/sim/TargetCatalog.h"

namespace {

const char *kAxes[6] = {"x", "y", "z", "e1", "e2", "e3"};

int axisIndex(const std::string &a)
{
  for (int i = 0; i < 6; ++i)
    if (a == kAxes[i])
      return i;
  throw CLI::ValidationError("--axis", "must be one of x, y, z, e1, e2, e3");
}

//! pm-servo's options (the tracker's are TrackerOptions').
struct Options
{
  std::string out = "results/servo", target = "C12", motion = "steps", axis = "x";
  std::string stepsPath = pm::app::dataPath("trajectories/table2.csv"), rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  double holdS = 1.5, moveS = 2.0, amplitude = 50, frequency = 0.5, durationS = 0, fps = 30;
  double maxVelocity = 300, maxAcceleration = 1500;
  int overlayEvery = 150, steps = 0;
  bool quiet = false, noVideo = false, freqSweep = false, grasp = false;
  pm::lab::LoopParams lp;
  pm::servo::ServoParams servo;
  pm::app::LabModelChoice lab;
  pm::sim::SceneParams sp;
  pm::app::DistractorChoice distractor;
};

void addMotionOptions(CLI::App &app, Options &o)
{
  app.add_option("--motion", o.motion, "the TC-robot's motion: steps (the waypoints of --trajectory) or sine")->check(CLI::IsMember({"steps", "sine"}));
  app.add_option("--trajectory", o.stepsPath, "waypoints of the steps (step,x,y,z,e1,e2,e3, in the hand frame at the start)");
  app.add_option("--steps", o.steps, "use only the first N waypoints (0: all)")->check(CLI::Range(0, 100000));
  app.add_option("--hold-s", o.holdS, "steps: time each is held (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--move-s", o.moveS, "steps: duration of each move (s; 2 s, since the PA-10's joint speeds cannot orbit "
                                      "Table 2's 40 deg rotation steps at 500 mm in 1 s)")->check(CLI::Range(0.01, 3600.0));
  app.add_option("--axis", o.axis, "sine: the variable moved (x, y, z, e1, e2, e3)");
  app.add_option("--amplitude-mm", o.amplitude, "sine: amplitude (mm; for e1..e3 the quaternion component)")->check(CLI::Range(0.0, 500.0));
  app.add_option("--frequency-hz", o.frequency, "sine: frequency")->check(CLI::Range(0.001, 10.0));
  app.add_option("--max-velocity", o.maxVelocity, "TC-robot velocity limit (mm/s, or 1/s for eps)")->check(CLI::PositiveNumber);
  app.add_option("--max-acceleration", o.maxAcceleration, "TC-robot acceleration limit (mm/s^2, or 1/s^2)")->check(CLI::PositiveNumber);
  app.add_option("--duration-s", o.durationS, "stop after this long (0: the steps' duration, 20 s for a sine)")->check(CLI::Range(0.0, 1e6));
  app.add_option("--fps", o.fps, "camera and servo rate")->check(CLI::Range(1.0, 1000.0));
}

void addLoopOptions(CLI::App &app, Options &o)
{
  pm::lab::LoopParams &lp = o.lp;
  app.add_flag("--oracle", lp.oracle, "servo on the true pose instead of the estimate (a baseline)");
  app.add_flag_function(
      "--filter,!--no-filter", [&lp](std::int64_t n) { lp.filter = n > 0 ? pm::lab::LoopParams::Filter::On : pm::lab::LoopParams::Filter::Off; },
      "alpha-beta filter of the estimate (base frame) with velocity feed-forward (default: only without the precise stage)");
  app.add_option("--max-sigma-mm", lp.maxSigmaMm, "hold the arm when the pose's reported 1-sigma uncertainty along an axis exceeds this (mm; 0: no check; docs/trust.md)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--max-sigma-deg", lp.maxSigmaDeg, "... or about an axis exceeds this (deg; 0: no check)")->check(CLI::Range(0.0, 1e6));
  app.add_option("--filter-alpha-rotation", lp.filterParams.alphaR, "filter: rotation gain")->check(CLI::Range(0.01, 1.0));
  app.add_option("--filter-beta-rotation", lp.filterParams.betaR, "filter: angular velocity gain")->check(CLI::Range(0.0, 1.9));
  app.add_option("--filter-alpha-translation", lp.filterParams.alphaT, "filter: translation gain")->check(CLI::Range(0.01, 1.0));
  app.add_option("--filter-beta-translation", lp.filterParams.betaT, "filter: velocity gain")->check(CLI::Range(0.0, 1.9));
  app.add_flag("--feed-forward-rotation,!--no-feed-forward-rotation", o.servo.feedForwardRotation, "feed the target's angular velocity forward too");
  app.add_flag("--grasp", o.grasp, "a grasp approach: the hand closes in on the still target from 500 to 300 mm at "
                                  "25 mm/s while servoed (with --gripper, its fingers in view); the tracker searches from "
                                  "250 mm (docs/occlusion.md)");
  app.add_flag("--freq-sweep", o.freqSweep, "run sines of 0.1 to 1 Hz on --axis and write bode.png and bode.csv");
  app.add_option("--overlay-every", o.overlayEvery, "write an overlay PNG every N frames (0: none)")->check(CLI::Range(0, 1000000));
  app.add_flag("--no-video", o.noVideo, "do not write servo.avi");
  app.add_option("--rig", o.rigPath, "rig file: one camera or more (data/rig/pa10_mono.json: one; pa10_trio.json: three)");
  app.add_option("--gain-zero", o.servo.gainAtZero, "vpAdaptiveGain: gain at zero error (1/s)")->check(CLI::PositiveNumber);
  app.add_option("--gain-infinity", o.servo.gainAtInfinity, "vpAdaptiveGain: gain at infinite error (1/s)")->check(CLI::PositiveNumber);
  app.add_flag("--feed-forward,!--no-feed-forward", o.servo.feedForward, "follow the target's estimated velocity");
}

void addLabOptions(CLI::App &app, Options &o)
{
  pm::app::addLabModelOptions(app, o.lab);
  pm::app::addRobotOption(app, o.lp.arm);
  app.add_flag("--realtime", o.lp.realTime, "simulator: drive ViSP's own threaded simulator of --robot (viper850 or afma6) as "
               "a real vpRobot is driven, in real time (not repeatable frame for frame); the pass before it is stepped");
  pm::app::addModelOptions(app, o.lab.photo);
  pm::app::addSceneOptions(app, o.sp);
  pm::app::addDistractorOptions(app, o.distractor);
}

//! The lab of a run: the rig, the scene (with its look-alike, if any) and the model the arm's pass makes.
struct Lab
{
  pm::core::CameraRig rig; //!< one camera or more
  std::unique_ptr<pm::sim::Scene> scene;
  pm::sim::SimulatedPhotoModel model;
  std::vector<pm::core::Phi> waypoints; //!< the steps' (none for a sine)
};

Lab makeLab(Options &o)
{
  Lab lab;
  lab.rig = pm::io::loadCameraRig(o.rigPath);
  o.lp.fps = o.fps;
  o.lab.arm = o.lp.arm; // the same arm makes the pass and servos
  lab.scene = std::make_unique<pm::sim::Scene>(pm::sim::makeTarget(o.target), o.sp);
  o.distractor.apply(*lab.scene);
  lab.model = pm::app::makeLabModel(*lab.scene, lab.rig, o.lab);
  if (o.motion == "steps")
    lab.waypoints = pm::io::readWaypoints(o.stepsPath, o.grasp ? 1 : o.steps); // a grasp: the target stands at the first
  return lab;
}

//! --grasp: the approach in the loop, a search space that reaches its end, a duration that holds it there.
void applyGrasp(Options &o, pm::tracker::TrackerParams &tp)
{
  if (!o.grasp)
    return;
  if (o.motion != "steps" || o.freqSweep)
    throw CLI::ValidationError("--grasp", "approaches a still target: not with --motion sine or --freq-sweep");
  o.lp.graspApproach = true;
  tp.search.space.lo[2] = std::min(tp.search.space.lo[2], o.lp.approach.toMm - 50);
  if (o.durationS <= 0) // settled, closed in, then held 3 s at the grasp's distance
    o.durationS = o.lp.approach.settleS + (o.lp.approach.fromMm - o.lp.approach.toMm) / o.lp.approach.mmPerS + 3;
}

//! --freq-sweep: sines of 0.1 to 1 Hz on the axis; bode.csv, bode.png and summary.json.
int runSweep(const Options &o, const Lab &lab, const pm::tracker::TrackerParams &tp, pm::io::StagedFiles &files)
{
  pm::lab::SweepParams sweep;
  sweep.axis = axisIndex(o.axis);
  sweep.amplitude = o.amplitude;
  sweep.maxVelocity = o.maxVelocity;
  sweep.maxAcceleration = o.maxAcceleration;
  pm::app::Progress progress("frequency sweep", sweep.frequenciesHz.size(), o.quiet);
  const std::vector<pm::lab::BodePoint> bode =
      pm::lab::frequencyResponse(lab.rig, *lab.scene, lab.model, tp, o.servo, o.lp, sweep, [&] { progress.step(); });
  progress.finish();
  std::ostringstream csv;
  csv << "frequency_hz,amplitude,gain,phase_lag_deg\n";
  pm::report::Series gainS{"gain", vpRGBa(40, 90, 200), {}, {}, false}, phaseS{"phase lag", vpRGBa(220, 60, 40), {}, {}, false};
  nlohmann::json rows = nlohmann::json::array();
  for (const pm::lab::BodePoint &p : bode) {
    csv << p.frequencyHz << "," << p.amplitude << "," << p.gain << "," << p.phaseLagDeg << "\n";
    rows.push_back({{"frequency_hz", p.frequencyHz}, {"amplitude", p.amplitude}, {"gain", p.gain}, {"phase_lag_deg", p.phaseLagDeg}});
    gainS.t.push_back(p.frequencyHz);
    gainS.y.push_back(p.gain);
    phaseS.t.push_back(p.frequencyHz);
    phaseS.y.push_back(p.phaseLagDeg);
  }
  pm::io::writeTextFile(files.stage("bode.csv"), csv.str());
  pm::io::writeImage(pm::report::drawTimePlots({{"tracking gain (hand / target amplitude)", "", {gainS}, 0, {}},
                                                {"phase lag of the hand (deg)", "deg", {phaseS}, 0, {}}},
                                               2, "frequency response of the visual servo, sine on " + o.axis + ", amplitude " +
                                                      pm::report::tickLabel(o.amplitude),
                                               "frequency [Hz]"),
                     files.stage("bode.png"));
  pm::io::writeTextFile(files.stage("summary.json"), nlohmann::json{{"axis", o.axis}, {"amplitude", o.amplitude}, {"sweep", rows}}.dump(2) + "\n");
  files.commit();
  if (!o.quiet)
    std::cout << "frequency response (" << o.axis << ", amplitude " << o.amplitude << "):\n" << csv.str() << "written to " << files.dir() << "/" << std::endl;
  return 0;
}

//! The closed loop: the TC-robot moves the target (steps or a sine), the arm servoes on the tracker's estimate.
std::unique_ptr<pm::lab::ClosedLoop> makeLoop(const Options &o, const Lab &lab, const pm::tracker::TrackerParams &tp)
{
  const std::vector<pm::core::Phi> &waypoints = lab.waypoints;
  const int ax = axisIndex(o.axis);
  auto makeTc = [&o, &waypoints, ax](const vpHomogeneousMatrix &wMh0) -> std::unique_ptr<pm::sim::TcRobot> {
    if (o.motion == "steps")
      return std::make_unique<pm::sim::TcRobot>(wMh0, pm::sim::Trajectory(waypoints, o.holdS, o.moveS));
    const pm::core::Phi phi0{0, 0, 500, 0, 0, 0};
    return std::make_unique<pm::sim::TcRobot>(wMh0, phi0, ax, o.amplitude, o.frequency, o.maxVelocity, o.maxAcceleration);
  };
  return std::make_unique<pm::lab::ClosedLoop>(lab.rig, *lab.scene, lab.model, tp, o.servo, o.lp, makeTc);
}

//! Runs the loop frame by frame: frames.csv as the frames come, the recordings (video, overlays), the run's log.
std::vector<double> runLoop(const Options &o, long nFrames, pm::lab::ClosedLoop &loop, pm::lab::RunLog &log,
                            pm::lab::RunRecorder &recorder, pm::io::StagedFiles &files)
{
  pm::app::Progress progress("servoing", static_cast<std::size_t>(nFrames), o.quiet);
  std::ofstream csv(files.stage("frames.csv"));
  pm::lab::writeLoopCsvHeader(csv, loop.arm().model().dof());
  std::vector<double> memoryMb; // resident memory at the start of each tenth of the run, and at its end
  for (long k = 0; k < nFrames; ++k) {
    if (k * 10 / nFrames >= static_cast<long>(memoryMb.size()))
      memoryMb.push_back(pm::app::residentMemoryMb());
    const pm::lab::LoopFrame f = loop.step();
    log.add(f);
    pm::lab::writeLoopCsvRow(csv, f, o.lp.oracle);
    recorder.record(k, f, loop, [&](const std::string &name) { return files.stage(name); });
    progress.step();
  }
  progress.finish();
  memoryMb.push_back(pm::app::residentMemoryMb());
  log.finish();
  recorder.finish();
  csv.close();
  if (!csv)
    throw pm::core::Error("cannot write " + files.finalPath("frames.csv"));
  return memoryMb;
}

//! The figures (the plotted errors are the maxima over the frames each sample stands for), summary.json, the summary on stdout.
void writeOutputs(const Options &o, const Lab &lab, const pm::lab::ClosedLoop &loop, const pm::lab::RunLog &log,
                  const pm::lab::RunRecorder &recorder, const std::vector<double> &memoryMb, pm::io::StagedFiles &files)
{
  const pm::sim::Scene &scene = *lab.scene;
  pm::io::writeImage(pm::lab::drawRunErrors(log, loop.arm().model().title() + " following " + scene.target().info.name +
                                                     (o.lp.oracle ? " (oracle: true pose)" : " (photo-model tracker)")),
                     files.stage("errors.png"));
  pm::io::writeImage(pm::lab::drawRunRelativePose(log), files.stage("relative_pose.png"));
  pm::io::writeImage(pm::lab::drawRunJoints(log, loop.arm().model()), files.stage("joints.png"));
  pm::lab::RunInfo info;
  info.arm = loop.arm().model().title();
  info.targetCode = scene.target().info.code;
  info.targetName = scene.target().info.name;
  info.trajectory = o.motion == "steps" ? "steps (" + std::to_string(lab.waypoints.size()) + ")"
                                        : "sine " + o.axis + " " + std::to_string(o.amplitude) + " at " + std::to_string(o.frequency) + " Hz";
  info.oracle = o.lp.oracle;
  info.jointLimitViolations = loop.arm().limitHits() + log.jointLimitViolations();
  info.memoryMb = memoryMb;
  info.overlays = recorder.overlays();
  info.video = o.noVideo ? "" : "servo.avi";
  pm::io::writeTextFile(files.stage("summary.json"), pm::lab::runSummaryJson(log, info));
  files.commit();
  if (!o.quiet)
    std::cout << pm::lab::runSummaryText(log, info) << "  written to " << files.dir()
              << "/ (frames.csv, errors.png, relative_pose.png, joints.png, " << (o.noVideo ? "" : "servo.avi, ")
              << (info.overlays ? std::to_string(info.overlays) + " overlay_*.png, " : "") << "summary.json)"
              << std::endl;
}

//! The main job: the loop run, recorded and summed up.
int runServo(const Options &o, const Lab &lab, const pm::tracker::TrackerParams &tp, pm::io::StagedFiles &files)
{
  const std::unique_ptr<pm::lab::ClosedLoop> loop = makeLoop(o, lab, tp);
  // Nothing here grows with the run: frames.csv is written as the frames come, the figures are
  // computed online and the plots drawn from a decimated record (pm::lab::RunLog).
  const double seconds = o.durationS > 0 ? o.durationS
                                         : (o.motion == "steps" ? pm::sim::Trajectory(lab.waypoints, o.holdS, o.moveS).duration() : 20.0);
  const long nFrames = static_cast<long>(std::floor(seconds * o.fps)) + 1;
  pm::lab::RunLog log(nFrames, o.fps, loop->arm().model());
  std::unique_ptr<pm::lab::RunRecorder> recorder;
  try {
    recorder = std::make_unique<pm::lab::RunRecorder>(o.noVideo ? "" : files.stage("servo.avi"), o.fps, lab.rig[0].width * static_cast<unsigned>(lab.rig.size()),
                                                      lab.rig[0].height, o.overlayEvery, o.lp.oracle);
  } catch (const pm::core::Error &) {
    throw pm::core::Error("cannot write the video '" + files.finalPath("servo.avi") + "' (OpenCV's MJPG writer failed)");
  }
  const std::vector<double> memoryMb = runLoop(o, nFrames, *loop, log, *recorder, files);
  writeOutputs(o, lab, *loop, log, *recorder, memoryMb, files);
  return 0;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"The main job: the eye-in-hand PA-10 keeps the target 500 mm in front of its hand by position-based visual "
               "servoing (ViSP's vpServo) on the photo-model tracker's pose, while the TC-robot moves the target through "
               "Table 2's steps or a sinusoid. Writes frames.csv, errors.png (relative pose error), relative_pose.png "
               "(estimate against truth), joints.png, overlays, servo.avi (left and right views with the model) and "
               "summary.json; --freq-sweep writes a Bode plot of the tracking.",
               "pm-servo"};
  app.option_defaults()->always_capture_default();
  Options o;
  app.add_option("--out", o.out, "output folder (created if missing)");
  app.add_option("--target", o.target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  addMotionOptions(app, o);
  addLoopOptions(app, o);
  addLabOptions(app, o);
  pm::app::TrackerOptions trackerOptions(app, pm::tracker::TrackerParams());
  app.add_flag("--quiet", o.quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    pm::tracker::TrackerParams tp = trackerOptions.resolve();
    applyGrasp(o, tp);
    const Lab lab = makeLab(o);
    axisIndex(o.axis); // a bad --axis is refused before anything is written
    pm::io::StagedFiles files(o.out);
    return o.freqSweep ? runSweep(o, lab, tp, files) : runServo(o, lab, tp, files);
  }, {{"--trajectory", "--motion", {"steps", "sine"}}, {"--steps-file", "--trajectory", {}}});
}
