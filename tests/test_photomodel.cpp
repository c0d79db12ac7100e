// Photo-model generation (Fig. 4), its file format and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include <cmath>
#include <random>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/ViewpointIndex.h"
#include "pm/model/BackgroundSubtraction.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/model/Silhouette.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
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
  pm::model::PhotoModelParams p;
  const pm::model::PhotoModelBuild b = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500, p);
  const pm::core::PhotoModel &m = b.model;
  EXPECT_NEAR(m.centroidU, d.cu, 0.3);
  EXPECT_NEAR(m.centroidV, d.cv, 0.3);
  const double expectedIn = M_PI * d.r * d.r / (p.stepPx * p.stepPx);
  EXPECT_NEAR(static_cast<double>(m.inner.size()), expectedIn, 0.05 * expectedIn);
  EXPECT_LT(pm::core::hueDistance(m.targetHue, pm::core::hueDeg(vpRGBa(200, 40, 30))), 1.f);
  EXPECT_LT(pm::core::hueDistance(m.backgroundHue, pm::core::hueDeg(vpRGBa(30, 90, 170))), 2.f);
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
  pm::model::PhotoModelParams coarse, fine;
  fine.stepPx = 4;
  fine.stripRows = 3;
  fine.stripGapPx = 10;
  const auto a = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500, coarse).model;
  const auto b = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500, fine).model;
  EXPECT_NEAR(static_cast<double>(b.inner.size()) / static_cast<double>(a.inner.size()), 4.0, 0.3);
  EXPECT_GT(b.outer.size(), 2 * a.outer.size());
  for (const auto &q : b.outer)
    EXPECT_GE(std::hypot(q.u - d.cu, q.v - d.cv) - d.r, 10 - 1.5);
}

TEST(PhotoModel, SmallHolesFilledLargeHolesKept)
{
  Disc d = redDisc();
  // Holes in the disc that show the background photo itself: a small spot (a background-like spot
  // on the target, filled) and a big window onto the background (kept).
  auto window = [&](double cu, double cv, double r) {
    for (unsigned v = 0; v < d.tg.getHeight(); ++v)
      for (unsigned u = 0; u < d.tg.getWidth(); ++u)
        if ((u - cu) * (u - cu) + (v - cv) * (v - cv) <= r * r)
          d.tg[v][u] = d.bg[v][u];
  };
  window(d.cu - 25, d.cv, 4);
  window(d.cu + 25, d.cv, 20);
  const auto b = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500);
  EXPECT_EQ(b.region[static_cast<unsigned>(d.cv)][static_cast<unsigned>(d.cu - 25)], 255);
  EXPECT_EQ(b.region[static_cast<unsigned>(d.cv)][static_cast<unsigned>(d.cu + 25)], 0);
}

TEST(PhotoModel, EveryCatalogTargetGivesAModel)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::sim::SceneParams sp;
  sp.supersampling = 1; // keeps the suite fast; the outline is what matters here
  for (const auto &info : pm::sim::targetCatalog()) {
    pm::sim::TargetShape shape = pm::sim::makeTarget(info.code, 0.5);
    vpImage<vpRGBa> bg, tg;
    pm::sim::Scene(shape, sp).renderPhotos(rig.left.cam, 640, 480, 500, bg, tg);
    const pm::core::PhotoModel m = pm::model::buildPhotoModel(bg, tg, rig.left.cam, 500).model;
    EXPECT_GT(m.inner.size(), 20u) << info.code;
    EXPECT_GT(m.outer.size(), 20u) << info.code;
    EXPECT_GT(pm::core::hueDistance(m.targetHue, m.backgroundHue), 60.f) << info.code;
    // Made flat, the toy projects without parallax, so the model's origin (the region's centroid)
    // falls on the toy's own origin (its outline's centroid): the frames agree to within the photo's
    // resolution (1 mm = 1.5 px: tentacles and arm tips 2-4 px wide lose their blended edge pixels).
    shape.info.depthMm = 0;
    std::fill(shape.height.begin(), shape.height.end(), 0.f);
    pm::sim::Scene(shape, sp).renderPhotos(rig.left.cam, 640, 480, 500, bg, tg);
    const pm::core::PhotoModel f = pm::model::buildPhotoModel(bg, tg, rig.left.cam, 500).model;
    EXPECT_LT(std::hypot((f.centroidU - 320) * 500 / 754, (f.centroidV - 240) * 500 / 754), 1.0) << info.code;
  }
}

