#include "models/sam_amg/mask_nms.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace cls::amg {

namespace {

// torch.max(dim) propagates NaN.
inline float nan_max(float a, float b) {
  if (std::isnan(a)) return a;
  if (std::isnan(b)) return b;
  return b > a ? b : a;
}

void check_inputs(size_t n_masks, size_t n_scores) {
  if (n_masks != n_scores) throw Error("mask_nms: masks and scores differ in length");
}

// The top-3 fallback of mask_nms (see the header): indices into the sorted order.
void keep_top3_if_none(std::vector<char>& keep) {
  if (std::find(keep.begin(), keep.end(), 1) != keep.end()) return;
  for (size_t i = 0; i < keep.size() && i < 3; ++i) keep[i] = 1;
}

}  // namespace

std::vector<int> score_order(const std::vector<double>& scores) {
  std::vector<int> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return scores[a] > scores[b]; });
  return order;
}

std::vector<int> select_kept(const std::vector<int>& order, const std::vector<double>& sorted_scores,
                             const std::vector<float>& iou_max, const std::vector<float>& inner_u,
                             const std::vector<float>& inner_l, const MaskNmsParams& p) {
  const size_t n = order.size();
  // Comparisons of float32 tensors with Python floats happen in float32; the scores are float64.
  const float iou_thr = static_cast<float>(p.iou_thr);
  const float inner_limit = static_cast<float>(1.0 - p.inner_thr);
  std::vector<char> keep(n), conf(n), ku(n), kl(n);
  for (size_t k = 0; k < n; ++k) {
    keep[k] = iou_max[k] <= iou_thr;
    conf[k] = sorted_scores[k] > p.score_thr;
    ku[k] = inner_u[k] <= inner_limit;
    kl[k] = inner_l[k] <= inner_limit;
  }
  keep_top3_if_none(conf);
  keep_top3_if_none(ku);
  keep_top3_if_none(kl);
  std::vector<int> selected;
  for (size_t k = 0; k < n; ++k)
    if (keep[k] && conf[k] && ku[k] && kl[k]) selected.push_back(order[k]);
  return selected;
}

// ---- reference: preprocess.py mask_nms, literally ----------------------------------------------

std::vector<int> mask_nms_reference(const std::vector<BinaryMask>& masks, const std::vector<double>& scores,
                                    const MaskNmsParams& params) {
  check_inputs(masks.size(), scores.size());
  const int n = static_cast<int>(masks.size());
  const std::vector<int> idx = score_order(scores);
  std::vector<double> sorted_scores(n);
  for (int k = 0; k < n; ++k) sorted_scores[k] = scores[idx[k]];
  std::vector<float> area(n);
  for (int k = 0; k < n; ++k) area[k] = static_cast<float>(masks[idx[k]].area());

  std::vector<float> iou(static_cast<size_t>(n) * n, 0.0f), inner(static_cast<size_t>(n) * n, 0.0f);
  auto at = [n](std::vector<float>& m, int i, int j) -> float& { return m[static_cast<size_t>(i) * n + j]; };
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      const BinaryMask& a = masks[idx[i]];
      const BinaryMask& b = masks[idx[j]];
      if (a.height != b.height || a.width != b.width) throw Error("mask_nms: masks differ in size");
      int64_t inter = 0, uni = 0;
      for (size_t p = 0; p < a.pixels.size(); ++p) {
        inter += (a.pixels[p] && b.pixels[p]);
        uni += (a.pixels[p] || b.pixels[p]);
      }
      const float fi = static_cast<float>(inter), fu = static_cast<float>(uni);
      at(iou, i, j) = fi / fu;
      const float ri = fi / area[i], rj = fi / area[j];
      if (ri < 0.5f && rj >= 0.85f) at(inner, i, j) = 1.0f - rj * ri;
      if (ri >= 0.85f && rj < 0.5f) at(inner, j, i) = 1.0f - rj * ri;
    }
  // iou.triu_(1).max(0); triu(inner, 1).max(0); tril(inner, 1).max(0).
  std::vector<float> iou_max(n, 0.0f), inner_u(n, 0.0f), inner_l(n, 0.0f);
  for (int c = 0; c < n; ++c) {
    float mi = -INFINITY, mu = -INFINITY, ml = -INFINITY;
    for (int r = 0; r < n; ++r) {
      mi = nan_max(mi, r < c ? at(iou, r, c) : 0.0f);
      mu = nan_max(mu, r < c ? at(inner, r, c) : 0.0f);
      ml = nan_max(ml, r >= c - 1 ? at(inner, r, c) : 0.0f);
    }
    iou_max[c] = mi, inner_u[c] = mu, inner_l[c] = ml;
  }
  return select_kept(idx, sorted_scores, iou_max, inner_u, inner_l, params);
}

// ---- fast: packed masks, bounding-range popcounts, threads -------------------------------------

namespace {
void finish_ranges(PackedMask& m) {
  m.row_begin = m.height, m.row_end = 0, m.word_begin = m.words_per_row, m.word_end = 0;
  m.area = 0;
  for (int y = 0; y < m.height; ++y)
    for (int w = 0; w < m.words_per_row; ++w) {
      const uint64_t word = m.bits[static_cast<size_t>(y) * m.words_per_row + w];
      if (!word) continue;
      m.area += __builtin_popcountll(word);
      m.row_begin = std::min(m.row_begin, y);
      m.row_end = y + 1;
      m.word_begin = std::min(m.word_begin, w);
      m.word_end = std::max(m.word_end, w + 1);
    }
  if (m.area == 0) m.row_begin = m.row_end = m.word_begin = m.word_end = 0;
}
}  // namespace

