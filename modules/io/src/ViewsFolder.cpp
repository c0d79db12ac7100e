#include "pm/io/ViewsFolder.h"

#include <cstdio>
#include <filesystem>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PoseFile.h"
#include "pm/io/StagedFiles.h"

namespace pm::io {

namespace fs = std::filesystem;

namespace {
const char *const kStems[5] = {"left", "right", "background_left", "background_right", "pose_fPh"};

std::string viewName(std::size_t k)
{
  char b[32];
  std::snprintf(b, sizeof b, "view %02zu", k);
  return b;
}
} // namespace

std::string viewFileName(const std::string &stem, std::size_t k)
{
  char b[64];
  std::snprintf(b, sizeof b, "_%02zu", k);
  return stem + b + (stem == "pose_fPh" ? ".yaml" : ".png");
}

std::vector<model::PassView> loadViewsFolder(const std::string &dir, const core::StereoRig &rig, std::size_t minViews, bool backgrounds)
{
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw core::Error("the views folder '" + dir + "' does not exist");
  std::vector<model::PassView> views;
  // Room for every view first: a view without backgrounds must not be copied by a reallocation
  // (ViSP 3.5 copies an empty vpImage with memcpy(nullptr)).
  std::size_t count = 0;
  while (count < 1000 && (fs::exists(fs::path(dir) / viewFileName("left", count), ec) ||
                          fs::exists(fs::path(dir) / viewFileName("pose_fPh", count), ec)))
    ++count;
  views.reserve(count + 1);
  for (std::size_t k = 0; k < 1000; ++k) {
    bool any = false, all = true;
    std::string missing;
    for (const char *stem : kStems) {
      if (!backgrounds && std::string(stem).rfind("background", 0) == 0)
        continue;
      const bool here = fs::exists(fs::path(dir) / viewFileName(stem, k), ec);
      any = any || here;
      if (!here && all) {
        all = false;
        missing = viewFileName(stem, k);
      }
    }
    if (!any)
      break;
    const std::string name = viewName(k);
    if (!all)
      throw core::Error(name + " of '" + dir + "' lacks " + missing + " (each view needs " + viewFileName("left", k) + ", " +
                  viewFileName("right", k) + ", " +
                  (backgrounds ? viewFileName("background_left", k) + ", " + viewFileName("background_right", k) + " " : std::string()) +
                  "and " + viewFileName("pose_fPh", k) + ")");
    model::PassView v;
    v.name = name;
    auto image = [&](const char *stem, const core::PinholeCamera &cam, vpImage<vpRGBa> &out) {
      const std::string path = (fs::path(dir) / viewFileName(stem, k)).string();
      try {
        out = readColorImage(path);
      } catch (const core::Error &e) {
        throw core::Error(name + ": " + e.what());
      }
      if (out.getWidth() != cam.width || out.getHeight() != cam.height)
        throw core::Error(name + ": " + viewFileName(stem, k) + " is " + std::to_string(out.getWidth()) + "x" +
                    std::to_string(out.getHeight()) + " but the rig's camera is " + std::to_string(cam.width) + "x" +
                    std::to_string(cam.height));
    };
    image("left", rig.left, v.left);
    image("right", rig.right, v.right);
    if (backgrounds) {
      image("background_left", rig.left, v.backgroundLeft);
      image("background_right", rig.right, v.backgroundRight);
    }
    try {
      v.fMh = readPoseYaml((fs::path(dir) / viewFileName("pose_fPh", k)).string());
    } catch (const core::Error &e) {
      throw core::Error(name + ": " + e.what());
    }
    views.push_back(std::move(v));
  }
  if (views.empty())
    throw core::Error("the views folder '" + dir + "' holds no view (" + viewFileName("left", 0) + ", " +
                viewFileName("right", 0) + ", ... expected)");
  if (views.size() < minViews)
    throw core::Error("the views folder '" + dir + "' holds " + std::to_string(views.size()) + " views; at least " +
                std::to_string(minViews) + " are needed");
  return views;
}

void saveViewsFolder(const std::vector<model::PassView> &views, const std::string &dir)
{
  StagedFiles out(dir);
  for (std::size_t k = 0; k < views.size(); ++k) {
    const model::PassView &v = views[k];
    writeImage(v.left, out.stage(viewFileName("left", k)));
    writeImage(v.right, out.stage(viewFileName("right", k)));
    if (v.backgroundLeft.getSize() > 0) // a pass against a plain backdrop has none
      writeImage(v.backgroundLeft, out.stage(viewFileName("background_left", k)));
    if (v.backgroundRight.getSize() > 0)
      writeImage(v.backgroundRight, out.stage(viewFileName("background_right", k)));
    writePoseYaml(v.fMh, out.stage(viewFileName("pose_fPh", k)));
  }
  out.commit();
}

} // namespace pm::io
