#include "pm/compare/Scenario.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"
#include "pm/io/PoseTableFile.h"
#include "pm/sim/Trajectory.h"

namespace pm::compare {

const std::vector<std::string> &scenarioNames()
{
  static const std::vector<std::string> names{"table2", "sinusoid", "fast", "occlusion", "lighting", "loss"};
  return names;
}

const std::vector<std::string> &allScenarioNames()
{
  static const std::vector<std::string> names{"table2",     "sinusoid",       "fast",    "occlusion", "lighting",
                                              "loss",       "random6dof",     "still-backdrop", "clutter", "grasp"};
  return names;
}

namespace {
Scenario fromTrajectory(const pm::sim::Trajectory &traj, double fps)
{
  Scenario s;
  s.fps = fps;
  const int n = static_cast<int>(std::floor(traj.duration() * fps)) + 1;
  for (int k = 0; k < n; ++k) {
    ScenarioFrame f;
    f.hMo = core::toHomogeneousMatrix(traj.at(k / fps));
    f.moving = traj.moving(k / fps);
    s.frames.push_back(f);
  }
  return s;
}

//! \e seconds of frames, each made by \e frameAt(t), all moving.
template <typename F>
Scenario timed(double seconds, double fps, F frameAt)
{
  Scenario s;
  s.fps = fps;
  for (int k = 0; k < static_cast<int>(seconds * fps); ++k) {
    ScenarioFrame f = frameAt(k / fps);
    f.moving = true;
    s.frames.push_back(f);
  }
  return s;
}

//! A slow sway about the rest pose, for the scenarios that test something else than motion.
core::Phi sway(double t)
{
  return {30 * std::sin(2 * M_PI * 0.2 * t), 15 * std::sin(2 * M_PI * 0.13 * t), 500, 0, 0, 0.03 * std::sin(2 * M_PI * 0.2 * t)};
}

double ramp(double t, double t0, double t1, double a, double b)
{
  if (t <= t0)
    return a;
  if (t >= t1)
    return b;
  return a + (b - a) * (t - t0) / (t1 - t0);
}
} // namespace

Scenario makeScenario(const std::string &name, const std::vector<core::Phi> &table2, int steps)
{
  const double fps = 30;
  Scenario s;
  if (name == "table2") {
    std::vector<core::Phi> w = table2;
    if (steps > 0 && steps < static_cast<int>(w.size()))
      w.resize(static_cast<std::size_t>(steps));
    if (w.empty())
      throw core::Error("scenario table2: no waypoint");
    s = fromTrajectory(pm::sim::Trajectory(w, 1.5, 1.0), fps);
    s.description = "Table 2's " + std::to_string(w.size()) + " steps, hold 1.5 s, move 1 s";
  } else if (name == "sinusoid") {
    s = timed(10, fps, [](double t) {
      ScenarioFrame f;
      f.hMo = core::toHomogeneousMatrix(core::Phi{60 * std::sin(2 * M_PI * 0.5 * t), 30 * std::sin(2 * M_PI * 0.25 * t), 500, 0, 0,
                                      0.1 * std::sin(2 * M_PI * 0.5 * t)});
      return f;
    });
    s.description = "x 60 mm at 0.5 Hz, y 30 mm at 0.25 Hz, 11 deg about z at 0.5 Hz, 10 s";
  } else if (name == "fast") {
    const std::vector<core::Phi> w{{0, 0, 500, 0, 0, 0},    {80, 0, 500, 0, 0, 0},  {80, 60, 500, 0, 0, 0.05},
                             {0, 60, 520, 0, 0, 0.05}, {-60, 0, 480, 0, 0, 0}, {0, 0, 500, 0, 0, 0}};
    s = fromTrajectory(pm::sim::Trajectory(w, 0.5, 0.25), fps);
    s.description = "moves of 60 to 100 mm in 0.25 s (up to 600 mm/s), held 0.5 s";
  } else if (name == "occlusion") {
    s = timed(8, fps, [](double t) {
      ScenarioFrame f;
      f.hMo = core::toHomogeneousMatrix(sway(t));
      f.occluded = t >= 2 && t < 6;
      return f;
    });
    s.description = "slow sway; a strand of seaweed in front of the toy from 2 s to 6 s";
  } else if (name == "lighting") {
    s = timed(8, fps, [](double t) {
      ScenarioFrame f;
      f.hMo = core::toHomogeneousMatrix(sway(t));
      f.exposure = t < 4 ? ramp(t, 1, 2.5, 1.0, 0.4) : ramp(t, 4, 5.5, 0.4, 1.5);
      f.lightX = ramp(t, 1, 7, -0.35, 0.8);
      return f;
    });
    s.description = "slow sway; exposure 1 to 0.4 (1-2.5 s), then 1.5 (4-5.5 s); the light swings left to right";
  } else if (name == "random6dof") {
    // Each of the six coordinates a sum of two sines of fixed random frequencies (0.04 to 0.25 Hz)
    // and phases (drawn once from seed 31): smooth, never repeating within the 20 s; the rotation
    // a theta-u vector whose every component reaches at most 45 deg.
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> freq(0.04, 0.25), phase(0, 2 * M_PI);
    double f[6][2], ph[6][2];
    for (int i = 0; i < 6; ++i)
      for (int k = 0; k < 2; ++k) {
        f[i][k] = freq(rng);
        ph[i][k] = phase(rng);
      }
    const double amp[6] = {40, 40, 30, 45 * M_PI / 180, 45 * M_PI / 180, 45 * M_PI / 180};
    s = timed(20, fps, [&](double t) {
      double v[6];
      for (int i = 0; i < 6; ++i)
        v[i] = amp[i] * (0.6 * std::sin(2 * M_PI * f[i][0] * t + ph[i][0]) + 0.4 * std::sin(2 * M_PI * f[i][1] * t + ph[i][1]));
      ScenarioFrame fr;
      fr.hMo = vpHomogeneousMatrix(vpTranslationVector(v[0] * 1e-3, v[1] * 1e-3, 0.5 + v[2] * 1e-3), vpThetaUVector(v[3], v[4], v[5]));
      return fr;
    });
    s.description = "a random smooth 6-DoF motion: x, y +-40 mm, z +-30 mm, up to 45 deg about every axis, 20 s";
  } else if (name == "still-backdrop") {
    s = timed(10, fps, [](double t) {
      ScenarioFrame f;
      const double w = 2 * M_PI * 0.2 * t;
      f.hMo = core::toHomogeneousMatrix(core::Phi{60 * std::sin(w), 30 * std::sin(0.65 * w), 500 + 20 * std::sin(0.5 * w),
                                                  0.05 * std::sin(0.8 * w), 0.06 * std::sin(w), 0.05 * std::sin(w)});
      f.stillBackdrop = true;
      return f;
    });
    s.description = "x 60 mm, y 30 mm, z 20 mm, turns up to 7 deg, in front of a backdrop that stands still 50 mm farther back, 10 s";
  } else if (name == "clutter") {
    s = timed(8, fps, [](double t) {
      ScenarioFrame f;
      f.hMo = core::toHomogeneousMatrix(sway(t));
      f.clutter = true;
      return f;
    });
    s.description = "slow sway among three other toys, one of similar hue, 8 s";
  } else if (name == "grasp") {
    s = timed(10, fps, [](double t) {
      ScenarioFrame f;
      f.hMo = core::toHomogeneousMatrix(core::Phi{10 * std::sin(2 * M_PI * 0.2 * t), 0, ramp(t, 1, 8, 500, 300), 0, 0, 0});
      f.gripper = true;
      return f;
    });
    s.description = "from 500 to 300 mm in front of the hand (1-8 s), the gripper's fingers in view, 10 s";
  } else if (name == "loss") {
    const int blank0 = static_cast<int>(2 * fps), blank1 = blank0 + static_cast<int>(0.5 * fps), jump = static_cast<int>(5 * fps);
    for (int k = 0; k < static_cast<int>(8 * fps); ++k) {
      ScenarioFrame f;
      core::Phi p{0, 0, 500, 0, 0, 0};
      p[0] = ramp(k, blank0, blank1, 0, 60); // moves while the frames are blank
      if (k >= jump) {                       // the jump: 50 mm and 8 degrees about z at once
        p[0] = 60 - 40;
        p[1] = 30;
        p[5] = std::sin(4 * M_PI / 180);
      }
      f.hMo = core::toHomogeneousMatrix(p);
      f.blank = k >= blank0 && k < blank1;
      f.moving = f.blank;
      s.frames.push_back(f);
    }
    s.lossEnds = {blank1, jump};
    s.description = "blank for 0.5 s while the target moves 60 mm (at 2 s); jumps 50 mm and 8 deg (at 5 s)";
  } else {
    throw core::Error("unknown scenario '" + name + "'");
  }
  s.name = name;
  return s;
}

std::vector<Scenario> makeScenarios(const std::vector<std::string> &names, const std::string &table2Path, int steps)
{
  std::vector<core::Phi> table2;
  for (const auto &row : io::readPoseTable(table2Path, "step"))
    table2.push_back(row.second);
  std::vector<Scenario> seqs;
  for (const auto &name : names)
    seqs.push_back(makeScenario(name, table2, steps));
  return seqs;
}

void prepareForScenarios(const std::vector<std::string> &names, sim::SceneParams &scene, rmga::SearchSpace &space)
{
  auto has = [&](const char *n) { return std::find(names.begin(), names.end(), n) != names.end(); };
  scene.clutter = scene.clutter || has("clutter");
  if (has("grasp"))
    space.lo[2] = std::min(space.lo[2], 250.0);
}

sim::StereoImages renderScenarioFrame(sim::Scene &scene, const core::StereoRig &rig, const Scenario &s, std::size_t k)
{
  std::vector<vpImage<vpRGBa>> im = renderScenarioViews(scene, rig, s, k);
  sim::StereoImages pair;
  pair.left = std::move(im[0]);
  pair.right = std::move(im[1]);
  return pair;
}

std::vector<vpImage<vpRGBa>> renderScenarioViews(sim::Scene &scene, const core::CameraRig &rig, const Scenario &s, std::size_t k)
{
  const ScenarioFrame &f = s.frames.at(k);
  scene.params().exposure = f.exposure;
  scene.params().lightDirHand[0] = f.lightX;
  scene.params().occluder = f.occluded;
  scene.params().stillBackdrop = f.stillBackdrop;
  scene.params().gripper = f.gripper;
  if (f.clutter && !scene.hasClutter())
    throw core::Error("scenario " + s.name + ": clutter in a scene made without it (sim::SceneParams::clutter)");
  scene.params().clutter = f.clutter;
  if (!f.blank) // a still backdrop stays where it stood at the first frame
    return scene.renderRig(rig, f.hMo, static_cast<std::uint64_t>(k),
                           f.stillBackdrop ? f.hMo.inverse() * s.frames.front().hMo : vpHomogeneousMatrix());
  std::vector<vpImage<vpRGBa>> im;
  im.reserve(rig.size());
  for (const core::PinholeCamera &c : rig.cameras)
    im.emplace_back(c.height, c.width, vpRGBa(0, 0, 0, 255));
  return im;
}

} // namespace pm::compare
