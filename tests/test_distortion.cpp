// Lens distortion: the model against ViSP's and OpenCV's, the camera files that carry it, the
// simulator that renders through it, the fitness that reads through it, and the rig calibration
// (OpenCV's real stereo chessboard pairs when opencv-doc is installed; a known simulated rig).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpXmlParserCamera.h>

#include "TestSupport.h"
#include "pm/calib/CameraCalibration.h"
#include "pm/calib/HandEye.h"
#include "pm/calib/RigCalibration.h"
#include "pm/calib/RigComparison.h"
#include "pm/core/Error.h"
#include "pm/core/HuePlane.h"
#include "pm/core/StereoFitness.h"
#include "pm/core/UndistortMap.h"
#include "pm/io/CameraFile.h"
#include "pm/io/CameraXml.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PoseFile.h"
#include "pm/io/RigFile.h"
#include "pm/model/HullGeometry.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/TargetShape.h"

using pm::test::errorOf;
using pm::test::runProgram;
using pm::test::TempDir;

namespace {

const std::string kOpenCvData = "/usr/share/doc/opencv-doc/examples/data/";

vpCameraParameters labCam()
{
  vpCameraParameters c;
  c.initPersProjWithoutDistortion(754, 754, 320, 240);
  return c;
}

const pm::core::LensDistortion kBarrel{{-0.25, 0.08, 0.001, -0.0005, 0.0}};

} // namespace

TEST(LensDistortion, DistortAndUndistortAreInverseOverTheImage)
{
  const vpCameraParameters cam = labCam();
  kBarrel.validate(cam, 640, 480, "test");
  std::vector<vpImagePoint> raw;
  for (int v = 0; v <= 480; v += 40)
    for (int u = 0; u <= 640; u += 40)
      raw.emplace_back(v, u);
  const auto ideal = kBarrel.undistort(cam, raw);
  double worst = 0, moved = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    worst = std::max(worst, vpImagePoint::distance(kBarrel.distort(cam, ideal[i]), raw[i]));
    moved = std::max(moved, vpImagePoint::distance(ideal[i], raw[i]));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(moved, 20.0); // barrel: the corners' rays lie far outside where a pinhole puts them
  const pm::core::LensDistortion none;
  EXPECT_TRUE(none.isNone());
  EXPECT_EQ(vpImagePoint::distance(none.distort(cam, vpImagePoint(10, 20)), vpImagePoint(10, 20)), 0.0);
}

TEST(LensDistortion, ViSPsModelIsK1)
{
  // ViSP's perspectiveProjWithDistortion: u = u0 + px x (1 + kud r^2); ours with k1 = kud must agree.
  vpCameraParameters visp;
  visp.initPersProjWithDistortion(754, 750, 322, 238, -0.21, 0.23);
  vpCameraParameters pin;
  pin.initPersProjWithoutDistortion(754, 750, 322, 238);
  const pm::core::LensDistortion d{{-0.21, 0, 0, 0, 0}};
  EXPECT_TRUE(d.isVispModel());
  EXPECT_FALSE(kBarrel.isVispModel());
  for (double x : {-0.4, -0.1, 0.0, 0.25})
    for (double y : {-0.3, 0.05, 0.3}) {
      double u = 0, v = 0;
      vpMeterPixelConversion::convertPoint(visp, x, y, u, v);
      const vpImagePoint ours = d.distort(pin, vpImagePoint(238 + 750 * y, 322 + 754 * x));
      EXPECT_NEAR(ours.get_u(), u, 1e-9);
      EXPECT_NEAR(ours.get_v(), v, 1e-9);
    }
}

TEST(LensDistortion, ALensThatFoldsTheImageOrABadCountIsRefused)
{
  const vpCameraParameters cam = labCam();
  // k1 = -0.6: the distorted radius peaks at r = 0.745 (0.497) before the corner (0.53): two rays per pixel.
  EXPECT_NE(errorOf([&] { pm::core::LensDistortion{{-0.6, 0, 0, 0, 0}}.validate(cam, 640, 480, "left camera"); }).find("folds the image"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { pm::core::LensDistortion{{-0.1, 0, 0}}.validate(cam, 640, 480, "left camera"); }).find("3 distortion coefficients"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { pm::core::LensDistortion{{NAN, 0, 0, 0}}.validate(cam, 640, 480, "left camera"); }).find("not finite"),
            std::string::npos);
  vpCameraParameters small;
  small.initPersProjWithoutDistortion(754, 754, 100, 100);
  EXPECT_EQ(errorOf([&] { pm::core::LensDistortion{{-0.6, 0, 0, 0, 0}}.validate(small, 200, 200, "small"); }), ""); // inside its fold
  pm::core::StereoRig rig = pm::lab::labRigWithLens(kBarrel);
  rig.right.distortion = pm::core::LensDistortion{{-0.6, 0, 0, 0, 0}};
  EXPECT_NE(errorOf([&] { rig.validate(); }).find("camera 'right'"), std::string::npos);
}

TEST(UndistortMap, EachIdealPixelLooksWhereTheLensPutsIt)
{
  pm::core::StereoRig rig = pm::lab::labRigWithLens(kBarrel);
  const pm::core::UndistortMap map(rig.left);
  const auto &idx = map.nearest();
  for (unsigned v = 0; v < 480; v += 37)
    for (unsigned u = 0; u < 640; u += 41) {
      const vpImagePoint raw = kBarrel.distort(rig.left.cam, vpImagePoint(v, u));
      const std::int32_t i = idx[static_cast<std::size_t>(v) * 640 + u];
      ASSERT_GE(i, 0); // barrel: every ideal pixel is seen by the raw image
      EXPECT_LE(std::fabs(static_cast<double>(i % 640) - raw.get_u()), 0.5 + 1e-3);
      EXPECT_LE(std::fabs(static_cast<double>(i / 640) - raw.get_v()), 0.5 + 1e-3);
    }
  // A pinhole camera's map is the identity.
  rig.right.distortion = pm::core::LensDistortion();
  const pm::core::UndistortMap id(rig.right);
  for (std::size_t i = 0; i < id.nearest().size(); i += 997)
    EXPECT_EQ(id.nearest()[i], static_cast<std::int32_t>(i));
  EXPECT_DOUBLE_EQ(id.coverage(), 1.0);
}

