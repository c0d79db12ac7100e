// The rig: the shipped lab rigs (stereo, one camera, three), symmetric rigs, files and their errors.
#include <filesystem>

#include <gtest/gtest.h>

#include <visp3/core/vpMeterPixelConversion.h>

#include "TestSupport.h"
#include "pm/core/CameraImages.h"
#include "pm/core/Error.h"
#include "pm/io/PoseTableFile.h"
#include "pm/io/RigFile.h"
#include "pm/model/PassRig.h"

namespace {

vpImagePoint project(const pm::core::PinholeCamera &c, double X, double Y, double Z)
{
  const vpHomogeneousMatrix cMh = c.cMh();
  const double x = cMh[0][0] * X + cMh[0][1] * Y + cMh[0][2] * Z + cMh[0][3];
  const double y = cMh[1][0] * X + cMh[1][1] * Y + cMh[1][2] * Z + cMh[1][3];
  const double z = cMh[2][0] * X + cMh[2][1] * Y + cMh[2][2] * Z + cMh[2][3];
  vpImagePoint ip;
  vpMeterPixelConversion::convertPoint(c.cam, x / z, y / z, ip);
  return ip;
}

} // namespace

TEST(Rig, ShippedLabRigMatchesTheHardware)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  EXPECT_NEAR(rig.baseline(), 0.323, 1e-9);
  for (const pm::core::PinholeCamera *c : {&rig.left, &rig.right}) {
    EXPECT_EQ(c->width, 640u);
    EXPECT_EQ(c->height, 480u);
    EXPECT_DOUBLE_EQ(c->cam.get_px(), 754);
    EXPECT_DOUBLE_EQ(c->cam.get_py(), 754);
    EXPECT_DOUBLE_EQ(c->cam.get_u0(), 320);
    EXPECT_DOUBLE_EQ(c->cam.get_v0(), 240);
    // A target 500 mm straight ahead of the hand sits at each image centre (toe-in).
    const vpImagePoint ip = project(*c, 0, 0, 0.5);
    EXPECT_NEAR(ip.get_u(), 320, 1e-6) << c->name;
    EXPECT_NEAR(ip.get_v(), 240, 1e-6) << c->name;
  }
  EXPECT_LT(rig.left.hMc[0][3], 0); // left camera on the left of the hand
  EXPECT_NEAR(rig.cLMcR().getTranslationVector().frobeniusNorm(), 0.323, 1e-9);
}

TEST(Rig, ParallelCamerasSeeTheTargetOffCentre)
{
  vpCameraParameters cam(754, 754, 320, 240);
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, 0.323, 0.0);
  const double shift = 754 * 0.1615 / 0.5; // ~244 px, VISP_NOTES.md
  EXPECT_NEAR(project(rig.left, 0, 0, 0.5).get_u(), 320 + shift, 1e-6);
  EXPECT_NEAR(project(rig.right, 0, 0, 0.5).get_u(), 320 - shift, 1e-6);
}

TEST(Rig, ToeInIsAParameter)
{
  vpCameraParameters cam(754, 754, 320, 240);
  const double toe = pm::core::StereoRig::toeInFor(0.323, 0.8);
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, 0.323, toe);
  EXPECT_NEAR(project(rig.left, 0, 0, 0.8).get_u(), 320, 1e-6);
  EXPECT_NEAR(project(rig.right, 0, 0, 0.8).get_u(), 320, 1e-6);
  EXPECT_NEAR(toe * 180 / M_PI, std::atan(0.1615 / 0.8) * 180 / M_PI, 1e-12);
}

TEST(Rig, SaveLoadRoundTrip)
{
  pm::test::TempDir dir("rig");
  vpCameraParameters cam(800, 790, 330.5, 245.25);
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 800, 600, 0.3, 0.2);
  pm::io::saveRig(rig, dir.file("r.json"), "r_cameras.xml");
  const pm::core::StereoRig back = pm::io::loadRig(dir.file("r.json"));
  EXPECT_DOUBLE_EQ(back.left.cam.get_px(), 800);
  EXPECT_DOUBLE_EQ(back.right.cam.get_v0(), 245.25);
  EXPECT_EQ(back.left.width, 800u);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 4; ++c) {
      EXPECT_NEAR(back.left.hMc[r][c], rig.left.hMc[r][c], 1e-9);
      EXPECT_NEAR(back.right.hMc[r][c], rig.right.hMc[r][c], 1e-9);
    }
  EXPECT_TRUE(pm::test::listFiles(dir.path()) == (std::vector<std::string>{"r.json", "r_cameras.xml"}));
}