TEST(PhotoModel, FileRoundTrip)
{
  const Disc d = redDisc();
  const pm::core::PhotoModel m = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500).model;
  pm::test::TempDir dir("model");
  pm::io::savePhotoModel(m, dir.file("m.json"));
  const pm::core::PhotoModel r = pm::io::loadPhotoModel(dir.file("m.json"));
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
  EXPECT_NE(pm::test::errorOf([&] { pm::model::buildPhotoModel(d.bg, small, kCam, 500); }).find("320x240"), std::string::npos);
}

TEST(PhotoModel, TargetOfTheBackgroundsHueGivesEmptySIn)
{
  Disc d = redDisc();
  d.tg = pm::test::bluePhoto(640, 480, 3);
  pm::test::paintDisc(d.tg, d.cu, d.cv, d.r, vpRGBa(40, 100, 180)); // blue on blue
  EXPECT_NE(pm::test::errorOf([&] { pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500); }).find("S_in is empty"), std::string::npos);
}

TEST(PhotoModel, BadParametersAndDistanceAreRefused)
{
  const Disc d = redDisc();
  pm::model::PhotoModelParams p;
  p.stepPx = 0;
  EXPECT_THROW(pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500, p), pm::core::Error);
  EXPECT_THROW(pm::model::buildPhotoModel(d.bg, d.tg, kCam, -1), pm::core::Error);
  vpCameraParameters bad;
  bad.initPersProjWithoutDistortion(-754, 754, 320, 240);
  EXPECT_THROW(pm::model::buildPhotoModel(d.bg, d.tg, bad, 500), pm::core::Error);
}

TEST(PhotoModel, CorruptFilesAreClearErrors)
{
  const Disc d = redDisc();
  const pm::core::PhotoModel m = pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500).model;
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

// ---- The stereo photo-model (the rig's two cameras, a depth per point) ----

