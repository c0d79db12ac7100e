// The relief targets R1..R3 (bodies a flat photo-model cannot fake) and the scene light with cast
// shadows and stronger highlights: sizes, the head's lifted outline and off-centre nose, the
// catalogue of 12 unchanged, the shadow on the backdrop, the old images unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/ShadowMap.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

const vpCameraParameters kCam(754, 754, 320, 240);

//! FNV-1a over the R, G, B bytes of an image.
std::uint64_t imageHash(const vpImage<vpRGBa> &I)
{
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned i = 0; i < I.getSize(); ++i)
    for (const unsigned char c : {I.bitmap[i].R, I.bitmap[i].G, I.bitmap[i].B}) {
      h ^= c;
      h *= 0x100000001b3ULL;
    }
  return h;
}

//! Mean of R + G + B over the 5 x 5 pixels around the projection of target-frame point (x, y, z) mm
//! seen by a camera straight ahead at \e distanceMm from the backdrop.
double brightnessAt(const vpImage<vpRGBa> &I, double x, double y, double z, double distanceMm)
{
  const double Z = distanceMm + z;
  const int u = static_cast<int>(std::lround(kCam.get_px() * x / Z + kCam.get_u0()));
  const int v = static_cast<int>(std::lround(kCam.get_py() * y / Z + kCam.get_v0()));
  if (u < 2 || v < 2 || u + 2 >= static_cast<int>(I.getWidth()) || v + 2 >= static_cast<int>(I.getHeight())) {
    ADD_FAILURE() << "point " << x << ", " << y << " is out of the image";
    return 0;
  }
  double s = 0;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i) {
      const vpRGBa &p = I[static_cast<unsigned>(v + j)][static_cast<unsigned>(u + i)];
      s += p.R + p.G + p.B;
    }
  return s / 25;
}

//! Hue (deg) of an RGB triple, -1 for a grey.
double hueOf(double r, double g, double b)
{
  const double mx = std::max({r, g, b}), mn = std::min({r, g, b}), d = mx - mn;
  if (d < 1e-9)
    return -1;
  double h = mx == r ? std::fmod((g - b) / d, 6.0) : mx == g ? (b - r) / d + 2 : (r - g) / d + 4;
  h *= 60;
  return h < 0 ? h + 360 : h;
}

} // namespace

TEST(ReliefTargets, SizesMatchTheirNominalSizes)
{
  ASSERT_EQ(pm::sim::reliefTargetCatalog().size(), 3u);
  for (const auto &info : pm::sim::reliefTargetCatalog()) {
    const pm::sim::TargetShape s = pm::sim::makeTarget(info.code, 0.5);
    EXPECT_EQ(s.info.code, info.code);
    double w = 0, h = 0;
    s.measuredExtent(w, h);
    EXPECT_NEAR(w, info.widthMm, 0.02 * info.widthMm + 1) << info.code;
    EXPECT_NEAR(h, info.heightMm, 0.02 * info.heightMm + 1) << info.code;
    float maxH = 0;
    for (std::size_t k = 0; k < s.sdf.size(); ++k)
      if (s.sdf[k] < 0)
        maxH = std::max(maxH, s.height[k]);
    EXPECT_NEAR(maxH, info.depthMm, 0.01 * info.depthMm) << info.code;
  }
  EXPECT_NEAR(pm::sim::reliefTargetCatalog()[0].widthMm, 140, 1e-9);
  EXPECT_NEAR(pm::sim::reliefTargetCatalog()[0].heightMm, 100, 1e-9);
  EXPECT_NEAR(pm::sim::reliefTargetCatalog()[0].depthMm, 30, 1e-9);
  EXPECT_NEAR(pm::sim::reliefTargetCatalog()[1].widthMm, 120, 1e-9);
  EXPECT_GE(pm::sim::reliefTargetCatalog()[1].depthMm, 40);
}

