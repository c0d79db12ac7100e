// The stereo fitness (Eqs. 8-11): exact scores, wrap-around, off-image points, kernels, threads,
// errors, and the fitness maps of the 12 targets (Figs. 10, 11).
#include <gtest/gtest.h>

#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPoint.h>

#include <array>
#include <random>
#include <thread>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/HuePlane.h"
#include "pm/core/StereoFitness.h"
#include "pm/io/RigFile.h"
#include "pm/rmga/SmoothAscent.h"
#include "pm/rmga/StereoObjective.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

pm::core::StereoRig labRig() { return pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json")); }

//! A model of (2 half + 1)^2 S_in points of hue \e hue on a grid of \e stepMm and \e nOut S_out points
//! on a circle of 50 mm around them; background hue 210. The default: 49 S_in on 10 mm, 20 S_out.
pm::core::PhotoModel gridModel(float hue, int half = 3, double stepMm = 10, int nOut = 20)
{
  pm::core::PhotoModel m;
  m.distanceMm = 500;
  m.px = m.py = 754;
  m.u0 = 320;
  m.v0 = 240;
  m.photoWidth = 640;
  m.photoHeight = 480;
  m.backgroundHue = 210;
  for (int j = -half; j <= half; ++j)
    for (int i = -half; i <= half; ++i) {
      pm::core::ModelPoint p;
      p.x = static_cast<float>(stepMm * i);
      p.y = static_cast<float>(stepMm * j);
      p.hue = hue;
      m.inner.push_back(p);
    }
  for (int k = 0; k < nOut; ++k) {
    pm::core::ModelPoint p;
    p.x = static_cast<float>(50 * std::cos(k * M_PI / (nOut / 2.0)));
    p.y = static_cast<float>(50 * std::sin(k * M_PI / (nOut / 2.0)));
    p.hue = 210;
    m.outer.push_back(p);
  }
  return m;
}

vpImage<vpRGBa> uniform(unsigned char r, unsigned char g, unsigned char b) { return vpImage<vpRGBa>(480, 640, vpRGBa(r, g, b)); }

const pm::core::Phi kAhead{0, 0, 500, 0, 0, 0};

} // namespace

TEST(Fitness, ExactScoresOnUniformImages)
{
  const pm::core::StereoRig rig = labRig();
  const pm::core::PhotoModel m = gridModel(0.f); // a red model: 49 S_in, 20 S_out
  pm::core::StereoFitness fit(rig, m);
  const double n = 69;
  // All of the image is background (hue 210): S_in -0.005 each, S_out +0.1 each.
  fit.setImages(uniform(0, 127, 255), uniform(0, 127, 255));
  EXPECT_NEAR(pm::core::hueDeg(vpRGBa(0, 127, 255)), 210.1f, 0.1f);
  EXPECT_DOUBLE_EQ(fit.evaluate(kAhead), (49 * -0.005 + 20 * 0.1) / n);
  // All of it is the target's red: S_in +2, S_out -0.5.
  fit.setImages(uniform(255, 0, 0), uniform(255, 0, 0));
  EXPECT_DOUBLE_EQ(fit.evaluate(kAhead), (49 * 2.0 + 20 * -0.5) / n);
  // Green is neither: S_in 0, S_out -0.5.
  fit.setImages(uniform(0, 255, 0), uniform(0, 255, 0));
  EXPECT_DOUBLE_EQ(fit.evaluate(kAhead), (20 * -0.5) / n);
  const pm::core::FitnessDetail d = fit.evaluateDetail(kAhead);
  EXPECT_EQ(d.counts[0].inOther, 49);
  EXPECT_EQ(d.counts[1].outOther, 20);
  // Scores and tolerances are parameters.
  pm::core::FitnessParams p;
  p.outOther = -1.0;
  pm::core::StereoFitness fit2(rig, m, p);
  fit2.setImages(uniform(0, 255, 0), uniform(0, 255, 0));
  EXPECT_DOUBLE_EQ(fit2.evaluate(kAhead), -20.0 / n);
}

TEST(Fitness, EachCameraIsScoredWithTheViewNearestItsDirectionOnOneScale)
{
  // A stereo model of two views: the left camera's (49 red S_in, 20 S_out) and the right camera's
  // (25 green S_in, 10 S_out), each with its camera's centre in the model frame at kAhead.
  const pm::core::StereoRig rig = labRig();
  pm::core::PhotoModel m = gridModel(0.f);
  for (pm::core::ModelPoint &p : m.inner)
    p.z = -2;
  const vpHomogeneousMatrix hMm = pm::core::toHomogeneousMatrix(kAhead);
  const vpHomogeneousMatrix mMcL = hMm.inverse() * rig.left.hMc, mMcR = hMm.inverse() * rig.right.hMc;
  pm::core::ModelView right;
  for (unsigned i = 0; i < 3; ++i) {
    m.cameraMm[i] = mMcL[i][3] * 1e3;
    right.cameraMm[i] = mMcR[i][3] * 1e3;
  }
  const pm::core::PhotoModel green = gridModel(120.f, 2, 8, 10);
  right.inner = green.inner;
  right.outer = green.outer;
  for (pm::core::ModelPoint &p : right.inner)
    p.z = -1;
  m.views.push_back(right);
  pm::core::StereoFitness fit(rig, m);
  // The left image is red (the left view's S_in all match), the right one green (the right view's do).
  fit.setImages(uniform(255, 0, 0), uniform(0, 255, 0));
  const pm::core::FitnessDetail d = fit.evaluateDetail(kAhead);
  EXPECT_EQ(d.counts[0].inMatch, 49);
  EXPECT_EQ(d.counts[0].outOther, 20);
  EXPECT_EQ(d.counts[1].inMatch, 25);
  EXPECT_EQ(d.counts[1].outOther, 10);
  EXPECT_DOUBLE_EQ(d.score[0], (49 * 2.0 + 20 * -0.5) / 69);
  // The right view's sum on the left view's scale: both at their best score the same.
  const double best0 = (49 * 2.0 + 20 * 0.1) / 69, best1 = 25 * 2.0 + 10 * 0.1;
  EXPECT_DOUBLE_EQ(d.score[1], (25 * 2.0 + 10 * -0.5) * best0 / best1);
  EXPECT_EQ(fit.pointScores(kAhead, 0).size(), 69u);
  EXPECT_EQ(fit.pointScores(kAhead, 1).size(), 35u);
  // Turned by 90 deg about y, both cameras look from the model's side: the right view's camera
  // (at +x) is the nearer to both.
  const pm::core::Phi side{0, 0, 500, 0, std::sin(M_PI / 4), 0};
  EXPECT_EQ(fit.pointScores(side, 0).size(), 35u);
  EXPECT_EQ(fit.pointScores(side, 1).size(), 35u);
  const pm::core::Phi otherSide{0, 0, 500, 0, -std::sin(M_PI / 4), 0};
  EXPECT_EQ(fit.pointScores(otherSide, 0).size(), 69u);
  EXPECT_EQ(fit.pointScores(otherSide, 1).size(), 69u);
  // Views are for stereo models only, and each needs its camera.
  pm::core::PhotoModel flat = gridModel(0.f);
  flat.cameraMm[2] = -500;
  flat.views.push_back(right);
  EXPECT_THROW(pm::core::StereoFitness(rig, flat), pm::core::Error);
  pm::core::PhotoModel noCamera = m;
  noCamera.views[0].cameraMm[0] = noCamera.views[0].cameraMm[1] = noCamera.views[0].cameraMm[2] = 0;
  EXPECT_THROW(pm::core::StereoFitness(rig, noCamera), pm::core::Error);
}

