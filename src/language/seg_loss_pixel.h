#pragma once
// One pixel of the one-pass language loss (language_loss.h, paper 3.3), shared by the CPU loop
// (language_loss.cpp) and the CUDA kernel (seg_loss_cuda.cu), and the arguments of both passes. The tests
// check both against the dense reference (language_loss).
#include <cmath>
#include <cstdint>

#include "core/host_device.h"

namespace cls {

struct SegLossWeights {
  double lambda_sam = 1.0, lambda_citygml = 0.5;
  bool baseline = false;  // LangSplat's objective: every SAM-valid pixel with weight 1, no CityGML term
  double inv = 1.0;       // 1 / (H W L): every term's common denominator
};

// Whether a pixel's SAM segment s and CityGML region g (-1 = none) lie in their tables of ks and kg rows.
CLS_HD bool ids_in_tables(int s, int g, int64_t ks, int64_t kg) { return s >= -1 && s < ks && g >= -1 && g < kg; }

// The weight of sign(Z^ - Z_SAM) at a pixel with coverage m and SAM segment s (-1 = none).
CLS_HD float sam_weight(const SegLossWeights& w, int s, float m) {
  return s < 0 ? 0.f : float((w.baseline ? 1.0 : (1 - m) + w.lambda_sam * m) * w.inv);
}

// The weight of sign(Z^ - Z_GML) at a pixel with coverage m and CityGML region g (-1 = none).
CLS_HD float citygml_weight(const SegLossWeights& w, int g, float m) {
  return g < 0 ? 0.f : float(w.lambda_citygml * m * w.inv);
}

// One channel of an L1 term: adds |z - t| to `abs` and returns w sgn(z - t) (torch's abs backward:
// sgn(0) = 0).
CLS_HD float l1_channel(float z, float t, float w, float& abs) {
  const float d = z - t;
  abs += fabsf(d);
  return w * (float(d > 0) - float(d < 0));
}

// The unweighted terms summed over pixels: L_SAM (outside coverage), L_SAM-GML and L_CityGML (inside),
// from a pixel's summed |Z^ - Z_SAM| and |Z^ - Z_GML|; times `inv` they are the terms of language_loss().
struct SegLossSums {
  double sam = 0, sam_gml = 0, citygml = 0;
};

CLS_HD void add_pixel(SegLossSums& sums, float m, float abs_sam, float abs_gml) {
  sums.sam += (1 - m) * abs_sam;
  sums.sam_gml += m * abs_sam;
  sums.citygml += m * abs_gml;
}

// One pass over a view's pixels (host pointers for the CPU pass, device pointers for the CUDA one).
struct SegLossArgs {
  const float* rendered = nullptr;   // Z^: n x l
  const int32_t* sam_ids = nullptr;  // n, -1 = no segment; null = no pixel has one
  const float* sam_table = nullptr;  // ks x l
  int64_t ks = 0;
  const int32_t* gml_ids = nullptr;  // n, -1 = no region; null = none (the baseline passes null)
  const float* gml_table = nullptr;  // kg x l
  int64_t kg = 0;
  const float* coverage = nullptr;  // n, 0/1
  int64_t n = 0;
  int l = 0;
  SegLossWeights weights;
  float* grad = nullptr;  // n x l: dL/dZ^ (left unwritten at pixels whose ids lie outside their tables)
};

}  // namespace cls