TEST(UndistortMap, ASignedDistanceResampledKeepsItsZeroLineWhereAResampledMaskMovesOutward)
{
  // A disc in the raw image, off the image's centre where the lens bends it. Its silhouette's signed
  // distance resampled into the ideal image has its zero line on the disc's edge as the lens maps it
  // (within a tenth of a pixel on average over the edge); the mask itself resampled and thresholded
  // low (as a background subtraction counts a fifth-covered pixel as target) lies outward.
  const pm::core::StereoRig rig = pm::lab::labRigWithLens(kBarrel);
  const pm::core::UndistortMap map(rig.left);
  const double cu = 470, cv = 330, R = 40;
  vpImage<unsigned char> mask(480, 640, 0);
  for (unsigned v = 0; v < 480; ++v)
    for (unsigned u = 0; u < 640; ++u)
      mask[v][u] = std::hypot(u - cu, v - cv) <= R ? 255 : 0;
  cv::Mat dist = pm::model::hull::signedDistance(mask);
  std::vector<float> ideal(640 * 480), rawMask(640 * 480), idealMask(640 * 480);
  map.undistortField(dist.ptr<float>(), ideal.data(), -1e3f);
  for (std::size_t i = 0; i < rawMask.size(); ++i)
    rawMask[i] = mask.bitmap[i] ? 1.f : 0.f;
  map.undistortField(rawMask.data(), idealMask.data(), 0.f);
  const auto at = [](const std::vector<float> &f, double u, double v) { // bilinear
    const int u0 = static_cast<int>(std::floor(u)), v0 = static_cast<int>(std::floor(v));
    const double a = u - u0, b = v - v0;
    const auto p = [&](int uu, int vv) { return static_cast<double>(f[static_cast<std::size_t>(vv) * 640 + static_cast<std::size_t>(uu)]); };
    return (1 - a) * (1 - b) * p(u0, v0) + a * (1 - b) * p(u0 + 1, v0) + (1 - a) * b * p(u0, v0 + 1) + a * b * p(u0 + 1, v0 + 1);
  };
  double fieldOffset = 0, maskOffset = 0;
  const int n = 360;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    // The edge in the ideal image, and the outward normal there (through the lens).
    const vpImagePoint e = kBarrel.undistort(rig.left.cam, vpImagePoint(cv + R * std::sin(t), cu + R * std::cos(t)));
    const vpImagePoint o = kBarrel.undistort(rig.left.cam, vpImagePoint(cv + (R + 1) * std::sin(t), cu + (R + 1) * std::cos(t)));
    const double nu = o.get_u() - e.get_u(), nv = o.get_v() - e.get_v(), len = std::hypot(nu, nv);
    // Along the normal: where the resampled field crosses 0, and where the resampled mask crosses 0.2.
    double zero = 0, low = 0;
    for (double s = -3; s <= 3; s += 0.01) {
      const double u = e.get_u() + s * nu / len, v = e.get_v() + s * nv / len;
      if (at(ideal, u, v) > 0)
        zero = s;
      if (at(idealMask, u, v) > 0.2)
        low = s;
    }
    fieldOffset += zero / n;
    maskOffset += low / n;
  }
  std::cout << "the edge through the lens: signed distance resampled " << fieldOffset << " px, mask resampled (0.2) " << maskOffset << " px\n";
  EXPECT_LT(std::fabs(fieldOffset), 0.1);
  EXPECT_GT(maskOffset, fieldOffset + 0.2);
}

TEST(UndistortMap, TheSimulatorRendersThroughTheLensWhereItProjects)
{
  // A chessboard rendered by a distorted camera: its corners, found in the raw image and undistorted,
  // lie where the pinhole camera projects the board's true corners.
  const pm::core::StereoRig rig = pm::lab::labRigWithLens(kBarrel);
  pm::calib::ChessBoard board;
  board.squareMm = board.marginMm = 25;
  pm::sim::SceneParams sp;
  sp.supersampling = 3;
  sp.shadows = pm::sim::ShadowMode::Off;
  const pm::sim::Scene scene(pm::sim::flatPrint(board.render(8.0), board.widthMm(), "board"), sp);
  const vpHomogeneousMatrix hMb(0.09, 0.06, 0.47, 0.1, -0.15, 0.2); // off-centre: the lens bends its corners by pixels
  vpImage<vpRGBa> I;
  pm::sim::Rasterizer raster;
  scene.render(raster, rig.left, hMb, 0, 0, I);
  const auto raw = board.findCorners(I, "test");
  const auto ideal = kBarrel.undistort(rig.left.cam, raw);
  const vpHomogeneousMatrix cMb = rig.left.cMh() * hMb;
  double s2 = 0, bend = 0;
  for (int r = 0; r < board.innerRows; ++r)
    for (int c = 0; c < board.innerCols; ++c) {
      vpPoint P = board.corner(r, c);
      P.track(cMb);
      double u = 0, v = 0;
      vpMeterPixelConversion::convertPoint(rig.left.cam, P.get_x(), P.get_y(), u, v);
      const std::size_t k = static_cast<std::size_t>(r * board.innerCols + c);
      s2 += vpImagePoint::sqrDistance(ideal[k], vpImagePoint(v, u));
      bend = std::max(bend, vpImagePoint::distance(raw[k], vpImagePoint(v, u)));
    }
  const double rms = std::sqrt(s2 / (board.innerRows * board.innerCols));
  EXPECT_LT(rms, 0.15);
  EXPECT_GT(bend, 5.0); // the raw corners are pixels away from the pinhole's
  // The chessboard's own pose with the lens: the rendered pose.
  const pm::calib::BoardView view = board.find(I, rig.left.cam, rig.left.distortion, "test");
  EXPECT_LT((view.cMb.getTranslationVector() - cMb.getTranslationVector()).frobeniusNorm() * 1e3, 0.5);
  EXPECT_LT((cMb.inverse() * view.cMb).getThetaUVector().getTheta() * 180 / M_PI, 0.1);
  // Without it, the pose is off.
  const pm::calib::BoardView pinhole = board.find(I, rig.left.cam, "test");
  EXPECT_GT((pinhole.cMb.getTranslationVector() - cMb.getTranslationVector()).frobeniusNorm() * 1e3, 3.0);
}

