// The simulated cameras: rasterizer geometry, anti-aliasing, noise, exposure, relief, occluder.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <cstring>
#include <random>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/Pose.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/sim/MeshOutlineCut.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/Clutter.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SeaBottom.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/TargetShape.h"
#include "pm/sim/ShadowMap.h"
#include "pm/sim/Noise.h"

namespace {

const vpCameraParameters kCam(754, 754, 320, 240);

//! A square of side 2*hw (m) at z = 0 of its frame, with a texture: left half red, right half green
//! (or all white).
pm::sim::Mesh square(double hw, bool white = false)
{
  auto tex = std::make_shared<pm::sim::Texture>();
  tex->width = 2;
  tex->height = 1;
  tex->rgb = {255, 0, 0, 0, 255, 0};
  if (white)
    tex->rgb = {255, 255, 255, 255, 255, 255};
  pm::sim::Mesh m;
  const float h = static_cast<float>(hw);
  m.vertices = {{-h, -h, 0, 0, 0, -1, 0, 0, -1}, {h, -h, 0, 0, 0, -1, 1, 0, -1}, {h, h, 0, 0, 0, -1, 1, 0, -1},
                {-h, h, 0, 0, 0, -1, 0, 0, -1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.texture = tex;
  return m;
}

pm::core::StereoRig labRig() { return pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json")); }

//! Pixels (coverage > 0.5) of object \e id in the rasterizer's last image.
std::vector<std::pair<unsigned, unsigned>> pixelsOf(const pm::sim::Rasterizer &r, std::uint8_t id)
{
  std::vector<std::pair<unsigned, unsigned>> p;
  for (unsigned v = 0; v < r.height(); ++v)
    for (unsigned u = 0; u < r.width(); ++u)
      if (r.coverage(u, v, id) > 0.5)
        p.emplace_back(u, v);
  std::sort(p.begin(), p.end());
  return p;
}

double meanAbsDiff(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b)
{
  double s = 0;
  for (unsigned i = 0; i < a.getSize(); ++i)
    s += std::abs(a.bitmap[i].R - b.bitmap[i].R) + std::abs(a.bitmap[i].G - b.bitmap[i].G) +
         std::abs(a.bitmap[i].B - b.bitmap[i].B);
  return s / (3.0 * a.getSize());
}

} // namespace

TEST(Rasterizer, EdgesCoverTheExactAreaFraction)
{
  // Half-width so that the left edge falls at u = 320 - 75.25 = 244.75: pixel 245 is 3/4 covered.
  const double hw = 75.25 * 0.5 / 754;
  pm::sim::Rasterizer r;
  r.reset(640, 480, 4);
  r.clear(0, 0, 0);
  r.draw(square(hw, true), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), kCam, pm::sim::Lighting(), 9);
  EXPECT_DOUBLE_EQ(r.coverage(245, 240, 9), 0.75);
  EXPECT_DOUBLE_EQ(r.coverage(244, 240, 9), 0.0);
  EXPECT_DOUBLE_EQ(r.coverage(300, 240, 9), 1.0);
  EXPECT_DOUBLE_EQ(r.coverage(395, 240, 9), 0.75); // right edge at 395.25
  EXPECT_DOUBLE_EQ(r.coverage(396, 240, 9), 0.0);
  // The resolved pixel blends: 3/4 of the square's colour.
  vpImage<vpRGBa> I;
  r.resolve(I, 1.0, 0.0, 0);
  EXPECT_NEAR(I[240][245].R, 0.75 * I[240][260].R, 1.5);
}

TEST(Rasterizer, TextureOrientationAndDepthOrder)
{
  pm::sim::Rasterizer r;
  r.reset(640, 480, 1);
  r.clear(0, 0, 0);
  r.draw(square(0.05), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), kCam, pm::sim::Lighting(), 1);
  vpImage<vpRGBa> I;
  r.resolve(I, 1.0, 0.0, 0);
  EXPECT_GT(I[240][260].R, 100); // left half red
  EXPECT_LT(I[240][260].G, 60);
  EXPECT_GT(I[240][380].G, 100); // right half green
  // A farther square drawn after a nearer one stays hidden behind it.
  r.draw(square(0.2), vpHomogeneousMatrix(0, 0, 0.6, 0, 0, 0), kCam, pm::sim::Lighting(), 2);
  EXPECT_DOUBLE_EQ(r.coverage(320, 240, 1), 1.0);
  EXPECT_DOUBLE_EQ(r.coverage(100, 240, 2), 1.0);
}

TEST(Rasterizer, SharedEdgesLeaveNoCracks)
{
  // A panel of 40 x 30 quads, its inner vertices jittered, seen obliquely: it covers the whole image,
  // so every sample must show it (a sample on an edge shared by two triangles belongs to exactly one).
  auto tex = std::make_shared<pm::sim::Texture>();
  tex->width = tex->height = 1;
  tex->rgb = {200, 200, 200};
  pm::sim::Mesh m;
  m.texture = tex;
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
  const int nx = 40, ny = 30;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool inner = i > 0 && j > 0 && i < nx && j < ny;
      m.vertices.push_back({static_cast<float>(-1.0 + 2.0 * i / nx) + (inner ? jitter(rng) : 0.f),
                            static_cast<float>(-0.75 + 1.5 * j / ny) + (inner ? jitter(rng) : 0.f), 0, 0, 0, -1, 0, 0, -1});
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (nx + 1) + i), b = a + 1, d = a + nx + 1, c = d + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  // And the sea-bottom panel itself, seen straight on as in the photos.
  pm::sim::SeaBottomParams sb;
  const pm::sim::Mesh panel = pm::sim::makeBackdropMesh(tex, sb, 0.0);
  pm::sim::Rasterizer r;
  const std::vector<std::pair<const pm::sim::Mesh *, vpHomogeneousMatrix>> cases = {
      {&m, vpHomogeneousMatrix(0.02, -0.01, 0.6, 0.2, -0.3, 0.1)},
      {&panel, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0)},
      {&panel, vpHomogeneousMatrix(0.01, 0.003, 0.52, 0, 0, 0)}};
  for (const auto &[mesh, pose] : cases)
    for (unsigned ss : {1u, 2u, 3u}) {
      r.reset(640, 480, ss);
      r.clear(0, 0, 0);
      r.draw(*mesh, pose, kCam, pm::sim::Lighting(), 1);
      int holes = 0;
      for (unsigned v = 0; v < 480; ++v)
        for (unsigned u = 0; u < 640; ++u)
          holes += r.coverage(u, v, 1) < 1.0;
      EXPECT_EQ(holes, 0) << "supersampling " << ss;
    }
}