TEST(Fitness, HueDistancesWrapAround)
{
  const pm::core::StereoRig rig = labRig();
  pm::core::StereoFitness fit(rig, gridModel(355.f));
  fit.setImages(uniform(255, 42, 0), uniform(255, 42, 0)); // hue 10 deg: 15 deg from 355
  EXPECT_NEAR(pm::core::hueDeg(vpRGBa(255, 42, 0)), 9.9f, 0.1f);
  EXPECT_EQ(fit.evaluateDetail(kAhead).counts[0].inMatch, 49);
  pm::core::FitnessParams tight;
  tight.inTolDeg = 10;
  pm::core::StereoFitness fit2(rig, gridModel(355.f), tight);
  fit2.setImages(uniform(255, 42, 0), uniform(255, 42, 0));
  EXPECT_EQ(fit2.evaluateDetail(kAhead).counts[0].inMatch, 0);
}

TEST(Fitness, OffTheImagesIsFiniteAndScoresOffImage)
{
  const pm::core::StereoRig rig = labRig();
  pm::core::StereoFitness fit(rig, gridModel(0.f));
  fit.setImages(uniform(255, 0, 0), uniform(255, 0, 0));
  for (const pm::core::Phi &far : {pm::core::Phi{5000, 0, 500, 0, 0, 0}, pm::core::Phi{0, 0, -500, 0, 0, 0}, pm::core::Phi{0, 0, 1e9, 0, 0, 0},
                             pm::core::Phi{0, 0, 0, 0, 0, 0}, pm::core::Phi{1e30, -1e30, 1e-30, 0.5, 0.5, 0.5}}) {
    const double f = fit.evaluate(far);
    EXPECT_TRUE(std::isfinite(f)) << far.toString();
  }
  EXPECT_DOUBLE_EQ(fit.evaluate({5000, 0, 500, 0, 0, 0}), 0.0);
  pm::core::FitnessParams p;
  p.offImage = -1;
  pm::core::StereoFitness fit2(rig, gridModel(0.f), p);
  fit2.setImages(uniform(255, 0, 0), uniform(255, 0, 0));
  EXPECT_DOUBLE_EQ(fit2.evaluate({5000, 0, 500, 0, 0, 0}), -1.0);
  EXPECT_DOUBLE_EQ(fit2.evaluate({0, 0, -500, 0, 0, 0}), -1.0); // behind the cameras
}

TEST(Fitness, InvalidInputIsRefused)
{
  const pm::core::StereoRig rig = labRig();
  pm::core::StereoFitness fit(rig, gridModel(0.f));
  EXPECT_THROW(fit.evaluate(kAhead), pm::core::Error); // no images yet
  EXPECT_THROW(fit.setImages(vpImage<vpRGBa>(240, 320), uniform(0, 0, 0)), pm::core::Error);
  fit.setImages(uniform(0, 0, 0), uniform(0, 0, 0));
  EXPECT_THROW(fit.evaluate({0, 0, 500, 0.8, 0.8, 0}), pm::core::Error);
  EXPECT_THROW(fit.evaluate({NAN, 0, 500, 0, 0, 0}), pm::core::Error);
  // One invalid pose in a batch: refused before any thread starts.
  std::vector<pm::core::Phi> batch(20, kAhead);
  batch[13] = {0, 0, 500, 0.8, 0.8, 0};
  std::vector<double> out(batch.size());
  EXPECT_THROW(fit.evaluate(batch.data(), batch.size(), out.data()), pm::core::Error);
  pm::core::PhotoModel empty = gridModel(0.f);
  empty.inner.clear();
  EXPECT_THROW(pm::core::StereoFitness(rig, empty), pm::core::Error);
  pm::core::FitnessParams bad;
  bad.inTolDeg = -1;
  EXPECT_THROW(pm::core::StereoFitness(rig, gridModel(0.f), bad), pm::core::Error);
}

TEST(HuePlane, MatchesThePerPixelFormula)
{
  const vpImage<vpRGBa> I = pm::test::bluePhoto(64, 48, 9);
  vpImage<vpRGBa> J = I;
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> c(0, 255);
  for (unsigned k = 0; k < J.getSize(); ++k)
    J.bitmap[k] = vpRGBa(static_cast<unsigned char>(c(rng)), static_cast<unsigned char>(c(rng)), static_cast<unsigned char>(c(rng)));
  pm::core::HuePlane plane;
  for (float minSat : {0.f, 0.1f, 0.5f}) { // the vectorised plane and the per-pixel formula agree to the bit
    plane.compute(J, minSat);
    for (unsigned v = 0; v < J.getHeight(); ++v)
      for (unsigned u = 0; u < J.getWidth(); ++u)
        ASSERT_EQ(plane.at(u, v), pm::core::hueDeci(J[v][u], minSat)) << u << "," << v << " min saturation " << minSat;
  }
  plane.compute(J);
  for (unsigned v = 0; v < J.getHeight(); ++v)
    for (unsigned u = 0; u < J.getWidth(); ++u) {
      const pm::core::Hsv h = pm::core::rgbToHsv(J[v][u]);
      if (h.s > 0) {
        EXPECT_LE(pm::core::hueDistance(plane.at(u, v) / 10.f, h.h), 0.05f + 1e-4f);
      }
    }
  plane.compute(vpImage<vpRGBa>(2, 2, vpRGBa(128, 128, 128)), 0.1f);
  EXPECT_EQ(plane.at(1, 1), pm::core::HuePlane::kNoHue); // grey has no hue when a minimum saturation is set
}

