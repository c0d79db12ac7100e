#include "pm/io/CameraFile.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>
#include <yaml-cpp/yaml.h>
#include <visp3/core/vpException.h>
#include <visp3/core/vpXmlParserCamera.h>

#include "pm/core/Error.h"
#include "pm/io/CameraXml.h"
#include "pm/io/QuietStdout.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/WellFormedXml.h"

namespace pm::io {

namespace {

std::string readAll(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw core::Error("the intrinsics file '" + path + "' does not exist or cannot be read");
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

//! What a camera file says, whatever its syntax.
struct Fields
{
  struct Matrix
  {
    bool present = false;
    long long rows = 0, cols = 0;
    std::vector<double> values;
  };
  Matrix K, D;
  long long width = 0, height = 0; //!< 0: not given
  std::string distortionModel;
};

void checkShape(const Fields::Matrix &m, const std::string &key)
{
  if (m.rows < 1 || m.cols < 1 || m.rows > 1000 || m.cols > 1000)
    throw core::Error("\"" + key + "\" says " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ": not a matrix of this kind");
  if (m.rows * m.cols != static_cast<long long>(m.values.size()))
    throw core::Error("\"" + key + "\" says " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + " but holds " +
                std::to_string(m.values.size()) + " values");
}

//! YAML (OpenCV's and ROS's) through yaml-cpp: OpenCV's own YAML parser loops forever on some
//! malformed files (fuzzing found one), yaml-cpp refuses them.
Fields yamlFields(std::string text)
{
  if (text.rfind("%YAML:", 0) == 0) // OpenCV's header is not YAML's directive
    text.erase(0, text.find('\n') == std::string::npos ? text.size() : text.find('\n') + 1);
  Fields f;
  try {
    const YAML::Node root = YAML::Load(text);
    if (!root.IsMap())
      throw core::Error("it is not a map of fields");
    const auto matrix = [&](const char *key, Fields::Matrix &m) {
      const YAML::Node n = root[key];
      if (!n)
        return;
      m.present = true;
      if (n.IsSequence()) { // a plain list
        for (const YAML::Node &x : n)
          m.values.push_back(x.as<double>());
        m.rows = 1;
        m.cols = static_cast<long long>(m.values.size());
      } else if (n.IsMap() && n["data"] && n["data"].IsSequence() && n["rows"] && n["cols"]) {
        m.rows = n["rows"].as<long long>();
        m.cols = n["cols"].as<long long>();
        for (const YAML::Node &x : n["data"])
          m.values.push_back(x.as<double>());
      } else {
        throw core::Error(std::string("\"") + key + "\" is not a matrix (rows, cols, data)");
      }
      checkShape(m, key);
    };
    matrix("camera_matrix", f.K);
    matrix("distortion_coefficients", f.D);
    for (const char *key : {"image_width", "image_height"})
      if (root[key])
        (key[6] == 'w' ? f.width : f.height) = root[key].as<long long>();
    if (root["distortion_model"])
      f.distortionModel = root["distortion_model"].as<std::string>();
  } catch (const YAML::Exception &e) {
    throw core::Error("it cannot be read: " + e.msg);
  }
  return f;
}

//! OpenCV's XML through cv::FileStorage.
Fields xmlFields(const std::string &text)
{
  Fields f;
  try {
    cv::FileStorage fs(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    if (!fs.isOpened())
      throw core::Error("it cannot be parsed");
    const auto matrix = [&](const char *key, Fields::Matrix &m) {
      const cv::FileNode n = fs[key];
      if (n.empty() || n.isNone())
        return;
      m.present = true;
      const cv::FileNode nr = n["rows"], nc = n["cols"], d = n["data"];
      if (!nr.isInt() || !nc.isInt() || d.empty())
        throw core::Error(std::string("\"") + key + "\" is not a matrix (rows, cols, data)");
      m.rows = static_cast<int>(nr);
      m.cols = static_cast<int>(nc);
      if (m.rows < 1 || m.cols < 1 || m.rows > 1000 || m.cols > 1000) // checked before OpenCV allocates (fuzzing found 17 GB asked for)
        checkShape(m, key);
      cv::Mat mat;
      n >> mat;
      if (mat.empty())
        throw core::Error(std::string("\"") + key + "\" is not a matrix");
      mat.convertTo(mat, CV_64F);
      m.values.assign(mat.begin<double>(), mat.end<double>());
      checkShape(m, key);
    };
    matrix("camera_matrix", f.K);
    matrix("distortion_coefficients", f.D);
    for (const char *key : {"image_width", "image_height"}) {
      const cv::FileNode n = fs[key];
      if (n.empty() || n.isNone())
        continue;
      if (!n.isInt())
        throw core::Error(std::string("\"") + key + "\" must be a positive integer");
      (key[6] == 'w' ? f.width : f.height) = static_cast<int>(n);
    }
  } catch (const cv::Exception &e) {
    throw core::Error(std::string("it cannot be read: ") + e.err);
  } catch (const core::Error &) {
    throw;
  } catch (const std::exception &e) { // OpenCV's parser lets some standard exceptions out
    throw core::Error(std::string("it cannot be read (") + e.what() + ")");
  }
  return f;
}

CameraFile fromFields(const Fields &f, bool ros)
{
  CameraFile c;
  c.format = ros ? "ros" : "opencv";
  if (!f.K.present)
    throw core::Error("no \"camera_matrix\"");
  if (f.K.rows != 3 || f.K.cols != 3)
    throw core::Error("\"camera_matrix\" must be 3x3, it is " + std::to_string(f.K.rows) + "x" + std::to_string(f.K.cols));
  const std::vector<double> &K = f.K.values;
  for (double x : K)
    if (!std::isfinite(x))
      throw core::Error("\"camera_matrix\" holds a value that is not finite");
  if (!(K[0] > 0 && K[4] > 0))
    throw core::Error("\"camera_matrix\": focal lengths must be positive (fx = " + std::to_string(K[0]) + ", fy = " +
                std::to_string(K[4]) + ")");
  if (K[1] != 0 || K[3] != 0 || K[6] != 0 || K[7] != 0 || K[8] != 1)
    throw core::Error("\"camera_matrix\" is not a camera matrix [fx 0 cx; 0 fy cy; 0 0 1] (a skew is not supported)");
  try {
    c.camera.cam.initPersProjWithoutDistortion(K[0], K[4], K[2], K[5]);
  } catch (const vpException &e) { // ViSP takes a focal length under 1e-6 for 0 (fuzzing found it)
    throw core::Error("\"camera_matrix\": " + e.getStringMessage() + " (focal lengths must be positive)");
  }
  if (f.D.present)
    c.camera.distortion.coefficients = f.D.values;
  if (ros) {
    const std::string model = f.distortionModel.empty() ? "plumb_bob" : f.distortionModel;
    if (model != "plumb_bob" && model != "rational_polynomial")
      throw core::Error("distortion_model \"" + model + "\" is not supported (plumb_bob or rational_polynomial)");
  }
  for (const long long *v : {&f.width, &f.height})
    if (*v < 0 || *v > 1000000)
      throw core::Error(std::string("\"") + (v == &f.width ? "image_width" : "image_height") + "\" must be a positive integer");
  c.camera.width = static_cast<unsigned>(f.width);
  c.camera.height = static_cast<unsigned>(f.height);
  return c;
}

CameraFile fromVispXml(const std::string &path, const std::string &name, unsigned w, unsigned h)
{
  refuseUnsafeCameraXml(path);
  CameraFile c;
  c.format = "visp-xml";
  int status = vpXmlParserCamera::SEQUENCE_ERROR;
  try {
    QuietStdout quiet;
    vpXmlParserCamera parser;
    status = parser.parse(c.camera.cam, path, name, vpCameraParameters::perspectiveProjWithDistortion, w, h);
  } catch (const vpException &) {
    status = vpXmlParserCamera::SEQUENCE_ERROR;
  }
  if (status == vpXmlParserCamera::SEQUENCE_OK) {
    requireValidIntrinsics(c.camera.cam, path, name);
    const double kud = c.camera.cam.get_kud();
    if (!std::isfinite(kud))
      throw core::Error("camera '" + name + "' in '" + path + "': kud is not finite");
    c.camera.distortion.coefficients = {kud, 0, 0, 0, 0};
    c.camera.cam.initPersProjWithoutDistortion(c.camera.cam.get_px(), c.camera.cam.get_py(), c.camera.cam.get_u0(), c.camera.cam.get_v0());
  } else {
    c.camera.cam = readCameraXml(path, name, w, h);
  }
  c.camera.width = w;
  c.camera.height = h;
  return c;
}

} // namespace

CameraFile readCameraFile(const std::string &path, const std::string &name, unsigned w, unsigned h)
{
  if (!std::filesystem::is_regular_file(path))
    throw core::Error("the intrinsics file '" + path + "' does not exist");
  const std::string text = readAll(path);
  CameraFile c;
  try {
    // Text only: OpenCV's XML parser crashes on a NUL byte (fuzzing found it), and no camera file holds control characters.
    if (text.size() > 1000000)
      throw core::Error("it is " + std::to_string(text.size()) + " bytes long: not a camera file");
    for (unsigned char ch : text)
      if (ch < 0x20 && ch != '\t' && ch != '\n' && ch != '\r')
        throw core::Error("it holds a control character (byte " + std::to_string(static_cast<int>(ch)) + "): not a text file");
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    const bool xml = first != std::string::npos && text[first] == '<';
    if (xml)
      requireWellFormedXml(text); // before OpenCV's and ViSP's parsers, which read past a cut file
    if (xml && text.find("<opencv_storage") != std::string::npos)
      c = fromFields(xmlFields(text), false);
    else if (xml && text.find("<camera>") != std::string::npos)
      c = fromVispXml(path, name, w, h);
    else if (text.rfind("%YAML", 0) == 0)
      c = fromFields(yamlFields(text), false);
    else if (text.find("camera_matrix") != std::string::npos)
      c = fromFields(yamlFields(text), true); // ROS's camera_info
    else
      throw core::Error("not a camera file this program knows (ViSP camera XML, OpenCV FileStorage with camera_matrix, "
                  "ROS camera_info YAML)");
    if (w && h && c.camera.width && c.camera.height && (c.camera.width != w || c.camera.height != h))
      throw core::Error("it is for " + std::to_string(c.camera.width) + "x" + std::to_string(c.camera.height) + " images, the camera's are " +
                  std::to_string(w) + "x" + std::to_string(h));
    if (w && h) {
      c.camera.width = w;
      c.camera.height = h;
    }
    if (c.camera.width && c.camera.height)
      c.camera.distortion.validate(c.camera.cam, c.camera.width, c.camera.height, "camera '" + name + "'");
    else
      c.camera.distortion.validate(c.camera.cam, 1, 1, "camera '" + name + "'"); // counts and values at least
  } catch (const core::Error &e) {
    const std::string what = e.what();
    if (what.find(path) != std::string::npos)
      throw;
    throw core::Error("intrinsics file '" + path + "': " + what);
  }
  c.camera.name = name;
  return c;
}

void writeOpenCvCameraFile(const core::PinholeCamera &camera, const std::string &path)
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
    throw core::Error("cannot write the camera file '" + path + "': " + e.err);
  }
}

} // namespace pm::io