namespace {

pm::core::StereoRig stereoLabRig() { return pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json")); }

//! A w x h picture of saturated patches of many hues (not the backdrop's blue) with fine detail.
vpImage<vpRGBa> colourfulPicture(unsigned w, unsigned h, unsigned seed)
{
  vpImage<vpRGBa> I(h, w);
  std::uint32_t s = seed * 2654435761u + 1;
  auto rnd = [&s] {
    s = s * 1664525u + 1013904223u;
    return static_cast<double>(s >> 8) / 16777216.0;
  };
  const double hues[5] = {0, 35, 60, 110, 300}; // red, orange, yellow, green, magenta
  const int cell = 6;
  for (unsigned v = 0; v < h; v += cell)
    for (unsigned u = 0; u < w; u += cell) {
      const double hue = hues[static_cast<int>(rnd() * 5) % 5] + 10 * rnd(), val = 0.45 + 0.55 * rnd();
      const double hh = std::fmod(hue, 360.0) / 60.0, f = hh - std::floor(hh), sat = 0.85;
      const double p = val * (1 - sat), q = val * (1 - sat * f), t = val * (1 - sat * (1 - f));
      const double tab[6][3] = {{val, t, p}, {q, val, p}, {p, val, t}, {p, q, val}, {t, p, val}, {val, p, q}};
      const double *c = tab[static_cast<int>(hh) % 6];
      const vpRGBa rgb(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                       static_cast<unsigned char>(255 * c[2]));
      for (unsigned j = v; j < std::min(h, v + cell); ++j)
        for (unsigned i = u; i < std::min(w, u + cell); ++i)
          I[j][i] = rgb;
    }
  return I;
}

struct StereoPhotos
{
  vpImage<vpRGBa> bgL, bgR, L, R;
};

StereoPhotos stereoPhotos(const pm::sim::Scene &scene, const pm::core::StereoRig &rig, double distanceMm)
{
  StereoPhotos p;
  pm::sim::Rasterizer r;
  const vpHomogeneousMatrix hMo(0, 0, distanceMm * 1e-3, 0, 0, 0);
  scene.render(r, rig.left, hMo, 0, 4, p.bgL, false);
  scene.render(r, rig.right, hMo, 0, 5, p.bgR, false);
  scene.render(r, rig.left, hMo, 0, 6, p.L, true);
  scene.render(r, rig.right, hMo, 0, 7, p.R, true);
  return p;
}

} // namespace

TEST(StereoPhotoModel, ABoxTopLiesAtItsHeightAndTheOriginAtItsCentroid)
{
  // A 120 x 90 mm picture on a block whose top is flat 30 mm in front of its base, beyond a
  // rounded edge 30 mm wide: the points of the flat top must lie at hand z = 500 - 30.
  const pm::core::StereoRig rig = stereoLabRig();
  const pm::sim::TargetShape box = pm::sim::targetFromImage(colourfulPicture(480, 360, 3), 120, 30, "box");
  const pm::sim::Scene scene(box);
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig, 500);
  const pm::core::PhotoModel &m = sm.build.model;
  ASSERT_TRUE(m.hasDepth());
  EXPECT_NEAR(sm.backdropMm, 500, 25); // the backdrop measured, not given (left camera's axis)
  EXPECT_LT(m.nInDropped, static_cast<int>(m.inner.size())); // most of a textured picture matches
  int onTop = 0;
  double sum[3] = {0, 0, 0};
  for (const auto &q : m.inner) {
    const double xh = q.x + m.originInHandMm[0], yh = q.y + m.originInHandMm[1], zh = q.z + m.originInHandMm[2];
    sum[0] += xh;
    sum[1] += yh;
    sum[2] += zh;
    if (std::fabs(xh) < 25 && std::fabs(yh) < 10) { // the flat top, 30 mm from every edge
      ++onTop;
      EXPECT_NEAR(zh, 470, 1.5) << "point at " << xh << ", " << yh;
    }
    EXPECT_GT(zh, 470 - 3); // nothing in front of the top
    EXPECT_LT(zh, 500 + 3); // nothing behind the base
  }
  EXPECT_GT(onTop, 10);
  for (int i = 0; i < 3; ++i) // the origin is the 3-D centroid of S_in
    EXPECT_NEAR(sum[i] / static_cast<double>(m.inner.size()), m.originInHandMm[i], 1e-3);
  EXPECT_NEAR(m.depthRangeMm[0], 470, 2);
  EXPECT_NEAR(m.depthRangeMm[1], 500, 3);
  // The model frame in the toy's: the toy's origin is at its base, so z is the centroid's height.
  EXPECT_NEAR(sm.oMm[2][3] * 1e3, m.originInHandMm[2] - 500, 1e-6);
  // S_out lies at the depth of the matched surface next to the silhouette: between the top and
  // the base, nearer the base. (The box's true silhouette is at its base, where its rounded edge
  // is vertical; the last few millimetres of that edge are too steep to match, so S_out sits up to
  // about 18 mm in front of it: the limit of matching, stated in the README.)
  std::vector<double> outZ;
  for (const auto &q : m.outer) {
    outZ.push_back(q.z + m.originInHandMm[2]);
    EXPECT_GT(outZ.back(), 470 - 2);
    EXPECT_LT(outZ.back(), 500 + 5); // region pixels on the edge that matched the backdrop just behind it
  }
  std::nth_element(outZ.begin(), outZ.begin() + static_cast<long>(outZ.size() / 2), outZ.end());
  EXPECT_GT(outZ[outZ.size() / 2], 485.0) << "median depth of S_out";
}

