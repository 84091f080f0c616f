#pragma once
// LangSplat's fork of SAM's SamAutomaticMaskGenerator.generate: one pass of the point grid over
// every crop that yields four lists (default = all three multimask outputs, s / m / l = output
// 0 / 1 / 2), each filtered, NMS'ed within and across crops and cleaned of small regions.
// The model is behind AmgModel, so this file needs no LibTorch and can be tested with a stub.
#include <cstdint>
#include <vector>

#include "models/sam_amg/amg_geometry.h"
#include "models/sam_amg/mask_record.h"

namespace cls::amg {

struct AmgParams {
  int points_per_side = 32;
  int points_per_batch = 64;
  double pred_iou_thresh = 0.7;          // LangSplat (SAM's default is 0.88)
  double stability_score_thresh = 0.85;  // LangSplat (SAM's default is 0.95)
  double stability_score_offset = 1.0;
  double box_nms_thresh = 0.7;
  int crop_n_layers = 1;                 // LangSplat (SAM's default is 0)
  double crop_nms_thresh = 0.7;
  double crop_overlap_ratio = 512.0 / 1500.0;
  int crop_n_points_downscale_factor = 1;
  int64_t min_mask_region_area = 100;    // LangSplat (SAM's default is 0)
  float mask_threshold = 0.0f;           // Sam.mask_threshold
};

// What the generator needs from SAM (SamPredictor). Prediction and upsampling are split so that
// only masks that pass the predicted-IoU filter (which needs no mask) are upsampled to the crop
// size: that upsampling (Sam.postprocess_masks) is most of the AMG's time otherwise.
class AmgModel {
 public:
  virtual ~AmgModel() = default;
  // set_image on an RGB crop, HWC uint8, contiguous.
  virtual void set_image(const uint8_t* rgb, int height, int width) = 0;
  // The side of the model's square input (image_encoder.img_size, 1024 for the official models): the
  // generator scales its points to it (SamPredictor.transform = sam::ResizeLongestSide(img_size)).
  virtual int input_size() const = 0;
  // predict_torch(points[:, None, :], labels = 1, multimask_output=True, return_logits=True) for the
  // image last set: `points_input` are already transformed to the model's input frame (float64, as
  // the AMG passes NumPy points). Fills iou_predictions [B, 3], float32, and keeps the low-res
  // mask logits of this batch for upsample_masks.
  virtual void predict_points(const std::vector<Point2d>& points_input, std::vector<float>& iou_predictions) = 0;
  // The mask logits of the last predict_points at the crop size (postprocess_masks) for the masks
  // `indices` into the flattened [B * 3] outputs: fills mask_logits [indices.size(), h, w], float32.
  virtual void upsample_masks(const std::vector<int64_t>& indices, std::vector<float>& mask_logits) = 0;
};

// `rgb`: HWC uint8 image, contiguous. threads <= 0: OpenMP's default (for the per-mask work).
MaskLevels generate_masks(AmgModel& model, const uint8_t* rgb, int height, int width, const AmgParams& params,
                          int threads = 0);

// The stages of generate(), exposed for tests.
struct AmgCandidate {  // one mask of MaskData between the stages
  MaskRle rle;         // image size
  BoxXyxy box;         // crop frame inside a crop, image frame after uncropping
  float predicted_iou = 0.0f;
  float stability_score = 0.0f;
  Point2d point{};     // crop frame inside a crop, image frame after uncropping
  CropBox crop;
};
// postprocess_small_regions: holes then islands per mask, NMS preferring unchanged masks.
std::vector<AmgCandidate> postprocess_small_regions(std::vector<AmgCandidate> data, int64_t min_area,
                                                    double nms_thresh, int threads = 0);
MaskRecord to_record(const AmgCandidate& c);

}  // namespace cls::amg
