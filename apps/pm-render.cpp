//! pm-render: renders what the stereo rig sees of a simulated target on the sea bottom.
#include <algorithm>
#include <numeric>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/Overlay.h"
#include "pm/app/Progress.h"
#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

namespace {

vpImage<vpRGBa> halfSize(const vpImage<vpRGBa> &I)
{
  vpImage<vpRGBa> o(I.getHeight() / 2, I.getWidth() / 2);
  for (unsigned v = 0; v < o.getHeight(); ++v)
    for (unsigned u = 0; u < o.getWidth(); ++u) {
      unsigned s[3] = {0, 0, 0};
      for (unsigned j = 0; j < 2; ++j)
        for (unsigned i = 0; i < 2; ++i) {
          const vpRGBa &p = I[2 * v + j][2 * u + i];
          s[0] += p.R, s[1] += p.G, s[2] += p.B;
        }
      o[v][u] = vpRGBa(static_cast<unsigned char>(s[0] / 4), static_cast<unsigned char>(s[1] / 4),
                       static_cast<unsigned char>(s[2] / 4));
    }
  return o;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Renders the left and right images the stereo rig sees of a simulated target (one of the paper's 12 "
               "sea creatures, or a user's image) resting on the sea-bottom backdrop, at a pose phi in the hand "
               "frame. Writes <target>_left.png, <target>_right.png, <target>_stereo.png, <target>_relief.png (the "
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
  app.add_option("--rig", rigPath, "stereo rig file");
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
  app.add_option("--repeat", repeat, "stereo frames rendered to time the renderer")->check(CLI::Range(1, 1000));
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const auto v = pm::app::parseNumbers(pose, 6, "--pose");
    const pm::Phi phi{v[0], v[1], v[2], v[3], v[4], v[5]};
    const vpHomogeneousMatrix hMo = pm::toHomogeneousMatrix(phi);
    const pm::StereoRig rig = pm::io::loadRig(rigPath);

    std::vector<std::string> codes;
    if (all)
      for (const auto &t : pm::sim::targetCatalog())
        codes.push_back(t.code);
    else
      codes.push_back(texture.empty() ? target : std::string("user"));

    pm::io::StagedFiles files(out);
    nlohmann::json targets = nlohmann::json::array();
    std::vector<vpImage<vpRGBa>> thumbs;
    std::vector<double> renderMs;
    pm::app::Progress progress("rendering", codes.size() * static_cast<std::size_t>(repeat + 2), quiet);
    for (const auto &code : codes) {
      const pm::sim::TargetShape shape = code == "user" ? pm::sim::targetFromImage(pm::io::readColorImage(texture), widthMm, depthMm, texture)
                                                        : pm::sim::makeTarget(code);
      pm::sim::Scene scene(shape, sp);
      distractor.apply(scene);
      pm::sim::StereoImages im;
      double ms = 0;
      for (int r = 0; r < repeat; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        im = scene.renderStereo(rig, hMo, static_cast<std::uint64_t>(r));
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        progress.step();
      }
      ms /= repeat;
      renderMs.push_back(ms);
      // The relief seen from three sides: turned about y by -0.3, 0, +0.3 (quaternion vector).
      vpImage<vpRGBa> turned[3];
      pm::sim::Rasterizer raster;
      for (int k = 0; k < 3; ++k) {
        pm::Phi p = phi;
        p.e2 = (k - 1) * 0.3;
        scene.render(raster, rig.left, pm::toHomogeneousMatrix(p), 0, 0, turned[k]);
      }
      progress.step(2);
      const std::string c = shape.info.code == "user" ? "user" : shape.info.code;
      vpImage<vpRGBa> L = im.left, R = im.right;
      pm::report::drawLabel(L, c + " " + shape.info.name + " - left", 8, 8, vpRGBa(255, 255, 255));
      pm::report::drawLabel(R, "right", 8, 8, vpRGBa(255, 255, 255));
      pm::io::writeImage(im.left, files.stage(c + "_left.png"));
      pm::io::writeImage(im.right, files.stage(c + "_right.png"));
      pm::io::writeImage(pm::report::sideBySide(L, R), files.stage(c + "_stereo.png"));
      vpImage<vpRGBa> rel = pm::report::sideBySide(pm::report::sideBySide(halfSize(turned[0]), halfSize(turned[1])), halfSize(turned[2]));
      pm::report::drawLabel(rel, c + " turned eps2 = -0.3, 0, +0.3 (left camera)", 6, 6, vpRGBa(255, 255, 255));
      pm::io::writeImage(rel, files.stage(c + "_relief.png"));
      double w = 0, h = 0;
      shape.measuredExtent(w, h);
      targets.push_back({{"code", c},
                         {"name", shape.info.name},
                         {"nominal_size_mm", {shape.info.widthMm, shape.info.heightMm, shape.info.depthMm}},
                         {"measured_outline_mm", {w, h}},
                         {"triangles", scene.targetTriangles()},
                         {"render_stereo_ms", ms}});
      vpImage<vpRGBa> th = halfSize(im.left);
      pm::report::drawLabel(th, c + " " + shape.info.name, 4, 4, vpRGBa(255, 255, 255));
      thumbs.push_back(th);
    }
    progress.finish();
    if (all) {
      const unsigned tw = thumbs[0].getWidth(), th = thumbs[0].getHeight();
      vpImage<vpRGBa> g(3 * th, 4 * tw);
      for (std::size_t i = 0; i < thumbs.size(); ++i)
        g.insert(thumbs[i], vpImagePoint(static_cast<double>((i / 4) * th), static_cast<double>((i % 4) * tw)));
      pm::io::writeImage(g, files.stage("gallery.png"));
    }
    const double meanMs = std::accumulate(renderMs.begin(), renderMs.end(), 0.0) / static_cast<double>(renderMs.size());
    const nlohmann::json summary{{"pose", v},
                                 {"supersampling", sp.supersampling},
                                 {"noise_sigma", sp.noiseSigma},
                                 {"exposure", sp.exposure},
                                 {"occluder", sp.occluder},
                                 {"render_stereo_ms_mean", meanMs},
                                 {"targets", targets}};
    pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
    files.commit();
    if (!quiet)
      std::cout << std::fixed << std::setprecision(1) << "rendered " << codes.size() << " target(s) at phi = "
                << phi.toString() << ": " << meanMs << " ms per stereo frame (" << rig.left.width << "x"
                << rig.left.height << ", " << sp.supersampling << "x" << sp.supersampling
                << " samples per pixel), written to " << files.dir() << "/" << std::endl;
    return 0;
  });
}