TEST(HuePlane, AWindowHoldsTheHueInsideAndNoHueOutsideWhateverCameBefore)
{
  vpImage<vpRGBa> J(48, 64);
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> c(0, 255);
  for (unsigned k = 0; k < J.getSize(); ++k)
    J.bitmap[k] = vpRGBa(static_cast<unsigned char>(c(rng)), static_cast<unsigned char>(c(rng)), static_cast<unsigned char>(c(rng)));
  pm::core::HuePlane full, plane;
  full.compute(J, 0.1f);
  auto expectWindow = [&](const pm::core::PixelRect &w, const std::vector<std::int64_t> &extra, const char *what) {
    for (int v = 0; v < 48; ++v)
      for (int u = 0; u < 64; ++u) {
        const bool in = (u >= w.u0 && u < w.u1 && v >= w.v0 && v < w.v1) ||
                        std::find(extra.begin(), extra.end(), static_cast<std::int64_t>(v * 64 + u)) != extra.end();
        ASSERT_EQ(plane.at(static_cast<unsigned>(u), static_cast<unsigned>(v)),
                  in ? full.at(static_cast<unsigned>(u), static_cast<unsigned>(v)) : pm::core::HuePlane::kNoHue)
            << what << " pixel " << u << "," << v;
      }
  };
  plane.compute(J, 0.1f); // the whole image first, then windows that overlap, move, shrink, pass the edges
  const std::vector<pm::core::PixelRect> windows = {{10, 5, 40, 30}, {20, 15, 60, 47}, {-5, -3, 12, 9}, {30, 20, 31, 21}, {50, 40, 90, 80}, {}};
  for (const pm::core::PixelRect &w : windows) {
    plane.compute(J, 0.1f, w);
    const pm::core::PixelRect clipped = w.grown(0, 64, 48);
    expectWindow(clipped, {}, "window");
    EXPECT_TRUE(plane.window().u0 == clipped.u0 && plane.window().v0 == clipped.v0 && plane.window().u1 == clipped.u1 &&
                plane.window().v1 == clipped.v1);
  }
  // Pixels added outside the window get their hue, until the next compute.
  plane.compute(J, 0.1f, {10, 10, 20, 20});
  const std::vector<std::int64_t> extra = {0, 63, 47 * 64 + 63, 12 * 64 + 40, 15 * 64 + 15};
  plane.addPixels(J, 0.1f, extra.data(), extra.size());
  expectWindow({10, 10, 20, 20}, extra, "added pixels");
  plane.compute(J, 0.1f, {30, 30, 35, 35});
  expectWindow({30, 30, 35, 35}, {}, "after the added pixels");
  const std::int64_t bad = 64 * 48;
  EXPECT_THROW(plane.addPixels(J, 0.1f, &bad, 1), pm::core::Error);
  EXPECT_THROW(plane.addPixels(vpImage<vpRGBa>(4, 4), 0.1f, extra.data(), 1), pm::core::Error);
}

//! The AVX2 and the scalar kernels give exactly the same F for every pose of \e ps.
static void expectKernelsAgree(const pm::core::StereoFitness &fit, const std::vector<pm::core::Phi> &ps)
{
  std::vector<double> a(ps.size()), b(ps.size());
  fit.evaluate(ps.data(), ps.size(), a.data());
  pm::core::StereoFitness scalar = fit; // the same planes, the scalar kernels
  scalar.useScalarKernel(true);
  EXPECT_STREQ(scalar.kernelName(), "scalar");
  scalar.evaluate(ps.data(), ps.size(), b.data());
  for (std::size_t i = 0; i < ps.size(); ++i)
    ASSERT_EQ(a[i], b[i]) << ps[i].toString() << " kernel " << fit.kernelName();
}

class FitnessOnC12 : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    rig = new pm::core::StereoRig(labRig());
    const pm::sim::Scene scene(pm::sim::makeTarget("C12", 0.5));
    const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({10, -5, 510, 0.02, -0.03, 0.05});
    const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig->left.cam, 640, 480, 500);
    fit = new pm::core::StereoFitness(*rig, sm.build.model);
    model = new pm::core::PhotoModel(sm.build.model);
    ims = new pm::sim::StereoImages(scene.renderStereo(*rig, hMo, 0));
    fit->setImages(ims->left, ims->right);
    truth = sm.truth(hMo);
  }
  static void TearDownTestSuite()
  {
    delete fit;
    delete rig;
    delete model;
    delete ims;
  }
  static std::vector<pm::core::Phi> randomPoses(std::size_t n)
  {
    std::mt19937 rng(123);
    std::uniform_real_distribution<double> pos(-180, 180), z(320, 680), e(-0.37, 0.37);
    std::vector<pm::core::Phi> v;
    for (std::size_t i = 0; i < n; ++i)
      v.push_back({pos(rng), pos(rng), z(rng), e(rng), e(rng), e(rng)});
    return v;
  }
  static pm::core::StereoRig *rig;
  static pm::core::StereoFitness *fit;
  static pm::core::PhotoModel *model;
  static pm::sim::StereoImages *ims;
  static pm::core::Phi truth;
};
pm::core::PhotoModel *FitnessOnC12::model = nullptr;
pm::sim::StereoImages *FitnessOnC12::ims = nullptr;
pm::core::StereoRig *FitnessOnC12::rig = nullptr;
pm::core::StereoFitness *FitnessOnC12::fit = nullptr;
pm::core::Phi FitnessOnC12::truth;

TEST_F(FitnessOnC12, Avx2AndScalarKernelsAgreeExactly)
{
  expectKernelsAgree(*fit, randomPoses(2000));
}