TEST(StereoPhotoModel, FileVersionsTwoAndThreeKeepDepthAndViewsAndAFlatModelStaysVersionOne)
{
  const pm::core::StereoRig rig = stereoLabRig();
  const pm::sim::Scene crab(pm::sim::makeTarget("C12", 0.5));
  pm::model::StereoModelParams leftOnly;
  leftOnly.rightView = false;
  const pm::core::PhotoModel one = pm::sim::makeSimulatedStereoPhotoModel(crab, rig, 500, leftOnly).build.model;
  pm::model::StereoModelParams twoViews;
  twoViews.rightView = true;
  const pm::core::PhotoModel two = pm::sim::makeSimulatedStereoPhotoModel(crab, rig, 500, twoViews).build.model;
  ASSERT_TRUE(one.views.empty());
  ASSERT_EQ(two.views.size(), 1u); // the right camera's own view
  pm::test::TempDir dir("model2");
  auto same = [](const std::vector<pm::core::ModelPoint> &a, const std::vector<pm::core::ModelPoint> &b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_FLOAT_EQ(a[i].x, b[i].x);
      EXPECT_FLOAT_EQ(a[i].z, b[i].z);
      EXPECT_FLOAT_EQ(a[i].hue, b[i].hue);
      EXPECT_FLOAT_EQ(a[i].v, b[i].v);
    }
  };
  for (const pm::core::PhotoModel *m : {&one, &two}) {
    pm::io::savePhotoModel(*m, dir.file("m.json"));
    const std::string version = m->views.empty() ? "\"version\":2" : "\"version\":3";
    EXPECT_NE(pm::test::readText(dir.file("m.json")).find(version), std::string::npos) << version;
    const pm::core::PhotoModel r = pm::io::loadPhotoModel(dir.file("m.json"));
    same(r.inner, m->inner);
    same(r.outer, m->outer);
    for (int i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(r.originInHandMm[i], m->originInHandMm[i]);
      EXPECT_DOUBLE_EQ(r.cameraMm[i], m->views.empty() ? 0.0 : m->cameraMm[i]);
    }
    EXPECT_EQ(r.nInDropped, m->nInDropped);
    ASSERT_EQ(r.views.size(), m->views.size());
    for (std::size_t k = 0; k < r.views.size(); ++k) {
      same(r.views[k].inner, m->views[k].inner);
      same(r.views[k].outer, m->views[k].outer);
      for (int i = 0; i < 3; ++i)
        EXPECT_DOUBLE_EQ(r.views[k].cameraMm[i], m->views[k].cameraMm[i]);
    }
  }
  // The views' cameras are the rig's, in the model frame: the left and the right camera's centres.
  for (unsigned i = 0; i < 3; ++i) {
    EXPECT_NEAR(two.cameraMm[i], rig.left.hMc[i][3] * 1e3 - two.originInHandMm[i], 1e-9);
    EXPECT_NEAR(two.views[0].cameraMm[i], rig.right.hMc[i][3] * 1e3 - two.originInHandMm[i], 1e-9);
  }
  // A flat model is written as before: version 1, five numbers a point.
  const Disc d = redDisc();
  const std::string flat = pm::io::photoModelToJson(pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500).model);
  EXPECT_NE(flat.find("\"version\":1"), std::string::npos);
  EXPECT_EQ(flat.find("origin_in_hand_mm"), std::string::npos);
  // Refused with pm::core::Error: a version 7; a version 3 file called version 4 (no shared surface);
  // a version 3 without views or without a view's camera; a version 2 file with points of five numbers.
  const std::string v3 = pm::test::readText(dir.file("m.json"));
  auto refused = [&](std::string text, const std::string &from, const std::string &to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos)
      return std::string();
    text.replace(at, from.size(), to);
    pm::test::writeText(dir.file("bad.json"), text);
    return pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("bad.json")); });
  };
  EXPECT_NE(refused(v3, "\"version\":3", "\"version\":7").find("version"), std::string::npos);
  EXPECT_NE(refused(v3, "\"version\":3", "\"version\":4").find("surface"), std::string::npos);
  EXPECT_NE(refused(v3, "\"views\":[", "\"viewz\":[").find("views"), std::string::npos);
  EXPECT_NE(refused(v3, "\"camera_mm\":[", "\"camera_mm\":[0,0,0],\"unused\":[").find("camera"), std::string::npos);
  std::string v2five = pm::io::photoModelToJson(pm::model::buildPhotoModel(d.bg, d.tg, kCam, 500).model);
  v2five.replace(v2five.find("\"version\":1"), 11, "\"version\":2");
  pm::test::writeText(dir.file("bad2.json"), v2five);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("bad2.json")); }), "");
}