TEST(Rasterizer, AnEdgeJustPastASampleColumnOrRowLeavesNoCrack)
{
  // Four quads meeting on a vertical and a horizontal mesh line that project 0.0008 sample past a
  // sample column and row (within the edge test's 1/256 px grid of it): the triangle that owns the
  // samples on the line still covers them (its bounds from the same fixed-point vertices as the
  // edge test; bounds from the floating-point vertices left 1,119 samples uncovered here).
  auto tex = std::make_shared<pm::sim::Texture>();
  tex->width = tex->height = 1;
  tex->rgb = {200, 200, 200};
  pm::sim::Rasterizer r;
  const double z = 0.5;
  for (unsigned ss : {1u, 2u, 3u}) {
    const double pxs = kCam.get_px() * ss, u0s = kCam.get_u0() * ss + (ss - 1) / 2.0, v0s = kCam.get_v0() * ss + (ss - 1) / 2.0;
    const float xe = static_cast<float>((343 * ss + 0.0008 - u0s) / pxs * z), ye = static_cast<float>((251 * ss + 0.0008 - v0s) / pxs * z);
    pm::sim::Mesh m;
    m.texture = tex;
    const float xs[3] = {-0.5f, xe, 0.5f}, ys[3] = {-0.5f, ye, 0.5f};
    for (float y : ys)
      for (float x : xs)
        m.vertices.push_back({x, y, 0, 0, 0, -1, 0, 0, -1});
    for (std::uint32_t j = 0; j < 2; ++j)
      for (std::uint32_t i = 0; i < 2; ++i) {
        const std::uint32_t a = j * 3 + i, b = a + 1, d = a + 3, c = d + 1;
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      }
    r.reset(640, 480, ss);
    r.clear(0, 0, 0);
    r.draw(m, vpHomogeneousMatrix(0, 0, z, 0, 0, 0), kCam, pm::sim::Lighting(), 1);
    int holes = 0;
    for (unsigned v = 0; v < 480; ++v)
      for (unsigned u = 0; u < 640; ++u)
        holes += r.coverage(u, v, 1) < 1.0;
    EXPECT_EQ(holes, 0) << "supersampling " << ss;
  }
}

namespace {

//! The three scenes of data/render_reference (see its README), noise-free, rendered by \e raster.
std::vector<std::pair<std::string, pm::sim::StereoImages>> referenceScenes(pm::sim::Rasterizer &raster, double noiseSigma = 0)
{
  struct Case
  {
    std::string code;
    pm::core::Phi phi;
    bool occluder;
    std::string distractor;
    unsigned supersampling;
  };
  const std::vector<Case> cases = {{"C12", {0, 0, 500, 0, 0, 0}, false, "", 2},
                                   {"R1", {20, -10, 480, 0.05, -0.1, 0.02}, false, "", 2},
                                   {"C05", {-10, 15, 520, 0.02, 0.04, -0.1}, true, "C12", 1}};
  const pm::core::StereoRig rig = labRig();
  std::vector<std::pair<std::string, pm::sim::StereoImages>> out;
  for (const Case &c : cases) {
    pm::sim::SceneParams sp;
    sp.noiseSigma = noiseSigma;
    sp.occluder = c.occluder;
    sp.supersampling = c.supersampling;
    pm::sim::Scene scene(pm::sim::makeTarget(c.code), sp);
    if (!c.distractor.empty()) {
      scene.setDistractor(pm::sim::makeTarget(c.distractor));
      scene.params().distractor = true;
    }
    pm::sim::StereoImages im;
    scene.render(raster, rig.left, pm::core::toHomogeneousMatrix(c.phi), 0, 0, im.left);
    scene.render(raster, rig.right, pm::core::toHomogeneousMatrix(c.phi), 0, 1, im.right);
    out.emplace_back(c.code, std::move(im));
  }
  return out;
}

} // namespace

TEST(Rasterizer, ImagesMatchTheReferenceWithinOneGreyLevel)
{
  // The crops rendered before the renderer was made faster (issue 18): a toy under the hand light,
  // a relief target with cast shadows and highlights, and a masked toy behind an occluder with a
  // look-alike, at supersampling 1. The sensor noise is 2 grey levels; the images must agree far
  // inside it: no channel off by more than 1, and the mean difference a few thousandths.
  pm::sim::Rasterizer raster;
  for (const auto &[code, im] : referenceScenes(raster))
    for (const auto &[side, I] : {std::make_pair("left", &im.left), std::make_pair("right", &im.right)}) {
      const vpImage<vpRGBa> ref = pm::io::readColorImage(pm::test::dataPath("render_reference/" + code + "_" + side + ".png"));
      int maxDiff = 0;
      double sum = 0;
      for (unsigned v = 0; v < ref.getHeight(); ++v)
        for (unsigned u = 0; u < ref.getWidth(); ++u) {
          const vpRGBa a = ref[v][u], b = (*I)[132 + v][176 + u];
          for (int d : {a.R - b.R, a.G - b.G, a.B - b.B}) {
            maxDiff = std::max(maxDiff, std::abs(d));
            sum += std::abs(d);
          }
        }
      EXPECT_LE(maxDiff, 1) << code << " " << side;
      EXPECT_LT(sum / (3.0 * ref.getSize()), 0.005) << code << " " << side;
    }
}

