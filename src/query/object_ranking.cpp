#include "query/object_ranking.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace cls {
using nlohmann::json;

std::vector<ObjectScore> rank_objects(const CityObjects& objects, const int32_t* object_of, const float* scores,
                                      const float* means, int64_t n, const ObjectRankingOptions& o) {
  if (o.level < 1 || o.level > 3) throw UsageError("object ranking: level must be 1, 2 or 3");
  const size_t count = objects.objects.size();
  // The answering object of every finest object, looked up once.
  std::vector<int32_t> answer(count);
  for (size_t k = 0; k < count; ++k) answer[k] = objects.at_level(static_cast<int32_t>(k), o.level);

  std::vector<ObjectScore> acc(count);
  std::vector<double> sum(count, 0.0);
  for (int64_t i = 0; i < n; ++i) {
    const int32_t f = object_of[i];
    if (f < 0 || static_cast<size_t>(f) >= count) continue;
    const int32_t a = answer[f];
    if (a < 0) continue;
    ObjectScore& s = acc[a];
    const double score = scores[i];
    s.max_score = s.gaussians == 0 ? score : std::max(s.max_score, score);
    ++s.gaussians;
    sum[a] += score;
    s.above += score >= o.threshold;
    for (int d = 0; d < 3; ++d) s.center[d] += means[3 * i + d];
  }
  std::vector<ObjectScore> ranked;
  for (size_t k = 0; k < count; ++k) {
    ObjectScore& s = acc[k];
    if (s.gaussians < std::max<int64_t>(o.min_gaussians, 1)) continue;
    s.object = static_cast<int32_t>(k);
    s.mean_score = sum[k] / s.gaussians;
    s.above /= s.gaussians;
    for (double& c : s.center) c /= s.gaussians;
    ranked.push_back(s);
  }
  // The radius needs the centres: a second pass over the Gaussians of ranked objects.
  std::vector<int32_t> slot(count, -1);
  for (size_t r = 0; r < ranked.size(); ++r) slot[ranked[r].object] = static_cast<int32_t>(r);
  for (int64_t i = 0; i < n; ++i) {
    const int32_t f = object_of[i];
    if (f < 0 || static_cast<size_t>(f) >= count || answer[f] < 0 || slot[answer[f]] < 0) continue;
    ObjectScore& s = ranked[slot[answer[f]]];
    const double dx = means[3 * i] - s.center[0], dy = means[3 * i + 1] - s.center[1], dz = means[3 * i + 2] - s.center[2];
    s.radius = std::max(s.radius, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  std::sort(ranked.begin(), ranked.end(), [](const ObjectScore& a, const ObjectScore& b) {
    return a.mean_score != b.mean_score ? a.mean_score > b.mean_score : a.object < b.object;
  });
  return ranked;
}

namespace {

std::string id_of(const CityObjects& objects, int32_t k) { return k >= 0 ? objects.objects[k].id : ""; }

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

json object_ranking_json(const CityObjects& objects, const std::vector<ObjectScore>& ranking, size_t top) {
  json rows = json::array();
  for (size_t r = 0; r < ranking.size() && (top == 0 || r < top); ++r) {
    const ObjectScore& s = ranking[r];
    rows.push_back({{"rank", r + 1},
                    {"index", s.object},
                    {"id", id_of(objects, s.object)},
                    {"class", objects.class_name(s.object)},
                    {"level", objects.objects[s.object].level},
                    {"building", id_of(objects, objects.at_level(s.object, 3))},
                    {"part", id_of(objects, objects.part_of(s.object))},
                    {"gaussians", s.gaussians},
                    {"mean_score", s.mean_score},
                    {"max_score", s.max_score},
                    {"above", s.above},
                    {"center", s.center},
                    {"radius", s.radius}});
  }
  return rows;
}

std::string object_ranking_csv(const CityObjects& objects, const std::vector<ObjectScore>& ranking) {
  std::ostringstream out;
  out.precision(6);
  out << "rank,id,class,level,building,part,gaussians,mean_score,max_score,above_threshold\n";
  for (size_t r = 0; r < ranking.size(); ++r) {
    const ObjectScore& s = ranking[r];
    out << r + 1 << ',' << csv_field(id_of(objects, s.object)) << ',' << csv_field(objects.class_name(s.object)) << ','
        << objects.objects[s.object].level << ',' << csv_field(id_of(objects, objects.at_level(s.object, 3))) << ','
        << csv_field(id_of(objects, objects.part_of(s.object))) << ',' << s.gaussians << ',' << s.mean_score << ',' << s.max_score << ',' << s.above << '\n';
  }
  return out.str();
}

}  // namespace cls
