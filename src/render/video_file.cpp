#include "render/video_file.h"

#include <unistd.h>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace fs = std::filesystem;

VideoFile::VideoFile(fs::path path, double fps, cv::Size size) : path_(std::move(path)), size_(size) {
  if (!(fps > 0)) fail(path_.string(), "the frame rate must be positive");
  if (size.width <= 0 || size.height <= 0 || size.width % 2 || size.height % 2)
    fail(path_.string(), "frame size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                             " is not a positive even size");
  fs::create_directories(path_.parent_path());
  // The extension stays .mp4: OpenCV picks the container by it.
  tmp_ = path_.parent_path() / ("." + path_.stem().string() + ".tmp" + std::to_string(::getpid()) + ".mp4");
  for (const char* codec : {"avc1", "mp4v"}) {
    const int fourcc = cv::VideoWriter::fourcc(codec[0], codec[1], codec[2], codec[3]);
    if (writer_.open(tmp_.string(), cv::CAP_FFMPEG, fourcc, fps, size_)) {
      codec_ = codec;
      break;
    }
    log_verbose(path_.string() + ": OpenCV/FFmpeg cannot encode " + codec);
  }
  if (!writer_.isOpened()) fail(path_.string(), "OpenCV's FFmpeg backend can encode neither H.264 (avc1) nor MPEG-4 (mp4v)");
}

VideoFile::~VideoFile() {
  if (finished_) return;
  writer_.release();
  std::error_code ec;
  fs::remove(tmp_, ec);
}

void VideoFile::write(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3 || bgr.size() != size_)
    fail(path_.string(), "frame of another size or type than the video's " + std::to_string(size_.width) + "x" +
                             std::to_string(size_.height) + " 8-bit BGR");
  writer_.write(bgr);
}

void VideoFile::finish() {
  writer_.release();
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) fail(path_.string(), "cannot move the video into place: " + ec.message());
  finished_ = true;
}

}  // namespace cls
