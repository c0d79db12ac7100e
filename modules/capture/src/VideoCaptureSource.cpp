#include "pm/capture/VideoCaptureSource.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <thread>
#include <filesystem>
#include <sstream>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "pm/core/Error.h"

namespace pm::capture {

namespace {
bool allDigits(const std::string &s)
{
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}
double nowMs()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

//! One read of a live stream, done by a thread of its own so that a camera that never answers can be given up on.
struct PendingRead
{
  std::mutex mutex;
  std::condition_variable done;
  bool finished = false, ok = false;
  cv::Mat frame;
};

struct VideoCaptureSource::Stream
{
  std::string spec, side;
  std::shared_ptr<cv::VideoCapture> capture = std::make_shared<cv::VideoCapture>();
  cv::VideoCapture &cap = *capture;
  bool live = false;       //!< a camera (device index, /dev path) or a pipeline, not a file
  bool stalled = false;    //!< a read never came back: the stream cannot be used again
  bool held = false, ended = false;
  cv::Mat frame;
  double t = 0;            //!< the held frame's time (ms)
  bool useArrival = false; //!< the backend gives no timestamps
  double lastT = -1;

  //! Reads the next frame into the hold; false at the end of the stream.
  //! A live stream's read, given up after \e timeoutS (the reading thread is left to the driver, holding the capture).
  bool readLive(double timeoutS)
  {
    if (stalled)
      throw core::Error("the " + side + " source '" + spec + "' stalled earlier");
    auto pending = std::make_shared<PendingRead>();
    std::shared_ptr<cv::VideoCapture> c = capture;
    std::thread([pending, c] {
      cv::Mat f;
      bool ok = false;
      try {
        ok = c->read(f);
      } catch (...) {
        ok = false;
      }
      std::lock_guard<std::mutex> lock(pending->mutex);
      pending->ok = ok;
      pending->frame = f;
      pending->finished = true;
      pending->done.notify_one();
    }).detach();
    std::unique_lock<std::mutex> lock(pending->mutex);
    if (!pending->done.wait_for(lock, std::chrono::duration<double>(timeoutS), [&] { return pending->finished; })) {
      stalled = true;
      throw core::Error("the " + side + " source '" + spec + "' stalled: no frame for " + std::to_string(timeoutS) + " s");
    }
    frame = pending->frame;
    return pending->ok;
  }

