//! pm-render: renders what the stereo rig sees of a simulated target on the sea bottom.
#include <iomanip>
#include <iostream>
#include <map>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/app/Progress.h"
#include "pm/core/Pose.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/lab/TargetRendering.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

int main(int argc, char **argv)
{
  CLI::App app{"Renders the image each camera of the rig sees of a simulated target (one of the paper's 12 "
               "sea creatures, or a user's image) resting on the sea-bottom backdrop, at a pose phi in the hand "
               "frame. Writes <target>_<camera>.png for each camera (a stereo rig: <target>_left.png, <target>_right.png), "
               "<target>_stereo.png (any other rig: <target>_views.png), <target>_relief.png (the "
               "toy turned by +-0.3 about y: its relief changes the view) and summary.json with the render time.",
               "pm-render"};
  app.option_defaults()->always_capture_default();
  std::string out, target = "C12", texture, pose = "0,0,500,0,0,0";
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  double widthMm = 150, depthMm = 20;
  bool all = false, quiet = false;
  int repeat = 5;
  pm::sim::SceneParams sp;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", target, "target C01..C12, or a relief target R1..R3 (box, head, tower)");
  app.add_flag("--all-targets", all, "render the 12 targets and a gallery.png")->excludes(optTarget);
  app.add_option("--texture", texture, "render a target made from this image instead (PNG/JPEG)")->excludes(optTarget);
  app.add_option("--width-mm", widthMm, "with --texture: physical width (mm)")->check(CLI::PositiveNumber);
  app.add_option("--depth-mm", depthMm, "with --texture: relief (mm)")->check(CLI::NonNegativeNumber);
  app.add_option("--pose", pose, "phi = x,y,z,eps1,eps2,eps3 of the target in the hand frame (mm, quaternion vector)");
  app.add_option("--rig", rigPath, "rig file: one camera or more (data/rig/pa10_mono.json: one, pa10_trio.json: three)");
  pm::app::addSceneOptions(app, sp);
  pm::app::DistractorChoice distractor;
  pm::app::addDistractorOptions(app, distractor);
  const std::map<std::string, pm::sim::ShadowMode> shadowModes{
      {"auto", pm::sim::ShadowMode::Auto}, {"on", pm::sim::ShadowMode::On}, {"off", pm::sim::ShadowMode::Off}};
  app.add_option("--shadows", sp.shadows,
                 "light: auto (a light fixed in the scene with cast shadows for R1..R3, the hand light for the "
                 "others), on, or off (the hand light, no shadows)")
      ->transform(CLI::CheckedTransformer(shadowModes, CLI::ignore_case))
      ->group("Simulator");
  app.add_option("--repeat", repeat, "frames of the rig rendered to time the renderer")->check(CLI::Range(1, 1000));
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const auto v = pm::app::parseNumbers(pose, 6, "--pose");
    const pm::core::Phi phi{v[0], v[1], v[2], v[3], v[4], v[5]};
    const pm::core::CameraRig rig = pm::io::loadCameraRig(rigPath);

    std::vector<std::string> codes;
    if (all)
      for (const auto &t : pm::sim::targetCatalog())
        codes.push_back(t.code);
    else
      codes.push_back(texture.empty() ? target : std::string("user"));

    std::vector<pm::lab::RenderedTarget> rendered;
    pm::app::Progress progress("rendering", codes.size() * static_cast<std::size_t>(repeat + 2), quiet);
    for (const auto &code : codes) {
      const pm::sim::TargetShape shape = code == "user" ? pm::sim::targetFromImage(pm::io::readColorImage(texture), widthMm, depthMm, texture)
                                                        : pm::sim::makeTarget(code);
      pm::sim::Scene scene(shape, sp);
      distractor.apply(scene);
      rendered.push_back(pm::lab::renderTarget(scene, shape, rig, phi, repeat, [&](std::size_t n) { progress.step(n); }));
    }
    progress.finish();
    const double meanMs = pm::lab::writeRenderedTargets(out, rendered, phi, sp, all);
    if (!quiet)
      std::cout << std::fixed << std::setprecision(1) << "rendered " << codes.size() << " target(s) at phi = "
                << phi.toString() << ": " << meanMs << " ms per frame of " << rig.size() << (rig.size() == 1 ? " camera (" : " cameras (")
                << rig[0].width << "x" << rig[0].height << ", " << sp.supersampling << "x" << sp.supersampling
                << " samples per pixel), written to " << out << "/" << std::endl;
    return 0;
  });
}