TEST(Rasterizer, EightWidePathGivesTheSameImagesAsOneAtATime)
{
  if (!pm::sim::Rasterizer::simdAvailable())
    GTEST_SKIP() << "no AVX2 on this processor";
  pm::sim::Rasterizer wide, narrow;
  narrow.setSimd(false);
  // With sensor noise: the filter's 8-wide path adds it too.
  const auto a = referenceScenes(wide, 2.0), b = referenceScenes(narrow, 2.0);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(std::memcmp(a[k].second.left.bitmap, b[k].second.left.bitmap, a[k].second.left.getSize() * 4), 0) << a[k].first;
    EXPECT_EQ(std::memcmp(a[k].second.right.bitmap, b[k].second.right.bitmap, a[k].second.right.getSize() * 4), 0) << a[k].first;
  }
  // And a 2 x 1 texture, whose last texel the 4-byte loads must not read past (left to the scalar loop).
  for (pm::sim::Rasterizer *r : {&wide, &narrow}) {
    r->reset(640, 480, 2);
    r->clear(0, 0, 0);
    r->draw(square(0.05), vpHomogeneousMatrix(0.01, 0, 0.5, 0.1, 0.2, 0.3), kCam, pm::sim::Lighting(), 1);
  }
  vpImage<vpRGBa> I, J;
  wide.resolve(I, 1.0, 0.0, 0);
  narrow.resolve(J, 1.0, 0.0, 0);
  EXPECT_EQ(std::memcmp(I.bitmap, J.bitmap, I.getSize() * 4), 0);
  EXPECT_GT(I[240][300].R, 100);
}

TEST(Rasterizer, BandedRenderGivesTheSameImageAsDrawThenResolve)
{
  // The sea bottom, a relief target lit with cast shadows and gloss, a look-alike without shadows:
  // render() band by band against clear(), draw() each, resolve() on the whole frame, with noise,
  // for supersampling 1 to 3 (bands of whole pixel rows) and image heights that are not a multiple
  // of a band.
  const pm::sim::TargetShape toyShape = pm::sim::makeTarget("R1");
  const pm::sim::Mesh toy = pm::sim::buildTargetMesh(toyShape), other = pm::sim::buildTargetMesh(pm::sim::makeTarget("C05"));
  const pm::sim::SeaBottomParams sea;
  const pm::sim::Mesh backdrop = pm::sim::makeBackdropMesh(pm::sim::makeSeaBottomTexture(sea), sea, 0.5);
  const double towardLight[3] = {0.3, -0.4, -0.866};
  const pm::sim::ShadowMap shadow(toy, towardLight, 0.5e-3);
  const vpHomogeneousMatrix cMo = pm::core::toHomogeneousMatrix({15, -10, 480, 0.1, -0.15, 0.05});
  pm::sim::Lighting lit;
  for (unsigned i = 0; i < 3; ++i) {
    lit.dirCamera[i] = 0;
    for (unsigned k = 0; k < 3; ++k)
      lit.dirCamera[i] += cMo[i][k] * towardLight[k];
  }
  lit.shadow = &shadow;
  pm::sim::Lighting gloss = lit, plain = lit;
  gloss.specular = 0.4;
  gloss.shininess = 30;
  plain.shadow = nullptr;
  pm::sim::Rasterizer::DrawCall calls[3];
  calls[0] = {&backdrop, cMo, lit, 1};
  calls[1] = {&toy, cMo, gloss, 2};
  calls[2] = {&other, cMo * pm::core::toHomogeneousMatrix({-70, 40, -5, 0, 0, 0.7}), plain, 4};
  const float tank[3] = {0.04f, 0.06f, 0.09f};
  for (unsigned ss = 1; ss <= 3; ++ss)
    for (unsigned h : {480u, 173u}) {
      pm::sim::Rasterizer banded, whole;
      banded.reset(640, h, ss);
      whole.reset(640, h, ss);
      whole.clear(tank[0], tank[1], tank[2]);
      for (const auto &c : calls)
        whole.draw(*c.mesh, c.cMo, kCam, c.light, c.id);
      vpImage<vpRGBa> I, J;
      whole.resolve(I, 1.3, 2.0, 77);
      banded.render(tank, calls, 3, kCam, J, 1.3, 2.0, 77);
      ASSERT_EQ(I.getHeight(), J.getHeight());
      EXPECT_EQ(std::memcmp(I.bitmap, J.bitmap, I.getSize() * 4), 0) << "supersampling " << ss << ", height " << h;
      // The id and depth buffers hold the whole frame after render() too.
      std::size_t toyPixels = 0, same = 0, n = 0;
      for (unsigned v = 0; v < h; v += 3)
        for (unsigned u = 0; u < 640; u += 3, ++n) {
          const double a = whole.depthAt(u, v, 2), b = banded.depthAt(u, v, 2);
          same += (std::isnan(a) && std::isnan(b)) || a == b;
          toyPixels += whole.coverage(u, v, 2) == 1.0;
        }
      EXPECT_EQ(same, n);
      EXPECT_GT(toyPixels, 100u); // the toy is in view
    }
  // What render() leaves is not a frame for resolve() or for more draws until clear().
  pm::sim::Rasterizer r;
  r.reset(64, 48, 2);
  vpImage<vpRGBa> I;
  r.render(tank, calls, 1, kCam, I, 1.0, 0.0, 0);
  EXPECT_THROW(r.resolve(I, 1.0, 0.0, 0), pm::core::Error);
  EXPECT_THROW(r.draw(square(0.05), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), kCam, pm::sim::Lighting(), 1), pm::core::Error);
  r.clear(0, 0, 0);
  r.draw(square(0.05), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), kCam, pm::sim::Lighting(), 1);
  EXPECT_NO_THROW(r.resolve(I, 1.0, 0.0, 0));
  // A bad call draws nothing: the output image is left as it was.
  pm::sim::Rasterizer::DrawCall bad[2] = {calls[0], calls[1]};
  bad[1].id = 0;
  vpImage<vpRGBa> K(5, 7, vpRGBa(1, 2, 3, 4));
  EXPECT_THROW(r.render(tank, bad, 2, kCam, K, 1.0, 0.0, 0), pm::core::Error);
  EXPECT_EQ(K.getWidth(), 7u);
  EXPECT_EQ(K[0][0].B, 3);
}

