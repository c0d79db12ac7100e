// Hue in degrees, wrap-around distances, circular means.
#include <gtest/gtest.h>

#include <random>

#include <visp3/core/vpImageConvert.h>

#include "pm/core/Hue.h"

TEST(Hue, AgreesWithViSPRGBaToHSV)
{
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> c(0, 255);
  const unsigned n = 20000;
  vpImage<vpRGBa> I(1, n);
  for (unsigned i = 0; i < n; ++i)
    I.bitmap[i] = vpRGBa(static_cast<unsigned char>(c(rng)), static_cast<unsigned char>(c(rng)),
                         static_cast<unsigned char>(c(rng)));
  std::vector<double> h(n), s(n), v(n);
  vpImageConvert::RGBaToHSV(reinterpret_cast<unsigned char *>(I.bitmap), h.data(), s.data(), v.data(), n);
  for (unsigned i = 0; i < n; ++i) {
    const pm::core::Hsv o = pm::core::rgbToHsv(I.bitmap[i]);
    if (o.s > 0) { // ViSP's hue of a grey pixel is arbitrary; ours is 0
      EXPECT_NEAR(pm::core::hueDistance(o.h, static_cast<float>(h[i] * 360.0)), 0.f, 1e-3f) << i;
    }
    EXPECT_NEAR(o.s, s[i], 1e-5);
    EXPECT_NEAR(o.v, v[i], 1e-5);
  }
}

TEST(Hue, PrimaryColours)
{
  EXPECT_FLOAT_EQ(pm::core::hueDeg(vpRGBa(255, 0, 0)), 0.f);
  EXPECT_FLOAT_EQ(pm::core::hueDeg(vpRGBa(0, 255, 0)), 120.f);
  EXPECT_FLOAT_EQ(pm::core::hueDeg(vpRGBa(0, 0, 255)), 240.f);
  EXPECT_FLOAT_EQ(pm::core::hueDeg(vpRGBa(255, 0, 255)), 300.f);
  EXPECT_FLOAT_EQ(pm::core::rgbToHsv(vpRGBa(128, 128, 128)).s, 0.f);
}

TEST(Hue, DistanceWrapsAround)
{
  EXPECT_FLOAT_EQ(pm::core::hueDistance(0.f, 359.f), 1.f);
  EXPECT_FLOAT_EQ(pm::core::hueDistance(359.f, 0.f), 1.f);
  EXPECT_FLOAT_EQ(pm::core::hueDistance(10.f, 350.f), 20.f);
  EXPECT_FLOAT_EQ(pm::core::hueDistance(0.f, 180.f), 180.f);
  EXPECT_FLOAT_EQ(pm::core::hueDistance(90.f, 120.f), 30.f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 360.f);
  for (int i = 0; i < 1000; ++i) {
    const float a = u(rng), b = u(rng);
    EXPECT_FLOAT_EQ(pm::core::hueDistance(a, b), pm::core::hueDistance(b, a));
    EXPECT_LE(pm::core::hueDistance(a, b), 180.f);
    EXPECT_GE(pm::core::hueDistance(a, b), 0.f);
  }
}

TEST(Hue, SignedDifferenceAndOnTheCircle)
{
  EXPECT_DOUBLE_EQ(pm::core::hueDifference(10, 350), 20.0);
  EXPECT_DOUBLE_EQ(pm::core::hueDifference(350, 10), -20.0);
  EXPECT_DOUBLE_EQ(pm::core::hueDifference(190, 10), 180.0); // half way round: +180, never -180
  EXPECT_DOUBLE_EQ(pm::core::hueDifference(10, 190), 180.0);
  EXPECT_DOUBLE_EQ(pm::core::hueDifference(725, 0), 5.0);
  for (double a = -400; a < 800; a += 37.5)
    for (double b = 0; b < 360; b += 45) {
      const double d = pm::core::hueDifference(a, b);
      EXPECT_GT(d, -180.0);
      EXPECT_LE(d, 180.0);
      EXPECT_NEAR(pm::core::hueDistance(static_cast<float>(pm::core::hueOnCircle(a)), static_cast<float>(b)), std::fabs(d), 1e-4);
    }
  EXPECT_DOUBLE_EQ(pm::core::hueOnCircle(-30), 330.0);
  EXPECT_DOUBLE_EQ(pm::core::hueOnCircle(720), 0.0);
  EXPECT_DOUBLE_EQ(pm::core::hueOnCircle(359.5), 359.5);
  EXPECT_DOUBLE_EQ(pm::core::hueOnCircle(-1e-20), 0.0); // never 360
}

TEST(Hue, CircularMeanAcrossZero)
{
  EXPECT_NEAR(pm::core::hueDistance(pm::core::circularMeanHue({350.f, 10.f}), 0.f), 0.f, 1e-4f);
  EXPECT_NEAR(pm::core::circularMeanHue({200.f, 220.f}), 210.f, 1e-4f);
  EXPECT_FLOAT_EQ(pm::core::circularMeanHue({}), 0.f);
}