TEST(ReliefTargets, HeadOutlineIsAboveTheBaseAndItsNoseOffCentre)
{
  const pm::sim::TargetShape s = pm::sim::makeTarget("R2", 0.25);
  ASSERT_EQ(s.base.size(), s.sdf.size());
  // On the outline (the first texels inside it) the underside is >= 10 mm above the backdrop.
  float minRim = 1e9f, minBase = 1e9f;
  int rim = 0;
  for (std::size_t k = 0; k < s.sdf.size(); ++k) {
    if (s.sdf[k] < 0 && s.sdf[k] > -0.5f) {
      minRim = std::min(minRim, s.base[k]);
      ++rim;
      EXPECT_NEAR(s.base[k], s.height[k], 0.1f - 15.f * s.sdf[k]); // the two sheets meet on the outline
    }
    if (s.sdf[k] < 0)
      minBase = std::min(minBase, s.base[k]);
  }
  ASSERT_GT(rim, 500);
  EXPECT_GE(minRim, 10.f);
  EXPECT_NEAR(minBase, 0.f, 1e-6f); // the stand reaches the backdrop
  // The nearest point (the largest height) is >= 15 mm from the outline's centroid (the origin).
  std::size_t best = 0;
  for (std::size_t k = 0; k < s.sdf.size(); ++k)
    if (s.sdf[k] < 0 && s.height[k] > s.height[best])
      best = k;
  const int c = static_cast<int>(best % static_cast<std::size_t>(s.cols)), r = static_cast<int>(best / static_cast<std::size_t>(s.cols));
  const double x = (c - s.originCol) * s.texelMm, y = (r - s.originRow) * s.texelMm;
  EXPECT_GT(std::hypot(x, y), 15.0) << "nearest point at " << x << ", " << y;
  // Its mesh is a closed body: a top sheet and an underside.
  const pm::sim::Mesh m = pm::sim::buildTargetMesh(s, 1.0);
  int up = 0, down = 0;
  for (const auto &v : m.vertices)
    (v.nz < 0 ? up : down)++;
  EXPECT_GT(down, up / 2);
}

TEST(ReliefTargets, TowerIsTallAndTheBoxHasSteepSides)
{
  const pm::sim::TargetShape t = pm::sim::makeTarget("R3", 0.25);
  EXPECT_GE(t.info.depthMm, 100);
  EXPECT_GE(*std::max_element(t.height.begin(), t.height.end()), 100.f);
  EXPECT_TRUE(t.base.empty()); // it stands on the backdrop
  // The box: 2 mm inside its outline the front face is already >= 25 of its 30 mm.
  const pm::sim::TargetShape b = pm::sim::makeTarget("R1", 0.25);
  int n = 0;
  for (std::size_t k = 0; k < b.sdf.size(); ++k)
    if (b.sdf[k] < -2.0f && b.sdf[k] > -2.3f) {
      EXPECT_GE(b.height[k], 25.f);
      ++n;
    }
  EXPECT_GT(n, 100);
}

TEST(ReliefTargets, ColoursStayAwayFromTheBackdropHue)
{
  for (const char *code : {"R1", "R2", "R3"}) {
    const pm::sim::TargetShape s = pm::sim::makeTarget(code, 0.5);
    int in = 0, far = 0;
    for (std::size_t k = 0; k < s.sdf.size(); ++k) {
      if (s.sdf[k] >= 0)
        continue;
      ++in;
      const double h = hueOf(s.rgb[3 * k], s.rgb[3 * k + 1], s.rgb[3 * k + 2]);
      const double d = h < 0 ? 180 : std::min(std::fabs(h - 205), 360 - std::fabs(h - 205));
      far += d > 40;
    }
    EXPECT_GT(far, 0.9 * in) << code;
  }
}

TEST(ReliefTargets, CatalogueOfTwelveUnchanged)
{
  const auto &cat = pm::sim::targetCatalog();
  ASSERT_EQ(cat.size(), 12u);
  const char *codes[] = {"C01", "C02", "C03", "C04", "C05", "C06", "C07", "C08", "C09", "C10", "C11", "C12"};
  for (std::size_t i = 0; i < 12; ++i)
    EXPECT_EQ(cat[i].code, codes[i]);
  EXPECT_TRUE(pm::sim::isCatalogTarget("r2"));
  EXPECT_TRUE(pm::sim::isReliefTarget("R3"));
  EXPECT_FALSE(pm::sim::isReliefTarget("C12"));
  EXPECT_TRUE(pm::sim::makeTarget("C12", 0.5).base.empty());
  EXPECT_THROW(pm::sim::makeTarget("R4"), pm::core::Error);
}