TEST(UndistortMap, TheFitnessReadsThroughTheLens)
{
  // C12 rendered by a distorted rig: F at the truth, read through the lens, equals the pinhole rig's F
  // on its own images within a few per cent; read as if the lens were a pinhole, it is lower.
  pm::sim::SceneParams quiet;
  quiet.noiseSigma = 0; // the same noise at the same raw pixel would make the raw planes look alike
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"), quiet);
  const pm::core::StereoRig pin = pm::lab::labRigWithLens(pm::core::LensDistortion());
  const pm::core::StereoRig lens = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.3, 0.1, 0, 0, 0}});
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(scene, pin);
  const vpHomogeneousMatrix hMo(0.14, 0.08, 0.5, 0.1, 0.05, 0.3); // off-centre in both images, where the lens bends
  const pm::core::Phi truth = sm.truth(hMo);
  pm::core::StereoFitness fPin(pin, sm.build.model), fLens(lens, sm.build.model), fNaive(pin, sm.build.model);
  const auto imPin = scene.renderStereo(pin, hMo, 0), imLens = scene.renderStereo(lens, hMo, 0);
  fPin.setImages(imPin.left, imPin.right);
  fLens.setImages(imLens.left, imLens.right);
  fNaive.setImages(imLens.left, imLens.right);
  EXPECT_NEAR(fLens.evaluate(truth), fPin.evaluate(truth), 0.05 * fPin.evaluate(truth));
  // Where F peaks in x, y around the truth: through the lens, at the truth; reading the raw images as
  // a pinhole's, off by the lens's bend (barrel: toward the image centre).
  auto peak = [&](const pm::core::StereoFitness &f) {
    double best = -1e9, bx = 0, by = 0;
    for (int dx = -12; dx <= 12; ++dx)
      for (int dy = -12; dy <= 12; ++dy) {
        pm::core::Phi p = truth;
        p.x += dx;
        p.y += dy;
        const double v = f.evaluate(p);
        if (v > best)
          best = v, bx = dx, by = dy;
      }
    return std::hypot(bx, by);
  };
  EXPECT_LE(peak(fLens), 1.5);
  EXPECT_GE(peak(fNaive), 3.0);
  // The drawn points land on the raw image where the lens puts them.
  const auto pts = fLens.pointScores(truth, 0), flat = fPin.pointScores(truth, 0);
  ASSERT_EQ(pts.size(), flat.size());
  const vpImagePoint expect = lens.left.distortion.distort(lens.left.cam, vpImagePoint(flat[0].v, flat[0].u));
  EXPECT_NEAR(pts[0].u, expect.get_u(), 1e-3);
  EXPECT_NEAR(pts[0].v, expect.get_v(), 1e-3);
}

TEST(CameraFile, ReadsViSPOpenCvAndRosFiles)
{
  TempDir d("camfile");
  // ViSP's XML with its distortion model.
  vpCameraParameters visp;
  visp.initPersProjWithDistortion(700, 701, 330, 250, -0.2, 0.22);
  {
    vpXmlParserCamera p;
    ASSERT_EQ(p.save(visp, d.file("cam.xml"), "left", 640, 480), vpXmlParserCamera::SEQUENCE_OK);
  }
  const auto x = pm::io::readCameraFile(d.file("cam.xml"), "left", 640, 480);
  EXPECT_EQ(x.format, "visp-xml");
  EXPECT_DOUBLE_EQ(x.camera.cam.get_px(), 700);
  ASSERT_EQ(x.camera.distortion.coefficients.size(), 5u);
  EXPECT_DOUBLE_EQ(x.camera.distortion.coefficients[0], -0.2);
  // Writes the text as a camera file and reads it.
  const auto read = [&](const std::string &name, const std::string &text) {
    pm::test::writeText(d.file(name), text);
    return pm::io::readCameraFile(d.file(name), "left", 640, 480);
  };
  // ROS camera_info.
  const auto r = read("ros.yaml", "image_width: 640\nimage_height: 480\ncamera_name: narrow_stereo/left\n"
                                  "camera_matrix:\n  rows: 3\n  cols: 3\n  data: [535.9, 0, 342.3, 0, 536.1, 235.6, 0, 0, 1]\n"
                                  "distortion_model: plumb_bob\ndistortion_coefficients:\n  rows: 1\n  cols: 5\n"
                                  "  data: [-0.266, -0.0386, 0.00178, -0.00028, 0.238]\n");
  EXPECT_EQ(r.format, "ros");
  EXPECT_DOUBLE_EQ(r.camera.cam.get_py(), 536.1);
  EXPECT_DOUBLE_EQ(r.camera.distortion.coefficients[4], 0.238);
  // OpenCV's own sample calibration file, when opencv-doc is installed.
  if (std::filesystem::exists(kOpenCvData + "left_intrinsics.yml")) {
    const auto o = pm::io::readCameraFile(kOpenCvData + "left_intrinsics.yml", "left", 640, 480);
    EXPECT_EQ(o.format, "opencv");
    EXPECT_NEAR(o.camera.cam.get_px(), 535.9157, 1e-3);
    EXPECT_NEAR(o.camera.distortion.coefficients[0], -0.26637, 1e-5);
  }
  // OpenCV's XML form of the same.
  const auto cx = read("cv.xml", "<?xml version=\"1.0\"?>\n<opencv_storage>\n<camera_matrix type_id=\"opencv-matrix\">"
                                "<rows>3</rows><cols>3</cols><dt>d</dt><data>536. 0. 342. 0. 537. 235. 0. 0. 1.</data>"
                                "</camera_matrix>\n<distortion_coefficients type_id=\"opencv-matrix\"><rows>4</rows>"
                                "<cols>1</cols><dt>d</dt><data>-0.2 0.01 0.001 0.002</data></distortion_coefficients>\n"
                                "</opencv_storage>\n");
  EXPECT_EQ(cx.format, "opencv");
  EXPECT_DOUBLE_EQ(cx.camera.cam.get_py(), 537);
  EXPECT_EQ(cx.camera.distortion.coefficients, (std::vector<double>{-0.2, 0.01, 0.001, 0.002}));
  // Written by us, read back.
  pm::core::PinholeCamera cam{"left", r.camera.cam, 640, 480, vpHomogeneousMatrix(), r.camera.distortion};
  pm::io::writeOpenCvCameraFile(cam, d.file("back.yml"));
  const auto b = pm::io::readCameraFile(d.file("back.yml"), "left", 640, 480);
  EXPECT_EQ(b.camera.distortion.coefficients, r.camera.distortion.coefficients);
  EXPECT_DOUBLE_EQ(b.camera.cam.get_u0(), 342.3);
}

