#include "TestSupport.h"

#include "pm/core/Error.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pm::test {

TempDir::TempDir(const std::string &tag)
{
  static int counter = 0;
  m_path = (fs::temp_directory_path() / ("pm-test-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++))).string();
  fs::remove_all(m_path);
  fs::create_directories(m_path);
}

TempDir::~TempDir()
{
  std::error_code ec;
  fs::remove_all(m_path, ec);
}

std::string readText(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void writeText(const std::string &path, const std::string &text)
{
  std::ofstream f(path, std::ios::binary);
  f << text;
}

RunResult runProgram(const std::string &name, const std::string &args)
{
  return runCommand(std::string(PM_TEST_BIN_DIR) + "/" + name + " " + args);
}

RunResult runCommand(const std::string &command)
{
  TempDir tmp("run");
  const std::string cmd = command + " > " + tmp.file("out") + " 2> " + tmp.file("err") + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + (WIFSIGNALED(raw) ? WTERMSIG(raw) : 0);
  r.out = readText(tmp.file("out"));
  r.err = readText(tmp.file("err"));
  return r;
}

std::string errorOf(const std::function<void()> &f)
{
  try {
    f();
  } catch (const pm::core::Error &e) {
    return e.what();
  }
  return "";
}

std::string dataPath(const std::string &relative) { return std::string(PM_TEST_DATA_DIR) + "/" + relative; }

std::vector<std::string> listFiles(const std::string &dir)
{
  std::vector<std::string> v;
  if (fs::is_directory(dir))
    for (const auto &e : fs::directory_iterator(dir))
      v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

vpImage<vpRGBa> bluePhoto(unsigned w, unsigned h, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 3.0);
  vpImage<vpRGBa> I(h, w);
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u) {
      const double t = 0.8 + 0.2 * std::sin(u * 0.05) * std::cos(v * 0.07);
      auto c = [&](double x) { return static_cast<unsigned char>(std::clamp(x * t + n(rng), 0.0, 255.0)); };
      I[v][u] = vpRGBa(c(30), c(90), c(170));
    }
  return I;
}

void paintDisc(vpImage<vpRGBa> &I, double cu, double cv, double r, const vpRGBa &c)
{
  for (unsigned v = 0; v < I.getHeight(); ++v)
    for (unsigned u = 0; u < I.getWidth(); ++u)
      if ((u - cu) * (u - cu) + (v - cv) * (v - cv) <= r * r)
        I[v][u] = c;
}

} // namespace pm::test