TEST_F(FitnessOnC12, HueWindowsAroundAPoseGiveItsFitnessAndAddHueUnderGivesAnyOther)
{
  pm::core::StereoFitness windowed(*rig, *model);
  std::array<pm::core::PixelRect, 2> w;
  for (int cam = 0; cam < 2; ++cam)
    w[static_cast<std::size_t>(cam)] = windowed.footprint(truth, cam).grown(4, 640, 480);
  windowed.setImages(ims->left, ims->right, w);
  pm::core::StereoFitness whole(*rig, *model);
  whole.setImages(ims->left, ims->right);
  // At the pose and near it (within the 4-pixel margin): F as on the whole images.
  EXPECT_DOUBLE_EQ(windowed.evaluate(truth), whole.evaluate(truth));
  const pm::core::Phi near{truth.x + 1, truth.y - 1, truth.z, truth.e1, truth.e2, truth.e3};
  EXPECT_DOUBLE_EQ(windowed.evaluate(near), whole.evaluate(near));
  // Far from it, the window's outside matches nothing: F differs, until its hue is added.
  const pm::core::Phi far{truth.x + 120, truth.y + 60, truth.z, truth.e1, truth.e2, truth.e3};
  EXPECT_NE(windowed.evaluate(far), whole.evaluate(far));
  windowed.addHueUnder(ims->left, ims->right, &far, 1);
  EXPECT_DOUBLE_EQ(windowed.evaluate(far), whole.evaluate(far));
  EXPECT_DOUBLE_EQ(windowed.evaluate(truth), whole.evaluate(truth));
  // A footprint holds every point that falls on the image.
  for (int cam = 0; cam < 2; ++cam) {
    const pm::core::PixelRect fp = whole.footprint(truth, cam);
    for (const pm::core::PointScore &s : whole.pointScores(truth, cam))
      if (s.u >= -0.5 && s.v >= -0.5 && s.u < 639.5 && s.v < 479.5) {
        EXPECT_GE(std::lround(s.u), fp.u0);
        EXPECT_LT(std::lround(s.u), fp.u1);
        EXPECT_GE(std::lround(s.v), fp.v0);
        EXPECT_LT(std::lround(s.v), fp.v1);
      }
  }
  EXPECT_THROW(windowed.addHueUnder(vpImage<vpRGBa>(4, 4), vpImage<vpRGBa>(4, 4), &truth, 1), pm::core::Error);
}

TEST_F(FitnessOnC12, ThreadSafeAndBatchEqualsSingle)
{
  const auto ps = randomPoses(400);
  std::vector<double> seq(ps.size()), par(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i)
    seq[i] = fit->evaluate(ps[i]);
  std::thread t1([&] { fit->evaluate(ps.data(), 200, par.data()); });
  std::thread t2([&] { fit->evaluate(ps.data() + 200, 200, par.data() + 200); });
  t1.join();
  t2.join();
  EXPECT_EQ(seq, par);
  // The batch of one caller on two cores: the same values.
  std::vector<double> two(ps.size());
  fit->evaluate(ps.data(), ps.size(), two.data());
  EXPECT_EQ(seq, two);
}

TEST_F(FitnessOnC12, TruthBeatsPosesThirtyMillimetresOrOneTenthAway)
{
  const double fTruth = fit->evaluate(truth);
  for (std::size_t k = 0; k < 6; ++k)
    for (double s : {-1.0, 1.0}) {
      pm::core::Phi p = truth;
      p[k] += s * (k < 3 ? 30.0 : 0.1);
      EXPECT_GT(fTruth, fit->evaluate(p)) << "variable " << k << " moved by " << s;
    }
}

namespace {

struct MapErrors
{
  double x, y, yOfYz, z, e1, e2, e2OfE2e3, e3;
  double reprojE1E2, reprojE2E3;
  int positionLosses; //!< poses 30 mm from the truth (x, y, z, both ways) scoring at least as high as it
  int rollLosses;     //!< poses 0.1 from the truth in eps3 scoring at least as high
  int tiltLosses;     //!< poses 0.1 from the truth in eps1 or eps2 scoring higher by more than one point's worth
};

MapErrors mapErrors(const std::string &code, double reliefScale)
{
  const pm::core::StereoRig rig = labRig();
  pm::sim::TargetShape shape = pm::sim::makeTarget(code, 0.5);
  shape.scaleRelief(reliefScale);
  const pm::sim::Scene scene(shape);
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500);
  pm::core::StereoFitness fit(rig, sm.build.model);
  const auto im = scene.renderStereo(rig, hMo, 0);
  fit.setImages(im.left, im.right);
  const pm::core::Phi t = sm.truth(hMo);
  const auto specs = pm::core::paperFitnessMaps();
  pm::core::FitnessMap m[4];
  for (int i = 0; i < 4; ++i)
    m[i] = pm::core::computeFitnessMap(fit, t, specs[static_cast<std::size_t>(i)]);
  auto reproj = [&](const pm::core::FitnessMap &mm) {
    pm::core::Phi p = t;
    p[mm.spec.a] = mm.peakA;
    p[mm.spec.b] = mm.peakB;
    return fit.reprojectionRms(p, t);
  };
  int positionLosses = 0, rollLosses = 0, tiltLosses = 0;
  const double fTruth = fit.evaluate(t);
  for (std::size_t k = 0; k < 6; ++k)
    for (double s : {-1.0, 1.0}) {
      pm::core::Phi p = t;
      p[k] += s * (k < 3 ? 30.0 : 0.1);
      const double f = fit.evaluate(p);
      if (k < 3)
        positionLosses += f >= fTruth;
      else if (k == 5)
        rollLosses += f >= fTruth;
      else // one model point changing class in one camera moves F by at most 2.5 / (2 n)
        tiltLosses += f > fTruth + 1.25 / static_cast<double>(fit.modelSize());
    }
  return {m[0].peakA - t.x,  m[0].peakB - t.y,  m[1].peakA - t.y,  m[1].peakB - t.z, m[2].peakA - t.e1,
          m[2].peakB - t.e2, m[3].peakA - t.e2, m[3].peakB - t.e3, reproj(m[2]),     reproj(m[3]), positionLosses, rollLosses, tiltLosses};
}

} // namespace

// The photo-model is a plane; the toys have relief. Made flat, every target's four maps peak at the
// truth within the tolerances (2 mm; 0.02 in eps, or under 1 px of reprojection where a
// tilt of a thin target cannot be seen by the cameras), and the truth scores higher than every pose
// 30 mm or 0.1 away (a tilt of 0.1 about the long axis of the 30 mm tall moray eel, which moves its
// points by 1 px, ties with it to within one point's worth of F).
TEST(FitnessMaps, FlatTargetsPeakAtTheTruth)
{
  for (const auto &info : pm::sim::targetCatalog()) {
    const MapErrors e = mapErrors(info.code, 0.0);
    EXPECT_LE(std::fabs(e.x), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.y), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.yOfYz), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.z), 2.0) << info.code;
    EXPECT_TRUE(std::max(std::fabs(e.e1), std::fabs(e.e2)) <= 0.02 || e.reprojE1E2 < 1.0)
        << info.code << " e1 " << e.e1 << " e2 " << e.e2 << " reprojection " << e.reprojE1E2 << " px";
    EXPECT_TRUE(std::max(std::fabs(e.e2OfE2e3), std::fabs(e.e3)) <= 0.02 || e.reprojE2E3 < 1.0)
        << info.code << " e2 " << e.e2OfE2e3 << " e3 " << e.e3 << " reprojection " << e.reprojE2E3 << " px";
    EXPECT_EQ(e.positionLosses, 0) << info.code << ": a pose 30 mm from the truth scores as high";
    EXPECT_EQ(e.rollLosses, 0) << info.code << ": a pose 0.1 from the truth in eps3 scores as high";
    EXPECT_EQ(e.tiltLosses, 0) << info.code << ": a pose 0.1 from the truth in eps1 or eps2 scores higher by more than one point";
  }
}

