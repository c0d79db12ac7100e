#include "pm/sim/TargetCatalog.h"

#include <algorithm>
#include <cctype>
#include <functional>

#include "CreatureParts.h"
#include "ReliefTargets.h"
#include "pm/core/Error.h"

namespace pm::sim {

namespace {

using catalog::creatureBuilders;
using catalog::reliefBuilders;

std::string upper(const std::string &code)
{
  std::string u = code;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
  return u;
}

int indexIn(const std::vector<TargetInfo> &cat, const std::string &code)
{
  const std::string u = upper(code);
  for (std::size_t i = 0; i < cat.size(); ++i)
    if (cat[i].code == u)
      return static_cast<int>(i);
  return -1;
}

int indexOf(const std::string &code) { return indexIn(targetCatalog(), code); }

int reliefIndexOf(const std::string &code) { return indexIn(reliefTargetCatalog(), code); }

} // namespace

const std::vector<TargetInfo> &targetCatalog()
{
  static const std::vector<TargetInfo> cat = [] {
    std::vector<TargetInfo> v;
    for (const auto &b : creatureBuilders())
      v.push_back(b().info);
    return v;
  }();
  return cat;
}

const std::vector<TargetInfo> &reliefTargetCatalog()
{
  static const std::vector<TargetInfo> cat = {{"R1", "poster box", 140, 100, 30},
                                              {"R2", "head on a stand", 120, 150, 55},
                                              {"R3", "pagoda tower", 70, 90, 110}};
  return cat;
}

const std::vector<TargetInfo> &labTargetCatalog()
{
  static const std::vector<TargetInfo> cat = [] {
    std::vector<TargetInfo> v = targetCatalog();
    v.insert(v.end(), reliefTargetCatalog().begin(), reliefTargetCatalog().end());
    return v;
  }();
  return cat;
}

bool isCatalogTarget(const std::string &code) { return indexOf(code) >= 0 || reliefIndexOf(code) >= 0; }

bool isReliefTarget(const std::string &code) { return reliefIndexOf(code) >= 0; }

TargetShape makeTarget(const std::string &code, double texelMm)
{
  const int i = indexOf(code), ri = reliefIndexOf(code);
  if (i < 0 && ri < 0)
    throw core::Error("unknown target '" + code + "': the catalogue has C01..C12 and R1..R3");
  if (!(texelMm > 0.02 && texelMm <= 5))
    throw core::Error("target texel size must lie in (0.02, 5] mm");
  if (ri >= 0)
    return reliefBuilders()[static_cast<std::size_t>(ri)](texelMm);
  return catalog::rasterise(creatureBuilders()[static_cast<std::size_t>(i)](), texelMm);
}

} // namespace pm::sim
