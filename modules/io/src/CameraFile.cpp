#include "pm/io/CameraFile.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>
#include <visp3/core/vpException.h>
#include <visp3/core/vpXmlParserCamera.h>

#include "pm/core/Error.h"
#include "pm/io/CameraXml.h"
#include "pm/io/QuietStdout.h"
#include "pm/io/StagedFiles.h"

namespace pm::io {

namespace {

std::string readAll(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw Error("the intrinsics file '" + path + "' does not exist or cannot be read");
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

//! A matrix node: OpenCV's !!opencv-matrix, or ROS's {rows, cols, data}; row-major values.
std::vector<double> matrixValues(const cv::FileNode &n, const std::string &key, int &rows, int &cols)
{
  if (n.empty() || n.isNone())
    throw Error("no \"" + key + "\"");
  std::vector<double> v;
  if (n.isMap() && !n["data"].empty() && n["dt"].empty()) { // ROS
    rows = static_cast<int>(n["rows"]);
    cols = static_cast<int>(n["cols"]);
    const cv::FileNode d = n["data"];
    if (!d.isSeq())
      throw Error("\"" + key + ".data\" is not a list");
    for (auto it = d.begin(); it != d.end(); ++it) {
      if (!(*it).isReal() && !(*it).isInt())
        throw Error("\"" + key + ".data\" holds something that is not a number");
      v.push_back(static_cast<double>(*it));
    }
  } else if (n.isSeq()) { // a plain list
    for (auto it = n.begin(); it != n.end(); ++it) {
      if (!(*it).isReal() && !(*it).isInt())
        throw Error("\"" + key + "\" holds something that is not a number");
      v.push_back(static_cast<double>(*it));
    }
    rows = 1;
    cols = static_cast<int>(v.size());
  } else {
    cv::Mat m;
    try {
      n >> m;
    } catch (const cv::Exception &) {
      m.release();
    }
    if (m.empty())
      throw Error("\"" + key + "\" is not a matrix");
    m.convertTo(m, CV_64F);
    rows = m.rows;
    cols = m.cols;
    v.assign(m.begin<double>(), m.end<double>());
  }
  if (rows * cols != static_cast<int>(v.size()))
    throw Error("\"" + key + "\" says " + std::to_string(rows) + "x" + std::to_string(cols) + " but holds " +
                std::to_string(v.size()) + " values");
  return v;
}

CameraIntrinsics fromFileStorage(const std::string &text, bool ros)
{
  cv::FileStorage fs;
  try {
    fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  } catch (const cv::Exception &e) {
    throw Error(std::string("it cannot be parsed: ") + e.err);
  }
  if (!fs.isOpened())
    throw Error("it cannot be parsed");
  CameraIntrinsics c;
  c.format = ros ? "ros" : "opencv";
  int rows = 0, cols = 0;
  const std::vector<double> K = matrixValues(fs["camera_matrix"], "camera_matrix", rows, cols);
  if (rows != 3 || cols != 3)
    throw Error("\"camera_matrix\" must be 3x3, it is " + std::to_string(rows) + "x" + std::to_string(cols));
  for (double x : K)
    if (!std::isfinite(x))
      throw Error("\"camera_matrix\" holds a value that is not finite");
  if (!(K[0] > 0 && K[4] > 0))
    throw Error("\"camera_matrix\": focal lengths must be positive (fx = " + std::to_string(K[0]) + ", fy = " +
                std::to_string(K[4]) + ")");
  if (K[1] != 0 || K[3] != 0 || K[6] != 0 || K[7] != 0 || K[8] != 1)
    throw Error("\"camera_matrix\" is not a camera matrix [fx 0 cx; 0 fy cy; 0 0 1] (a skew is not supported)");
  c.cam.initPersProjWithoutDistortion(K[0], K[4], K[2], K[5]);
  const cv::FileNode d = fs["distortion_coefficients"];
  if (!d.empty() && !d.isNone())
    c.distortion.coefficients = matrixValues(d, "distortion_coefficients", rows, cols);
  if (ros) {
    const std::string model = fs["distortion_model"].empty() ? "plumb_bob" : fs["distortion_model"].string();
    if (model != "plumb_bob" && model != "rational_polynomial")
      throw Error("distortion_model \"" + model + "\" is not supported (plumb_bob or rational_polynomial)");
  }
  for (const char *key : {"image_width", "image_height"}) {
    const cv::FileNode n = fs[key];
    if (n.empty() || n.isNone())
      continue;
    if (!n.isInt() || static_cast<int>(n) <= 0)
      throw Error(std::string("\"") + key + "\" must be a positive integer");
    (key[6] == 'w' ? c.width : c.height) = static_cast<unsigned>(static_cast<int>(n));
  }
  return c;
}

CameraIntrinsics fromVispXml(const std::string &path, const std::string &name, unsigned w, unsigned h)
{
  CameraIntrinsics c;
  c.format = "visp-xml";
  int status = vpXmlParserCamera::SEQUENCE_ERROR;
  try {
    QuietStdout quiet;
    vpXmlParserCamera parser;
    status = parser.parse(c.cam, path, name, vpCameraParameters::perspectiveProjWithDistortion, w, h);
  } catch (const vpException &) {
    status = vpXmlParserCamera::SEQUENCE_ERROR;
  }
  if (status == vpXmlParserCamera::SEQUENCE_OK) {
    const double kud = c.cam.get_kud();
    c.distortion.coefficients = {kud, 0, 0, 0, 0};
    c.cam.initPersProjWithoutDistortion(c.cam.get_px(), c.cam.get_py(), c.cam.get_u0(), c.cam.get_v0());
  } else {
    c.cam = readCameraXml(path, name, w, h);
  }
  c.width = w;
  c.height = h;
  return c;
}

//! OpenCV's parser and node readers throw cv::Exception on malformed content: a pm::Error here.
template <class F> CameraIntrinsics guarded(F &&f)
{
  try {
    return f();
  } catch (const cv::Exception &e) {
    throw Error(std::string("it cannot be read: ") + e.err);
  }
}

} // namespace

CameraIntrinsics readCameraFile(const std::string &path, const std::string &name, unsigned w, unsigned h)
{
  if (!std::filesystem::is_regular_file(path))
    throw Error("the intrinsics file '" + path + "' does not exist");
  const std::string text = readAll(path);
  CameraIntrinsics c;
  try {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    const bool xml = first != std::string::npos && text[first] == '<';
    if (xml && text.find("<opencv_storage") != std::string::npos)
      c = guarded([&] { return fromFileStorage(text, false); });
    else if (xml && text.find("<camera>") != std::string::npos)
      c = fromVispXml(path, name, w, h);
    else if (text.rfind("%YAML", 0) == 0)
      c = guarded([&] { return fromFileStorage(text, false); });
    else if (text.find("camera_matrix") != std::string::npos)
      c = guarded([&] { return fromFileStorage("%YAML:1.0\n---\n" + text, true); }); // ROS writes YAML without OpenCV's header
    else
      throw Error("not a camera file this program knows (ViSP camera XML, OpenCV FileStorage with camera_matrix, "
                  "ROS camera_info YAML)");
    if (w && h && c.width && c.height && (c.width != w || c.height != h))
      throw Error("it is for " + std::to_string(c.width) + "x" + std::to_string(c.height) + " images, the camera's are " +
                  std::to_string(w) + "x" + std::to_string(h));
    if (w && h) {
      c.width = w;
      c.height = h;
    }
    if (c.width && c.height)
      c.distortion.validate(c.cam, c.width, c.height, "camera '" + name + "'");
    else
      c.distortion.validate(c.cam, 1, 1, "camera '" + name + "'"); // counts and values at least
  } catch (const Error &e) {
    const std::string what = e.what();
    if (what.find(path) != std::string::npos)
      throw;
    throw Error("intrinsics file '" + path + "': " + what);
  }
  return c;
}

void writeOpenCvCameraFile(const RigCamera &camera, const std::string &path)
{
  try {
    cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    fs << "camera_name" << camera.name;
    fs << "image_width" << static_cast<int>(camera.width) << "image_height" << static_cast<int>(camera.height);
    const cv::Matx33d K(camera.cam.get_px(), 0, camera.cam.get_u0(), 0, camera.cam.get_py(), camera.cam.get_v0(), 0, 0, 1);
    fs << "camera_matrix" << cv::Mat(K);
    std::vector<double> d = camera.distortion.coefficients;
    if (d.empty())
      d.assign(5, 0.0);
    fs << "distortion_coefficients" << cv::Mat(d, true).reshape(1, 1);
    writeTextFile(path, fs.releaseAndGetString());
  } catch (const cv::Exception &e) {
    throw Error("cannot write the camera file '" + path + "': " + e.err);
  }
}

} // namespace pm::io
