#include "georef/crs_name.h"

#include <map>
#include <regex>

#include "core/error.h"
#include "georef/proj_crs.h"

namespace cls {
namespace {

// The AdV's names (GeoInfoDok, "CRS-Kennungen") for what German state city models use.
const std::map<std::string, int> kAdvHorizontal = {
    {"ETRS89_UTM31", 25831}, {"ETRS89_UTM32", 25832}, {"ETRS89_UTM33", 25833}};
const std::map<std::string, int> kAdvVertical = {{"DE_DHHN2016_NH", 7837}, {"DE_DHHN92_NH", 5783}};

}  // namespace

std::optional<CrsName> parse_crs_name(const std::string& name) {
  std::smatch m;
  static const std::regex adv(R"(^urn:adv:crs:([A-Za-z0-9_]+)(?:\*([A-Za-z0-9_]+))?(?:\*[A-Za-z0-9_]+)?$)");
  if (std::regex_match(name, m, adv)) {
    const auto h = kAdvHorizontal.find(m[1]);
    if (h == kAdvHorizontal.end()) return std::nullopt;
    CrsName crs{h->second, 0};
    if (m[2].matched) {
      const auto v = kAdvVertical.find(m[2]);
      if (v == kAdvVertical.end()) return std::nullopt;
      crs.vertical_epsg = v->second;
    }
    return crs;
  }
  // Every EPSG code the name holds, in order: EPSG:N, EPSG::N, EPSG:version:N, .../EPSG/0/N.
  static const std::regex epsg(R"(EPSG(?::[0-9.]*)?:(\d{1,6})|/EPSG/[0-9.]+/(\d{1,6}))", std::regex::icase);
  CrsName crs;
  for (auto it = std::sregex_iterator(name.begin(), name.end(), epsg); it != std::sregex_iterator(); ++it) {
    const int code = std::stoi((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
    const std::optional<bool> vertical = is_vertical_crs(code);
    if (!vertical) return std::nullopt;  // a code PROJ does not know
    int& slot = *vertical ? crs.vertical_epsg : crs.horizontal_epsg;
    if (slot != 0) return std::nullopt;  // two of one kind: not a name we understand
    slot = code;
  }
  if (crs.horizontal_epsg == 0) return std::nullopt;
  return crs;
}

CrsName city_model_crs(const std::string& city_path, const std::string& file_crs, const std::string& given) {
  const std::string text = given.empty() ? file_crs : given;
  const std::optional<CrsName> crs = parse_crs_name(text);
  if (!crs)
    fail(given.empty() ? city_path : "--crs",
         text.empty() ? "the city model names no CRS (srsName / referenceSystem): give it with --crs EPSG:N"
                      : "CRS \"" + text + "\" is not one PROJ knows as EPSG:N (give --crs EPSG:N)");
  return *crs;
}

}  // namespace cls