TEST(StereoPhotoModel, FurtherPairsAddTheirViewsInTheModelFrame)
{
  // The poster box (whose depths the matching gets within 0.2 mm) photographed from five hand poses
  // (ahead, then turned by 15 deg about the hand's x and y axes around it): nine views, each the
  // same box in the same model frame.
  const pm::core::StereoRig rig = stereoLabRig();
  const pm::sim::Scene box(pm::sim::makeTarget("R1", 0.5));
  pm::model::StereoModelParams twoViews;
  twoViews.rightView = true;
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(box, rig, 500, twoViews, 15);
  const pm::core::PhotoModel &m = sm.build.model;
  ASSERT_EQ(m.views.size(), 9u);
  auto unit = [](const double c[3]) {
    const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    return std::array<double, 3>{c[0] / n, c[1] / n, c[2] / n};
  };
  const auto left0 = unit(m.cameraMm), right0 = unit(m.views[0].cameraMm);
  for (std::size_t k = 1; k < m.views.size(); ++k) {
    const pm::core::ModelView &v = m.views[k];
    // Its camera: the first pair's left or right camera turned by 15 deg about the toy.
    const auto c = unit(v.cameraMm), c0 = k % 2 ? left0 : right0;
    const double angle = std::acos(std::min(1.0, c[0] * c0[0] + c[1] * c0[1] + c[2] * c0[2])) * 180 / M_PI;
    EXPECT_NEAR(angle, 15.0, 1.0) << "view " << k;
    // Its points lie on the first view's surface: half of them nearer to its nearest point than a
    // point of the same surface can be from a grid of the sampling step (step / sqrt 2; the step is
    // 8 px, 5 mm at 470 mm), with no offset in depth (a wrong motion would put them tens of
    // millimetres off).
    const double stepMm = pm::model::PhotoModelParams().stepPx * 470 / rig.left.cam.get_px();
    std::vector<double> dist, dz;
    for (const pm::core::ModelPoint &p : v.inner) {
      double best = 1e30, z = 0;
      for (const pm::core::ModelPoint &r : m.inner) {
        const double d2 = (p.x - r.x) * (p.x - r.x) + (p.y - r.y) * (p.y - r.y) + (p.z - r.z) * (p.z - r.z);
        if (d2 < best) {
          best = d2;
          z = p.z - r.z;
        }
      }
      dist.push_back(std::sqrt(best));
      dz.push_back(z);
    }
    std::sort(dist.begin(), dist.end());
    std::sort(dz.begin(), dz.end());
    EXPECT_LT(dist[dist.size() / 2], stepMm / std::sqrt(2.0)) << "view " << k;
    EXPECT_LT(std::fabs(dz[dz.size() / 2]), 0.5) << "view " << k;
  }
  // A further pair that cannot be built names itself; nothing is returned.
  const StereoPhotos p = stereoPhotos(pm::sim::Scene(pm::sim::makeTarget("C12", 0.5)), rig, 500);
  std::vector<pm::model::StereoViewPair> more(2);
  for (pm::model::StereoViewPair &q : more)
    q = {p.bgL, p.bgR, p.L, p.R, vpHomogeneousMatrix()};
  more[1].right = p.bgR; // the toy missing from its right photo
  const std::string e = pm::test::errorOf([&] { pm::model::buildStereoPhotoModel(rig, p.bgL, p.bgR, p.L, p.R, more); });
  EXPECT_NE(e.find("view pair 3"), std::string::npos) << e;
  EXPECT_NE(e.find("right view"), std::string::npos) << e;
}

