#include "pm/app/Progress.h"

#include <cstdio>
#include <unistd.h>

namespace pm::app {

Progress::Progress(std::string label, std::size_t total, bool quiet)
    : m_label(std::move(label)), m_total(total ? total : 1), m_quiet(quiet), m_tty(isatty(fileno(stderr)) != 0),
      m_start(std::chrono::steady_clock::now()), m_lastDraw(m_start)
{
}

Progress::~Progress()
{
  if (!m_finished && m_tty && !m_quiet && m_done > 0)
    std::fputc('\n', stderr);
}

void Progress::step(std::size_t n)
{
  m_done += n;
  draw(false);
}

void Progress::finish()
{
  if (m_finished)
    return;
  const bool shown = m_done >= m_total && !m_tty;
  m_done = m_total;
  if (!shown)
    draw(true);
  m_finished = true;
}

void Progress::draw(bool force)
{
  if (m_quiet)
    return;
  const auto now = std::chrono::steady_clock::now();
  const double frac = std::min(1.0, static_cast<double>(m_done) / static_cast<double>(m_total));
  const int decile = static_cast<int>(frac * 10);
  if (m_tty) {
    if (!force && now - m_lastDraw < std::chrono::milliseconds(150))
      return;
  } else if (!force && decile == m_lastDecile) {
    return;
  }
  m_lastDraw = now;
  m_lastDecile = decile;
  const double elapsed = std::chrono::duration<double>(now - m_start).count();
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  char bar[31];
  const int filled = static_cast<int>(frac * 30);
  for (int i = 0; i < 30; ++i)
    bar[i] = i < filled ? '#' : '.';
  bar[30] = 0;
  std::fprintf(stderr, "%s%s [%s] %3d%%  %zu/%zu  %.1fs elapsed, ETA %.1fs%s", m_tty ? "\r" : "", m_label.c_str(), bar,
               static_cast<int>(frac * 100), m_done, m_total, elapsed, eta, m_tty ? (force ? "\n" : "") : "\n");
  std::fflush(stderr);
}

} // namespace pm::app