TEST(Rasterizer, ObjectIdZeroIsRefused)
{
  pm::sim::Rasterizer r;
  r.reset(64, 48, 1);
  r.clear(0, 0, 0);
  EXPECT_THROW(r.draw(square(0.05), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), kCam, pm::sim::Lighting(), 0), pm::core::Error);
}

TEST(Scene, TargetAtTheTruePoseSitsAtBothImageCentres)
{
  const pm::core::StereoRig rig = labRig();
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  for (const char *code : {"C04", "C12"}) {
    const pm::sim::Scene scene(pm::sim::makeTarget(code, 0.5));
    for (const pm::core::PinholeCamera *c : {&rig.left, &rig.right}) {
      pm::sim::Rasterizer r;
      vpImage<vpRGBa> I;
      scene.render(r, *c, hMo, 0, 0, I);
      const auto px = pixelsOf(r, 2);
      ASSERT_GT(px.size(), 1000u) << code;
      double su = 0, sv = 0;
      for (const auto &p : px)
        su += p.first, sv += p.second;
      // Toe-in: the target's outline centroid is near the image centre (within the relief's parallax).
      EXPECT_NEAR(su / static_cast<double>(px.size()), 320, 12) << code << " " << c->name;
      EXPECT_NEAR(sv / static_cast<double>(px.size()), 240, 6) << code << " " << c->name;
    }
  }
}

TEST(Scene, SameSeedSameImageAndNoiseOfTheRequestedSigma)
{
  const pm::core::StereoRig rig = labRig();
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({10, -5, 520, 0.05, 0, 0});
  pm::sim::SceneParams clean;
  clean.noiseSigma = 0;
  pm::sim::SceneParams noisy = clean;
  noisy.noiseSigma = 4;
  const pm::sim::TargetShape shape = pm::sim::makeTarget("C09", 0.5);
  const pm::sim::Scene a(shape, noisy), b(shape, clean);
  const pm::sim::StereoImages i1 = a.renderStereo(rig, hMo, 3), i2 = a.renderStereo(rig, hMo, 3);
  EXPECT_EQ(meanAbsDiff(i1.left, i2.left), 0.0);
  EXPECT_EQ(meanAbsDiff(i1.right, i2.right), 0.0);
  const pm::sim::StereoImages i3 = a.renderStereo(rig, hMo, 4); // next frame: new noise
  EXPECT_GT(meanAbsDiff(i1.left, i3.left), 1.0);
  // The noise is Gaussian with the requested sigma (mean |n| = sigma sqrt(2/pi)).
  const pm::sim::StereoImages c = b.renderStereo(rig, hMo, 3);
  EXPECT_NEAR(meanAbsDiff(i1.left, c.left), 4 * std::sqrt(2 / M_PI), 0.15);
}

TEST(Noise, ARunOfPixelsDrawsWhatEachPixelDraws)
{
  // The row-at-a-time draws resolve() uses are fastGaussian3's, pixel for pixel, at any stride.
  for (std::size_t stride : {3u, 4u}) {
    std::vector<float> run(stride * 50, -99.f);
    pm::sim::fastGaussian3Run(0xabcdef, 1234567, 50, run.data(), stride);
    for (std::size_t k = 0; k < 50; ++k) {
      float g[3];
      pm::sim::fastGaussian3(0xabcdef, 1234567 + k, g);
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_EQ(run[stride * k + c], g[c]) << k << " " << c;
      if (stride == 4) {
        EXPECT_EQ(run[stride * k + 3], -99.f); // the pad is not written
      }
    }
  }
}

TEST(Scene, ExposureScalesBrightness)
{
  const pm::core::StereoRig rig = labRig();
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  pm::sim::SceneParams p;
  p.noiseSigma = 0;
  pm::sim::SceneParams dim = p;
  dim.exposure = 0.5;
  const pm::sim::TargetShape shape = pm::sim::makeTarget("C01", 0.5);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> I, J;
  pm::sim::Scene(shape, p).render(r, rig.left, hMo, 0, 0, I);
  pm::sim::Scene(shape, dim).render(r, rig.left, hMo, 0, 0, J);
  double si = 0, sj = 0;
  for (unsigned k = 0; k < I.getSize(); ++k) {
    si += I.bitmap[k].R + I.bitmap[k].G + I.bitmap[k].B;
    sj += J.bitmap[k].R + J.bitmap[k].G + J.bitmap[k].B;
  }
  EXPECT_NEAR(sj / si, 0.5, 0.01);
}

