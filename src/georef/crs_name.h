#pragma once
// A city model's coordinate reference system as its file names it (CityGML srsName, CityJSON
// referenceSystem) -> EPSG codes, the form PROJ takes. Hand-written: PROJ reads "EPSG:25832" and the
// OGC URNs and URLs but not the AdV URNs of German state models ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH"),
// and the vertical part must stay apart (georeferencing resolves the heights itself, issue 34). Which
// code is vertical, PROJ's database says.
#include <optional>
#include <string>

namespace cls {

struct CrsName {
  int horizontal_epsg = 0;  // the projected (or geographic) CRS of x, y
  int vertical_epsg = 0;    // the heights' CRS where the name gives one (DHHN2016: 7837), 0 otherwise
};

// nullopt for a name none of the known forms matches, or whose EPSG codes PROJ does not know; the forms:
//   EPSG:25832, EPSG::25832, urn:ogc:def:crs:EPSG::25832, urn:ogc:def:crs:EPSG:6.12:25832,
//   urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837 (compound), http(s)://www.opengis.net/def/crs/EPSG/0/7415,
//   urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH[*GCG2016] (AdV: ETRS89 / UTM 31-33, DHHN92 / DHHN2016).
std::optional<CrsName> parse_crs_name(const std::string& name);

// The CRS of the city model read from `city_path` whose file names `file_crs`, or `given` (the user's
// --crs) when not empty. cls::Error naming the file (or --crs) when there is none or PROJ does not know
// it, and telling the user to give --crs EPSG:N.
CrsName city_model_crs(const std::string& city_path, const std::string& file_crs, const std::string& given);

}  // namespace cls
