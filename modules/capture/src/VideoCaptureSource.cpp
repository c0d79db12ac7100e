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
    : VideoCaptureSource(std::vector<std::string>{left, right}, params)
{
}

VideoCaptureSource::VideoCaptureSource(const std::vector<std::string> &sources, const VideoCaptureParams &params) : m_params(params)
{
  params.validate();
  if (sources.empty() || sources.size() > SourceStats::kMaxStreams)
    throw core::Error("video capture: " + std::to_string(sources.size()) + " sources; one per camera, one to four");
  m_stats.streams = sources.size();
  for (std::size_t k = 0; k < sources.size(); ++k) {
    m_s.push_back(std::make_unique<Stream>());
    Stream &s = *m_s.back();
    s.spec = sources[k];
    s.side = sources.size() == 2 ? (k ? "right" : "left") : sources.size() == 1 ? "camera's" : "camera " + std::to_string(k) + "'s";
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

namespace {

//! \e m (BGR, BGRA or grey) into \e dst as RGBa.
void toRGBa(const cv::Mat &m, vpImage<vpRGBa> &dst)
{
  cv::Mat rgba;
  if (m.channels() == 1)
    cv::cvtColor(m, rgba, cv::COLOR_GRAY2RGBA);
  else if (m.channels() == 4)
    cv::cvtColor(m, rgba, cv::COLOR_BGRA2RGBA);
  else
    cv::cvtColor(m, rgba, cv::COLOR_BGR2RGBA);
  dst.resize(static_cast<unsigned>(rgba.rows), static_cast<unsigned>(rgba.cols));
  for (int r = 0; r < rgba.rows; ++r)
    std::memcpy(static_cast<void *>(dst[r]), rgba.ptr(r), static_cast<std::size_t>(rgba.cols) * 4);
}

} // namespace

bool VideoCaptureSource::holdTogether()
{
  for (;;) {
    std::size_t oldest = 0, newest = 0;
    for (std::size_t k = 0; k < m_s.size(); ++k) {
      Stream &s = *m_s[k];
      if (s.ended)
        return false;
      if (!s.held && !s.read(m_params, m_stats, static_cast<int>(k)))
        return false;
      if (s.t < m_s[oldest]->t)
        oldest = k;
      if (s.t > m_s[newest]->t)
        newest = k;
    }
    if (m_s[newest]->t - m_s[oldest]->t <= m_params.maxSkewMs)
      return true;
    m_s[oldest]->held = false; // drop the oldest frame: its partners have gone by
    ++m_stats.unpaired[oldest];
  }
}

bool VideoCaptureSource::next(StereoFrame &f) { return pairThroughFrame(f); }

bool VideoCaptureSource::nextFrame(CameraFrame &f)
{
  if (m_params.maxPairs > 0 && m_stats.pairs >= m_params.maxPairs)
    return false;
  if (!holdTogether())
    return false;
  const Stream &first = *m_s[0];
  for (std::size_t k = 1; k < m_s.size(); ++k)
    if (m_s[k]->frame.size() != first.frame.size()) {
      std::ostringstream os;
      if (m_s.size() == 2)
        os << "the two streams differ in size: left '" << first.spec << "' is " << first.frame.cols << "x" << first.frame.rows
           << ", right '" << m_s[1]->spec << "' is " << m_s[1]->frame.cols << "x" << m_s[1]->frame.rows;
      else
        os << "the streams differ in size: '" << first.spec << "' is " << first.frame.cols << "x" << first.frame.rows << ", '"
           << m_s[k]->spec << "' is " << m_s[k]->frame.cols << "x" << m_s[k]->frame.rows;
      throw core::Error(os.str());
    }
  f.images.resize(m_s.size());
  double lo = first.t, hi = first.t;
  for (std::size_t k = 0; k < m_s.size(); ++k) {
    toRGBa(m_s[k]->frame, f.images[k]);
    m_s[k]->held = false;
    lo = std::min(lo, m_s[k]->t);
    hi = std::max(hi, m_s[k]->t);
  }
  if (m_t0 < 0)
    m_t0 = first.t;
  f.index = m_stats.pairs;
  f.timeS = (first.t - m_t0) * 1e-3;
  f.skewMs = m_s.size() == 2 ? first.t - m_s[1]->t : hi - lo;
  m_stats.maxSkewMs = std::max(m_stats.maxSkewMs, std::fabs(f.skewMs));
  ++m_stats.pairs;
  return true;
}

std::string VideoCaptureSource::describe() const
{
  std::string d = m_s.size() == 1 ? "video source " : "video sources ";
  for (std::size_t k = 0; k < m_s.size(); ++k)
    d += (k ? " + " : "") + m_s[k]->spec;
  return d;
}

} // namespace pm::capture
