#pragma once
// A city model that lacks some of its openings, as a survey that missed them (synth --drop-openings):
// the chosen windows and doors are merged into the surface they sit in, so their polygons stay (the
// wall is whole) but are labelled as that surface. The images and the ground truth keep every opening;
// only what the pipeline is given loses them.
#include <cstdint>
#include <string>

namespace cls::synth {

struct DroppedOpenings {
  std::string text;  // the edited city model
  int dropped = 0;   // openings merged into their surface
  int total = 0;     // openings in the file (CityJSON: Window/Door semantic surfaces, per geometry)
};

// Drops round(fraction * total) openings of the city model `text` (CityGML 1.0-3.0 or a CityJSON
// document; `path` names it in errors), chosen by `seed`. CityGML: each dropped Window / Door
// (WindowSurface / DoorSurface) element leaves the file, its surface members joining the same geometry
// property of the boundary surface that holds it. CityJSON: the surfaces of a dropped Window / Door
// semantic object take its parent's semantics (no parent: none). cls::Error naming `path` for a file that
// does not parse or an opening with no surface to join; cls::UsageError for a fraction outside [0, 1] or
// a CityJSONSeq file.
DroppedOpenings drop_openings(const std::string& path, const std::string& text, double fraction, uint64_t seed);

}  // namespace cls::synth
