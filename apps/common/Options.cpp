#include "pm/app/Options.h"

#include <iostream>

#include "pm/robot/ArmCatalog.h"
#include "pm/tracker/TrackerConfigFile.h"

namespace pm::app {

void addModelOptions(CLI::App &app, model::PhotoModelParams &p)
{
  const char *g = "Photo-model";
  app.add_option("--step-px", p.stepPx, "sampling step of S_in (grid) and along S_out (px)")->check(CLI::Range(1.0, 200.0))->group(g);
  app.add_option("--strip-gap-px", p.stripGapPx, "distance of S_out's first row from the target's outline (px)")
      ->check(CLI::Range(1.0, 200.0))->group(g);
  app.add_option("--strip-width-px", p.stripWidthPx, "width of the S_out strip beyond its first row (px)")
      ->check(CLI::Range(0.0, 200.0))->group(g);
  app.add_option("--strip-rows", p.stripRows, "rows of points across the S_out strip")->check(CLI::Range(1, 20))->group(g);
  app.add_option("--region-colour-tol", p.background.colourTolGrey, "grey levels off the background's own colour (as a shadow "
                 "dims it) that mark a target pixel (the model builders' one background subtraction)")
      ->check(CLI::Range(0.5, 254.0))->group(g);
  app.add_option("--min-saturation", p.minSaturation, "photo pixels less saturated carry no hue")->check(CLI::Range(0.0, 0.99))->group(g);
}

void addLabModelOptions(CLI::App &app, LabModelChoice &c)
{
  auto *fl = app.add_flag("--flat", c.flat, "simulator: the paper's flat photo-model (two photos face-on) instead of the "
                          "all-around one");
  auto *st = app.add_flag("--stereo", c.stereo, "simulator: the stereo snapshot photo-model (the rig's two cameras take the "
                          "photos, every point gets its relief) instead of the all-around one");
  app.add_option("--distance-mm", c.distanceMm, "simulator: the toy's distance when its photos are taken (the flat "
                 "model's photo distance)")->check(CLI::PositiveNumber);
  app.add_flag("--right-view", c.rightView, "simulator, --stereo: add the right camera's own views (S_in and S_out "
               "sampled in the right photos, scored in the right camera); without it both cameras are scored with the "
               "left photos' points");
  app.add_option("--view-turn-deg", c.viewTurnDeg, "simulator, --stereo: four further photo pairs with the hand "
                 "turned by this about its x and y axes around the toy (a multi-view model; 0: one pair)")
      ->check(CLI::Range(0.0, 45.0));
  auto *aa = app.add_flag("--all-around", c.allAroundAsked, "simulator: the all-around photo-model, the default: the arm "
                          "first walks the rig around the toy (a pass of --pass-views hand poses) and the model is built "
                          "from its silhouettes and photos");
  fl->excludes(st);
  aa->excludes(fl);
  aa->excludes(st);
  app.add_option("--pass-views", c.passViews, "simulator, all-around model: hand poses of the pass")->check(CLI::Range(6, 200));
  app.add_option("--pass-rings-deg", c.passRingsDeg, "simulator, all-around model: the pass's rings, their angles from the rest "
                 "axis (deg; the views spread over them in proportion to the angle)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 80.0));
  app.add_option("--backdrop-hue", c.allAroundParams.backdropHueDeg, "simulator, all-around model: segment the pass against "
                 "a plain backdrop of this hue (deg) instead of a second pass without the toy")->check(CLI::Range(0.0, 359.999));
  app.add_option("--viewpoints", c.allAroundParams.viewpoints.count, "simulator, all-around model: the model's viewing directions (K)")
      ->check(CLI::Range(1, 5000));
  app.add_option("--min-inside-px", c.allAroundParams.viewpoints.inMinInsidePx, "simulator, all-around model: the model's S_in points at least this far inside each viewpoint's outline through a sharp camera (px; raised by the blur the pass's photos show, docs/model-outline.md)")
      ->check(CLI::Range(0.0, 50.0));
  app.add_flag("--no-trust-calibration", [&c](std::int64_t) { c.calibrateTrust = false; },
               "simulator, all-around model: its trust not calibrated from its pass (the shipped confidence and sigmas; faster)");
  app.add_flag("--refine-outlines", c.allAroundParams.surface.refineOutlines, "simulator, all-around model: the outlines to a fraction of a "
               "pixel (sub-pixel silhouettes, the surface moved onto every view's outline; docs/model-outline.md)");
}

void addRobotOption(CLI::App &app, std::string &arm)
{
  app.add_option("--robot", arm, "simulator: the arm that carries the rig: pa10 (the paper's Mitsubishi PA-10), viper850 or "
                 "afma6 (ViSP's own models of its Viper850 and Afma6); each stepped in our own loop, repeatable")
      ->check(CLI::IsMember(robot::armNames()));
}

void addSceneOptions(CLI::App &app, sim::SceneParams &p)
{
  const char *g = "Simulator";
  app.add_option("--noise", p.noiseSigma, "sensor noise (grey levels)")->check(CLI::Range(0.0, 100.0))->group(g);
  app.add_option("--exposure", p.exposure, "brightness gain (lighting change)")->check(CLI::Range(0.05, 10.0))->group(g);
  app.add_flag("--occluder", p.occluder, "put a strand of seaweed in front of the target")->group(g);
  app.add_flag("--sweeping-bar", p.sweepingBar, "a violet bar 60 mm wide, 100 mm in front of the target, sweeps to and fro "
                                                "across it at 4 mm a frame (docs/occlusion.md)")->group(g);
  app.add_flag("--still-backdrop", p.stillBackdrop, "the backdrop stands still, 50 mm farther behind the target, while the "
                                                    "target moves in front of it (docs/occlusion.md)")->group(g);
  app.add_flag("--clutter", p.clutter, "three other toys of the catalogue stand around the target, one of similar hue "
                                       "(docs/occlusion.md)")->group(g);
  app.add_option("--backdrop-drift", p.backdropHueDriftDegPerS, "a background that changes: the backdrop's hue turns by "
                 "this many degrees a second (the model's pass sees it as it was; docs/occlusion.md)")
      ->check(CLI::Range(-90.0, 90.0))
      ->group(g);
  app.add_flag("--gripper", p.gripper, "a gripper's two fingers on the hand, entering the bottom of both images "
                                       "(pm-servo --grasp closes the hand in on the target; docs/occlusion.md)")->group(g);
  app.add_option_function<std::string>(
         "--vary", [&p](const std::string &names) { p.variation = sim::imageVariation(names); },
         "the images varied as another camera's: defocus, motion-blur, vignetting, shot-noise, white-balance, gamma, jpeg "
         "or camera (a mild mix), several comma-separated (docs/occlusion.md)")
      ->check([](const std::string &names) {
        try {
          sim::imageVariation(names);
          return std::string();
        } catch (const core::Error &e) {
          return std::string(e.what());
        }
      })
      ->group(g);
  app.add_option("--supersampling", p.supersampling, "samples per pixel along each axis (anti-aliasing)")
      ->check(CLI::Range(1u, 4u))->group(g);
  app.add_option("--seed", p.seed, "noise seed")->group(g);
}

void addDistractorOptions(CLI::App &app, DistractorChoice &c)
{
  const char *g = "Simulator";
  app.add_option("--distractor", c.target, "put a look-alike toy beside the target: a catalogue code (the same kind "
                 "as the target, or another of similar hue, e.g. C05 beside C12)")->group(g);
  app.add_option("--distractor-at", c.atMm, "the look-alike's position on the backdrop, x,y in the target frame (mm)")
      ->delimiter(',')
      ->expected(2)
      ->group(g);
}

void addFitnessOptions(CLI::App &app, core::FitnessParams &p)
{
  const char *g = "Fitness";
  app.add_option("--in-tol-deg", p.inTolDeg, "S_in: |H_I - H_M| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
  app.add_option("--in-bg-tol-deg", p.inBgTolDeg, "S_in: |H_B - H_I| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
  app.add_option("--out-bg-tol-deg", p.outBgTolDeg, "S_out: |H_B - H_I| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
}

TrackerOptions::TrackerOptions(CLI::App &app, const tracker::TrackerParams &defaults) : m_defaults(defaults), m_cli(defaults)
{
  const char *g = "Tracker";
  app.add_option("--config", m_config, "tracker configuration file (JSON); command-line options override it")
      ->check(CLI::ExistingFile)
      ->group(g);
  auto add = [&](CLI::Option *o, std::function<void(tracker::TrackerParams &, const tracker::TrackerParams &)> f) {
    o->group(g);
    m_set.emplace_back(o, std::move(f));
  };
  tracker::TrackerParams &p = m_cli;
  add(app.add_option("--budget-ms", p.search.budgetMs, "compute budget per frame, wall time (ms)")->check(CLI::Range(0.0, 1e6)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.budgetMs = c.search.budgetMs; t.search.budgetEvaluations = 0; });
  add(app.add_option("--budget-evals", p.search.budgetEvaluations, "compute budget per frame, fitness evaluations "
                                                            "(deterministic; overrides --budget-ms)")->check(CLI::Range(0L, 100000000L)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.budgetEvaluations = c.search.budgetEvaluations; });
  add(app.add_option("--steady-budget", p.steady.budgetFraction, "fraction of the budget for a steady frame (tracked "
                                                                "for a while, q near its recent best; 1: all frames alike)")
          ->check(CLI::Range(0.01, 1.0)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.steady.budgetFraction = c.steady.budgetFraction; });
  add(app.add_option("--steady-hue-margin", p.steady.hueMarginPx, "steady frames: hue only within this many pixels of "
                                                                 "where the model can land (0: the whole images)")
          ->check(CLI::Range(0, 10000)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.steady.hueMarginPx = c.steady.hueMarginPx; });
  add(app.add_option("--population", p.search.ga.population, "RM-GA individuals")->check(CLI::Range(2, 100000)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.population = c.search.ga.population; });
  add(app.add_option("--elite", p.search.ga.elite, "RM-GA individuals always kept"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.elite = c.search.ga.elite; });
  add(app.add_option("--tournament", p.search.ga.tournament, "RM-GA tournament size"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.tournament = c.search.ga.tournament; });
  add(app.add_option("--crossover-rate", p.search.ga.crossoverRate, "RM-GA crossover probability")->check(CLI::Range(0.0, 1.0)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.crossoverRate = c.search.ga.crossoverRate; });
  add(app.add_option("--mutation-per-bit", p.search.ga.mutationPerBit, "RM-GA probability to flip each of the 72 bits")
          ->check(CLI::Range(0.0, 1.0)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.mutationPerBit = c.search.ga.mutationPerBit; });
  add(app.add_flag("--predict,!--no-predict", p.search.ga.predictMotion, "option: move the population by the predicted motion"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.predictMotion = c.search.ga.predictMotion; });
  add(app.add_option("--restart-generations", p.search.ga.restartGenerations,
                     "option: restart all but the best after this many generations without gain (0: never)")
          ->check(CLI::Range(0, 1000000)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.restartGenerations = c.search.ga.restartGenerations; });
  add(app.add_option("--ga-seed", p.search.ga.seed, "RM-GA random seed"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.search.ga.seed = c.search.ga.seed; });
  add(app.add_option("--lock-quality", p.lock.quality, "normalised fitness q from which the target is tracked"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.lock.quality = c.lock.quality; });
  add(app.add_option("--lost-quality", p.lock.lostQuality, "normalised fitness q below which it is lost"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.lock.lostQuality = c.lock.lostQuality; });
  add(app.add_option("--verify-evals", p.verifier.evaluations, "evaluations of the challenger search that verifies a new lock "
                                                        "before it is trusted (0: every lock trusted at once)")
          ->check(CLI::Range(0L, 100000000L)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.verifier.evaluations = c.verifier.evaluations; });
  add(app.add_flag("--precise,!--no-precise", p.refinement.precise.enabled,
                   "the precise last stage after RM-GA (outline and interior, Gauss-Newton; needs an all-around model)"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.refinement.precise.enabled = c.refinement.precise.enabled; });
  add(app.add_flag("--stereo-visibility,!--no-stereo-visibility", p.fitness.stereoVisibility,
                   "a model point that misses in one camera on a hue not the target's, where the other camera sees what the "
                   "model says, is hidden there and leaves the fitness (off: the paper's, each camera alone; docs/occlusion.md)"),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.fitness.stereoVisibility = c.fitness.stereoVisibility; });
  add(app.add_option("--trust-threshold", p.judgement.confidence.threshold, "confidence from which an estimate is trusted")
          ->check(CLI::Range(0.001, 0.999)),
      [](tracker::TrackerParams &t, const tracker::TrackerParams &c) { t.judgement.confidence.threshold = c.judgement.confidence.threshold; });
}

tracker::TrackerParams TrackerOptions::resolve() const
{
  // The options given, applied in order over the defaults or the file: --budget-ms switches to a
  // wall-time budget (the defaults' is in evaluations), --budget-evals after it wins.
  std::string notice;
  tracker::TrackerParams p = m_config.empty() ? m_defaults : tracker::loadTrackerConfig(m_config, m_defaults, &notice);
  if (!notice.empty())
    std::cerr << "notice: " << notice << "\n";
  for (const auto &[opt, set] : m_set)
    if (opt->count() > 0)
      set(p, m_cli);
  p.validate();
  return p;
}

} // namespace pm::app
