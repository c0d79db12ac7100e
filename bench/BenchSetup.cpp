#include "BenchSetup.h"

#include <algorithm>
#include <cmath>

#include "pm/app/App.h"
#include "pm/io/RigFile.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::bench {

Setup::Setup()
{
  rig = pm::io::loadRig(pm::app::dataPath("rig/pa10_stereo.json"));
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500);
  model = sm.build.model;
  truth = sm.truth(hMo);
  // A 1,000-point model: the crab sampled more densely, thinned to exactly 1,000 points.
  pm::model::PhotoModelParams dense;
  dense.stepPx = 5;
  const pm::core::PhotoModel d = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500, dense).build.model;
  model1000 = d;
  const std::size_t nIn = 1000 * d.inner.size() / d.size(), nOut = 1000 - nIn;
  model1000.inner.clear();
  model1000.outer.clear();
  for (std::size_t i = 0; i < nIn; ++i)
    model1000.inner.push_back(d.inner[i * d.inner.size() / nIn]);
  for (std::size_t i = 0; i < nOut; ++i)
    model1000.outer.push_back(d.outer[i * d.outer.size() / nOut]);
  // The same 1,000 points with a relief (a dome 30 mm high): the 3-D kernel, same point count.
  model1000Depth = model1000;
  for (auto *set : {&model1000Depth.inner, &model1000Depth.outer})
    for (pm::core::ModelPoint &p : *set)
      p.z = -30.f * std::max(0.05f, 1.f - (p.x * p.x + p.y * p.y) / (90.f * 90.f));
  images = scene.renderStereo(rig, hMo, 0);
}

const Setup &setup()
{
  static const Setup s;
  return s;
}

std::vector<pm::core::Phi> poses(std::size_t n)
{
  std::vector<pm::core::Phi> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i);
    v.push_back({10 * std::sin(k), 10 * std::cos(1.3 * k), 500 + 20 * std::sin(0.7 * k), 0.05 * std::sin(2.1 * k),
                 0.05 * std::cos(1.7 * k), 0.05 * std::sin(0.3 * k)});
  }
  return v;
}

} // namespace pm::bench
