#include "pm/report/LiveView.h"

#include <cstdlib>
#include <iostream>

#include <visp3/core/vpDisplay.h>
#include <visp3/core/vpException.h>
#include <visp3/gui/vpDisplayX.h>

#include "pm/report/Overlay.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"

namespace pm::report {

LiveView::LiveView() = default;
LiveView::~LiveView() = default;

bool LiveView::open(const std::string &title)
{
  m_title = title;
#ifdef VISP_HAVE_X11
  const char *d = std::getenv("DISPLAY");
  if (!d || !*d) {
    std::cerr << "no X display (DISPLAY is not set): running without the window" << std::endl;
    return false;
  }
  m_wanted = true;
  return true;
#else
  std::cerr << "this build of ViSP has no X11 display: running without the window" << std::endl;
  return false;
#endif
}

void LiveView::show(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::vector<core::PointScore> &scoresLeft,
                    const std::vector<core::PointScore> &scoresRight, const std::string &status)
{
  if (!m_wanted)
    return;
  show(core::CameraImages(left, right), {scoresLeft, scoresRight}, status);
}

void LiveView::show(const core::CameraImages &images, const std::vector<std::vector<core::PointScore>> &scores, const std::string &status)
{
  if (!m_wanted || images.size() == 0)
    return;
  std::vector<std::string> labels = cameraLabels(images.size(), "");
  labels[0] = status;
  showFrame(drawCameras(images, scores, labels));
}

void LiveView::showFrame(const vpImage<vpRGBa> &both)
{
  if (!m_display) {
#ifdef VISP_HAVE_X11
    m_frame = both;
    try {
      auto disp = std::make_unique<vpDisplayX>();
      disp->init(m_frame, 0, 0, m_title);
      m_display = std::move(disp);
    } catch (const vpException &e) {
      std::cerr << "cannot open a window on the X display (" << e.getStringMessage() << "): running without it" << std::endl;
      m_wanted = false;
      return;
    }
#endif
  }
  if (both.getWidth() != m_frame.getWidth() || both.getHeight() != m_frame.getHeight())
    return; // a frame of another size: not drawn
  m_frame = both;
  vpDisplay::display(m_frame);
  vpDisplay::flush(m_frame);
}

void LiveView::capture(const std::string &pngPath)
{
  if (!m_display)
    throw core::Error("no window to capture");
  vpImage<vpRGBa> shot;
  vpDisplay::getImage(m_frame, shot);
  io::writeImage(shot, pngPath);
}

} // namespace pm::report
