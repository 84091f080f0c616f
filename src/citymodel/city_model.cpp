#include "citymodel/city_model.h"

#include <fstream>

#include "citymodel/citygml_reader.h"
#include "citymodel/cityjson_reader.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

size_t content_start(const std::string& text) {
  const size_t after_bom = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  return text.find_first_not_of(" \t\r\n", after_bom);
}

// The first bytes of a file: enough to tell XML from JSON without reading a large CityGML twice.
std::string file_head(const std::string& path, size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file");
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<size_t>(in.gcount()));
  return head;
}

}  // namespace

Codec<int> lod_codec() {
  Codec<int> c = default_codec<int>();
  c.text = [](const int& lod) { return lod == 0 ? std::string("highest") : std::to_string(lod); };
  c.parse = [](const std::string& text) {
    if (text == "highest" || text == "0") return 0;
    if (text == "1" || text == "2" || text == "3") return text[0] - '0';
    throw std::invalid_argument("must be 1, 2, 3 or highest, not '" + text + "'");
  };
  c.from_json = [](const nlohmann::json& j) {
    const int lod = j.get<int>();
    if (lod < 0 || lod > 3) throw std::invalid_argument("must be 1, 2, 3 or 0 (highest), not " + j.dump());
    return lod;
  };
  return c;
}

Taxonomy load_taxonomy(const CityModelOptions& options) {
  return options.taxonomy_path.empty() ? Taxonomy::builtin() : Taxonomy::load(options.taxonomy_path);
}

CityFormat detect_city_format(const std::string& text) {
  const size_t start = content_start(text);
  if (start == std::string::npos) return CityFormat::Unknown;
  if (text[start] == '<') return CityFormat::CityGML;
  if (text[start] != '{') return CityFormat::Unknown;
  return is_cityjson_seq(text) ? CityFormat::CityJSONSeq : CityFormat::CityJSON;
}

SemanticMesh load_city_model(const std::string& path, const Taxonomy& taxonomy, int lod) {
  // The head tells XML from JSON without reading a large CityGML file twice.
  const std::string head = file_head(path, 4096);
  switch (detect_city_format(head)) {
    case CityFormat::CityGML:
      return read_citygml(path, taxonomy, lod);
    case CityFormat::Unknown:
      if (content_start(head) == std::string::npos && head.size() < 4096) fail(path, "empty file");
      fail(path, "unknown format: expected CityGML (XML) or CityJSON / CityJSONSeq (JSON)");
    default:
      break;
  }
  const std::string text = read_text_file(path);
  if (detect_city_format(text) == CityFormat::CityJSONSeq) {
    log_verbose(cat(path, ": CityJSONSeq"));
    return parse_cityjson_seq(text, path, taxonomy, lod);
  }
  return parse_cityjson(text, path, taxonomy, lod);
}

}  // namespace cls
