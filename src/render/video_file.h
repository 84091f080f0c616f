#pragma once
// An MP4 written frame by frame with OpenCV's VideoWriter (FFmpeg backend), into a temporary file that
// finish() renames into place, so a reader never sees half a video.
#include <filesystem>
#include <string>

#include <opencv2/core/mat.hpp>
#include <opencv2/videoio.hpp>

namespace cls {

class VideoFile {
 public:
  // H.264 ("avc1", what browsers play) where the FFmpeg build can encode it, else MPEG-4 part 2
  // ("mp4v"). Both sides of `size` must be even (4:2:0 chroma). cls::Error naming `path` if neither opens.
  VideoFile(std::filesystem::path path, double fps, cv::Size size);
  ~VideoFile();  // removes the temporary if finish() was not reached
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;

  void write(const cv::Mat& bgr);  // 8-bit BGR of the size given; cls::Error otherwise
  void finish();                   // closes the file and renames it into place
  const std::string& codec() const { return codec_; }

 private:
  std::filesystem::path path_, tmp_;
  cv::Size size_;
  cv::VideoWriter writer_;
  std::string codec_;
  bool finished_ = false;
};

}  // namespace cls