TEST(CameraFile, BadFilesAreClearErrors)
{
  TempDir d("camfile-bad");
  const std::string head = "%YAML:1.0\n---\n";
  const std::string K = "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 500., 0., 320., 0., 500., 240., 0., 0., 1. ]\n";
  struct Case { std::string text, expect; };
  const Case cases[] = {
      {"hello: 1\n", "not a camera file"},
      {head + "image_width: 640\n", "no \"camera_matrix\""},
      {head + "camera_matrix: !!opencv-matrix\n   rows: 2\n   cols: 2\n   dt: d\n   data: [ 1., 0., 0., 1. ]\n", "must be 3x3"},
      {head + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ -5., 0., 320., 0., 500., 240., 0., 0., 1. ]\n", "focal lengths must be positive"},
      {head + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 1e-9, 0., 320., 0., 500., 240., 0., 0., 1. ]\n", "focal lengths must be positive"},
      {head + K + "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 3\n   dt: d\n   data: [ 0.1, 0., 0. ]\n", "3 distortion coefficients"},
      {head + K + "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n   data: [ -0.9, 0., 0., 0., 0. ]\n", "folds the image"},
      {head + K + "image_width: 320\nimage_height: 240\n", "for 320x240 images"},
      {"image_width: 640\ncamera_matrix:\n  rows: 3\n  cols: 3\n  data: [1, 2]\n", "holds 2 values"},
      {"camera_matrix:\n  rows: 3\n  cols: 3\n  data: [500, 0, 320, 0, 500, 240, 0, 0, 1]\ndistortion_model: equidistant\n", "not supported"},
      {head + "camera_matrix: [ 1, 2\n", "cannot be read"},
      // OpenCV 4.6's XML parser reads past the end of a file cut inside an attribute (fuzzing found it).
      {"<?xml version=\"1.0\"?>\n<opencv_storage>\n<image_width>640</image_width>\n<distortion_coefficients type_id=",
       "not well-formed XML (line 4"},
  };
  for (const Case &c : cases) {
    pm::test::writeText(d.file("c.yml"), c.text);
    const std::string e = errorOf([&] { pm::io::readCameraFile(d.file("c.yml"), "left", 640, 480); });
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.text << " -> " << e;
    EXPECT_NE(e.find("c.yml"), std::string::npos) << e;
  }
  EXPECT_NE(errorOf([&] { pm::io::readCameraFile(d.file("none.yml"), "left", 640, 480); }).find("does not exist"), std::string::npos);
}

TEST(CameraFile, AKannalaBrandtModelIsRefusedBeforeViSPsParserReadsPastItsCoefficients)
{
  // ViSP 3.5 reads k1..k5 it does not have when one is missing (a null read, found by fuzzing),
  // for any model of any camera in the file: such a file must never reach its parser.
  TempDir d("camfile-kb");
  const std::string model = "<model><type>%sDistortion</type><px>600</px><py>600</py><u0>320</u0><v0>240</v0>"
                            "<kud>0.1</kud><kdu>-0.1</kdu></model>";
  const auto file = [&](const std::string &type) {
    std::string m = model;
    m.replace(m.find("%s"), 2, type);
    return "<?xml version=\"1.0\"?>\n<root><camera><name>left</name><image_width>640</image_width>"
           "<image_height>480</image_height>" + m + "</camera></root>\n";
  };
  for (const std::string type : {"ProjWithKannalaBrandt", "ProjWithKannalaBran&#100;t"}) {
    pm::test::writeText(d.file("c.xml"), file(type));
    const std::string a = errorOf([&] { pm::io::readCameraFile(d.file("c.xml"), "left", 640, 480); });
    const std::string b = errorOf([&] { pm::io::readCameraXml(d.file("c.xml"), "left", 640, 480); });
    for (const std::string &e : {a, b}) {
      EXPECT_NE(e.find(type == "ProjWithKannalaBrandt" ? "Kannala-Brandt" : "character reference"), std::string::npos) << e;
      EXPECT_NE(e.find("c.xml"), std::string::npos) << e;
    }
  }
  // The same file with ViSP's own model with distortion is read.
  pm::test::writeText(d.file("c.xml"), file("perspectiveProjWith"));
  const pm::io::CameraFile c = pm::io::readCameraFile(d.file("c.xml"), "left", 640, 480);
  EXPECT_EQ(c.format, "visp-xml");
  EXPECT_DOUBLE_EQ(c.camera.cam.get_px(), 600.0);
  ASSERT_FALSE(c.camera.distortion.coefficients.empty());
  EXPECT_DOUBLE_EQ(c.camera.distortion.coefficients[0], 0.1);
  // ViSP's parser hands back px = 0 with a distortion model (fuzzing found it): a clear error, not ViSP's exception.
  std::string zero = file("perspectiveProjWith");
  zero.replace(zero.find("<px>600"), 7, "<px>0");
  pm::test::writeText(d.file("c.xml"), zero);
  const std::string e = errorOf([&] { pm::io::readCameraFile(d.file("c.xml"), "left", 640, 480); });
  EXPECT_NE(e.find("must be positive"), std::string::npos) << e;
  EXPECT_NE(e.find("c.xml"), std::string::npos) << e;
  // ViSP's parser reads a negative px with a distortion model without a word.
  zero.replace(zero.find("<px>0"), 5, "<px>-600");
  pm::test::writeText(d.file("c.xml"), zero);
  EXPECT_NE(errorOf([&] { pm::io::readCameraFile(d.file("c.xml"), "left", 640, 480); }).find("must be positive"), std::string::npos);
}

