#include "pm/lab/RunRecorder.h"

#include <cstdio>
#include <iomanip>
#include <sstream>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <visp3/core/vpImageConvert.h>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/report/Overlay.h"

namespace pm::lab {

struct RunRecorder::Video
{
  cv::VideoWriter writer;
};

RunRecorder::RunRecorder(const std::string &videoPath, double fps, unsigned width, unsigned height, int overlayEvery, bool oracle)
  : m_every(overlayEvery), m_oracle(oracle)
{
  if (videoPath.empty())
    return;
  m_video = std::make_unique<Video>();
  // Half size and half rate (15 fps for 30 fps cameras): a minute of servoing in ~30 MB.
  if (!m_video->writer.open(videoPath, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps / 2,
                            cv::Size(static_cast<int>(width / 2), static_cast<int>(height / 2))))
    throw core::Error("cannot write the video '" + videoPath + "' (OpenCV's MJPG writer failed)");
}

RunRecorder::~RunRecorder() = default;

void RunRecorder::record(long k, const LoopFrame &f, const ClosedLoop &loop, const std::function<std::string(const std::string &)> &place)
{
  const bool wantOverlay = m_every > 0 && k % m_every == 0;
  const bool wantVideo = m_video && k % 2 == 0;
  if (!wantVideo && !wantOverlay)
    return;
  const core::Phi used = core::fromHomogeneousMatrix(f.hMmUsed);
  std::ostringstream label;
  label << std::fixed << std::setprecision(1) << "t " << f.t << " s  " << (m_oracle ? "oracle" : toString(f.track.state))
        << "  error " << f.translationErrorMm << " mm " << f.rotationErrorDeg << " deg  visible " << std::setprecision(0)
        << 100 * f.track.visibleShare << " % (magenta: hidden)  " << (f.servoing ? "servoing" : "held: ")
        << (f.servoing ? "" : f.heldBy ? f.heldBy : "oracle");
  // Every camera's view side by side, the first with the frame's label, each with the model's points
  // at the pose used and, after the precise stage, its lines (cyan kept, magenta hidden).
  vpImage<vpRGBa> pair;
  for (std::size_t c = 0; c < loop.images().size(); ++c) {
    const int cam = static_cast<int>(c);
    vpImage<vpRGBa> view = report::drawPointScores(loop.images()[c], loop.tracker().fitness().pointScores(used, cam),
                                                   c == 0 ? label.str() : loop.rig()[c].name);
    if (const precise::PreciseStage *stage = loop.tracker().preciseStage(); stage && f.track.precise)
      report::drawCorrespondenceLines(view, stage->lines(cam));
    pair = c == 0 ? view : report::sideBySide(pair, view);
  }
  if (wantVideo) {
    cv::Mat bgra, bgr, half; // ViSP converts to BGRA; the writer takes BGR
    vpImageConvert::convert(pair, bgra);
    cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
    cv::resize(bgr, half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
    m_video->writer.write(half);
  }
  if (wantOverlay) {
    char name[64];
    std::snprintf(name, sizeof name, "overlay_%05ld.png", k);
    io::writeImage(pair, place(name));
    ++m_overlays;
  }
}

void RunRecorder::finish()
{
  if (m_video)
    m_video->writer.release();
}

} // namespace pm::lab
