#pragma once
/*!
  \file QuietStdout.h
  Keeps what ViSP prints on the standard output (vpXmlParserCamera on std::cout,
  vpHandEyeCalibration with printf) out of the programs' output while an object of this class
  lives: std::cout's buffer and file descriptor 1 are redirected. Process-wide: use it where
  no other thread writes to the standard output.
*/
#include <cstdio>
#include <iostream>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace pm::io {

/*!
  Silences the standard output while it lives (see QuietStdout.h); not copyable.

  \code
#include <visp3/core/vpXmlParserCamera.h>

#include "pm/io/QuietStdout.h"

int main()
{
  vpCameraParameters cam;
  vpXmlParserCamera parser;
  pm::io::QuietStdout quiet; // until the end of the scope
  return parser.parse(cam, "cameras.xml", "left", vpCameraParameters::perspectiveProjWithoutDistortion, 640, 480);
}
  \endcode
*/
class QuietStdout
{
public:
  //! Flushes stdout, then sends std::cout to a string and file descriptor 1 to /dev/null.
  QuietStdout() : m_old(std::cout.rdbuf(m_sink.rdbuf()))
  {
    std::fflush(stdout);
    m_fd = dup(1);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, 1);
      close(null);
    }
  }
  //! Flushes stdout and gives std::cout and file descriptor 1 back.
  ~QuietStdout()
  {
    std::fflush(stdout);
    if (m_fd >= 0) {
      dup2(m_fd, 1);
      close(m_fd);
    }
    std::cout.rdbuf(m_old);
  }
  QuietStdout(const QuietStdout &) = delete;
  QuietStdout &operator=(const QuietStdout &) = delete;

private:
  std::ostringstream m_sink;
  std::streambuf *m_old;
  int m_fd = -1;
};

} // namespace pm::io