TEST(RigFile, ALensSurvivesTheRoundTripInOpenCvAndViSPFiles)
{
  TempDir d("rig-lens");
  pm::core::StereoRig rig = pm::lab::labRigWithLens(kBarrel);
  pm::io::saveRig(rig, d.file("rig.json"), "cams.xml");
  const pm::core::StereoRig back = pm::io::loadRig(d.file("rig.json"));
  EXPECT_EQ(back.left.distortion.coefficients, kBarrel.coefficients);
  EXPECT_EQ(back.right.distortion.coefficients, kBarrel.coefficients);
  EXPECT_TRUE(std::filesystem::exists(d.file("rig_left.yml")));
  const auto j = nlohmann::json::parse(pm::test::readText(d.file("rig.json")));
  EXPECT_EQ(j["version"], 2);
  // The XML holds ViSP's one-coefficient model fitted to the lens: within a pixel over the image.
  const auto x = pm::io::readCameraFile(d.file("cams.xml"), "left", 640, 480);
  double worst = 0;
  for (int v = 0; v <= 480; v += 60)
    for (int u = 0; u <= 640; u += 80)
      worst = std::max(worst, vpImagePoint::distance(x.camera.distortion.distort(x.camera.cam, vpImagePoint(v, u)),
                                                     kBarrel.distort(rig.left.cam, vpImagePoint(v, u))));
  EXPECT_LT(worst, 2.0);
  EXPECT_GT(worst, 0.0);
  // A lens ViSP's model holds exactly stays in the XML alone (version 1).
  rig.left.distortion = rig.right.distortion = pm::core::LensDistortion{{-0.2, 0, 0, 0, 0}};
  pm::io::saveRig(rig, d.file("rig1.json"), "cams1.xml");
  EXPECT_EQ(nlohmann::json::parse(pm::test::readText(d.file("rig1.json")))["version"], 1);
  EXPECT_DOUBLE_EQ(pm::io::loadRig(d.file("rig1.json")).left.distortion.coefficients[0], -0.2);
  // A pinhole rig is written as before: no distortion.
  const pm::core::StereoRig lab = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  EXPECT_TRUE(lab.left.distortion.isNone());
}

TEST(RigCalibration, ASimulatedRigWithALensIsRecovered)
{
  pm::calib::ChessBoard board;
  board.squareMm = board.marginMm = 25;
  const pm::core::StereoRig truth = pm::lab::labRigWithLens(kBarrel);
  pm::lab::SimulatedCalibrationParams sp;
  const auto pairs = pm::lab::renderCalibrationPairs(truth, board, 60, sp);
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, truth);
  EXPECT_LT(e.translationErrorMm, 0.5);
  EXPECT_LT(std::fabs(e.baselineErrorMm), 0.5);
  EXPECT_LT(e.rotationErrorDeg, 0.1);
  EXPECT_LT(c.rmsStereoPx, 0.3);
  EXPECT_LT(e.reprojectionRmsPx[0], 0.6); // over the whole image, corners included
  EXPECT_LT(e.reprojectionRmsPx[1], 0.6);
  EXPECT_GE(c.pairsUsed, 10);
  EXPECT_GT(c.viewsUsed[0], c.pairsUsed); // views of one camera alone help its lens
  for (const auto &p : c.pairs) {
    if (!p.used) {
      EXPECT_NE(p.reason.find("not all found"), std::string::npos) << p.reason;
    }
  }
}

TEST(RigCalibration, TooFewUsableViewsSayWhichAndWhy)
{
  pm::calib::ChessBoard board;
  const pm::core::StereoRig truth = pm::lab::labRigWithLens(kBarrel);
  pm::sim::SceneParams sp;
  sp.shadows = pm::sim::ShadowMode::Off;
  const pm::sim::Scene scene(pm::sim::flatPrint(board.render(8.0), board.widthMm(), "board"), sp);
  const auto im = scene.renderStereo(truth, vpHomogeneousMatrix(0, 0, 0.5, 0.05, 0, 0), 0);
  std::vector<pm::calib::StereoImagePair> pairs(1);
  pairs[0].name = "good pair";
  pairs[0].left = im.left;
  pairs[0].right = im.right;
  pm::calib::StereoImagePair blank;
  blank.name = "blank pair";
  blank.left = blank.right = vpImage<vpRGBa>(480, 640, vpRGBa(128, 128, 128));
  pairs.push_back(blank);
  pm::calib::StereoImagePair small = pairs[0];
  small.name = "small pair";
  small.right = vpImage<vpRGBa>(240, 320, vpRGBa(128, 128, 128));
  pairs.push_back(small);
  // A blurred pair: the board found, its edges too wide.
  pm::calib::StereoImagePair blurred = pairs[0];
  blurred.name = "blurred pair";
  for (vpImage<vpRGBa> *I : {&blurred.left, &blurred.right}) {
    cv::Mat m(static_cast<int>(I->getHeight()), static_cast<int>(I->getWidth()), CV_8UC4, I->bitmap);
    cv::GaussianBlur(m, m, cv::Size(0, 0), 4.0);
  }
  pairs.push_back(blurred);
  const std::string e = errorOf([&] { pm::calib::calibrateRig(pairs, board); });
  EXPECT_NE(e.find("1 usable pair of 4"), std::string::npos) << e;
  EXPECT_NE(e.find("blank pair: chessboard"), std::string::npos) << e;
  EXPECT_NE(e.find("small pair: right image is 320x240"), std::string::npos) << e;
  EXPECT_NE(e.find("blurred pair: blurred"), std::string::npos) << e;
  EXPECT_NE(errorOf([&] { pm::calib::calibrateRig({}, board); }).find("no image pair"), std::string::npos);
}