TEST(Scene, ReliefChangesTheViewAndHidesParts)
{
  // The jellyfish (110 mm deep) turned by eps2 = 0.3: its outline differs from the same toy made flat.
  const pm::core::StereoRig rig = labRig();
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0.3, 0});
  pm::sim::TargetShape deep = pm::sim::makeTarget("C06", 0.5);
  pm::sim::TargetShape flat = deep;
  flat.info.depthMm = 0;
  std::fill(flat.height.begin(), flat.height.end(), 0.f);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> I;
  pm::sim::Scene(deep, pm::sim::SceneParams()).render(r, rig.left, hMo, 0, 0, I);
  const auto a = pixelsOf(r, 2);
  pm::sim::Scene(flat, pm::sim::SceneParams()).render(r, rig.left, hMo, 0, 0, I);
  const auto b = pixelsOf(r, 2);
  std::vector<std::pair<unsigned, unsigned>> both;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  const double iou = static_cast<double>(both.size()) / static_cast<double>(a.size() + b.size() - both.size());
  EXPECT_LT(iou, 0.85) << "relief should change the outline seen from the side";
  // And the two cameras see the toy differently (not a shifted copy): compare the toy's pixel counts.
  const pm::sim::Scene scene(deep, pm::sim::SceneParams());
  pm::sim::Rasterizer rl, rr;
  vpImage<vpRGBa> L, R;
  scene.render(rl, rig.left, hMo, 0, 0, L);
  scene.render(rr, rig.right, hMo, 0, 1, R);
  const double nl = static_cast<double>(pixelsOf(rl, 2).size()), nr = static_cast<double>(pixelsOf(rr, 2).size());
  EXPECT_GT(std::fabs(nl - nr) / std::max(nl, nr), 0.05);
}

namespace {
//! The crab 500 mm ahead of the lab rig, a rasterizer and an image to render it with.
struct CrabAhead
{
  pm::core::StereoRig rig = labRig();
  vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  pm::sim::TargetShape shape = pm::sim::makeTarget("C12", 0.5);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> I;
};
} // namespace

namespace {
vpImage<vpRGBa> flat(unsigned char level, unsigned w = 64, unsigned h = 48)
{
  return vpImage<vpRGBa>(h, w, vpRGBa(level, level, level, 255));
}
double meanRed(const vpImage<vpRGBa> &I, unsigned u0, unsigned v0, unsigned u1, unsigned v1)
{
  double s = 0;
  for (unsigned v = v0; v < v1; ++v)
    for (unsigned u = u0; u < u1; ++u)
      s += I[v][u].R;
  return s / ((u1 - u0) * (v1 - v0));
}
//! Sum over the image of |I(u + 1, v) - I(u, v)| (along x) or |I(u, v + 1) - I(u, v)| (along y), red channel.
double gradientEnergy(const vpImage<vpRGBa> &I, bool alongX)
{
  double s = 0;
  for (unsigned v = 0; v + 1 < I.getHeight(); ++v)
    for (unsigned u = 0; u + 1 < I.getWidth(); ++u)
      s += std::abs(static_cast<int>(alongX ? I[v][u + 1].R : I[v + 1][u].R) - static_cast<int>(I[v][u].R));
  return s;
}
} // namespace

TEST(ImageVariation, EachPresetChangesTheImagesAsARealCameraWould)
{
  using pm::sim::imageVariation;
  EXPECT_FALSE(pm::sim::ImageVariation().any());
  EXPECT_FALSE(imageVariation("").any());
  for (const std::string &name : pm::sim::imageVariationNames()) {
    EXPECT_TRUE(imageVariation(name).any()) << name;
    EXPECT_NO_THROW(imageVariation(name).validate()) << name;
  }
  EXPECT_THROW(imageVariation("defocus,nope"), pm::core::Error);
  const pm::sim::ImageVariation both = imageVariation("defocus,jpeg");
  EXPECT_GT(both.defocusSigmaPx, 0);
  EXPECT_GT(both.jpegQuality, 0);
  pm::sim::ImageVariation bad;
  bad.gamma = 0;
  EXPECT_THROW(bad.validate(), pm::core::Error);

  // The tone: white balance (warm) and gamma on a mid grey, exactly.
  vpImage<vpRGBa> g = flat(128);
  imageVariation("white-balance").applyAfterSensor(g, 1);
  EXPECT_EQ(g[10][10].R, 147); // 128 x 1.15
  EXPECT_EQ(g[10][10].G, 128);
  EXPECT_EQ(g[10][10].B, 109); // 128 x 0.85
  g = flat(128);
  imageVariation("gamma").applyAfterSensor(g, 1);
  EXPECT_EQ(g[10][10].R, 102); // 255 (128 / 255)^(1 / 0.75)
  // The shot noise grows as the square root of the signal: 0.6 sqrt(level) grey levels.
  for (int level : {50, 200}) {
    vpImage<vpRGBa> n = flat(static_cast<unsigned char>(level), 200, 200);
    imageVariation("shot-noise").applyAfterSensor(n, 7);
    double s = 0, s2 = 0;
    for (unsigned k = 0; k < n.getSize(); ++k) {
      s += n.bitmap[k].G;
      s2 += static_cast<double>(n.bitmap[k].G) * n.bitmap[k].G;
    }
    const double m = s / n.getSize(), sd = std::sqrt(s2 / n.getSize() - m * m);
    EXPECT_NEAR(m, level, 0.3);
    EXPECT_NEAR(sd, 0.6 * std::sqrt(static_cast<double>(level)), 0.1 * 0.6 * std::sqrt(static_cast<double>(level))) << level;
  }

  // The optics and JPEG on a rendered image of the crab.
  CrabAhead c;
  const pm::sim::Scene scene(c.shape);
  scene.render(c.r, c.rig.left, c.hMo, 0, 0, c.I);
  const vpImage<vpRGBa> plain = c.I;
  vpImage<vpRGBa> I = plain;
  imageVariation("defocus").applyOptics(I); // softer in both directions
  EXPECT_LT(gradientEnergy(I, true), 0.6 * gradientEnergy(plain, true));
  EXPECT_LT(gradientEnergy(I, false), 0.6 * gradientEnergy(plain, false));
  I = plain;
  pm::sim::ImageVariation along;
  along.motionBlurPx = 8; // along x: x's gradients fall much more than y's
  along.applyOptics(I);
  EXPECT_LT(gradientEnergy(I, true) / gradientEnergy(plain, true), 0.8 * gradientEnergy(I, false) / gradientEnergy(plain, false));
  I = plain;
  imageVariation("vignetting").applyOptics(I); // the corners 35 % darker, the centre as it was
  EXPECT_NEAR(meanRed(I, 0, 0, 8, 8) / meanRed(plain, 0, 0, 8, 8), 0.65, 0.03);
  EXPECT_NEAR(meanRed(I, 316, 236, 324, 244), meanRed(plain, 316, 236, 324, 244), 1.0);
  I = plain;
  imageVariation("jpeg").applyAfterSensor(I, 1); // lossy, but close
  double se = 0;
  for (unsigned k = 0; k < I.getSize(); ++k)
    se += std::pow(I.bitmap[k].G - plain.bitmap[k].G, 2);
  const double psnr = 10 * std::log10(255.0 * 255.0 / (se / I.getSize()));
  EXPECT_GT(psnr, 28.0);
  EXPECT_LT(psnr, 60.0);
  // In a scene: none gives the renderer's images bit for bit; a variation changes them.
  pm::sim::SceneParams p;
  p.variation = imageVariation("");
  pm::sim::Scene(c.shape, p).render(c.r, c.rig.left, c.hMo, 0, 0, I);
  EXPECT_TRUE(I == plain);
  p.variation = imageVariation("camera");
  pm::sim::Scene(c.shape, p).render(c.r, c.rig.left, c.hMo, 0, 0, I);
  EXPECT_FALSE(I == plain);
}