TEST(StereoPhotoModel, BadInputIsAClearError)
{
  const pm::core::StereoRig rig = stereoLabRig();
  const pm::sim::Scene scene(pm::sim::makeTarget("C12", 0.5));
  const StereoPhotos p = stereoPhotos(scene, rig, 500);
  auto build = [&](const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR, const vpImage<vpRGBa> &L,
                   const vpImage<vpRGBa> &R) {
    return pm::test::errorOf([&] { pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R); });
  };
  // The target in the left view only.
  EXPECT_NE(build(p.bgL, p.bgR, p.L, p.bgR).find("not found in the right view"), std::string::npos);
  // The target cut by the right view's border: the right photo taken with the toy 150 mm to the left.
  {
    pm::sim::Rasterizer r;
    vpImage<vpRGBa> R2;
    scene.render(r, rig.right, vpHomogeneousMatrix(0.16, 0, 0.5, 0, 0, 0), 0, 7, R2, true);
    const std::string e = build(p.bgL, p.bgR, p.L, R2);
    EXPECT_TRUE(e.find("right view") != std::string::npos || e.find("right") != std::string::npos) << e;
  }
  // Photos whose size differs from the rig's.
  const vpImage<vpRGBa> small(240, 320, vpRGBa(0, 0, 255));
  EXPECT_NE(build(p.bgL, p.bgR, small, p.R).find("rig's left camera is 640x480"), std::string::npos);
  // A background pair that does not match the photo pair (another backdrop).
  {
    pm::sim::SceneParams other;
    other.seaBottom.seed = 99;
    other.exposure = 0.5;
    const StereoPhotos q = stereoPhotos(pm::sim::Scene(pm::sim::makeTarget("C12", 0.5), other), rig, 500);
    const std::string e = build(q.bgL, q.bgR, p.L, p.R);
    EXPECT_NE(e.find("background pair does not match"), std::string::npos) << e;
  }
  // A target with too little texture to match: refused, not faked.
  {
    const vpImage<vpRGBa> plain(200, 300, vpRGBa(200, 30, 30));
    pm::sim::SceneParams sp;
    sp.noiseSigma = 0;
    sp.specular = 0;
    const pm::sim::Scene plainScene(pm::sim::targetFromImage(plain, 120, 15, "plain"), sp);
    const StereoPhotos u = stereoPhotos(plainScene, rig, 500);
    pm::model::StereoModelParams strict;
    strict.minMatchedFraction = 0.9;
    const std::string e = pm::test::errorOf([&] { pm::model::buildStereoPhotoModel(rig, u.bgL, u.bgR, u.L, u.R, strict); });
    EXPECT_NE(e.find("too little texture"), std::string::npos) << e;
  }
}

//! The view of largest dot product with \e c, the first on a tie (none above -2: view 0), by scanning them all.
static std::size_t nearestByScan(const std::vector<pm::core::Vec3> &dirs, const double c[3])
{
  std::size_t best = 0;
  double bestDot = -2;
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    const double d = dirs[k][0] * c[0] + dirs[k][1] * c[1] + dirs[k][2] * c[2];
    if (d > bestDot) {
      bestDot = d;
      best = k;
    }
  }
  return best;
}

TEST(ViewpointIndex, GivesTheExactNearestViewForAnyDirectionAndAnyNumberOfViews)
{
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 1);
  auto randomUnit = [&] { return pm::core::unit({g(rng), g(rng), g(rng)}); };
  for (std::size_t n : {1u, 5u, 16u, 17u, 240u, 960u}) {
    std::vector<pm::core::Vec3> dirs;
    // Half on a Fibonacci sphere (as a pass's viewpoints), half random (bunched views, sparse regions).
    for (std::size_t k = 0; k < n; ++k) {
      if (k % 2 == 0) {
        const double z = 1 - 2 * (static_cast<double>(k) + 0.5) / static_cast<double>(n), r = std::sqrt(1 - z * z);
        const double a = 2.399963229728653 * static_cast<double>(k);
        dirs.push_back({r * std::cos(a), r * std::sin(a), z});
      } else {
        dirs.push_back(randomUnit());
      }
    }
    const pm::core::ViewpointIndex index(dirs);
    ASSERT_EQ(index.size(), n);
    std::vector<pm::core::Vec3> unitDirs;
    for (std::size_t k = 0; k < n; ++k)
      unitDirs.push_back(index.direction(k));
    std::size_t mismatches = 0;
    for (int q = 0; q < 20000; ++q) {
      pm::core::Vec3 d = randomUnit();
      if (q % 2 && n > 1) { // on the boundary between two views, where a coarse lookup errs
        const pm::core::Vec3 a = dirs[static_cast<std::size_t>(q) % n], b = dirs[static_cast<std::size_t>(q * 7 + 1) % n];
        d = pm::core::unit(pm::core::add(a, b));
        d = pm::core::unit(pm::core::add(d, pm::core::scaled(randomUnit(), 1e-4)));
      }
      const double c[3] = {500 * d[0], 500 * d[1], 500 * d[2]}; // a camera 500 mm away
      mismatches += index.nearest(c) != nearestByScan(unitDirs, c);
    }
    EXPECT_EQ(mismatches, 0u) << n << " views";
  }
}