// With their relief (up to 110 mm), the maps still have one main peak at the truth in x, y and the
// in-plane rotation eps3 (the 2 mm and 0.02). The depth z and the tilts eps1, eps2 are
// pulled by the relief's parallax, which a plane cannot follow: z peaks in front of the base plane,
// but inside the toy (between its base and its top), and the tilts within the paper's own bound
// (Table 1: 0.15). The truth scores higher than every pose 30 mm away and 0.1 away in eps3; a tilt of
// 0.1 (eps1, eps2) matches the relief's parallax better for the dolphin, jellyfish and anemonefish,
// so the tilts are not asserted there. Measured values are in README (pm-fitness-map).
TEST(FitnessMaps, TargetsWithReliefPeakNearTheTruth)
{
  for (const auto &info : pm::sim::targetCatalog()) {
    const MapErrors e = mapErrors(info.code, 1.0);
    EXPECT_LE(std::fabs(e.x), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.y), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.yOfYz), 2.0) << info.code;
    EXPECT_LE(std::fabs(e.e3), 0.02) << info.code;
    EXPECT_LE(e.z, 2.0) << info.code;
    EXPECT_GE(e.z, -info.depthMm) << info.code;
    EXPECT_LE(std::max({std::fabs(e.e1), std::fabs(e.e2), std::fabs(e.e2OfE2e3)}), 0.15) << info.code;
    EXPECT_EQ(e.positionLosses, 0) << info.code << ": a pose 30 mm from the truth scores as high";
    EXPECT_EQ(e.rollLosses, 0) << info.code << ": a pose 0.1 from the truth in eps3 scores as high";
  }
}

// ---- The fitness of a model with depth (the stereo photo-model) ----

class FitnessOnC12Stereo : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    rig = new pm::core::StereoRig(labRig());
    const pm::sim::Scene scene(pm::sim::makeTarget("C12", 0.5));
    const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({10, -5, 510, 0.02, -0.03, 0.05});
    pm::model::StereoModelParams twoViews; // the left and the right camera's views
    twoViews.rightView = true;
    const auto sm = pm::sim::makeSimulatedStereoPhotoModel(scene, *rig, 500, twoViews);
    model = new pm::core::PhotoModel(sm.build.model);
    fit = new pm::core::StereoFitness(*rig, *model);
    const auto im = scene.renderStereo(*rig, hMo, 0);
    fit->setImages(im.left, im.right);
    truth = sm.truth(hMo);
    // The one-view model (the left photo's points for both cameras, one pair of photos).
    pm::model::StereoModelParams leftOnly;
    leftOnly.rightView = false;
    const auto mv = pm::sim::makeSimulatedStereoPhotoModel(scene, *rig, 500, leftOnly);
    oneView = new pm::core::StereoFitness(*rig, mv.build.model);
    oneView->setImages(im.left, im.right);
    truthOneView = mv.truth(hMo);
  }
  static void TearDownTestSuite()
  {
    delete oneView;
    delete fit;
    delete model;
    delete rig;
  }
  static pm::core::StereoRig *rig;
  static pm::core::PhotoModel *model;
  static pm::core::StereoFitness *fit, *oneView;
  static pm::core::Phi truth, truthOneView;
};
pm::core::StereoRig *FitnessOnC12Stereo::rig = nullptr;
pm::core::PhotoModel *FitnessOnC12Stereo::model = nullptr;
pm::core::StereoFitness *FitnessOnC12Stereo::fit = nullptr;
pm::core::StereoFitness *FitnessOnC12Stereo::oneView = nullptr;
pm::core::Phi FitnessOnC12Stereo::truth;
pm::core::Phi FitnessOnC12Stereo::truthOneView;

TEST_F(FitnessOnC12Stereo, Avx2AndScalarKernelsAgreeExactlyWithDepth)
{
  ASSERT_TRUE(fit->hasDepth());
  std::mt19937 rng(321);
  std::uniform_real_distribution<double> pos(-180, 180), z(320, 680), e(-0.37, 0.37);
  std::vector<pm::core::Phi> ps;
  for (int i = 0; i < 2000; ++i)
    ps.push_back({pos(rng), pos(rng), z(rng), e(rng), e(rng), e(rng)});
  expectKernelsAgree(*fit, ps);
}

TEST_F(FitnessOnC12Stereo, PointsAreProjectedWithTheirDepthAsViSPDoes)
{
  const pm::core::Phi phi{5, -8, 520, 0.05, -0.1, 0.2};
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(phi);
  for (int cam = 0; cam < 2; ++cam) {
    const pm::core::PinholeCamera &c = cam ? rig->right : rig->left;
    // The left camera is scored with the left photo's points, the right one with the right's.
    ASSERT_EQ(model->views.size(), 1u);
    const std::vector<pm::core::ModelPoint> &in = cam ? model->views[0].inner : model->inner;
    const std::vector<pm::core::ModelPoint> &out = cam ? model->views[0].outer : model->outer;
    const auto scores = fit->pointScores(phi, cam);
    ASSERT_EQ(scores.size(), in.size() + out.size());
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const pm::core::ModelPoint &p = i < in.size() ? in[i] : out[i - in.size()];
      vpPoint P(p.x * 1e-3, p.y * 1e-3, p.z * 1e-3);
      P.track(c.cMh() * hMo);
      double u = 0, v = 0;
      vpMeterPixelConversion::convertPoint(c.cam, P.get_x(), P.get_y(), u, v);
      ASSERT_NEAR(scores[i].u, u, 0.02) << "point " << i << " camera " << cam;
      ASSERT_NEAR(scores[i].v, v, 0.02) << "point " << i << " camera " << cam;
    }
  }
}

