#pragma once
// `citylangsplat enrich`: the run's city model as CityJSON 2.0 with what the run learned of every
// CityObject and semantic surface (issue 35 §2, docs/export.md): city_observations.h's counts, the mean
// scores of each object's Gaussians for the classes of its level and for given text queries. The
// attributes follow our CityJSON Extension (data/schemas/citylangsplat.ext.json, written beside the
// output); the geometry is the city model's own polygons (cityjson_writer.h), unchanged.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/opening_proposals.h"

namespace cls {

struct EnrichOptions {
  std::string run;                        // a `run` output directory
  std::string out;                        // "" = RUN/enriched.city.json
  std::string method = "citylangsplat";   // whose language model scores the objects
  std::vector<std::string> queries;       // texts whose mean scores each object gets
  std::string city;                       // the city model; "" = the one run.json names
  int64_t sample_points = 200000;         // points spread over the city model for the covered fraction
  // `changes`: also what the model lacks (opening_proposals.h) and what the photos contradict, added to
  // the document as proposed Window/Door surfaces and listed in changes.json beside it.
  bool changes = false;
  ProposalSettings proposals;
  double contradiction_density = 0.1;     // a seen surface with fewer Gaussians per m2 than this share of the median
  double contradiction_seen_area = 1.0;   // m2: surfaces seen less than this are not judged
};

// The name of the Extension file written beside the output (the document's "extensions" url).
inline constexpr const char* kCityJsonExtensionFile = "citylangsplat.ext.json";

// Writes OUT and the Extension beside it (atomically, after every input was read and checked), with
// `changes` also changes.json beside OUT; returns a summary {"file", "objects", "surfaces", "queries",
// "proposals", "contradicted"}. cls::UsageError for bad options, cls::Error
// naming the file for unreadable or mismatched inputs (a city model other than the run's).
nlohmann::json run_enrich(const EnrichOptions& options);

}  // namespace cls
