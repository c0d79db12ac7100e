#include "pm/trust/HeldOutViews.h"

#include <algorithm>

namespace pm::trust {

std::vector<std::vector<std::size_t>> heldOutFolds(std::size_t views, std::size_t count)
{
  if (views < 2 || count == 0)
    return {};
  const std::size_t n = std::min(count, views - 1);
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < n; ++i) // the i-th of n spread over views 1 .. views - 1
    out.push_back({1 + (2 * i + 1) * (views - 1) / (2 * n)});
  return out;
}

FoldModel buildFoldModel(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                         const model::PassMeasurements &measured, const std::vector<std::size_t> &heldOut)
{
  model::AllAroundBuild b = model::buildAllAroundModelWithout(rig, pass, params, measured, heldOut);
  FoldModel m;
  m.model = std::move(b.model);
  m.fMm = b.fMm;
  m.heldOut = heldOut;
  return m;
}

} // namespace pm::trust