TEST_F(FitnessOnC12Stereo, PeakIsAtTheTruthInDepthAndTilt)
{
  // F of the one-view stereo model along z and along each tilt through the truth: its maximum
  // lies within 1.5 mm and 0.01 of the truth (the flat model's lies 4.5 mm in front of the crab's
  // base: the relief it lacks). (The lab's multi-view model peaks at 0.015 in eps1 at this pose;
  // it is measured where it matters, in detection: README.)
  auto argmax = [&](int k, double half, double step) {
    double best = -1e9, at = 0;
    for (double d = -half; d <= half + 1e-9; d += step) {
      pm::core::Phi p = truthOneView;
      p[static_cast<std::size_t>(k)] += d;
      const double f = oneView->evaluate(p);
      if (f > best) {
        best = f;
        at = d;
      }
    }
    return at;
  };
  EXPECT_LE(std::fabs(argmax(2, 20, 0.5)), 1.5) << "z";
  EXPECT_LE(std::fabs(argmax(3, 0.08, 0.0025)), 0.01) << "eps1";
  EXPECT_LE(std::fabs(argmax(4, 0.08, 0.0025)), 0.01) << "eps2";
}

TEST_F(FitnessOnC12Stereo, OneCameraOrThreeScoreEachCameraAsTheStereoRigDoesAndFIsTheirMean)
{
  // The crab rendered in the three cameras of the lab's three-camera rig (the stereo pair and one
  // above the hand's centre). Without the stereo visibility each camera is scored alone, so camera k
  // of any rig scores as camera k of the stereo rig; F is the mean over the rig's cameras.
  const pm::sim::Scene scene(pm::sim::makeTarget("C12", 0.5));
  const pm::core::CameraRig three = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_trio.json"));
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({10, -5, 510, 0.02, -0.03, 0.05});
  const std::vector<vpImage<vpRGBa>> im = scene.renderRig(three, hMo, 0);
  ASSERT_EQ(im.size(), 3u);
  pm::sim::StereoImages pair = scene.renderStereo(*rig, hMo, 0); // the same two images (ViSP's == is not const)
  EXPECT_TRUE(pair.left == im[0] && pair.right == im[1]);
  const vpImage<vpRGBa> *images[3] = {&im[0], &im[1], &im[2]};
  pm::core::FitnessParams alone;
  alone.stereoVisibility = false;
  pm::core::StereoFitness stereo(*rig, *model, alone), one(pm::core::CameraRig(std::vector<pm::core::PinholeCamera>{three[0]}), *model, alone), trio(three, *model, alone);
  stereo.setImages(im[0], im[1]);
  one.setImages(images);
  trio.setImages(images);
  ASSERT_EQ(one.scorer().cameraCount(), 1);
  ASSERT_EQ(trio.scorer().cameraCount(), 3);
  const std::vector<pm::core::Phi> poses = {truth, {12, -9, 515, 0.05, -0.05, 0.08}, {-20, 10, 490, 0.0, 0.1, -0.1}};
  for (const pm::core::Phi &p : poses) {
    const pm::core::FitnessDetail s = stereo.evaluateDetail(p), o = one.evaluateDetail(p), t = trio.evaluateDetail(p);
    ASSERT_EQ(o.cameras, 1);
    EXPECT_EQ(o.score[0], s.score[0]);
    EXPECT_EQ(o.fitness, s.score[0]); // one camera: F is its score
    EXPECT_EQ(one.evaluate(p), o.fitness);
    EXPECT_EQ(t.score[0], s.score[0]);
    EXPECT_EQ(t.score[1], s.score[1]);
    EXPECT_DOUBLE_EQ(t.fitness, (t.score[0] + t.score[1] + t.score[2]) / 3);
    EXPECT_EQ(trio.evaluate(p), t.fitness);
    EXPECT_GT(t.counts[2].inMatch, 0);
  }
  // Every camera alone peaks at the truth against a pose 30 mm or 0.1 away, and so does each rig.
  for (const pm::core::Phi &off : {pm::core::Phi{truth.x + 30, truth.y, truth.z, truth.e1, truth.e2, truth.e3},
                                   pm::core::Phi{truth.x, truth.y, truth.z, truth.e1, truth.e2, truth.e3 + 0.1}}) {
    EXPECT_GT(one.evaluate(truth), one.evaluate(off) + 0.1);
    EXPECT_GT(trio.evaluate(truth), trio.evaluate(off) + 0.1);
    EXPECT_GT(trio.evaluateDetail(truth).score[2], trio.evaluateDetail(off).score[2] + 0.1);
  }
  // Depth from one view: the outline's size, and its place in a camera toed in 17.9 deg. Along z through
  // the truth, F of one camera peaks at the truth as the pair's does, and falls away from it at least
  // half as steeply (measured: 0.102 over 10 mm for the left camera alone, 0.075 for the pair).
  auto peakAndFall = [&](const pm::core::StereoFitness &f, double &atMm, double &fall10) {
    double best = -1e9;
    for (double d = -20; d <= 20 + 1e-9; d += 0.5) {
      pm::core::Phi p = truth;
      p.z += d;
      const double v = f.evaluate(p);
      if (v > best)
        best = v, atMm = d;
    }
    pm::core::Phi near = truth, far = truth;
    near.z -= 10, far.z += 10;
    fall10 = f.evaluate(truth) - 0.5 * (f.evaluate(near) + f.evaluate(far));
  };
  double monoAt = 0, monoFall = 0, pairAt = 0, pairFall = 0;
  peakAndFall(one, monoAt, monoFall);
  peakAndFall(stereo, pairAt, pairFall);
  std::cout << "along z: one camera peaks at " << monoAt << " mm, falls " << monoFall << " over 10 mm; the pair " << pairAt << " mm, "
            << pairFall << "\n";
  EXPECT_LE(std::fabs(monoAt), 3.0);
  EXPECT_LE(std::fabs(pairAt), 3.0);
  EXPECT_GT(monoFall, 0.5 * pairFall);
  // The batch, early rejection and the smooth score run over the rig's cameras too.
  double batch[3], rejected[3], cost[3];
  trio.scorer().evaluate(trio.frame(), poses.data(), 3, batch);
  trio.scorer().evaluate(trio.frame(), poses.data(), 3, rejected, -1e9, cost);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(batch[i], trio.evaluate(poses[i]));
    EXPECT_EQ(rejected[i], batch[i]);
  }
  double g[6];
  EXPECT_NEAR(one.scorer().evaluateSmoothGradient(one.frame(), truth, g), one.evaluateSmooth(truth), 1e-4);
  // A stereo pair given to a rig of another size, or a camera it does not have: clear errors.
  EXPECT_NE(pm::test::errorOf([&] { one.setImages(im[0], im[1]); }).find("the rig has 1 camera"), std::string::npos);
  EXPECT_NE(pm::test::errorOf([&] { (void)trio.pointScores(truth, 3); }).find("no camera 3"), std::string::npos);
}

