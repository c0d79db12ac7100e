#pragma once
// Shared helpers of the test suites: temporary folders, running the programs, synthetic photos.
#include <functional>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::test {

//! A fresh empty folder under the system's temporary folder, removed at destruction.
class TempDir
{
public:
  explicit TempDir(const std::string &tag);
  ~TempDir();
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  const std::string &path() const { return m_path; }
  std::string file(const std::string &name) const { return m_path + "/" + name; }

private:
  std::string m_path;
};

struct RunResult
{
  int status = -1;     //!< exit status
  std::string out, err; //!< captured stdout and stderr
};

//! Runs program \e name of the build (e.g. "pm-make-model") with \e args (shell words).
RunResult runProgram(const std::string &name, const std::string &args);
//! Runs a shell command line (e.g. "xvfb-run -a /path/pm-track ...").
RunResult runCommand(const std::string &command);
std::string dataPath(const std::string &relative);
std::string readText(const std::string &path);
void writeText(const std::string &path, const std::string &text);
//! Files of a folder, sorted by name.
std::vector<std::string> listFiles(const std::string &dir);

//! The message of the pm::core::Error that \e f throws ("" if none).
std::string errorOf(const std::function<void()> &f);

//! A w x h photo of a textured blue background (hue ~210), with noise from \e seed.
vpImage<vpRGBa> bluePhoto(unsigned w, unsigned h, unsigned seed);
//! Paints a disc of colour \e c (radius r px, centre cu, cv) onto \e I.
void paintDisc(vpImage<vpRGBa> &I, double cu, double cv, double r, const vpRGBa &c);

} // namespace pm::test
