//! pm-export-scene: a lab scene written out for another renderer (Blender's Cycles, scripts/cycles/render.py).
#include <iostream>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/io/RigFile.h"
#include "pm/lab/SceneExport.h"

int main(int argc, char **argv)
{
  CLI::App app{"Writes a lab scene for another renderer (scripts/cycles/render.py renders it with Blender's Cycles): the toy's mesh "
               "cut along its outline and its texture, the backdrop, the rig, the pass's hand poses, a sequence of the toy's "
               "poses with its truth and an area light, in scene.json and OBJ files; and the same pass and sequence rendered by "
               "our own rasterizer (lab_views/, lab_sequence/) for comparison.",
               "pm-export-scene"};
  app.option_defaults()->always_capture_default();
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  pm::lab::SceneExportParams p;
  app.add_option("--out", out, "output folder (replaced)")->required();
  app.add_option("--target", p.target, "the toy: C01..C12, or a relief target R1..R3");
  app.add_option("--backdrop", p.backdrop, "the other renderer's backdrop: sea-bottom (the lab's) or cloth (a green cloth)");
  app.add_flag("--still-backdrop", p.stillBackdrop, "the backdrop stands still behind the toy while the toy moves (else the toy rests on it)");
  app.add_option("--still-gap-mm", p.stillGapMm, "the still backdrop's distance behind the toy (mm)")->check(CLI::Range(0.0, 500.0));
  app.add_option("--light-size-mm", p.lightSizeMm, "the side of the square area light (mm): the larger, the softer the shadows")
      ->check(CLI::PositiveNumber);
  app.add_option("--rig", rigPath, "stereo rig file");
  bool quiet = false;
  app.add_flag("--quiet", quiet, "nothing on stdout");

  return pm::app::run(app, argc, argv, [&] {
    pm::lab::exportScene(p, pm::io::loadRig(rigPath), out);
    if (!quiet)
      std::cout << "scene of " << p.target << " written to " << out << "/ (render it: blender -b -P scripts/cycles/render.py -- " << out
              << ")" << std::endl;
    return 0;
  });
}