TEST(SmoothFitness, EqualsTheFitnessWhereEveryPixelScoresAlike)
{
  const pm::core::StereoRig rig = labRig();
  pm::core::StereoFitness fit(rig, gridModel(0.f));
  for (const vpImage<vpRGBa> &im : {uniform(0, 127, 255), uniform(255, 0, 0), uniform(0, 255, 0)}) {
    fit.setImages(im, im);
    for (const pm::core::Phi &p : {kAhead, pm::core::Phi{3.3, -7.1, 480.2, 0.05, -0.02, 0.3}})
      EXPECT_NEAR(fit.evaluateSmooth(p), fit.evaluate(p), 1e-12);
  }
  EXPECT_DOUBLE_EQ(fit.evaluateSmooth({5000, 0, 500, 0, 0, 0}), 0.0); // off the images
  EXPECT_THROW(fit.evaluateSmooth({0, 0, 500, 0.8, 0.8, 0}), pm::core::Error);
}

TEST_F(FitnessOnC12, SmoothFitnessIsContinuousWhereTheFitnessIsAStaircase)
{
  // From 300 poses along x, the largest change of each score over a step of h and of h / 10:
  // F is a staircase (its largest jump is a whole point's worth whatever the step), the smooth
  // score is continuous (its largest change shrinks with the step).
  auto largestChange = [&](double h, bool smooth) {
    double m = 0;
    for (int i = 0; i < 300; ++i) {
      pm::core::Phi a = truth;
      a.x += 0.02 * i; // 0.02 mm is about 1/30 px at 500 mm
      pm::core::Phi b = a;
      b.x += h;
      m = std::max(m, smooth ? std::fabs(fit->evaluateSmooth(b) - fit->evaluateSmooth(a)) : std::fabs(fit->evaluate(b) - fit->evaluate(a)));
    }
    return m;
  };
  const double h = 0.02, point = 2.0 / (2.0 * static_cast<double>(fit->modelSize())); // an S_in point matching in one camera
  EXPECT_GT(largestChange(h / 10, false), 0.5 * point);
  EXPECT_LT(largestChange(h / 10, true), 0.2 * point);
  EXPECT_LT(largestChange(h / 10, true), 0.2 * largestChange(h, true));
  EXPECT_GT(largestChange(h, true), 0.0);
  // Near the truth both scores agree within a few points' worth.
  EXPECT_NEAR(fit->evaluateSmooth(truth), fit->evaluate(truth), 10 * point);
}

TEST(SmoothFitness, ItsClimbFindsTheBoxFromTwoMillimetresAndADegreeAway)
{
  // The poster box's stereo model (its depth exact to a fraction of a millimetre): RM-GA's
  // staircase fitness is flat over about a degree of tilt; the climb along the smooth score's
  // gradient (the tracker's smooth ascent, climbSmooth) gets back from a pose 2 mm and 1 deg off
  // in 24 evaluations onto the smooth score's ridge: most of the rotation error gone and 90 %
  // of the way up to the peak's score (with this one-view model the peak lies about 0.4 deg from
  // the truth: the climb from the truth itself stops there; the ridge is flat over a few tenths).
  const pm::core::StereoRig rig = labRig();
  const pm::sim::Scene box(pm::sim::makeTarget("R1", 0.25));
  pm::model::StereoModelParams leftOnly; // the one-view model (with the right camera's view: 0.7 mm, 0.35 deg)
  leftOnly.rightView = false;
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(box, rig, 500, leftOnly);
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({8, -6, 520, 0.03, -0.02, 0.04});
  const pm::core::Phi truth = sm.truth(hMo);
  pm::core::StereoFitness fit(rig, sm.build.model, pm::tracker::trackerFitnessDefaults());
  const auto im = box.renderStereo(rig, hMo, 0);
  fit.setImages(im.left, im.right);
  pm::rmga::StereoObjective smooth(fit);
  auto rotationDeg = [](const pm::core::Phi &a, const pm::core::Phi &b) {
    return (pm::core::toHomogeneousMatrix(a).inverse() * pm::core::toHomogeneousMatrix(b)).getThetaUVector().getTheta() * 180 / M_PI;
  };
  pm::core::Phi start = truth;
  start.x += 1.2;
  start.z -= 1.6;
  start.e1 += 0.0087 * 0.8; // about 0.8 deg
  start.e2 -= 0.0087 * 0.6;
  EXPECT_NEAR(std::hypot(start.x - truth.x, start.z - truth.z), 2.0, 0.01);
  EXPECT_NEAR(rotationDeg(start, truth), 1.0, 0.05);
  pm::rmga::SmoothAscentParams a;
  a.maxEvaluations = 24;
  const pm::rmga::SmoothAscentResult c = pm::rmga::climbSmooth(smooth, &start, 1, a);
  EXPECT_LE(c.evaluations, 24);
  EXPECT_GT(c.score, c.startScore);
  EXPECT_LT(std::hypot(c.best.x - truth.x, c.best.y - truth.y, c.best.z - truth.z), 0.5);
  // Most of the tilt gone: the ridge is flat over a few tenths of a degree, and where along it the climb
  // stops the model decides (under 0.5 deg before issue 56's background subtraction, 0.51 after it;
  // 0.28 from the peak, the peak 0.38 from the truth).
  EXPECT_LT(rotationDeg(c.best, truth), 0.6);
  pm::core::Phi fromTruth = truth;
  const pm::rmga::SmoothAscentResult peak = pm::rmga::climbSmooth(smooth, &fromTruth, 1, a);
  std::cout << "the climb ends " << rotationDeg(c.best, truth) << " deg from the truth, " << rotationDeg(c.best, peak.best)
            << " from the peak (the peak " << rotationDeg(peak.best, truth) << " from the truth)\n";
  EXPECT_GT(c.score, c.startScore + 0.9 * (peak.score - c.startScore));
}

