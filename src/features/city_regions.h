#pragma once
// The CityGML branch's regions of one view (paper 3.1): R^{l,c} = (C^l == c and M == 1).
//  - class mode (the paper): one region per level l and class c present in the view;
//  - instance mode: one region per 8-connected component of R^{l,c} within one building
//    (building.png), i.e. per window, door, wall surface, building as seen in the view; often
//    sharper, since CLIP then sees one object per crop instead of all windows at once.
// Regions with fewer than `min_pixels` pixels are skipped: their pixels stay -1 in the seg map
// (no CityGML supervision there), since a CLIP crop of a handful of pixels carries no meaning.
// Order: level, then class id, then (instance mode) building, then component in raster order of
// its first pixel; the seg map's ids index this list.
#include <ATen/core/Tensor.h>
#include <opencv2/core.hpp>

#include <array>
#include <vector>

#include "citymodel/taxonomy.h"
#include "features/feature_provider.h"
#include "features/feature_stage.h"
#include "features/view_features.h"

namespace cls {

struct CityRegionSet {
  std::vector<RegionMask> masks;    // one per region, CV_8UC1 0/255
  std::vector<CityRegion> regions;  // the same regions' records (pixels, instance, building)
  std::vector<int32_t> seg;         // 3 x H x W region ids, -1 elsewhere
};

// labels: CV_16UC1 C^1..C^3 (0 = none, k = class k-1); coverage CV_8UC1 (nonzero = M = 1);
// building CV_16UC1 (0 = none, k = building k-1), needed in instance mode only (may be empty in
// class mode). Labels beyond the taxonomy are a cls::Error naming `what`.
CityRegionSet extract_city_regions(const std::array<cv::Mat, 3>& labels, const cv::Mat& coverage, const cv::Mat& building,
                                   RegionMode mode, const Taxonomy& taxonomy, int min_pixels, const std::string& what);

// The paper's fusion f^{gml+txt} = (1 - alpha) f^gml + alpha f^txt, then L2-normalised (the rows
// are CLIP directions; the normalisation keeps them on the unit sphere like the SAM features).
// gml: R x D; txt: R x D (the class text feature of each region's class).
at::Tensor fuse_features(const at::Tensor& gml, const at::Tensor& txt, double alpha);

}  // namespace cls
