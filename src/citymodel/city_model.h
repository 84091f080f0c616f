#pragma once
// Loads a city model of any supported encoding into a SemanticMesh, deciding by content:
// XML -> CityGML 1.0/2.0/3.0, a JSON document -> CityJSON, JSON lines -> CityJSONSeq.
#include <string>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"
#include "core/option_codec.h"

namespace cls {

// What every command that reads a city model takes from the command line (--lod, --taxonomy).
struct CityModelOptions {
  int lod = 0;                // 1, 2, 3, or 0 for the highest LoD available
  std::string taxonomy_path;  // "" = the built-in taxonomy
};

// --lod as an option: "1", "2", "3", "highest" (or "0") <-> the LoD number (0 = the highest available);
// in JSON the number.
Codec<int> lod_codec();
// The user's taxonomy file, or the built-in one.
Taxonomy load_taxonomy(const CityModelOptions& options);

enum class CityFormat { CityGML, CityJSON, CityJSONSeq, Unknown };
// From the file's first bytes (a UTF-8 byte order mark and white space are skipped); for JSON the
// first line decides between a document and a sequence, so `text` should be the whole file.
CityFormat detect_city_format(const std::string& text);

// cls::Error naming the file for unreadable files, unknown formats and everything the readers reject.
SemanticMesh load_city_model(const std::string& path, const Taxonomy& taxonomy, int lod);

}  // namespace cls
