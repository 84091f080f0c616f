#include "models/sam_amg/automatic_mask_generator.h"

#include <omp.h>

#include <algorithm>

#include "core/error.h"
#include "core/log.h"
#include "models/sam/resize_longest_side.h"
#include "models/sam_amg/box_nms.h"
#include "models/sam_amg/small_regions.h"

namespace cls::amg {

namespace {

int thread_count(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

BoxF to_float(const BoxXyxy& b) {
  return {static_cast<float>(b.x0), static_cast<float>(b.y0), static_cast<float>(b.x1), static_cast<float>(b.y1)};
}

// _process_batch_data for one (point, output) mask that passed the predicted-IoU filter: the other
// filters, then the uncropped RLE. Returns false when a filter drops the mask. The filters do not
// depend on the level, so each mask is processed once and shared by `default` and its own level.
bool process_mask(const float* logits, int ch, int cw, float iou, const Point2d& point, const CropBox& crop,
                  int im_h, int im_w, const AmgParams& p, AmgCandidate& out) {
  const float stability = stability_score(logits, ch, cw, p.mask_threshold, static_cast<float>(p.stability_score_offset));
  if (p.stability_score_thresh > 0.0 && !(stability >= static_cast<float>(p.stability_score_thresh))) return false;
  BinaryMask full(im_h, im_w);  // uncrop_masks: zero padding around the crop
  for (int y = 0; y < ch; ++y) {
    const float* row = logits + static_cast<size_t>(y) * cw;
    uint8_t* dst = full.pixels.data() + static_cast<size_t>(y + crop.y0) * im_w + crop.x0;
    for (int x = 0; x < cw; ++x) dst[x] = row[x] > p.mask_threshold;
  }
  const BoxXyxy box = mask_to_box(full.pixels.data() + static_cast<size_t>(crop.y0) * im_w + crop.x0, ch, cw, im_w);
  if (is_box_near_crop_edge(box, crop, im_h, im_w)) return false;
  out.rle = mask_to_rle(full);
  out.box = box;
  out.predicted_iou = iou;
  out.stability_score = stability;
  out.point = point;
  out.crop = crop;
  return true;
}

}  // namespace

MaskRecord to_record(const AmgCandidate& c) {
  MaskRecord r;
  r.segmentation = c.rle;
  r.area = area_from_rle(c.rle);
  r.bbox = {c.box.x0, c.box.y0, c.box.x1 - c.box.x0, c.box.y1 - c.box.y0};
  r.predicted_iou = c.predicted_iou;
  r.point = c.point;
  r.stability_score = c.stability_score;
  r.crop_box = {c.crop.x0, c.crop.y0, c.crop.width(), c.crop.height()};
  return r;
}

std::vector<AmgCandidate> postprocess_small_regions(std::vector<AmgCandidate> data, int64_t min_area,
                                                    double nms_thresh, int threads) {
  if (data.empty()) return data;
  const size_t n = data.size();
  std::vector<BinaryMask> masks(n);
  std::vector<float> scores(n);
  std::vector<BoxF> boxes(n);
  std::vector<BoxXyxy> new_boxes(n);
#pragma omp parallel for num_threads(thread_count(threads)) schedule(dynamic)
  for (size_t i = 0; i < n; ++i) {
    masks[i] = rle_to_mask(data[i].rle);
    const bool holes_changed = remove_small_regions(masks[i], min_area, SmallRegionMode::Holes);
    const bool islands_changed = remove_small_regions(masks[i], min_area, SmallRegionMode::Islands);
    scores[i] = (holes_changed || islands_changed) ? 0.0f : 1.0f;  // prefer untouched masks
    new_boxes[i] = mask_to_box(masks[i]);
    boxes[i] = to_float(new_boxes[i]);
  }
  const std::vector<int> keep = box_nms(boxes, scores, nms_thresh);
  std::vector<AmgCandidate> out;
  out.reserve(keep.size());
  for (int i : keep) {
    out.push_back(std::move(data[i]));
    if (scores[i] == 0.0f) {  // only changed masks get a new RLE and box
      out.back().rle = mask_to_rle(masks[i]);
      out.back().box = new_boxes[i];
    }
  }
  return out;
}

MaskLevels generate_masks(AmgModel& model, const uint8_t* rgb, int im_h, int im_w, const AmgParams& p,
                          int threads) {
  if (im_h <= 0 || im_w <= 0) throw Error("AMG: empty image");
  if (p.points_per_batch <= 0) throw Error("AMG: points_per_batch must be positive");
  const auto grids = build_all_layer_point_grids(p.points_per_side, p.crop_n_layers, p.crop_n_points_downscale_factor);
  const auto crops = generate_crop_boxes(im_h, im_w, p.crop_n_layers, p.crop_overlap_ratio);
  const int n_threads = thread_count(threads);
  sam::ResizeLongestSide transform;  // SamPredictor.transform: to the model's input frame
  transform.target_length = model.input_size();

  std::array<std::vector<AmgCandidate>, kNumLevels> all;  // over crops
  for (const CropBox& crop : crops) {
    const int ch = crop.height(), cw = crop.width();
    std::vector<uint8_t> crop_rgb(static_cast<size_t>(ch) * cw * 3);
    for (int y = 0; y < ch; ++y)
      std::copy_n(rgb + (static_cast<size_t>(y + crop.y0) * im_w + crop.x0) * 3, static_cast<size_t>(cw) * 3,
                  crop_rgb.data() + static_cast<size_t>(y) * cw * 3);
    model.set_image(crop_rgb.data(), ch, cw);

    std::vector<Point2d> points;  // point_grids[layer] * [crop_w, crop_h], float64
    for (const Point2d& g : grids[crop.layer]) points.push_back({g[0] * cw, g[1] * ch});

    std::array<std::vector<AmgCandidate>, kNumLevels> in_crop;
    std::vector<float> logits, ious;
    for (size_t b0 = 0; b0 < points.size(); b0 += p.points_per_batch) {
      const size_t b1 = std::min(points.size(), b0 + static_cast<size_t>(p.points_per_batch));
      const std::vector<Point2d> batch(points.begin() + b0, points.begin() + b1);
      std::vector<Point2d> transformed = batch;
      transform.apply_coords(transformed.data()->data(), transformed.size(), {ch, cw});
      model.predict_points(transformed, ious);
      const size_t nb = batch.size(), plane = static_cast<size_t>(ch) * cw;
      if (ious.size() != nb * 3)
        throw Error(cat("AMG: the model returned ", ious.size(), " IoU predictions for ", nb, " points"));
      // The predicted-IoU filter comes first in _process_batch_data and is the same for every
      // level, so masks it rejects are never needed: upsample only the others.
      // Tensor-vs-Python-float comparisons happen in float32.
      std::vector<int64_t> selected;
      for (size_t m = 0; m < nb * 3; ++m)
        if (!(p.pred_iou_thresh > 0.0) || ious[m] > static_cast<float>(p.pred_iou_thresh))
          selected.push_back(static_cast<int64_t>(m));
      if (selected.empty()) continue;
      model.upsample_masks(selected, logits);
      if (logits.size() != selected.size() * plane)
        throw Error(cat("AMG: the model returned ", logits.size(), " mask logits for ", selected.size(),
                        " masks at ", ch, "x", cw));
      const size_t ns = selected.size();
      std::vector<AmgCandidate> cand(ns);
      std::vector<char> ok(ns, 0);
#pragma omp parallel for num_threads(n_threads) schedule(dynamic)
      for (size_t i = 0; i < ns; ++i) {
        const size_t m = static_cast<size_t>(selected[i]);
        ok[i] = process_mask(logits.data() + i * plane, ch, cw, ious[m], batch[m / 3], crop, im_h, im_w, p, cand[i]);
      }
      for (size_t i = 0; i < ns; ++i)  // default: point-major over the 3 outputs; s/m/l: output k
        if (ok[i]) in_crop[kDefault].push_back(cand[i]);
      for (size_t i = 0; i < ns; ++i)
        if (ok[i]) in_crop[1 + selected[i] % 3].push_back(std::move(cand[i]));
    }
    // _process_crop_data: NMS by predicted IoU within the crop, then back to the image frame.
    for (int l = 0; l < kNumLevels; ++l) {
      std::vector<BoxF> boxes;
      std::vector<float> scores;
      for (const auto& c : in_crop[l]) boxes.push_back(to_float(c.box)), scores.push_back(c.predicted_iou);
      for (int i : box_nms(boxes, scores, p.box_nms_thresh)) {
        AmgCandidate c = std::move(in_crop[l][i]);
        c.box = {c.box.x0 + crop.x0, c.box.y0 + crop.y0, c.box.x1 + crop.x0, c.box.y1 + crop.y0};
        c.point = {c.point[0] + crop.x0, c.point[1] + crop.y0};
        all[l].push_back(std::move(c));
      }
    }
  }

  MaskLevels out;
  for (int l = 0; l < kNumLevels; ++l) {
    std::vector<AmgCandidate> data = std::move(all[l]);
    if (crops.size() > 1) {  // _generate_masks_data: prefer masks from smaller crops
      std::vector<BoxF> boxes;
      std::vector<float> scores;
      for (const auto& c : data) {
        boxes.push_back(to_float(c.box));
        scores.push_back(1.0f / static_cast<float>(static_cast<int64_t>(c.crop.width()) * c.crop.height()));
      }
      const auto keep = box_nms(boxes, scores, p.crop_nms_thresh);
      std::vector<AmgCandidate> kept;
      for (int i : keep) kept.push_back(std::move(data[i]));
      data = std::move(kept);
    }
    if (p.min_mask_region_area > 0)
      data = postprocess_small_regions(std::move(data), p.min_mask_region_area,
                                       std::max(p.box_nms_thresh, p.crop_nms_thresh), n_threads);
    for (const auto& c : data) out[l].push_back(to_record(c));
  }
  return out;
}

}  // namespace cls::amg
