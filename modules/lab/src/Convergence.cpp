#include "pm/lab/Convergence.h"

#include "pm/core/Error.h"

namespace pm::lab {

Convergence::Convergence(long windowFrames) : m_window(windowFrames)
{
  if (windowFrames < 1)
    throw core::Error("Convergence: the window must hold at least one frame");
}

bool Convergence::add(long frame, double t, bool within)
{
  if (converged())
    return false;
  if (!within) {
    m_run = 0;
    return false;
  }
  const bool starts = m_run == 0;
  if (starts) {
    m_runFrame = frame;
    m_runT = t;
  }
  if (++m_run >= m_window) {
    m_frame = m_runFrame;
    m_t = m_runT;
  }
  return starts;
}

void Convergence::finish()
{
  if (!converged() && m_run > 0) {
    m_frame = m_runFrame;
    m_t = m_runT;
  }
}

} // namespace pm::lab