TEST(ReliefTargets, ShadowMapHidesWhatIsBehindTheMesh)
{
  // A 20 mm square 10 mm in front of the plane z = 0, lit straight from the front.
  auto tex = std::make_shared<pm::sim::Texture>();
  tex->width = tex->height = 1;
  tex->rgb = {255, 255, 255};
  pm::sim::Mesh m;
  const float h = 0.01f, z = -0.01f;
  m.vertices = {{-h, -h, z, 0, 0, -1, 0, 0, -1}, {h, -h, z, 0, 0, -1, 0, 0, -1}, {h, h, z, 0, 0, -1, 0, 0, -1}, {-h, h, z, 0, 0, -1, 0, 0, -1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.texture = tex;
  const double toward[3] = {0, 0, -1};
  const pm::sim::ShadowMap map(m, toward, 0.5e-3);
  auto lit = [&](double x, double y, double zz) {
    double u = 0, v = 0, d = 0;
    map.project(x, y, zz, u, v, d);
    return map.visibility(static_cast<float>(u), static_cast<float>(v), static_cast<float>(d - 1e-4));
  };
  EXPECT_FLOAT_EQ(lit(0, 0, 0), 0.f);         // behind the square
  EXPECT_FLOAT_EQ(lit(0.005, -0.005, 0), 0.f);
  EXPECT_FLOAT_EQ(lit(0, 0, z), 1.f);         // on it
  EXPECT_FLOAT_EQ(lit(0.015, 0, 0), 1.f);     // beside it
  EXPECT_FLOAT_EQ(lit(0.5, 0.5, 0), 1.f);     // off the map
  EXPECT_THROW(pm::sim::ShadowMap(m, std::array<double, 3>{0, 0, 0}.data(), 1e-3), pm::core::Error);
}

TEST(ReliefTargets, BoxCastsAShadowOnTheBackdropAwayFromTheLight)
{
  const pm::sim::TargetShape box = pm::sim::makeTarget("R1");
  pm::sim::SceneParams on;
  on.noiseSigma = 0;
  ASSERT_EQ(on.shadows, pm::sim::ShadowMode::Auto);
  // The same light without shadows: the hand light along the scene light (the target faces the
  // camera, its frame parallel to the hand's), so only the shadows differ.
  pm::sim::SceneParams off = on;
  off.shadows = pm::sim::ShadowMode::Off;
  std::copy(on.sceneLightDir, on.sceneLightDir + 3, off.lightDirHand);
  const pm::sim::Scene sOn(box, on), sOff(box, off);
  EXPECT_TRUE(sOn.sceneLit());
  EXPECT_FALSE(sOff.sceneLit());
  const pm::core::PinholeCamera cam{"front", kCam, 640, 480, vpHomogeneousMatrix(), pm::core::LensDistortion()};
  const double dist = 500;
  const vpHomogeneousMatrix hMo(0, 0, dist * 1e-3, 0, 0, 0);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> a, b;
  sOn.render(r, cam, hMo, 0, 0, a);
  sOff.render(r, cam, hMo, 0, 0, b);
  // The light comes from the upper left, in front: the shadow falls right of and below the box
  // (its 30 mm height throws it 18 mm along x and y), on the backdrop (z = +0.5 mm).
  for (const auto &p : std::vector<std::array<double, 2>>{{80, 25}, {78, -10}, {20, 62}, {-30, 60}}) {
    const double lOn = brightnessAt(a, p[0], p[1], 0.5, dist), lOff = brightnessAt(b, p[0], p[1], 0.5, dist);
    EXPECT_LT(lOn, 0.7 * lOff) << "at " << p[0] << ", " << p[1];
  }
  // Left of and above the box, and far from it, the backdrop is lit the same.
  for (const auto &p : std::vector<std::array<double, 2>>{{-80, 0}, {0, -58}, {-200, -150}, {180, 130}}) {
    const double lOn = brightnessAt(a, p[0], p[1], 0.5, dist), lOff = brightnessAt(b, p[0], p[1], 0.5, dist);
    EXPECT_NEAR(lOn, lOff, 1.5) << "at " << p[0] << ", " << p[1];
  }
}

TEST(ReliefTargets, HighlightsAreStrongerUnderTheSceneLight)
{
  const pm::sim::TargetShape head = pm::sim::makeTarget("R2");
  pm::sim::SceneParams p;
  p.noiseSigma = 0;
  pm::sim::SceneParams matte = p;
  matte.sceneSpecular = 0;
  const pm::sim::Scene glossy(head, p), dull(head, matte);
  const pm::core::PinholeCamera cam{"front", kCam, 640, 480, vpHomogeneousMatrix(), pm::core::LensDistortion()};
  const vpHomogeneousMatrix hMo(0, 0, 0.5, 0, 0, 0);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> a, b;
  glossy.render(r, cam, hMo, 0, 0, a);
  dull.render(r, cam, hMo, 0, 0, b);
  double maxGain = 0;
  for (unsigned i = 0; i < a.getSize(); ++i)
    maxGain = std::max(maxGain, (a.bitmap[i].R + a.bitmap[i].G + a.bitmap[i].B) / 3.0 -
                                    (b.bitmap[i].R + b.bitmap[i].G + b.bitmap[i].B) / 3.0);
  EXPECT_GT(maxGain, 40); // grey levels at the brightest highlight
}

TEST(ReliefTargets, CreaturesRenderTheSameInAutoAndOffModes)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::sim::TargetShape crab = pm::sim::makeTarget("C12");
  const vpHomogeneousMatrix hMo(0, 0, 0.5, 0, 0, 0);
  pm::sim::SceneParams autoMode, offMode;
  offMode.shadows = pm::sim::ShadowMode::Off;
  const pm::sim::Scene a(crab, autoMode), b(crab, offMode);
  EXPECT_FALSE(a.sceneLit());
  const pm::sim::StereoImages ia = a.renderStereo(rig, hMo, 0), ib = b.renderStereo(rig, hMo, 0);
  EXPECT_EQ(imageHash(ia.left), imageHash(ib.left));
  EXPECT_EQ(imageHash(ia.right), imageHash(ib.right));
  // Until issue 18 this also held the hashes of the images of the code before the relief targets;
  // the faster renderer differs from it by at most 1 grey level: Rasterizer.ImagesMatchTheReference...
}

TEST(ReliefTargets, BadSceneLightParametersAreRefused)
{
  pm::sim::SceneParams p;
  EXPECT_NO_THROW(p.validate());
  p.sceneLightDir[2] = 0.5; // from behind the backdrop
  EXPECT_THROW(p.validate(), pm::core::Error);
  p = pm::sim::SceneParams();
  p.sceneShininess = 0;
  EXPECT_THROW(p.validate(), pm::core::Error);
  p = pm::sim::SceneParams();
  p.sceneSpecular = -1;
  EXPECT_THROW(p.validate(), pm::core::Error);
  p = pm::sim::SceneParams();
  p.shadowTexelMm = 0;
  EXPECT_THROW(p.validate(), pm::core::Error);
  p = pm::sim::SceneParams();
  p.shadows = static_cast<pm::sim::ShadowMode>(7);
  EXPECT_THROW(p.validate(), pm::core::Error);
}

namespace {

//! |error| quantile q of the stereo model's S_in depths against the renderer's depth (mm).
double depthErrorQuantile(const pm::sim::SimulatedPhotoModel &sm, double q)
{
  std::vector<double> a;
  for (double e : sm.inDepthErrorsMm())
    if (std::isfinite(e))
      a.push_back(std::fabs(e));
  if (a.empty())
    return std::numeric_limits<double>::infinity();
  std::sort(a.begin(), a.end());
  return a[std::min(a.size() - 1, static_cast<std::size_t>(q * static_cast<double>(a.size())))];
}

} // namespace

TEST(ReliefTargets, TheRenderersDepthIsTheGroundTruthOfTheStereoModel)
{
  // The poster box's flat front lies 30 mm in front of its base (hand z 470 at the photo pose):
  // the depth buffer read back says so, and the stereo model's points lie on it.
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::sim::Scene box(pm::sim::makeTarget("R1", 0.25));
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(box, rig, 500);
  ASSERT_EQ(sm.trueDepth.getWidth(), rig.left.width);
  const unsigned uc = rig.left.width / 2, vc = rig.left.height / 2;
  EXPECT_NEAR(sm.trueDepth[vc][uc], 470.0, 0.05);
  EXPECT_FALSE(std::isfinite(sm.trueDepth[5][5])); // the backdrop is not the toy
  const auto errors = sm.inDepthErrorsMm();
  ASSERT_EQ(errors.size(), sm.build.model.inner.size());
  EXPECT_LT(depthErrorQuantile(sm, 0.5), 0.5);
  EXPECT_LT(depthErrorQuantile(sm, 0.9), 1.0);

  // The most textured sea creature (C11): its rounded relief matched within a millimetre or so.
  const auto fish = pm::sim::makeSimulatedStereoPhotoModel(pm::sim::Scene(pm::sim::makeTarget("C11", 0.25)), rig, 500);
  EXPECT_LT(depthErrorQuantile(fish, 0.5), 1.0);
  EXPECT_LT(depthErrorQuantile(fish, 0.9), 3.0);
}