TEST(ViewpointIndex, IsTheModelsOwnViewsInOrder)
{
  pm::core::PhotoModel m;
  m.cameraMm[2] = -500; // its own view: from in front
  pm::core::ModelView back;
  back.cameraMm[2] = 500;
  m.views.push_back(back);
  const pm::core::ViewpointIndex index(m);
  ASSERT_EQ(index.size(), 2u);
  const double front[3] = {10, 0, -480}, behind[3] = {0, 20, 450};
  EXPECT_EQ(index.nearest(front), 0u);
  EXPECT_EQ(index.nearest(behind), 1u);
  EXPECT_NEAR(index.direction(1)[2], 1.0, 1e-12);
}

// The one background subtraction under a soft light: the umbra where a toy rests and its penumbra
// keep the backdrop's colour, however dark, and stay background; the toy's own colour stays the
// toy however dark its shaded side; black (under darkRatio of the backdrop) is the toy.
TEST(BackgroundSubtraction, ASoftLightsUmbraStaysBackgroundAndAnotherColourHoweverDarkIsTheTarget)
{
  // A strip of columns in the middle rows of a 160 x 60 image, the rest the backdrop as it was.
  const unsigned w = 160, h = 60, top = 20, rows = 20, left = 20;
  vpImage<vpRGBa> bg(h, w), photo(h, w);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 2.0);
  auto px = [&](double r, double g, double b) {
    auto c = [&](double v) { return static_cast<unsigned char>(std::clamp(std::lround(v + noise(rng)), 0L, 255L)); };
    return vpRGBa(c(r), c(g), c(b), 255);
  };
  const double B[3] = {40, 90, 140}; // the sea bottom's blue
  // Columns: 0-19 the umbra (12 % of the light), 20-59 a penumbra from 12 to 100 %, 60-79 a penumbra tinted by
  // light bounced off a red toy, 80-99 the red toy's shaded side, 100-109 black, 110-119 a grey part of the toy.
  for (unsigned v = 0; v < h; ++v)
    for (unsigned x = 0; x < w; ++x) {
      bg[v][x] = px(B[0], B[1], B[2]);
      if (v < top || v >= top + rows || x < left || x >= left + 120) {
        photo[v][x] = px(B[0], B[1], B[2]);
        continue;
      }
      const unsigned u = x - left;
      double k = 1;
      if (u < 20)
        k = 0.12;
      else if (u < 60)
        k = 0.12 + 0.88 * (u - 20) / 40.0;
      photo[v][x] = u < 60    ? px(k * B[0], k * B[1], k * B[2])
                    : u < 80  ? px(0.5 * B[0] + 9, 0.5 * B[1], 0.5 * B[2])
                    : u < 100 ? px(38, 7, 6)
                    : u < 110 ? px(2, 2, 2)
                              : px(90, 90, 90);
    }
  // The raw subtraction on the toy's columns; the silhouette (its specks of noise cleaned) on the backdrop's.
  pm::model::SilhouetteStats st;
  const vpImage<unsigned char> sil = pm::model::silhouette(photo, bg, pm::model::SilhouetteParams(), &st);
  const cv::Mat m = pm::model::subtractBackground(photo, bg, pm::model::BackgroundParams());
  auto share = [&](unsigned u0, unsigned u1, bool cleaned) {
    int n = 0;
    for (unsigned v = top; v < top + rows; ++v)
      for (unsigned u = left + u0; u < left + u1; ++u)
        n += cleaned ? sil[v][u] != 0 : m.at<unsigned char>(static_cast<int>(v), static_cast<int>(u)) != 0;
    return static_cast<double>(n) / (rows * (u1 - u0));
  };
  EXPECT_EQ(share(0, 20, true), 0.0);    // the umbra
  EXPECT_EQ(share(20, 60, true), 0.0);   // the penumbra
  EXPECT_EQ(share(60, 78, true), 0.0);   // the penumbra tinted by the toy (the cleaning's closing may reach 2 px)
  EXPECT_LE(share(0, 80, false), 0.02);  // before the cleaning, specks of noise at most
  EXPECT_EQ(share(80, 100, false), 1.0); // the toy's dark side
  EXPECT_EQ(share(100, 110, false), 1.0); // black
  EXPECT_EQ(share(110, 120, false), 1.0); // grey
  EXPECT_GT(st.shadowPx, 20 * static_cast<int>(rows)); // the darkened backdrop counted as shadow
}
