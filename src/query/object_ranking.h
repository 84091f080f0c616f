#pragma once
// The answer to a text query as city objects (issue 12): the CityGML/CityJSON objects ranked by the
// scores of the Gaussians that belong to them (provenance.h), at the query's level, as the label
// maps define the levels (level 1: openings, and surfaces without one; 2: surfaces; 3: buildings).
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "citymodel/city_objects.h"

namespace cls {

struct ObjectScore {
  int32_t object = -1;           // index into CityObjects::objects
  int64_t gaussians = 0;
  double mean_score = 0, max_score = 0;
  double above = 0;              // share of its Gaussians with score >= the threshold
  std::array<double, 3> center{};  // mean of its Gaussians' centres
  double radius = 0;             // largest distance of one of them from `center`
};

struct ObjectRankingOptions {
  int level = 1;               // 1, 2 or 3
  double threshold = 0.5;      // for `above`
  int64_t min_gaussians = 3;   // objects with fewer Gaussians are not ranked (too few to score)
};

// Objects by mean score, highest first (ties: lower index first). `object_of` (n, -1 none) holds each
// Gaussian's finest object, `scores` its score, `means` its centre (n x 3).
std::vector<ObjectScore> rank_objects(const CityObjects& objects, const int32_t* object_of, const float* scores,
                                      const float* means, int64_t n, const ObjectRankingOptions& options);

// Rows {rank, index, id, class, level, building, part ("" outside a BuildingPart), gaussians, mean_score,
// max_score, above, center, radius}; at most `top` rows (0 = all).
nlohmann::json object_ranking_json(const CityObjects& objects, const std::vector<ObjectScore>& ranking, size_t top = 0);
// The same rows as CSV with a header line (ids quoted where needed).
std::string object_ranking_csv(const CityObjects& objects, const std::vector<ObjectScore>& ranking);

}  // namespace cls