TEST(RigCalibration, OpenCvsRealStereoPairsAsOpenCvCalibratesThem)
{
  if (!std::filesystem::exists(kOpenCvData + "left01.jpg"))
    GTEST_SKIP() << "opencv-doc is not installed (apt-get install opencv-doc)";
  // The reference: OpenCV's own pipeline on the same images, written out here.
  const cv::Size ps(9, 6);
  std::vector<std::vector<cv::Point2f>> L, R;
  std::vector<std::vector<cv::Point3f>> O;
  std::vector<pm::calib::StereoImagePair> pairs;
  for (int i = 1; i <= 14; ++i) {
    if (i == 10)
      continue; // not in the package
    char n[16];
    std::snprintf(n, sizeof n, "%02d.jpg", i);
    pm::calib::StereoImagePair p;
    p.name = n;
    p.left = pm::io::readColorImage(kOpenCvData + "left" + n);
    p.right = pm::io::readColorImage(kOpenCvData + "right" + n);
    pairs.push_back(p);
    cv::Mat l = cv::imread(kOpenCvData + "left" + n, cv::IMREAD_GRAYSCALE), r = cv::imread(kOpenCvData + "right" + n, cv::IMREAD_GRAYSCALE);
    std::vector<cv::Point2f> cl, cr;
    ASSERT_TRUE(cv::findChessboardCorners(l, ps, cl, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE));
    ASSERT_TRUE(cv::findChessboardCorners(r, ps, cr, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE));
    const cv::TermCriteria tc(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01);
    cv::cornerSubPix(l, cl, {11, 11}, {-1, -1}, tc);
    cv::cornerSubPix(r, cr, {11, 11}, {-1, -1}, tc);
    L.push_back(cl);
    R.push_back(cr);
    std::vector<cv::Point3f> o;
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 9; ++x)
        o.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.f);
    O.push_back(o);
  }
  cv::Mat K1, D1, K2, D2, Rs, T, E, F;
  std::vector<cv::Mat> rv, tv;
  cv::calibrateCamera(O, L, {640, 480}, K1, D1, rv, tv);
  cv::calibrateCamera(O, R, {640, 480}, K2, D2, rv, tv);
  const double refRms = cv::stereoCalibrate(O, L, R, K1, D1, K2, D2, {640, 480}, Rs, T, E, F, cv::CALIB_FIX_INTRINSIC);

  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = board.marginMm = 1;
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  EXPECT_EQ(c.pairsUsed, 13);
  EXPECT_NEAR(c.rmsStereoPx, refRms, 0.1 * refRms);
  EXPECT_NEAR(c.rmsStereoPx, 0.447, 0.0447); // the figure
  EXPECT_NEAR(c.baselineMm, 3.345, 0.005 * 3.345);
  EXPECT_NEAR(c.baselineMm, cv::norm(T), 0.005 * 3.345);
  EXPECT_NEAR(c.rig.left.distortion.coefficients[0], -0.27, 0.03); // strong barrel
  EXPECT_NEAR(c.rig.baseline() * 1e3, 3.345, 0.005 * 3.345);

  // Written as a rig, its check on the same pairs agrees; a baseline 5 % longer does not.
  TempDir d("cv-rig");
  pm::io::saveRig(c.rig, d.file("rig.json"), "cameras.xml");
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    pm::io::writeImage(pairs[i].left, d.file("L_" + std::to_string(i) + ".png"));
    pm::io::writeImage(pairs[i].right, d.file("R_" + std::to_string(i) + ".png"));
  }
  const std::string args = " --pattern chessboard --board 6,9,1 --tolerance-mm 0.05 --left " + d.file("L_%d.png") +
                           " --right " + d.file("R_%d.png") + " --quiet --out " + d.file("check");
  const auto ok = runProgram("pm-calib-baseline", "--rig " + d.file("rig.json") + args);
  EXPECT_EQ(ok.status, 0) << ok.err;
  pm::core::StereoRig longer = c.rig;
  longer.left.hMc = vpHomogeneousMatrix(longer.left.hMc.getTranslationVector() * 1.05, longer.left.hMc.getRotationMatrix());
  longer.right.hMc = vpHomogeneousMatrix(longer.right.hMc.getTranslationVector() * 1.05, longer.right.hMc.getRotationMatrix());
  pm::io::saveRig(longer, d.file("longer.json"), "longer.xml");
  const auto bad = runProgram("pm-calib-baseline", "--rig " + d.file("longer.json") + args);
  EXPECT_EQ(bad.status, 3) << bad.err;
  // The same rig read as a pinhole (the lens dropped) does not agree: the false alarm the lens removes.
  pm::core::StereoRig pin = c.rig;
  pin.left.distortion = pin.right.distortion = pm::core::LensDistortion();
  pm::io::saveRig(pin, d.file("pin.json"), "pin.xml");
  EXPECT_EQ(runProgram("pm-calib-baseline", "--rig " + d.file("pin.json") + args).status, 3);
}