PackedMask pack_mask(const BinaryMask& mask) {
  PackedMask m;
  m.height = mask.height, m.width = mask.width, m.words_per_row = (mask.width + 63) / 64;
  m.bits.assign(static_cast<size_t>(m.height) * m.words_per_row, 0);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (mask.at(y, x)) m.bits[static_cast<size_t>(y) * m.words_per_row + x / 64] |= uint64_t(1) << (x % 64);
  finish_ranges(m);
  return m;
}

PackedMask pack_mask(const MaskRle& rle) {
  PackedMask m;
  m.height = rle.height, m.width = rle.width, m.words_per_row = (rle.width + 63) / 64;
  m.bits.assign(static_cast<size_t>(m.height) * m.words_per_row, 0);
  const uint64_t total = static_cast<uint64_t>(rle.height) * rle.width;
  uint64_t pos = 0;
  for (size_t i = 0; i < rle.counts.size(); ++i) {
    const uint64_t end = pos + rle.counts[i];
    if (end > total) throw Error("RLE: counts exceed the mask size");
    if (i % 2 == 1)
      for (uint64_t p = pos; p < end; ++p) {
        const uint64_t x = p / rle.height, y = p % rle.height;
        m.bits[y * m.words_per_row + x / 64] |= uint64_t(1) << (x % 64);
      }
    pos = end;
  }
  finish_ranges(m);
  return m;
}

int64_t intersection_area(const PackedMask& a, const PackedMask& b) {
  const int r0 = std::max(a.row_begin, b.row_begin), r1 = std::min(a.row_end, b.row_end);
  const int w0 = std::max(a.word_begin, b.word_begin), w1 = std::min(a.word_end, b.word_end);
  int64_t n = 0;
  for (int y = r0; y < r1; ++y) {
    const uint64_t* pa = a.bits.data() + static_cast<size_t>(y) * a.words_per_row;
    const uint64_t* pb = b.bits.data() + static_cast<size_t>(y) * b.words_per_row;
    for (int w = w0; w < w1; ++w) n += __builtin_popcountll(pa[w] & pb[w]);
  }
  return n;
}

std::vector<int> mask_nms_fast(const std::vector<PackedMask>& masks, const std::vector<double>& scores,
                               const MaskNmsParams& params, int threads) {
  check_inputs(masks.size(), scores.size());
  const int n = static_cast<int>(masks.size());
  for (const auto& m : masks)
    if (m.height != masks[0].height || m.width != masks[0].width) throw Error("mask_nms: masks differ in size");
  const std::vector<int> idx = score_order(scores);
  std::vector<double> sorted_scores(n);
  std::vector<const PackedMask*> ms(n);
  for (int k = 0; k < n; ++k) sorted_scores[k] = scores[idx[k]], ms[k] = &masks[idx[k]];

  // Column maxima start at 0: the zeroed triangles of the reference's matrices take part in max.
  std::vector<float> iou_max(n, 0.0f), inner_u(n, 0.0f), inner_l(n, 0.0f);
  const int n_threads = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel num_threads(n_threads)
  {
    std::vector<float> t_iou(n, 0.0f), t_u(n, 0.0f), t_l(n, 0.0f);
#pragma omp for schedule(dynamic, 4) nowait
    for (int i = 0; i < n; ++i) {
      const PackedMask& a = *ms[i];
      const float area_i = static_cast<float>(a.area);
      for (int j = i + 1; j < n; ++j) {
        const PackedMask& b = *ms[j];
        if (a.area == 0 && b.area == 0) {  // 0/0: NaN IoU, as torch computes it
          t_iou[j] = NAN;
          continue;
        }
        // Disjoint bounding ranges: I = 0, IoU 0 and no containment, nothing to record.
        if (a.row_end <= b.row_begin || b.row_end <= a.row_begin || a.word_end <= b.word_begin ||
            b.word_end <= a.word_begin)
          continue;
        const int64_t inter = intersection_area(a, b);
        if (inter == 0) continue;
        const float fi = static_cast<float>(inter);
        const float fu = static_cast<float>(a.area + b.area - inter);
        t_iou[j] = nan_max(t_iou[j], fi / fu);
        const float ri = fi / area_i, rj = fi / static_cast<float>(b.area);
        if (ri < 0.5f && rj >= 0.85f) {  // j (later) lies inside i: inner[i, j]
          const float v = 1.0f - rj * ri;
          t_u[j] = std::max(t_u[j], v);
          if (i == j - 1) t_l[j] = std::max(t_l[j], v);  // tril(diagonal=1) includes it
        }
        if (ri >= 0.85f && rj < 0.5f) t_l[i] = std::max(t_l[i], 1.0f - rj * ri);  // inner[j, i]
      }
    }
#pragma omp critical
    for (int k = 0; k < n; ++k) {
      iou_max[k] = nan_max(iou_max[k], t_iou[k]);
      inner_u[k] = std::max(inner_u[k], t_u[k]);
      inner_l[k] = std::max(inner_l[k], t_l[k]);
    }
  }
  return select_kept(idx, sorted_scores, iou_max, inner_u, inner_l, params);
}

}  // namespace cls::amg
