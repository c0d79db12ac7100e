#include "pm/app/Options.h"

namespace pm::app {

void addModelOptions(CLI::App &app, PhotoModelParams &p)
{
  const char *g = "Photo-model";
  app.add_option("--step-px", p.stepPx, "sampling step of S_in (grid) and along S_out (px)")->check(CLI::Range(1.0, 200.0))->group(g);
  app.add_option("--strip-gap-px", p.stripGapPx, "distance of S_out's first row from the target's outline (px)")
      ->check(CLI::Range(1.0, 200.0))->group(g);
  app.add_option("--strip-width-px", p.stripWidthPx, "width of the S_out strip beyond its first row (px)")
      ->check(CLI::Range(0.0, 200.0))->group(g);
  app.add_option("--strip-rows", p.stripRows, "rows of points across the S_out strip")->check(CLI::Range(1, 20))->group(g);
  app.add_option("--region-hue-tol-deg", p.regionHueTolDeg, "hue change that marks a target pixel (deg)")
      ->check(CLI::Range(1.0, 179.0))->group(g);
  app.add_option("--min-saturation", p.minSaturation, "photo pixels less saturated carry no hue")->check(CLI::Range(0.0, 0.99))->group(g);
}

void addSceneOptions(CLI::App &app, sim::SceneParams &p)
{
  const char *g = "Simulator";
  app.add_option("--noise", p.noiseSigma, "sensor noise (grey levels)")->check(CLI::Range(0.0, 100.0))->group(g);
  app.add_option("--exposure", p.exposure, "brightness gain (lighting change)")->check(CLI::Range(0.05, 10.0))->group(g);
  app.add_flag("--occluder", p.occluder, "put a strand of seaweed in front of the target")->group(g);
  app.add_option("--supersampling", p.supersampling, "samples per pixel along each axis (anti-aliasing)")
      ->check(CLI::Range(1u, 4u))->group(g);
  app.add_option("--seed", p.seed, "noise seed")->group(g);
}

void addFitnessOptions(CLI::App &app, FitnessParams &p)
{
  const char *g = "Fitness";
  app.add_option("--in-tol-deg", p.inTolDeg, "S_in: |H_I - H_M| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
  app.add_option("--in-bg-tol-deg", p.inBgTolDeg, "S_in: |H_B - H_I| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
  app.add_option("--out-bg-tol-deg", p.outBgTolDeg, "S_out: |H_B - H_I| tolerance (deg)")->check(CLI::Range(0.0, 180.0))->group(g);
}

} // namespace pm::app