TEST(Rig, NonPositiveFocalLengthIsAClearError)
{
  pm::test::TempDir dir("rig");
  pm::io::saveRig(pm::core::StereoRig::symmetric(vpCameraParameters(754, 754, 320, 240), 640, 480, 0.323, 0.3),
                  dir.file("r.json"), "r_cameras.xml");
  std::string xml = pm::test::readText(dir.file("r_cameras.xml"));
  xml.replace(xml.find("<px>754</px>"), 12, "<px>-754</px>");
  pm::test::writeText(dir.file("r_cameras.xml"), xml);
  const std::string e = pm::test::errorOf([&] { pm::io::loadRig(dir.file("r.json")); });
  EXPECT_NE(e.find("focal"), std::string::npos) << e;
  EXPECT_NE(e.find("r.json"), std::string::npos) << e;
}

TEST(Rig, BrokenFilesAreClearErrors)
{
  pm::test::TempDir dir("rig");
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadRig(dir.file("missing.json")); }).find("does not exist"), std::string::npos);
  pm::test::writeText(dir.file("bad.json"), "{ \"format\": \"visp-photomodel-rig\", \"version\": 1, ");
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadRig(dir.file("bad.json")); }).find("bad.json"), std::string::npos);
  pm::test::writeText(dir.file("noxml.json"),
                      R"({"format":"visp-photomodel-rig","version":1,"intrinsics_xml":"none.xml","cameras":[]})");
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadRig(dir.file("noxml.json")); }).find("none.xml"), std::string::npos);
  pm::io::saveRig(pm::core::StereoRig::symmetric(vpCameraParameters(754, 754, 320, 240), 640, 480, 0.323, 0.3),
                  dir.file("r.json"), "r_cameras.xml");
  std::string j = pm::test::readText(dir.file("r.json"));
  j.replace(j.find("\"right\""), 7, "\"middle\"");
  pm::test::writeText(dir.file("r.json"), j);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadRig(dir.file("r.json")); }).find("middle"), std::string::npos);
}

TEST(Rig, OneCameraAndThreeCamerasLoadAndAStereoRigIsTheirTwoCameraCase)
{
  const pm::core::StereoRig stereo = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  // The stereo file read as a rig of any size: its two cameras, left then right, the same values.
  const pm::core::CameraRig two = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_stereo.json"));
  ASSERT_EQ(two.size(), 2u);
  EXPECT_TRUE(two.isStereo());
  EXPECT_EQ(two[0].name, "left");
  EXPECT_TRUE(two[1].hMc == stereo.right.hMc);
  // One camera at the stereo rig's left camera's place: a target 500 mm ahead at its image centre.
  const pm::core::CameraRig one = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_mono.json"));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_FALSE(one.isStereo());
  EXPECT_TRUE(one[0].hMc == stereo.left.hMc);
  EXPECT_DOUBLE_EQ(one[0].cam.get_px(), stereo.left.cam.get_px());
  EXPECT_NEAR(project(one[0], 0, 0, 0.5).get_u(), 320, 1e-6);
  // Three: the stereo pair and a camera 150 mm above the hand's centre, tilted down onto the same point.
  const pm::core::CameraRig three = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_trio.json"));
  ASSERT_EQ(three.size(), 3u);
  EXPECT_TRUE(three[1].hMc == stereo.right.hMc);
  EXPECT_EQ(three[2].name, "top");
  EXPECT_NEAR(three[2].hMc[1][3], -0.150, 1e-12);
  const vpImagePoint top = project(three[2], 0, 0, 0.5);
  EXPECT_NEAR(top.get_u(), 320, 1e-6);
  EXPECT_NEAR(top.get_v(), 240, 1e-6);
  // A program that needs a stereo rig says how many cameras the file has.
  const std::string e = pm::test::errorOf([&] { (void)pm::io::loadRig(pm::test::dataPath("rig/pa10_mono.json")); });
  EXPECT_NE(e.find("1 camera;"), std::string::npos) << e;
  EXPECT_NE(e.find("pa10_mono.json"), std::string::npos) << e;
  EXPECT_NE(pm::test::errorOf([&] { (void)three.stereo(); }).find("3 cameras"), std::string::npos);
}

