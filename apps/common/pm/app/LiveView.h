#pragma once
/*!
  \file LiveView.h
  A ViSP window (vpDisplayX) showing both views side by side with the model drawn at the
  tracker's pose, its state and the frame time. Where there is no X display (DISPLAY unset, or
  the server refuses), open() says so in one plain line on stderr and the program runs headless.

      pm::app::LiveView view;
      view.open("pm-track");       // the window appears with the first frame
      view.show(left, right, tracker.pointScores(0), tracker.pointScores(1), "tracking q 0.91, 3.2 ms");
      view.capture("screen.png");   // what the X server shows, read back from the window
*/
#include <memory>
#include <string>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include "pm/core/StereoFitness.h"

class vpDisplay;

namespace pm::app {

class LiveView
{
public:
  LiveView();
  ~LiveView();
  //! Asks for the window; false (with a message on stderr) when there is no X display to open it on.
  bool open(const std::string &title);
  bool isOpen() const { return m_display != nullptr; }
  //! Draws one frame, opening the window at the first (nothing when no window could be opened).
  void show(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::vector<PointScore> &scoresLeft,
            const std::vector<PointScore> &scoresRight, const std::string &status);
  //! Writes what the window shows, read back from the X server (vpDisplay::getImage). Throws pm::Error if not open.
  void capture(const std::string &pngPath);

private:
  std::string m_title;
  bool m_wanted = false;
  vpImage<vpRGBa> m_frame;
  std::unique_ptr<vpDisplay> m_display;
};

} // namespace pm::app
