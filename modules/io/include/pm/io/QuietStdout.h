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

class QuietStdout
{
public:
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