TEST(Rig, AnyNumberOfCamerasSurvivesTheRoundTripAndNoneOrFiveIsAClearError)
{
  pm::test::TempDir dir("rig");
  const pm::core::CameraRig three = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_trio.json"));
  for (std::size_t n : {1u, 3u}) {
    const pm::core::CameraRig rig(std::vector<pm::core::PinholeCamera>(three.cameras.begin(), three.cameras.begin() + static_cast<long>(n)));
    const std::string json = dir.file("r" + std::to_string(n) + ".json");
    pm::io::saveRig(rig, json, "r" + std::to_string(n) + "_cameras.xml");
    const pm::core::CameraRig back = pm::io::loadCameraRig(json);
    ASSERT_EQ(back.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
      EXPECT_EQ(back[k].name, rig[k].name);
      EXPECT_DOUBLE_EQ(back[k].cam.get_px(), rig[k].cam.get_px());
      for (unsigned r = 0; r < 3; ++r)
        for (unsigned c = 0; c < 4; ++c)
          EXPECT_NEAR(back[k].hMc[r][c], rig[k].hMc[r][c], 1e-9) << k;
    }
  }
  pm::test::writeText(dir.file("none.json"), R"({"format":"visp-photomodel-rig","version":1,"intrinsics_xml":"r3_cameras.xml","cameras":[]})");
  EXPECT_NE(pm::test::errorOf([&] { (void)pm::io::loadCameraRig(dir.file("none.json")); }).find("1 to 4 cameras"), std::string::npos);
  pm::core::CameraRig five = three;
  five.cameras.insert(five.cameras.end(), three.cameras.begin(), three.cameras.begin() + 2);
  EXPECT_NE(pm::test::errorOf([&] { five.validate(); }).find("not 5"), std::string::npos);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::saveRig(five, dir.file("five.json"), "five.xml"); }).find("not 5"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.file("five.json")));
}

TEST(PassRig, OneCamerasSideStepPutsItWhereTheStereoRigsRightCameraSitsAndAStereoRigIsItself)
{
  // The lab's one-camera rig is the stereo rig's left camera: its pass's second image, after the
  // hand's side step, is taken from exactly where the stereo rig's right camera is.
  const pm::core::StereoRig stereo = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::core::CameraRig mono = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_mono.json"));
  ASSERT_EQ(mono.size(), 1u);
  const pm::core::StereoRig pair = pm::model::passRig(mono);
  const vpHomogeneousMatrix d = stereo.right.cMh() * pair.right.hMc;
  EXPECT_LT(d.getTranslationVector().frobeniusNorm(), 1e-9);
  EXPECT_LT(d.getThetaUVector().getTheta(), 1e-9);
  EXPECT_EQ(pair.right.width, mono[0].width);
  EXPECT_DOUBLE_EQ(pair.right.cam.get_px(), mono[0].cam.get_px());
  // The hand's step: a rigid motion that carries the camera there, 323 mm along the camera pair's baseline.
  const vpHomogeneousMatrix step = pm::model::sideStep(mono);
  const vpHomogeneousMatrix moved = step * mono[0].hMc;
  EXPECT_LT((stereo.right.cMh() * moved).getTranslationVector().frobeniusNorm(), 1e-9);
  EXPECT_NEAR((moved.getTranslationVector() - mono[0].hMc.getTranslationVector()).frobeniusNorm(), pm::model::kSideStepM, 1e-9);
  // A stereo rig needs no step; a trio takes its first two cameras.
  EXPECT_LT(pm::model::sideStep(stereo).getTranslationVector().frobeniusNorm(), 1e-12);
  const pm::core::StereoRig same = pm::model::passRig(stereo);
  EXPECT_EQ(same.right.hMc, stereo.right.hMc);
  const pm::core::CameraRig trio = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_trio.json"));
  EXPECT_EQ(pm::model::passRig(trio).right.hMc, trio[1].hMc);
  // What a tracker sees of a pass view: the first image, both, or a clear error.
  pm::model::PassView v;
  v.name = "view 03";
  v.left.resize(480, 640);
  v.right.resize(480, 640);
  EXPECT_EQ(pm::model::viewImages(v, 1).size(), 1u);
  EXPECT_EQ(&pm::model::viewImages(v, 2)[1], &v.right);
  EXPECT_EQ(pm::test::errorOf([&] { pm::model::viewImages(v, 3); }), "view 03: a pass view holds two images, and the rig has 3 cameras");
}

TEST(CameraImages, OneImagePerCameraOfItsSizeOrAClearError)
{
  const pm::core::CameraRig mono = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_mono.json"));
  vpImage<vpRGBa> a(480, 640), b(480, 640), small(100, 120);
  EXPECT_NO_THROW(pm::core::CameraImages(a).checkFor(mono, "tracker"));
  EXPECT_EQ(pm::test::errorOf([&] { pm::core::CameraImages(a, b).checkFor(mono, "tracker"); }),
            "tracker: 2 images for a rig of 1 camera (one image per camera)");
  EXPECT_EQ(pm::test::errorOf([&] { pm::core::CameraImages(small).checkFor(mono, "tracker"); }),
            "tracker: camera 0's image is 120x100 but the camera is 640x480");
  const std::vector<vpImage<vpRGBa>> five(5, a), none;
  EXPECT_NE(pm::test::errorOf([&] { pm::core::CameraImages::of(five); }).find("1 to 4 images"), std::string::npos);
  EXPECT_NE(pm::test::errorOf([&] { pm::core::CameraImages::of(none); }).find("not 0"), std::string::npos);
  const std::vector<vpImage<vpRGBa>> three(3, a);
  const pm::core::CameraImages c = pm::core::CameraImages::of(three);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(&c[2], &three[2]);
}

