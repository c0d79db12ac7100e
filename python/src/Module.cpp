// The Python module visp_photomodel (python/README in docs/tutorial-python.md): the model, the
// tracker and the servo loop from Python, with NumPy images.
#include <visp3/core/vpException.h>

#include "Bindings.h"
#include "pm/core/Error.h"
#include "pm/io/DataDir.h"

PYBIND11_MODULE(visp_photomodel, m)
{
  m.doc() = "visp-photomodel from Python: rigs and camera files, photo-models (loaded, saved, built from a pass of the hand), "
            "the photo-model tracker on NumPy images (H x W x 3 BGR as OpenCV gives them, H x W x 4 RGBA as ViSP holds "
            "them), and the simulated lab (stereo pairs of a toy at a pose, the servo loop frame by frame).\n\n"
            "Poses are 4 x 4 NumPy arrays in metres (hMo: the model in the hand frame). Errors raise "
            "visp_photomodel.Error with the one-line message the programs print after 'error: '.";
  static pybind11::exception<pm::core::Error> error(m, "Error", PyExc_RuntimeError);
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const pm::core::Error &e) {
      error(e.what());
    } catch (const vpException &e) {
      error(e.what());
    }
  });
  m.def(
      "data_path",
      [](const std::string &relative) { return pm::io::dataDir(PM_SOURCE_DATA_DIR, PM_INSTALL_DATA_DIR) + "/" + relative; },
      pybind11::arg("relative"),
      "The path of a shipped data file (e.g. 'rig/pa10_stereo.json'), where the programs find it: $PM_DATA_DIR, the source "
      "tree's data/, or the installed share/visp-photomodel/.");
  pmpy::bindRig(m);
  pmpy::bindImages(m);
  pmpy::bindModel(m);
  pmpy::bindTracker(m);
  pybind11::module_ lab = m.def_submodule("lab", "The simulated lab: the catalogue's toys rendered at a pose, their models, the servo loop.");
  pmpy::bindLab(lab);
}
