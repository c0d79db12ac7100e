#pragma once
/*!
  \file Tracker.h
  The photo-model tracker for Python: pm::tracker::PhotoModelTracker fed with NumPy images. It keeps
  the two views of RGBA arrays and the two buffers BGR arrays are converted into, so that a frame
  allocates nothing once the size is known; track() runs with the GIL released.

      tracker = visp_photomodel.Tracker(rig, model)
      result = tracker.track(left, right)   # H x W x 3 BGR (OpenCV) or H x W x 4 RGBA (ViSP), uint8
      if result.trusted: use(result.pose)   # 4 x 4, metres, the model in the hand frame
*/
#include <array>
#include <string>

#include <pybind11/numpy.h>

#include "pm/tracker/PhotoModelTracker.h"

namespace pmpy {

//! The tracker of the Python module (see the file's description).
class Tracker
{
public:
  /*!
    \e config: a tracker configuration file (empty: the defaults every program uses); \e keys: some
    of its keys as JSON text, over the file's (empty: none); \e seed and \e budgetEvaluations (when
    not negative) replace RM-GA's seed and the frame's evaluation budget. Throws pm::core::Error as
    PhotoModelTracker, loadTrackerConfig() and trackerParamsFromJson() do.
  */
  Tracker(const pm::core::CameraRig &rig, const pm::core::PhotoModel &model, const std::string &config, const std::string &keys,
          long seed, long budgetEvaluations);

  //! One frame: one image per camera as NumPy arrays (checked; see Arrays.h), the GIL released while it runs.
  pm::tracker::TrackResult track(const std::vector<pybind11::array> &images);
  //! A stereo rig's frame: track({left, right}).
  pm::tracker::TrackResult track(const pybind11::array &left, const pybind11::array &right) { return track(std::vector<pybind11::array>{left, right}); }
  //! The pixels the last track() read, camera by camera (the RGBA arrays' own buffers, or the BGR arrays' conversions).
  std::vector<const void *> pixelsRead() const { return std::vector<const void *>(m_read.begin(), m_read.begin() + static_cast<std::ptrdiff_t>(m_count)); }
  pm::tracker::PhotoModelTracker &tracker() { return m_tracker; }
  const pm::tracker::PhotoModelTracker &tracker() const { return m_tracker; }

private:
  pm::tracker::PhotoModelTracker m_tracker;
  static constexpr std::size_t kMax = pm::core::CameraRig::kMaxCameras;
  vpImage<vpRGBa> m_view[kMax];      //!< an RGBA array's own buffer, seen as an image
  vpImage<vpRGBa> m_converted[kMax]; //!< a BGR array, converted once per frame
  std::array<const void *, kMax> m_read{}; //!< pixelsRead()
  std::size_t m_count = 0;           //!< the images of the last track()
};

} // namespace pmpy
