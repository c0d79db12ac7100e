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
                            cv::Size(static_cast<int>(width), static_cast<int>(height / 2))))
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
  vpImage<vpRGBa> left = report::drawPointScores(loop.images().left, loop.tracker().fitness().pointScores(used, 0), label.str());
  vpImage<vpRGBa> right = report::drawPointScores(loop.images().right, loop.tracker().fitness().pointScores(used, 1), "right");
  if (const precise::PreciseStage *stage = loop.tracker().preciseStage(); stage && f.track.precise) {
    report::drawCorrespondenceLines(left, stage->lines(0)); // the lines of the frame's pose: cyan kept, magenta hidden
    report::drawCorrespondenceLines(right, stage->lines(1));
  }
  const vpImage<vpRGBa> pair = report::sideBySide(left, right);
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
