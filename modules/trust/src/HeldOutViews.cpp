#include "pm/trust/HeldOutViews.h"

#include <algorithm>

namespace pm::trust {

std::vector<std::vector<std::size_t>> heldOutFolds(std::size_t views, std::size_t count, std::size_t perModel)
{
  if (views < 2 || count == 0 || perModel == 0)
    return {};
  const std::size_t n = std::min(count, views - 1);
  std::vector<std::size_t> spread; // the i-th of n spread over views 1 .. views - 1
  for (std::size_t i = 0; i < n; ++i)
    spread.push_back(1 + (2 * i + 1) * (views - 1) / (2 * n));
  // perModel views a model, as far apart in the pass as n allows: i, i + models, i + 2 models, ...
  const std::size_t models = (n + perModel - 1) / perModel;
  std::vector<std::vector<std::size_t>> out(models);
  for (std::size_t i = 0; i < n; ++i)
    out[i % models].push_back(spread[i]);
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