TEST(PmCalibrateRig, WritesTheRigItsReportAndRefusesBadInput)
{
  TempDir d("calibrate-rig");
  const auto r = runProgram("pm-calibrate-rig", "--simulate 16 --board 6,9,25 --quiet --out " + d.file("o"));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char *f : {"rig.json", "cameras.xml", "rig_left.yml", "rig_right.yml", "coverage.png", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(d.file(std::string("o/") + f))) << f;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("o/summary.json")));
  EXPECT_LT(s["truth"]["rotation_error_deg"].get<double>(), 0.3);
  const pm::core::StereoRig rig = pm::io::loadRig(d.file("o/rig.json"));
  EXPECT_FALSE(rig.left.distortion.isNone());
  EXPECT_NEAR(rig.baseline() * 1e3, 323, 2);
  // Bad input: no images, unequal lists, a missing file, too few views; nothing written.
  EXPECT_EQ(runProgram("pm-calibrate-rig", "--out " + d.file("x")).status, 2);
  const auto unequal = runProgram("pm-calibrate-rig", "--left a.png b.png --right a.png --out " + d.file("x"));
  EXPECT_EQ(unequal.status, 2);
  EXPECT_NE(unequal.err.find("2 left images but 1 right"), std::string::npos) << unequal.err;
  const auto missing = runProgram("pm-calibrate-rig", "--left " + d.file("nope.png") + " --right " + d.file("nope.png") + " --out " + d.file("x"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_EQ(missing.err.rfind("error: ", 0), 0u) << missing.err;
  pm::io::writeImage(vpImage<vpRGBa>(480, 640, vpRGBa(90, 90, 90)), d.file("blank.png"));
  const auto few = runProgram("pm-calibrate-rig", "--left " + d.file("blank.png") + " --right " + d.file("blank.png") + " --out " + d.file("x"));
  EXPECT_EQ(few.status, 1);
  EXPECT_NE(few.err.find("0 usable pairs of 1"), std::string::npos) << few.err;
  EXPECT_FALSE(std::filesystem::exists(d.file("x")));
}

namespace {

//! The board poses of the used views of \e c and the hand poses of the same views in \e pass.
void usedPoses(const pm::calib::CameraCalibration &c, const pm::lab::CalibrationPass &pass, std::vector<vpHomogeneousMatrix> &cMo,
               std::vector<vpHomogeneousMatrix> &fMh)
{
  for (std::size_t i = 0; i < c.views.size(); ++i)
    if (c.views[i].used) {
      cMo.push_back(c.views[i].cMo);
      fMh.push_back(pass.fMh[i]);
    }
}

} // namespace

TEST(CameraCalibration, ACameraOnTheHandIsRecoveredWithItsLensAndItsPoseOnTheHand)
{
  pm::calib::ChessBoard board;
  board.squareMm = board.marginMm = 25;
  const pm::core::PinholeCamera truth = pm::lab::labRigWithLens(kBarrel).left; // off the hand's centre, toed in
  const pm::lab::CalibrationPass pass = pm::lab::renderCalibrationViews(truth, board, 24, pm::lab::SimulatedCalibrationParams());
  ASSERT_EQ(pass.views.size(), pass.fMh.size());
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(pass.views, board);
  EXPECT_GE(c.viewsUsed, 18);
  EXPECT_LT(c.rmsPx, 0.15);
  EXPECT_NEAR(c.camera.cam.get_px(), 754, 754 * 0.005);
  EXPECT_NEAR(c.camera.distortion.coefficients[0], -0.25, 0.05);
  for (const pm::calib::ViewReport &v : c.views)
    if (v.used) {
      // Each view's board pose puts the board where the renderer put it: the hand's pose, seen through the true hMc.
      const std::size_t i = static_cast<std::size_t>(&v - c.views.data());
      const vpHomogeneousMatrix cMoTrue = truth.hMc.inverse() * pass.fMh[i].inverse();
      EXPECT_LT((cMoTrue.getTranslationVector() - v.cMo.getTranslationVector()).frobeniusNorm() * 1e3, 2.0) << v.name;
    }
  std::vector<vpHomogeneousMatrix> cMo, fMh;
  usedPoses(c, pass, cMo, fMh);
  const pm::calib::HandEyeFit fit = pm::calib::solveHandEye(cMo, fMh);
  pm::core::PinholeCamera est = c.camera;
  est.hMc = fit.hMc;
  const pm::calib::CameraErrors e = pm::calib::compareCameras(est, truth);
  EXPECT_LT(e.translationErrorMm, 0.5);
  EXPECT_LT(e.rotationErrorDeg, 0.05);
  EXPECT_LT(e.reprojectionRmsPx, 1.0); // over the whole image, its corners (no board reached them) included
  EXPECT_LT(fit.spreadMm, 0.2);
  EXPECT_LT(fit.spreadDeg, 0.1);
  // The board's place in the world is the world's origin (the renderer's board frame).
  EXPECT_LT(fit.fMo.getTranslationVector().frobeniusNorm() * 1e3, 0.5);
}

TEST(HandEye, AHandPoseReadAtTheWrongViewShowsInTheBoardsSpreadAndBadListsAreRefused)
{
  pm::calib::ChessBoard board;
  board.squareMm = board.marginMm = 25;
  const pm::core::PinholeCamera truth = pm::lab::labRigWithLens(kBarrel).left;
  const pm::lab::CalibrationPass pass = pm::lab::renderCalibrationViews(truth, board, 12, pm::lab::SimulatedCalibrationParams());
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(pass.views, board);
  std::vector<vpHomogeneousMatrix> cMo, fMh;
  usedPoses(c, pass, cMo, fMh);
  ASSERT_GE(cMo.size(), 6u);
  const double good = pm::calib::solveHandEye(cMo, fMh).spreadMm;
  std::swap(fMh[1], fMh[2]); // two poses read at each other's view
  EXPECT_GT(pm::calib::solveHandEye(cMo, fMh).spreadMm, 50 * good);
  EXPECT_NE(errorOf([&] { pm::calib::solveHandEye(cMo, std::vector<vpHomogeneousMatrix>(fMh.begin(), fMh.end() - 1)); })
                .find("hand poses (one of each per view)"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { pm::calib::solveHandEye({cMo[0], cMo[1]}, {fMh[0], fMh[1]}); }).find("at least 3"), std::string::npos);
}

TEST(CameraCalibration, OpenCvsRealImagesAsOpenCvCalibratesThemAndBadViewsSayWhy)
{
  if (!std::filesystem::exists(kOpenCvData + "left01.jpg"))
    GTEST_SKIP() << "opencv-doc is not installed (apt-get install opencv-doc)";
  std::vector<pm::calib::CalibrationView> views;
  std::vector<std::vector<cv::Point2f>> L;
  std::vector<std::vector<cv::Point3f>> O;
  for (int i = 1; i <= 14; ++i) {
    if (i == 10)
      continue; // not in the package
    char n[16];
    std::snprintf(n, sizeof n, "left%02d.jpg", i);
    views.push_back({n, pm::io::readColorImage(kOpenCvData + n)});
    cv::Mat l = cv::imread(kOpenCvData + n, cv::IMREAD_GRAYSCALE);
    std::vector<cv::Point2f> cl;
    ASSERT_TRUE(cv::findChessboardCorners(l, {9, 6}, cl, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE));
    cv::cornerSubPix(l, cl, {11, 11}, {-1, -1}, cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01));
    L.push_back(cl);
    std::vector<cv::Point3f> o;
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 9; ++x)
        o.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.f);
    O.push_back(o);
  }
  cv::Mat K, D;
  std::vector<cv::Mat> rv, tv;
  const double refRms = cv::calibrateCamera(O, L, {640, 480}, K, D, rv, tv);
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = board.marginMm = 1;
  views.push_back({"blank", vpImage<vpRGBa>(480, 640, vpRGBa(128, 128, 128))});
  views.push_back({"small", vpImage<vpRGBa>(240, 320, vpRGBa(128, 128, 128))});
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(views, board);
  EXPECT_EQ(c.viewsUsed, 13);
  EXPECT_NEAR(c.rmsPx, refRms, 0.1 * refRms);
  EXPECT_NEAR(c.camera.cam.get_px(), K.at<double>(0, 0), 0.01 * K.at<double>(0, 0));
  EXPECT_NEAR(c.camera.cam.get_u0(), K.at<double>(0, 2), 2.0);
  EXPECT_NEAR(c.camera.distortion.coefficients[0], -0.27, 0.03); // strong barrel, as the stereo calibration finds it
  EXPECT_NE(c.views[13].reason.find("chessboard"), std::string::npos) << c.views[13].reason;
  EXPECT_NE(c.views[14].reason.find("camera image is 320x240"), std::string::npos) << c.views[14].reason;
  const std::vector<pm::calib::CalibrationView> two(views.begin() + 12, views.end());
  const std::string e = errorOf([&] { pm::calib::calibrateCamera(two, board); });
  EXPECT_NE(e.find("1 usable view of 3"), std::string::npos) << e;
  EXPECT_NE(e.find("blank: chessboard"), std::string::npos) << e;
}