TEST(PoseTable, ShippedTable2AndBrokenTables)
{
  const auto rows = pm::io::readPoseTable(pm::test::dataPath("trajectories/table2.csv"), "step");
  ASSERT_EQ(rows.size(), 20u);
  EXPECT_EQ(rows[11].first, 11);
  EXPECT_DOUBLE_EQ(rows[11].second.e1, 0.174);
  EXPECT_DOUBLE_EQ(rows[7].second.z, 550);
  pm::test::TempDir dir("table");
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"frame,x,y,z,e1,e2,e3\n0,0,0,500,0,0,0\n", "header"},
      {"step,x,y,z,e1,e2,e3\n0,0,0,five,0,0,0\n", "'five' is not a number"},
      {"step,x,y,z,e1,e2,e3\n0,0,0,500,0,0\n", "7 values"},
      {"step,x,y,z,e1,e2,e3\n0,0,0,500,0.9,0.9,0\n", "invalid pose"},
      {"step,x,y,z,e1,e2,e3\n0.5,0,0,500,0,0,0\n", "whole number"},
      {"step,x,y,z,e1,e2,e3\n# nothing\n", "no row"}};
  for (const auto &[text, expect] : bad) {
    pm::test::writeText(dir.file("t.csv"), text);
    const std::string e = pm::test::errorOf([&] { pm::io::readPoseTable(dir.file("t.csv"), "step"); });
    EXPECT_NE(e.find(expect), std::string::npos) << text << " -> " << e;
    EXPECT_NE(e.find("t.csv"), std::string::npos) << e;
  }
}

TEST(PinholeCamera, ItsProjectionIsViSPsAndGoesBackAlongItsRay)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::core::PinholeCamera &c = rig.right;
  const pm::core::PinholeCamera::Projection p = c.projection(); // placed in the hand frame
  EXPECT_EQ(p.w, static_cast<int>(c.width));
  EXPECT_EQ(p.h, static_cast<int>(c.height));
  for (const pm::core::Vec3 &X : {pm::core::Vec3{0, 0, 500}, pm::core::Vec3{40, -25, 520}, pm::core::Vec3{-60, 30, 470}}) {
    // ViSP's projection of the same point (metres) through cMh and the intrinsics.
    vpColVector Xh(4);
    Xh[0] = X[0] * 1e-3, Xh[1] = X[1] * 1e-3, Xh[2] = X[2] * 1e-3, Xh[3] = 1;
    const vpColVector Xc = c.cMh() * Xh;
    double uV = 0, vV = 0;
    vpMeterPixelConversion::convertPoint(c.cam, Xc[0] / Xc[2], Xc[1] / Xc[2], uV, vV);
    double u = 0, v = 0, z = 0;
    ASSERT_TRUE(p.project(X, u, v, z));
    EXPECT_NEAR(u, uV, 1e-9);
    EXPECT_NEAR(v, vV, 1e-9);
    EXPECT_NEAR(z, Xc[2] * 1e3, 1e-9);
    // Back along the ray through (u, v) at that depth: the point again.
    const pm::core::Vec3 B = p.backProject(u, v, z);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(B[k], X[k], 1e-9);
    const pm::core::Vec3 r = p.ray(u, v), d = pm::core::unit(pm::core::sub(X, p.centre));
    EXPECT_NEAR(pm::core::dot(r, d), 1.0, 1e-12);
  }
  double u, v, z;
  EXPECT_FALSE(p.project({0, 0, -500}, u, v, z)); // behind the hand: behind the camera
  // A camera looking at the origin from 500 mm along -z sees the origin at its principal point.
  const auto o = pm::core::PinholeCamera::Projection::lookingAtOrigin({0, 0, -500}, c.cam, c.width, c.height);
  ASSERT_TRUE(o.project({0, 0, 0}, u, v, z));
  EXPECT_NEAR(u, c.cam.get_u0(), 1e-9);
  EXPECT_NEAR(v, c.cam.get_v0(), 1e-9);
  EXPECT_NEAR(z, 500, 1e-9);
  pm::core::PinholeCamera bad = c;
  bad.width = 0;
  EXPECT_NE(pm::test::errorOf([&] { bad.validate(); }).find("image size"), std::string::npos);
}