TEST(Scene, OccluderHidesPartOfTheTarget)
{
  CrabAhead c;
  pm::sim::SceneParams p;
  pm::sim::Scene(c.shape, p).render(c.r, c.rig.left, c.hMo, 0, 0, c.I);
  const auto open = pixelsOf(c.r, 2).size();
  p.occluder = true;
  pm::sim::Scene(c.shape, p).render(c.r, c.rig.left, c.hMo, 0, 0, c.I);
  const auto hidden = pixelsOf(c.r, 2).size();
  EXPECT_GT(pixelsOf(c.r, 3).size(), 2000u);
  EXPECT_LT(static_cast<double>(hidden), 0.95 * static_cast<double>(open));
}

TEST(Scene, ABackdropWhoseHueDriftsTurnsOnlyTheBackdropByTheDriftAndNotForThePass)
{
  // 1 deg a second: 30 s into a run (frame 900) the backdrop's hue has turned 30 deg, its
  // brightness kept; the toy is untouched; the pass's scene (targetAlone) sees it as it was.
  CrabAhead c;
  pm::sim::SceneParams p;
  p.noiseSigma = 0;
  vpImage<vpRGBa> still, turned;
  pm::sim::Scene(c.shape, p).render(c.r, c.rig.left, c.hMo, 900, 0, still);
  p.backdropHueDriftDegPerS = 1;
  const pm::sim::Scene drifting(c.shape, p);
  drifting.render(c.r, c.rig.left, c.hMo, 900, 0, turned);
  std::vector<double> turns;
  long toy = 0, toySame = 0, lighter = 0;
  for (unsigned v = 0; v < turned.getHeight(); ++v)
    for (unsigned u = 0; u < turned.getWidth(); ++u) {
      const vpRGBa a = still[v][u], b = turned[v][u];
      if (c.r.coverage(u, v, 2) >= 1) {
        ++toy;
        toySame += a.R == b.R && a.G == b.G && a.B == b.B;
      } else if (c.r.coverage(u, v, 1) >= 1) {
        const pm::core::Hsv ha = pm::core::rgbToHsv(a), hb = pm::core::rgbToHsv(b);
        if (ha.s > 0.3 && ha.v > 0.2 && hb.s > 0.3) {
          double d = hb.h - ha.h;
          d -= 360 * std::round(d / 360);
          turns.push_back(d);
        }
        lighter += std::abs((b.R + b.G + b.B) - (a.R + a.G + a.B)) > 3;
      }
    }
  ASSERT_GT(turns.size(), 10000u);
  std::sort(turns.begin(), turns.end());
  EXPECT_NEAR(turns[turns.size() / 2], 30.0, 3.0);
  EXPECT_GT(toy, 5000);
  EXPECT_EQ(toySame, toy);
  EXPECT_LT(lighter, static_cast<long>(turns.size() / 100)); // the grey axis kept: brightness within rounding
  vpImage<vpRGBa> pass;
  drifting.targetAlone().render(c.r, c.rig.left, c.hMo, 900, 0, pass);
  EXPECT_TRUE(pass == still);
  p.backdropHueDriftDegPerS = 120;
  EXPECT_NE(pm::test::errorOf([&] { pm::sim::Scene(c.shape, p); }).find("backdrop hue drift"), std::string::npos);
}

TEST(Clutter, ThreeOtherToysOneOfTheNearestHueAroundTheTargetClearOfIt)
{
  for (const char *code : {"C12", "R2", "C05"}) {
    const pm::sim::TargetShape target = pm::sim::makeTarget(code, 1.0);
    const double hue = pm::sim::meanHueDeg(target);
    const std::vector<pm::sim::ClutterToy> toys = pm::sim::clutterAround(target);
    ASSERT_EQ(toys.size(), 3u) << code;
    auto gap = [&](const std::string &c) {
      const double d = std::fabs(pm::sim::meanHueDeg(pm::sim::makeTarget(c, 1.0)) - hue);
      return std::min(d, 360 - d);
    };
    EXPECT_TRUE(toys[0].similarHue);
    for (const pm::sim::TargetInfo &t : pm::sim::targetCatalog()) { // the nearest creature in hue
      if (t.code != code) {
        EXPECT_LE(gap(toys[0].code), gap(t.code)) << code << " " << t.code;
      }
    }
    EXPECT_LT(gap(toys[0].code), 15.0) << code;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_NE(toys[i].code, code);
      for (std::size_t j = i + 1; j < 3; ++j)
        EXPECT_NE(toys[i].code, toys[j].code);
      if (i > 0) {
        EXPECT_FALSE(toys[i].similarHue);
        EXPECT_GT(gap(toys[i].code), 60.0) << code << " " << toys[i].code;
      }
      // Clear of the target's nominal outline: beyond its half-extent on one axis.
      EXPECT_TRUE(std::fabs(toys[i].poseMm[0]) > target.info.widthMm / 2 + 25 ||
                  std::fabs(toys[i].poseMm[1]) > target.info.heightMm / 2 + 25) << code << " " << toys[i].code;
    }
  }
}

