// Photo-model generation (Fig. 4), its file format and its errors.
#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/PhotoModelBuilder.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

namespace {

const vpCameraParameters kCam(754, 754, 320, 240);

struct Disc
{
  vpImage<vpRGBa> bg, tg;
  double cu = 350, cv = 220, r = 60;
};

Disc redDisc()
{
  Disc d;
  d.bg = pm::test::bluePhoto(640, 480, 1);
  d.tg = pm::test::bluePhoto(640, 480, 2);
  pm::test::paintDisc(d.tg, d.cu, d.cv, d.r, vpRGBa(200, 40, 30));
  return d;
}

} // namespace

TEST(PhotoModel, DiscRegionCentroidAndSampling)
{
  const Disc d = redDisc();
  pm::PhotoModelParams p;
  const pm::PhotoModelBuild b = pm::buildPhotoModel(d.bg, d.tg, kCam, 500, p);
  const pm::PhotoModel &m = b.model;
  EXPECT_NEAR(m.centroidU, d.cu, 0.3);
  EXPECT_NEAR(m.centroidV, d.cv, 0.3);
  const double expectedIn = M_PI * d.r * d.r / (p.stepPx * p.stepPx);
  EXPECT_NEAR(static_cast<double>(m.inner.size()), expectedIn, 0.05 * expectedIn);
  EXPECT_LT(pm::hueDistance(m.targetHue, pm::hueDeg(vpRGBa(200, 40, 30))), 1.f);
  EXPECT_LT(pm::hueDistance(m.backgroundHue, pm::hueDeg(vpRGBa(30, 90, 170))), 2.f);
  for (const auto &q : m.inner) {
    EXPECT_LE(std::hypot(q.u - d.cu, q.v - d.cv), d.r + 0.5);
    // M_r = ((u - cu) d / px, (v - cv) d / py, 0)
    EXPECT_NEAR(q.x, (q.u - m.centroidU) * 500 / 754, 1e-3);
    EXPECT_NEAR(q.y, (q.v - m.centroidV) * 500 / 754, 1e-3);
    EXPECT_EQ(q.z, 0.f);
  }
  // S_out envelops S_in at the strip's distances from the outline.
  ASSERT_GT(m.outer.size(), 2u * 2 * M_PI * d.r / p.stepPx * 0.8);
  for (const auto &q : m.outer) {
    const double dist = std::hypot(q.u - d.cu, q.v - d.cv) - d.r;
    EXPECT_GE(dist, p.stripGapPx - 1.5);
    EXPECT_LE(dist, p.stripGapPx + p.stripWidthPx + 1.5);
  }
}

TEST(PhotoModel, DensityAndStripAreParameters)
{
  const Disc d = redDisc();
  pm::PhotoModelParams coarse, fine;
  fine.stepPx = 4;
  fine.stripRows = 3;
  fine.stripGapPx = 10;
  const auto a = pm::buildPhotoModel(d.bg, d.tg, kCam, 500, coarse).model;
  const auto b = pm::buildPhotoModel(d.bg, d.tg, kCam, 500, fine).model;
  EXPECT_NEAR(static_cast<double>(b.inner.size()) / static_cast<double>(a.inner.size()), 4.0, 0.3);
  EXPECT_GT(b.outer.size(), 2 * a.outer.size());
  for (const auto &q : b.outer)
    EXPECT_GE(std::hypot(q.u - d.cu, q.v - d.cv) - d.r, 10 - 1.5);
}

TEST(PhotoModel, SmallHolesFilledLargeHolesKept)
{
  Disc d = redDisc();
  pm::test::paintDisc(d.tg, d.cu - 25, d.cv, 4, vpRGBa(30, 90, 170));  // a blue spot: part of the target
  pm::test::paintDisc(d.tg, d.cu + 25, d.cv, 20, vpRGBa(30, 90, 170)); // a big window onto the background
  const auto b = pm::buildPhotoModel(d.bg, d.tg, kCam, 500);
  EXPECT_EQ(b.region[static_cast<unsigned>(d.cv)][static_cast<unsigned>(d.cu - 25)], 255);
  EXPECT_EQ(b.region[static_cast<unsigned>(d.cv)][static_cast<unsigned>(d.cu + 25)], 0);
}

TEST(PhotoModel, EveryCatalogTargetGivesAModel)
{
  const pm::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::sim::SceneParams sp;
  sp.supersampling = 1; // keeps the suite fast; the outline is what matters here
  for (const auto &info : pm::sim::targetCatalog()) {
    pm::sim::TargetShape shape = pm::sim::makeTarget(info.code, 0.5);
    vpImage<vpRGBa> bg, tg;
    pm::sim::Scene(shape, sp).renderPhotos(rig.left.cam, 640, 480, 500, bg, tg);
    const pm::PhotoModel m = pm::buildPhotoModel(bg, tg, rig.left.cam, 500).model;
    EXPECT_GT(m.inner.size(), 20u) << info.code;
    EXPECT_GT(m.outer.size(), 20u) << info.code;
    EXPECT_GT(pm::hueDistance(m.targetHue, m.backgroundHue), 60.f) << info.code;
    // Made flat, the toy projects without parallax, so the model's origin (the region's centroid)
    // falls on the toy's own origin (its outline's centroid): the frames agree to within the photo's
    // resolution (1 mm = 1.5 px: tentacles and arm tips 2-4 px wide lose their blended edge pixels).
    shape.info.depthMm = 0;
    std::fill(shape.height.begin(), shape.height.end(), 0.f);
    pm::sim::Scene(shape, sp).renderPhotos(rig.left.cam, 640, 480, 500, bg, tg);
    const pm::PhotoModel f = pm::buildPhotoModel(bg, tg, rig.left.cam, 500).model;
    EXPECT_LT(std::hypot((f.centroidU - 320) * 500 / 754, (f.centroidV - 240) * 500 / 754), 1.0) << info.code;
  }
}