  bool read(const VideoCaptureParams &p, SourceStats &stats, int k)
  {
    const bool ok = live ? readLive(p.stallTimeoutS) : cap.read(frame);
    if (!ok || frame.empty()) {
      ended = true;
      stats.problems.push_back("the " + side + " stream '" + spec + "' ended after " + std::to_string(stats.framesRead[k]) + " frames");
      return false;
    }
    ++stats.framesRead[k];
    double ts = cap.get(cv::CAP_PROP_POS_MSEC);
    if (!useArrival && (!std::isfinite(ts) || (stats.framesRead[k] > 1 && ts <= lastT)))
      useArrival = true; // no usable timestamps from this backend: times of arrival
    t = useArrival ? nowMs() : ts;
    lastT = ts;
    held = true;
    return true;
  }
};

void VideoCaptureParams::validate() const
{
  if (!(maxSkewMs >= 0) || !std::isfinite(maxSkewMs))
    throw core::Error("video capture: the largest skew must be a non-negative number of milliseconds");
  if (!(stallTimeoutS > 0))
    throw core::Error("video capture: the stall timeout must be positive");
}

VideoCaptureSource::VideoCaptureSource(const std::string &left, const std::string &right, const VideoCaptureParams &params)
    : m_params(params)
{
  params.validate();
  const std::string specs[2] = {left, right};
  for (int k = 0; k < 2; ++k) {
    m_s[k] = std::make_unique<Stream>();
    Stream &s = *m_s[k];
    s.spec = specs[k];
    s.side = k ? "right" : "left";
    s.live = allDigits(s.spec) || s.spec.rfind("/dev/", 0) == 0 || s.spec.find('!') != std::string::npos;
    const bool pipeline = s.spec.find('!') != std::string::npos;
    if (!allDigits(s.spec) && !pipeline && !std::filesystem::exists(s.spec))
      throw core::Error("cannot open the " + s.side + " source '" + s.spec + "': no such file or device");
    bool opened = false;
    try {
      if (allDigits(s.spec))
        opened = s.cap.open(std::stoi(s.spec), cv::CAP_ANY);
      else if (pipeline)
        opened = s.cap.open(s.spec, cv::CAP_GSTREAMER);
      else if (s.spec.rfind("/dev/", 0) == 0)
        opened = s.cap.open(s.spec, cv::CAP_V4L2);
      else // a video file: FFmpeg, else GStreamer (not every backend: some probe USB cameras for a file name)
        opened = s.cap.open(s.spec, cv::CAP_FFMPEG) || s.cap.open(s.spec, cv::CAP_GSTREAMER);
    } catch (const cv::Exception &) {
      opened = false;
    }
    if (!opened || !s.cap.isOpened())
      throw core::Error("cannot open the " + s.side + " source '" + s.spec +
                  "' (a device index such as 0, a V4L2 path such as /dev/video0, a video file, or a GStreamer pipeline "
                  "ending in appsink)");
  }
}

VideoCaptureSource::~VideoCaptureSource() = default;

bool VideoCaptureSource::next(StereoFrame &f)
{
  if (m_params.maxPairs > 0 && m_stats.pairs >= m_params.maxPairs)
    return false;
  Stream &L = *m_s[0], &R = *m_s[1];
  for (;;) {
    for (int k = 0; k < 2; ++k) {
      Stream &s = *m_s[k];
      if (s.ended)
        return false;
      if (!s.held && !s.read(m_params, m_stats, k))
        return false;
    }
    const double d = L.t - R.t;
    if (std::fabs(d) <= m_params.maxSkewMs)
      break;
    Stream &older = d < 0 ? L : R; // drop the older frame: its partner has gone by
    older.held = false;
    ++m_stats.unpaired[d < 0 ? 0 : 1];
  }
  if (L.frame.size() != R.frame.size()) {
    std::ostringstream os;
    os << "the two streams differ in size: left '" << L.spec << "' is " << L.frame.cols << "x" << L.frame.rows
       << ", right '" << R.spec << "' is " << R.frame.cols << "x" << R.frame.rows;
    throw core::Error(os.str());
  }
  vpImage<vpRGBa> *dst[2] = {&f.left, &f.right};
  for (int k = 0; k < 2; ++k) {
    const cv::Mat &m = m_s[k]->frame;
    cv::Mat rgba;
    if (m.channels() == 1)
      cv::cvtColor(m, rgba, cv::COLOR_GRAY2RGBA);
    else if (m.channels() == 4)
      cv::cvtColor(m, rgba, cv::COLOR_BGRA2RGBA);
    else
      cv::cvtColor(m, rgba, cv::COLOR_BGR2RGBA);
    dst[k]->resize(static_cast<unsigned>(rgba.rows), static_cast<unsigned>(rgba.cols));
    for (int r = 0; r < rgba.rows; ++r)
      std::memcpy(static_cast<void *>((*dst[k])[r]), rgba.ptr(r), static_cast<std::size_t>(rgba.cols) * 4);
    m_s[k]->held = false;
  }
  if (m_t0 < 0)
    m_t0 = L.t;
  f.index = m_stats.pairs;
  f.timeS = (L.t - m_t0) * 1e-3;
  f.skewMs = L.t - R.t;
  m_stats.maxSkewMs = std::max(m_stats.maxSkewMs, std::fabs(f.skewMs));
  ++m_stats.pairs;
  return true;
}

std::string VideoCaptureSource::describe() const { return "video sources " + m_s[0]->spec + " + " + m_s[1]->spec; }

} // namespace pm::capture
