#pragma once
/*!
  \file LiveView.h
  A ViSP window (vpDisplayX) showing both views side by side with the model's points drawn as they
  scored at the current pose (drawPointScores) and a status line (e.g. the tracker's state and the
  frame time). Where there is no X display the program runs headless, told so in one plain line on
  stderr: by open() when DISPLAY is unset (or ViSP was built without X11), by the first show() when
  the X server refuses the window. See the LiveView class for an example.
*/
#include <memory>

#include "pm/core/CameraImages.h"
#include <string>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include "pm/core/StereoFitness.h"

class vpDisplay;

namespace pm::report {

/*!
  A live window on a stereo pair: each show() draws the left and right images side by side, each
  with its model points coloured by class (drawPointScores), the status line on the left one and
  "right" on the right one. The window opens at the first show() after a successful open(), at the
  screen's top left, sized for that first frame; it closes when the LiveView is destroyed. The view
  owns the display and the frame it shows; it keeps no reference to the images it is given.
  Without an X display every call but capture() is harmless, so a program need not test for one.
  \code
  pm::core::StereoFitness fitness(rig, model);      // rig, model: pm/io/RigFile.h, pm/io/PhotoModelFile.h
  pm::report::LiveView view;
  view.open("pm-track");                      // false, said on stderr, when there is no X display
  fitness.setImages(IL, IR);                  // each new stereo pair, vpImage<vpRGBa>
  view.show(IL, IR, fitness.pointScores(phi, 0), fitness.pointScores(phi, 1), "tracking, F 0.91, 3.2 ms");
  if (view.isOpen())
    view.capture("screen.png");               // what the X server shows, read back from the window
  \endcode
*/
class LiveView
{
public:
  //! A view with no window: show() does nothing until open() succeeds.
  LiveView();
  //! Closes the window, if one was opened.
  ~LiveView();
  //! Asks for the window; false (with a message on stderr) when there is no X display to open it on.
  //! True only means DISPLAY is set: the window itself is opened by the first show(). \e title: the window's title.
  bool open(const std::string &title);
  //! True once the window is on screen (after the first show() that opened it), false before and when headless.
  bool isOpen() const { return m_display != nullptr; }
  /*!
    Draws one frame, opening the window at the first (nothing when no window could be opened).
    \e scoresLeft and \e scoresRight are the model's points in \e left and \e right (e.g.
    StereoFitness::pointScores at the current pose, camera 0 and 1); \e status is written on the
    left image. A frame whose side-by-side size differs from the first one's is not drawn.
  */
  void show(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::vector<core::PointScore> &scoresLeft,
            const std::vector<core::PointScore> &scoresRight, const std::string &status);
  /*!
    The same for a rig of any number of cameras: \e images side by side, \e scores[k] drawn on
    image k (fewer scores than images: the rest drawn bare), \e status on the first image.
  */
  void show(const core::CameraImages &images, const std::vector<std::vector<core::PointScore>> &scores, const std::string &status);
  //! Writes what the window shows, read back from the X server (vpDisplay::getImage). Throws pm::core::Error if not open.
  //! The format follows \e pngPath's extension (pm::io::writeImage, which throws pm::core::Error when it cannot write).
  void capture(const std::string &pngPath);

private:
  std::string m_title;                   //!< the window's title, given to open()
  bool m_wanted = false;                 //!< open() found a display: show() draws (false again once the window is refused)
  vpImage<vpRGBa> m_frame;               //!< the frame shown, both images side by side; the display is attached to it
  std::unique_ptr<vpDisplay> m_display;  //!< the window (a vpDisplayX), owned; null until the first show() opens it
  //! Shows \e frame (the images side by side), opening the window at the first.
  void showFrame(const vpImage<vpRGBa> &frame);
};

} // namespace pm::report
