#pragma once
// Region crops for CLIP as LangSplat's preprocess.py makes them from SAM masks:
//   get_seg_img: zero the pixels outside the mask, crop to the mask's SAM box (XYWH);
//   pad_img: centre the crop in a black square of side max(w, h) (offset (side - w) // 2);
//   cv2.resize(..., (224, 224)) (bilinear), then /255 and CLIP's mean/std (clip_pixels.h).
// SAM's box (batched_mask_to_box + box_xyxy_to_xywh) has w = max_x - min_x, so the crop
// image[y:y+h, x:x+w] leaves out the mask's last column and row: a LangSplat quirk kept here.
#include <opencv2/core.hpp>

#include <vector>

namespace cls::clip {

struct MaskBox {
  int x = 0, y = 0, w = 0, h = 0;  // SAM XYWH
};

// The SAM box of a mask (CV_8U, nonzero = inside); an empty mask gives {0, 0, 0, 0}.
MaskBox sam_mask_box(const cv::Mat& mask);

// get_seg_img + pad_img + cv2.resize for one mask of an RGB (CV_8UC3) image: a CV_8UC3
// out_size x out_size crop. A box with no pixels (empty mask, or a one-pixel-wide box) gives a
// black image (LangSplat's cv2.resize would fail on the fully empty case).
cv::Mat langsplat_region_crop(const cv::Mat& rgb, const cv::Mat& mask, const MaskBox& box, int out_size = 224);
cv::Mat langsplat_region_crop(const cv::Mat& rgb, const cv::Mat& mask, int out_size = 224);

}  // namespace cls::clip
