#pragma once
/*!
  \file QuietStdout.h
  Keeps what ViSP prints on std::cout (vpXmlParserCamera, vpHandEyeCalibration) out of the
  programs' output while an object of this class lives.
*/
#include <iostream>
#include <sstream>

namespace pm::io {

class QuietStdout
{
public:
  QuietStdout() : m_old(std::cout.rdbuf(m_sink.rdbuf())) {}
  ~QuietStdout() { std::cout.rdbuf(m_old); }
  QuietStdout(const QuietStdout &) = delete;
  QuietStdout &operator=(const QuietStdout &) = delete;

private:
  std::ostringstream m_sink;
  std::streambuf *m_old;
};

} // namespace pm::io