TEST(PmCalibrateRig, OneCameraWritesARigOfOneCameraOnTheHandAndRefusesBadInput)
{
  TempDir d("calibrate-one");
  const auto r = runProgram("pm-calibrate-rig", "--simulate 20 --cameras 1 --board 6,9,25 --quiet --out " + d.file("o"));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char *f : {"rig.json", "cameras.xml", "rig_camera.yml", "coverage.png", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(d.file(std::string("o/") + f))) << f;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("o/summary.json")));
  EXPECT_LT(s["truth"]["hMc_translation_error_mm"].get<double>(), 0.5);
  EXPECT_LT(s["truth"]["hMc_rotation_error_deg"].get<double>(), 0.05);
  const pm::core::CameraRig rig = pm::io::loadCameraRig(d.file("o/rig.json"));
  ASSERT_EQ(rig.cameras.size(), 1u);
  const pm::core::PinholeCamera truth = pm::lab::labRigWithLens(kBarrel).left;
  EXPECT_LT((rig.cameras[0].hMc.getTranslationVector() - truth.hMc.getTranslationVector()).frobeniusNorm() * 1e3, 0.5);

  // A user's images and hand poses, as files: the same calibration.
  const pm::lab::CalibrationPass pass = pm::lab::renderCalibrationViews(truth, pm::calib::ChessBoard(), 8, pm::lab::SimulatedCalibrationParams());
  for (std::size_t i = 0; i < pass.views.size(); ++i) {
    pm::io::writeImage(pass.views[i].image, d.file("C_" + std::to_string(i) + ".png"));
    pm::io::writePoseYaml(pass.fMh[i], d.file("pose_fPe_" + std::to_string(i) + ".yaml"));
  }
  const std::string images = " --camera-images " + d.file("C_%d.png") + " --out " + d.file("u") + " --quiet";
  const auto files = runProgram("pm-calibrate-rig", images + " --hand-poses " + d.file("pose_fPe_%d.yaml"));
  ASSERT_EQ(files.status, 0) << files.err;
  EXPECT_LT((pm::io::loadCameraRig(d.file("u/rig.json")).cameras[0].hMc.getTranslationVector() - truth.hMc.getTranslationVector())
                    .frobeniusNorm() * 1e3, 1.0);
  const auto given = runProgram("pm-calibrate-rig", images + " --hMc 0.01 0 0 0 0 0");
  ASSERT_EQ(given.status, 0) << given.err;
  EXPECT_NEAR(pm::io::loadCameraRig(d.file("u/rig.json")).cameras[0].hMc[0][3], 0.01, 1e-12);

  // Bad input: no pose on the hand, more images than poses, both ways of giving it; nothing written.
  const std::string x = " --camera-images " + d.file("C_%d.png") + " --out " + d.file("x");
  const auto noPose = runProgram("pm-calibrate-rig", x);
  EXPECT_EQ(noPose.status, 2);
  EXPECT_NE(noPose.err.find("--hand-poses"), std::string::npos) << noPose.err;
  const auto fewer = runProgram("pm-calibrate-rig", x + " --hand-poses " + d.file("pose_fPe_0.yaml"));
  EXPECT_EQ(fewer.status, 2);
  EXPECT_NE(fewer.err.find("8 images but 1 hand poses"), std::string::npos) << fewer.err;
  EXPECT_EQ(runProgram("pm-calibrate-rig", x + " --hMc 0 0 0 0 0 0 --hand-poses " + d.file("pose_fPe_%d.yaml")).status, 2);
  EXPECT_EQ(runProgram("pm-calibrate-rig", x + " --left a.png --right a.png --hMc 0 0 0 0 0 0").status, 2);
  EXPECT_FALSE(std::filesystem::exists(d.file("x")));
}

TEST(TagBoard, DetectNumbersCornersAsFindMatchesThem)
{
  // detect() numbers each tag corner without a camera; find() matches them with the tag's own pose.
  // At any in-plane turn both must agree: each detected corner lies where its board point projects.
  pm::calib::TagBoard b;
  pm::sim::SceneParams sp;
  sp.shadows = pm::sim::ShadowMode::Off;
  const pm::sim::Scene scene(pm::sim::flatPrint(b.render(8.0), b.widthMm(), "board"), sp);
  const pm::core::StereoRig rig = pm::lab::labRigWithLens(pm::core::LensDistortion());
  for (double turn : {0.0, 0.8, 2.0, -2.5}) {
    const vpHomogeneousMatrix hMb(0.01, 0.02, 0.5, 0.1, -0.1, turn);
    vpImage<vpRGBa> I;
    pm::sim::Rasterizer raster;
    scene.render(raster, rig.left, hMb, 0, 0, I);
    const pm::calib::PatternDetection d = b.detect(I, "test");
    ASSERT_EQ(d.pixels.size(), 36u) << turn;
    const vpHomogeneousMatrix cMb = rig.left.cMh() * hMb;
    for (std::size_t i = 0; i < d.pixels.size(); ++i) {
      vpPoint P = d.points[i];
      P.track(cMb);
      double u = 0, v = 0;
      vpMeterPixelConversion::convertPoint(rig.left.cam, P.get_x(), P.get_y(), u, v);
      EXPECT_LT(vpImagePoint::distance(d.pixels[i], vpImagePoint(v, u)), 1.5) << "turn " << turn << " id " << d.ids[i];
    }
  }
}

TEST(RigCalibration, ATagBoardCalibratesTheRigToo)
{
  pm::calib::TagBoard b;
  b.rows = 4;
  b.cols = 5;
  b.tagSizeMm = 30;
  b.pitchMm = 40;
  const pm::core::StereoRig truth = pm::lab::labRigWithLens(kBarrel);
  const auto pairs = pm::lab::renderCalibrationPairs(truth, b, 40, pm::lab::SimulatedCalibrationParams());
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, b);
  const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, truth);
  EXPECT_GE(c.pairsUsed, 30); // a board seen in part still pairs up
  EXPECT_LT(e.translationErrorMm, 1.0);
  EXPECT_LT(e.rotationErrorDeg, 0.1);
  EXPECT_LT(c.rmsStereoPx, 0.3);
}
