#pragma once
/*!
  \file Progress.h
  A progress bar with ETA on stderr for long runs (redrawn in place on a terminal, a line per
  10 % otherwise); silent when quiet.
*/
#include <chrono>
#include <string>

namespace pm::app {

class Progress
{
public:
  Progress(std::string label, std::size_t total, bool quiet);
  ~Progress();
  void step(std::size_t n = 1);
  void finish();

private:
  void draw(bool force);
  std::string m_label;
  std::size_t m_total, m_done = 0;
  bool m_quiet, m_tty, m_finished = false;
  int m_lastDecile = -1;
  std::chrono::steady_clock::time_point m_start, m_lastDraw;
};

} // namespace pm::app