TEST(PhotoModel, FileRoundTrip)
{
  const Disc d = redDisc();
  const pm::PhotoModel m = pm::buildPhotoModel(d.bg, d.tg, kCam, 500).model;
  pm::test::TempDir dir("model");
  pm::io::savePhotoModel(m, dir.file("m.json"));
  const pm::PhotoModel r = pm::io::loadPhotoModel(dir.file("m.json"));
  ASSERT_EQ(r.inner.size(), m.inner.size());
  ASSERT_EQ(r.outer.size(), m.outer.size());
  for (std::size_t i = 0; i < m.inner.size(); ++i) {
    EXPECT_FLOAT_EQ(r.inner[i].x, m.inner[i].x);
    EXPECT_FLOAT_EQ(r.inner[i].y, m.inner[i].y);
    EXPECT_FLOAT_EQ(r.inner[i].hue, m.inner[i].hue);
  }
  EXPECT_DOUBLE_EQ(r.distanceMm, 500);
  EXPECT_DOUBLE_EQ(r.px, 754);
  EXPECT_FLOAT_EQ(r.backgroundHue, m.backgroundHue);
  EXPECT_DOUBLE_EQ(r.centroidU, m.centroidU);
  EXPECT_EQ(pm::test::listFiles(dir.path()), std::vector<std::string>{"m.json"});
}

TEST(PhotoModel, PhotosOfDifferentSizesAreRefused)
{
  const Disc d = redDisc();
  vpImage<vpRGBa> small(240, 320);
  EXPECT_NE(pm::test::errorOf([&] { pm::buildPhotoModel(d.bg, small, kCam, 500); }).find("320x240"), std::string::npos);
}

TEST(PhotoModel, TargetOfTheBackgroundsHueGivesEmptySIn)
{
  Disc d = redDisc();
  d.tg = pm::test::bluePhoto(640, 480, 3);
  pm::test::paintDisc(d.tg, d.cu, d.cv, d.r, vpRGBa(40, 100, 180)); // blue on blue
  EXPECT_NE(pm::test::errorOf([&] { pm::buildPhotoModel(d.bg, d.tg, kCam, 500); }).find("S_in is empty"), std::string::npos);
}

TEST(PhotoModel, BadParametersAndDistanceAreRefused)
{
  const Disc d = redDisc();
  pm::PhotoModelParams p;
  p.stepPx = 0;
  EXPECT_THROW(pm::buildPhotoModel(d.bg, d.tg, kCam, 500, p), pm::Error);
  EXPECT_THROW(pm::buildPhotoModel(d.bg, d.tg, kCam, -1), pm::Error);
  vpCameraParameters bad;
  bad.initPersProjWithoutDistortion(-754, 754, 320, 240);
  EXPECT_THROW(pm::buildPhotoModel(d.bg, d.tg, bad, 500), pm::Error);
}

TEST(PhotoModel, CorruptFilesAreClearErrors)
{
  const Disc d = redDisc();
  const pm::PhotoModel m = pm::buildPhotoModel(d.bg, d.tg, kCam, 500).model;
  pm::test::TempDir dir("model");
  const std::string good = pm::io::photoModelToJson(m);
  struct Case
  {
    std::string text, expect;
  };
  std::string badHue = good;
  {
    const auto k = badHue.find("\"s_in\":[[") + 9;
    const auto c1 = badHue.find(',', k), c2 = badHue.find(',', c1 + 1), c3 = badHue.find(',', c2 + 1);
    badHue.replace(c2 + 1, c3 - c2 - 1, "400");
  }
  std::string noIn = good;
  noIn.replace(noIn.find("\"s_in\":["), 8, "\"s_in\":[],\"x\":[");
  const std::vector<Case> cases = {{good.substr(0, good.size() / 2), "corrupt"},
                                   {"", "corrupt"},
                                   {"[1,2,3]", "format"},
                                   {R"({"format":"something-else","version":1})", "format"},
                                   {badHue, "hue 400"},
                                   {noIn, "S_in is empty"}};
  for (const auto &c : cases) {
    pm::test::writeText(dir.file("m.json"), c.text);
    const std::string e = pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("m.json")); });
    EXPECT_NE(e.find(c.expect), std::string::npos) << "got: " << e;
    EXPECT_NE(e.find("m.json"), std::string::npos) << "got: " << e;
  }
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("none.json")); }).find("does not exist"), std::string::npos);
}