TEST(Scene, ClutterStandsBesideTheTargetAndMovesWithTheBackdrop)
{
  CrabAhead c;
  pm::sim::SceneParams p;
  std::size_t alone[2];
  for (unsigned k = 0; k < 2; ++k) {
    pm::sim::Scene(c.shape, p).render(c.r, k == 0 ? c.rig.left : c.rig.right, c.hMo, 0, k, c.I);
    alone[k] = pixelsOf(c.r, 2).size();
    EXPECT_TRUE(pixelsOf(c.r, 4).empty());
  }
  p.clutter = true;
  p.stillBackdrop = true;
  const pm::sim::Scene scene(c.shape, p);
  auto meanU = [](const std::vector<std::pair<unsigned, unsigned>> &px) {
    double s = 0;
    for (const auto &q : px)
      s += q.first;
    return s / static_cast<double>(px.size());
  };
  for (unsigned k = 0; k < 2; ++k) {
    const pm::core::PinholeCamera *cam = k == 0 ? &c.rig.left : &c.rig.right;
    scene.render(c.r, *cam, c.hMo, 0, k, c.I);
    const auto toy = pixelsOf(c.r, 2), others = pixelsOf(c.r, 4);
    EXPECT_GT(others.size(), 5000u);                                // the clutter is in view ...
    EXPECT_EQ(toy.size(), alone[k]);                                // ... and hides nothing of the toy
    // The target moved 30 mm to the left in front of the still backdrop: the clutter stays with the backdrop.
    const vpHomogeneousMatrix moved = c.hMo * vpHomogeneousMatrix(-0.03, 0, 0, 0, 0, 0);
    scene.render(c.r, *cam, moved, 0, k, c.I, true, vpHomogeneousMatrix(0.03, 0, 0, 0, 0, 0));
    EXPECT_NEAR(meanU(pixelsOf(c.r, 4)), meanU(others), 2.0);
    EXPECT_LT(meanU(pixelsOf(c.r, 2)), meanU(toy) - 30);
  }
}

TEST(Scene, TheGrippersFingersStayAtTheBottomOfBothImagesAndHideMoreOfTheTargetAsTheHandClosesIn)
{
  CrabAhead c;
  const vpHomogeneousMatrix near = pm::core::toHomogeneousMatrix({0, 0, 300, 0, 0, 0});
  pm::sim::SceneParams p;
  const pm::sim::Scene bare(c.shape, p);
  p.gripper = true;
  const pm::sim::Scene scene(c.shape, p);
  for (unsigned k = 0; k < 2; ++k) {
    const pm::core::PinholeCamera &cam = k == 0 ? c.rig.left : c.rig.right;
    double hiddenShare[2];
    std::vector<std::pair<unsigned, unsigned>> fingers[2];
    for (int d = 0; d < 2; ++d) {
      const vpHomogeneousMatrix &hMo = d == 0 ? c.hMo : near;
      bare.render(c.r, cam, hMo, 0, k, c.I);
      const double open = static_cast<double>(pixelsOf(c.r, 2).size());
      EXPECT_TRUE(pixelsOf(c.r, 3).empty());
      scene.render(c.r, cam, hMo, 0, k, c.I);
      fingers[d] = pixelsOf(c.r, 3);
      hiddenShare[d] = 1 - static_cast<double>(pixelsOf(c.r, 2).size()) / open;
      EXPECT_GT(fingers[d].size(), 10000u) << k;
      for (const auto &px : fingers[d]) // in the bottom half, entering from the image's edge
        ASSERT_GE(px.second, cam.height / 2) << k;
      EXPECT_TRUE(std::any_of(fingers[d].begin(), fingers[d].end(), [&](const auto &px) {
        return px.second == cam.height - 1 || px.first == 0 || px.first == cam.width - 1;
      }));
    }
    EXPECT_EQ(fingers[0], fingers[1]) << k; // fixed on the hand: the same pixels whatever the target's pose
    std::cout << "camera " << k << ": the fingers hide " << 100 * hiddenShare[0] << " % of the crab's pixels 500 mm ahead, "
              << 100 * hiddenShare[1] << " % 300 mm ahead" << std::endl;
    EXPECT_LT(hiddenShare[0], 0.01) << k;                  // 500 mm ahead: they touch the toy's lower edge at most
    EXPECT_GT(hiddenShare[1], hiddenShare[0] + 0.03) << k; // 300 mm ahead: they hide its lower legs
    EXPECT_LT(hiddenShare[1], 0.30) << k;
  }
  // The pass and the model's photos see the target alone.
  scene.targetAlone().render(c.r, c.rig.left, near, 0, 0, c.I);
  EXPECT_TRUE(pixelsOf(c.r, 3).empty());
  EXPECT_FALSE(scene.targetAlone().params().gripper);
}

