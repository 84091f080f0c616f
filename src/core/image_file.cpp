#include "core/image_file.h"

#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {

void write_image(const std::filesystem::path& path, const cv::Mat& image) {
  write_atomic(path, [&](const std::filesystem::path& tmp) {
    bool ok = false;
    try {
      ok = cv::imwrite(tmp.string(), image);
    } catch (const cv::Exception& e) {
      fail(path.string(), std::string("cannot write image: ") + e.what());
    }
    if (!ok) fail(path.string(), "cannot write image");
  });
}

}  // namespace cls