TEST_F(FitnessOnC12, SmoothGradientIsTheSmoothScoresSlopeAndItsValueTheSmoothScore)
{
  // The climb's score (AVX2, float sums) against the reference (scalar, double), and its gradient
  // against central differences along random small motions (applyTwist), on poses near the truth
  // where most points are in the images and many straddle a pixel edge.
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    pm::core::Phi q = truth;
    q.x += 2 * n01(rng), q.y += 2 * n01(rng), q.z += 4 * n01(rng);
    q.e1 += 0.01 * n01(rng), q.e2 += 0.01 * n01(rng), q.e3 += 0.01 * n01(rng);
    double g[6], M[36];
    const double s = fit->evaluateSmoothGradient(q, g, M);
    EXPECT_NEAR(s, fit->evaluateSmooth(q), 1e-5);
    double d[6];
    for (int k = 0; k < 6; ++k)
      d[k] = n01(rng) * (k < 3 ? 1.0 : 0.01); // mm, rad
    double slope = 0;
    for (int k = 0; k < 6; ++k)
      slope += g[k] * d[k];
    // Piecewise bilinear: a few points may cross a pixel edge within +-h, and bend that difference. A
    // wrong gradient is off at every step; a crossing bends one step's difference, not all of them.
    auto centralDifference = [&](double h) {
      double plus[6], minus[6], unused[6];
      for (int k = 0; k < 6; ++k)
        plus[k] = h * d[k], minus[k] = -h * d[k];
      return (fit->evaluateSmoothGradient(pm::core::applyTwist(q, plus), unused) -
              fit->evaluateSmoothGradient(pm::core::applyTwist(q, minus), unused)) / (2 * h);
    };
    const double tol = 0.05 * std::fabs(slope) + 2e-4;
    const double fd = centralDifference(1e-3), fdFiner = centralDifference(3e-4);
    EXPECT_LT(std::min(std::fabs(fd - slope), std::fabs(fdFiner - slope)), tol)
        << "trial " << trial << ": slope " << slope << ", central differences " << fd << " and " << fdFiner;
    checked += std::fabs(slope) > 1e-3;
  }
  EXPECT_GE(checked, 8); // the slopes were not all flat
  // Far off the images: nothing to climb.
  double g[6];
  EXPECT_DOUBLE_EQ(fit->evaluateSmoothGradient({5000, 0, 500, 0, 0, 0}, g), 0.0);
  for (double x : g)
    EXPECT_EQ(x, 0.0);
  EXPECT_THROW(fit->evaluateSmoothGradient({0, 0, 500, 0.8, 0.8, 0}, g), pm::core::Error);
}

TEST_F(FitnessOnC12, SmoothGradientKernelsAgreeAndTheMetricIsTheMeanImageMotion)
{
  const pm::core::Phi q{truth.x + 1.5, truth.y - 1, truth.z + 3, truth.e1 + 0.004, truth.e2 - 0.006, truth.e3 + 0.003};
  double gv[6], Mv[36], gs[6], Ms[36];
  const double sv = fit->evaluateSmoothGradient(q, gv, Mv);
  pm::core::StereoFitness scalar = *fit;
  scalar.useScalarKernel(true);
  const double ss = scalar.evaluateSmoothGradient(q, gs, Ms);
  EXPECT_NEAR(sv, ss, 1e-5);
  // Agreement measured against the gradient's size: the AVX2 kernel projects in float, the scalar
  // one in double, so a point on a pixel's edge may fall on either side, where the bilinear score's
  // slope jumps by that point's share (the crab's model has one such point for e3: 2.4e-4 of that
  // component, 3e-5 of the gradient; the other components agree to 5e-6 of themselves).
  const double gNorm = std::sqrt(gs[0] * gs[0] + gs[1] * gs[1] + gs[2] * gs[2] + gs[3] * gs[3] + gs[4] * gs[4] + gs[5] * gs[5]);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(gv[k], gs[k], 1e-4 * (gNorm + 1e-3)) << k;
  for (int k = 0; k < 36; ++k)
    EXPECT_NEAR(Mv[k], Ms[k], 1e-4 * std::fabs(Ms[k]) + 1e-6) << k;
  // d^T M d: the mean squared image motion of the points for a small motion d, as projecting them
  // before and after says (pointScores: every point, both cameras).
  const std::array<std::array<double, 6>, 2> motions{{{0.3, -0.2, 0.5, 0, 0, 0}, {0, 0, 0, 0.002, -0.001, 0.003}}};
  for (const auto &motion : motions) {
    const double *d = motion.data();
    double predicted = 0;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c)
        predicted += d[r] * Mv[6 * r + c] * d[c];
    const pm::core::Phi moved = pm::core::applyTwist(q, d);
    double sum = 0;
    int n = 0;
    for (int cam = 0; cam < 2; ++cam) {
      const auto a = fit->pointScores(q, cam), b = fit->pointScores(moved, cam);
      for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].cls != pm::core::PointScore::Off) {
          sum += (a[i].u - b[i].u) * (a[i].u - b[i].u) + (a[i].v - b[i].v) * (a[i].v - b[i].v);
          ++n;
        }
    }
    EXPECT_NEAR(predicted, sum / n, 0.03 * predicted) << "d = " << d[0] << ", " << d[3];
  }
}

TEST_F(FitnessOnC12, EarlyRejectionScoresHopelessPosesOnAQuarterAndTheOthersExactly)
{
  const auto ps = randomPoses(200);
  std::vector<double> exact(ps.size()), early(ps.size()), cost(ps.size()), coarse(ps.size()), coarseCost(ps.size());
  fit->evaluate(ps.data(), ps.size(), exact.data());
  const double threshold = 0.5;
  fit->evaluate(ps.data(), ps.size(), early.data(), threshold, cost.data());
  fit->evaluate(ps.data(), ps.size(), coarse.data(), 1e300, coarseCost.data()); // every pose on its first share
  int rejected = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (cost[i] < 1) { // rejected: its estimate is under the threshold, and is the coarse score
      ++rejected;
      EXPECT_LT(early[i], threshold);
      EXPECT_EQ(early[i], coarse[i]);
      EXPECT_NEAR(cost[i], 1.0 / pm::core::StereoFitness::kRejectStride, 0.01);
    } else {
      EXPECT_EQ(early[i], exact[i]) << i; // not rejected: F itself
    }
    EXPECT_NEAR(coarseCost[i], 1.0 / pm::core::StereoFitness::kRejectStride, 0.01);
  }
  EXPECT_GT(rejected, 150); // random poses: most are hopeless
  // The coarse score is an estimate of F: close to it where the model lies on the target.
  const pm::core::Phi near[3] = {truth, {truth.x + 3, truth.y, truth.z, truth.e1, truth.e2, truth.e3}, {truth.x, truth.y - 4, truth.z + 8, truth.e1, truth.e2, truth.e3}};
  double f[3], c[3], k[3];
  fit->evaluate(near, 3, f);
  fit->evaluate(near, 3, c, 1e300, k);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(c[i], f[i], 0.06) << i;
  // The same values whoever computes them (two cores or one at a time).
  for (std::size_t i = 0; i < 20; ++i) {
    double one = 0, oneCost = 0;
    fit->evaluate(&ps[i], 1, &one, threshold, &oneCost);
    EXPECT_EQ(one, early[i]);
    EXPECT_EQ(oneCost, cost[i]);
  }
}