TEST(Scene, AStereoPairIsTheSameWhateverWasRenderedBefore)
{
  // The renderer keeps its sample buffers from frame to frame: whatever was rendered before
  // (another toy, no anti-aliasing, supersampling 3, a look-alike, an occluder), a pair is the
  // same, bit for bit, as each image rendered alone with a new rasterizer.
  const pm::core::StereoRig rig = labRig();
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({10, -5, 520, 0.05, 0, 0.1});
  std::vector<pm::sim::Scene> scenes;
  scenes.emplace_back(pm::sim::makeTarget("C12", 0.5));
  pm::sim::SceneParams p;
  p.supersampling = 1;
  p.occluder = true;
  scenes.emplace_back(pm::sim::makeTarget("C05", 0.5), p);
  scenes.back().setDistractor(pm::sim::makeTarget("C12", 0.5));
  scenes.back().params().distractor = true;
  p.supersampling = 3;
  p.occluder = false;
  scenes.emplace_back(pm::sim::makeTarget("R1", 0.5), p);
  scenes.push_back(scenes.front());
  std::uint64_t frame = 3;
  for (const pm::sim::Scene &scene : scenes) {
    const pm::sim::StereoImages pair = scene.renderStereo(rig, hMo, frame);
    for (unsigned cam = 0; cam < 2; ++cam) {
      pm::sim::Rasterizer fresh;
      vpImage<vpRGBa> alone;
      scene.render(fresh, cam ? rig.right : rig.left, hMo, frame, cam, alone);
      const vpImage<vpRGBa> &I = cam ? pair.right : pair.left;
      ASSERT_EQ(I.getSize(), alone.getSize());
      EXPECT_EQ(0, std::memcmp(I.bitmap, alone.bitmap, alone.getSize() * sizeof(vpRGBa)))
          << "scene " << &scene - scenes.data() << ", camera " << cam;
    }
    ++frame;
  }
}

TEST(Targets, TwelveWithTheSizesOfFig8)
{
  ASSERT_EQ(pm::sim::targetCatalog().size(), 12u);
  for (const auto &info : pm::sim::targetCatalog()) {
    const pm::sim::TargetShape s = pm::sim::makeTarget(info.code, 0.5);
    double w = 0, h = 0;
    s.measuredExtent(w, h);
    EXPECT_NEAR(w, info.widthMm, 0.02 * info.widthMm + 1) << info.code;
    EXPECT_NEAR(h, info.heightMm, 0.02 * info.heightMm + 1) << info.code;
    const float maxH = *std::max_element(s.height.begin(), s.height.end());
    EXPECT_NEAR(maxH, info.depthMm, 0.01 * info.depthMm) << info.code;
  }
  EXPECT_TRUE(pm::sim::isCatalogTarget("c12"));
  EXPECT_THROW(pm::sim::makeTarget("C13"), pm::core::Error);
}

TEST(Targets, GenerationIsDeterministic)
{
  const auto a = pm::sim::makeTarget("C08", 0.5), b = pm::sim::makeTarget("C08", 0.5);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.height, b.height);
}

TEST(Targets, UserImageWithAlphaOutline)
{
  vpImage<vpRGBa> img(50, 100, vpRGBa(200, 150, 20, 255));
  for (unsigned v = 0; v < 50; ++v)
    for (unsigned u = 0; u < 50; ++u)
      img[v][u].A = 0; // left half transparent
  const pm::sim::TargetShape s = pm::sim::targetFromImage(img, 100, 10, "test");
  double w = 0, h = 0;
  s.measuredExtent(w, h);
  EXPECT_NEAR(w, 50, 1.5);
  EXPECT_NEAR(h, 50, 1.5);
  vpImage<vpRGBa> opaque(50, 100, vpRGBa(200, 150, 20, 255));
  pm::sim::targetFromImage(opaque, 100, 0, "flat").measuredExtent(w, h);
  EXPECT_NEAR(w, 100, 1.5);
  EXPECT_THROW(pm::sim::targetFromImage(opaque, -1, 0, "bad"), pm::core::Error);
}

TEST(Scene, BadParametersAreRefused)
{
  pm::sim::SceneParams p;
  p.supersampling = 0;
  EXPECT_THROW(p.validate(), pm::core::Error);
  p = pm::sim::SceneParams();
  p.exposure = 0;
  EXPECT_THROW(p.validate(), pm::core::Error);
}

// The toy's mesh cut along its outline for another renderer: a triangle's part where its linear mask
// is <= 0 and nothing else, so the cut mesh covers exactly the region the rasterizer keeps.
TEST(MeshOutlineCut, KeepsExactlyTheRegionInsideTheMask)
{
  // A flat 40 x 40 mm grid of 1 mm cells, masked by the distance to a circle of radius 15 mm.
  pm::sim::Mesh grid;
  grid.useMask = true;
  const int n = 41;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float x = static_cast<float>(i - 20), y = static_cast<float>(j - 20);
      pm::sim::MeshVertex v{x * 1e-3f, y * 1e-3f, 0, 0, 0, -1, x, y, std::sqrt(x * x + y * y) - 15.f};
      grid.vertices.push_back(v);
    }
  for (std::uint32_t j = 0; j + 1 < n; ++j)
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      grid.triangles.push_back({a, b, c});
      grid.triangles.push_back({a, c, d});
    }
  const pm::sim::Mesh cut = pm::sim::cutAlongOutline(grid);
  EXPECT_FALSE(cut.useMask);
  double area = 0, maxRadius = 0;
  for (const auto &t : cut.triangles) {
    const auto &a = cut.vertices[t[0]], &b = cut.vertices[t[1]], &c = cut.vertices[t[2]];
    area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) * 1e6; // mm^2
    for (const auto *v : {&a, &b, &c}) {
      EXPECT_LE(v->mask, 0.f);
      maxRadius = std::max(maxRadius, std::hypot(v->x, v->y) * 1e3);
    }
  }
  // The linear mask's zero line is a polygon inscribed in the circle, within 0.02 mm of it on 1 mm cells.
  EXPECT_LE(maxRadius, 15.0 + 1e-4);
  EXPECT_NEAR(area, M_PI * 15 * 15, 0.01 * M_PI * 15 * 15);
  EXPECT_GT(area, 0.99 * M_PI * 15 * 15);
  // A mesh without a mask comes back as it is.
  pm::sim::Mesh plain = grid;
  plain.useMask = false;
  EXPECT_EQ(pm::sim::cutAlongOutline(plain).triangles.size(), grid.triangles.size());
}
