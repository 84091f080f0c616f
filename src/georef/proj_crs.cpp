#include "georef/proj_crs.h"

#include <proj.h>
#include <proj_experimental.h>  // proj_create_compound_crs

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

// PROJ logs failed look-ups to stderr; our errors say what went wrong instead.
PJ_CONTEXT* quiet_context() {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  return context;
}

// The type of a CRS as PROJ reads it; nullopt for one it does not know.
std::optional<PJ_TYPE> crs_type(const std::string& definition) {
  PJ_CONTEXT* context = quiet_context();
  PJ* crs = proj_create(context, definition.c_str());
  std::optional<PJ_TYPE> type;
  if (crs && proj_is_crs(crs)) type = proj_get_type(crs);
  proj_destroy(crs);
  proj_context_destroy(context);
  return type;
}

}  // namespace

std::optional<bool> is_vertical_crs(int code) {
  const std::optional<PJ_TYPE> type = crs_type("EPSG:" + std::to_string(code));
  if (!type) return std::nullopt;
  return *type == PJ_TYPE_VERTICAL_CRS;
}

std::optional<bool> is_geocentric_crs(const std::string& definition) {
  const std::optional<PJ_TYPE> type = crs_type(definition);
  if (!type) return std::nullopt;
  return *type == PJ_TYPE_GEOCENTRIC_CRS;
}

CrsTransform::CrsTransform(const std::string& from, const std::string& to, const std::string& purpose)
    : context_(quiet_context()) {
  std::string problem;
  // The horizontal part of a CRS given as PROJ reads it (EPSG:N, WKT, PROJJSON, ...); nullptr and
  // `problem` set when there is none.
  auto horizontal = [&](const std::string& definition) -> PJ* {
    PJ* crs = proj_create(context_, definition.c_str());
    if (!crs || !proj_is_crs(crs)) {
      proj_destroy(crs);
      problem = cat(definition, ": PROJ (and its database, proj-data) does not know this coordinate reference system");
      return nullptr;
    }
    if (proj_get_type(crs) == PJ_TYPE_COMPOUND_CRS) {  // e.g. 7415: RD New + NAP height
      PJ* first = proj_crs_get_sub_crs(context_, crs, 0);
      proj_destroy(crs);
      crs = first;
    }
    if (!crs || proj_get_type(crs) == PJ_TYPE_VERTICAL_CRS) {
      proj_destroy(crs);
      problem = cat(definition, " is a vertical CRS: ", purpose, " need one with horizontal axes");
      return nullptr;
    }
    return crs;
  };
  PJ* source = horizontal(from);
  PJ* target = source ? horizontal(to) : nullptr;
  if (source && target) {
    PJ* raw = proj_create_crs_to_crs_from_pj(context_, source, target, nullptr, nullptr);
    // The axis order a GIS shows (longitude first; easting first): what forward() hands in and out.
    transform_ = raw ? proj_normalize_for_visualization(context_, raw) : nullptr;
    proj_destroy(raw);
    if (!transform_) problem = cat("PROJ has no transformation from ", from, " to ", to);
  }
  proj_destroy(source);
  proj_destroy(target);
  if (!transform_) {
    proj_context_destroy(context_);
    throw Error(problem);
  }
}

CrsTransform::~CrsTransform() {
  proj_destroy(transform_);
  proj_context_destroy(context_);
}

std::optional<std::array<double, 2>> CrsTransform::forward(double x, double y) const {
  const PJ_COORD out = proj_trans(transform_, PJ_FWD, proj_coord(x, y, 0, 0));
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y)) return std::nullopt;
  return std::array<double, 2>{out.xy.x, out.xy.y};
}

std::optional<std::array<double, 2>> CrsTransform::inverse(double x, double y) const {
  const PJ_COORD out = proj_trans(transform_, PJ_INV, proj_coord(x, y, 0, 0));
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y)) return std::nullopt;
  return std::array<double, 2>{out.xy.x, out.xy.y};
}

std::optional<std::array<double, 3>> CrsTransform::forward3(double x, double y, double z) const {
  const PJ_COORD out = proj_trans(transform_, PJ_FWD, proj_coord(x, y, z, 0));
  if (!std::isfinite(out.xyz.x) || !std::isfinite(out.xyz.y) || !std::isfinite(out.xyz.z)) return std::nullopt;
  return std::array<double, 3>{out.xyz.x, out.xyz.y, out.xyz.z};
}

GpsProjection::GpsProjection(int epsg)
    : epsg_(epsg), wgs84_to_crs_("EPSG:4326", "EPSG:" + std::to_string(epsg), "the photos' positions") {}

std::array<double, 2> GpsProjection::project(double latitude, double longitude) const {
  const auto xy = wgs84_to_crs_.forward(longitude, latitude);
  if (!xy) throw Error(cat("EPSG:", epsg_, ": the GPS position ", latitude, ", ", longitude, " lies outside what it can represent"));
  return *xy;
}

std::array<double, 2> GpsProjection::unproject(double x, double y) const {
  const auto lonlat = wgs84_to_crs_.inverse(x, y);
  if (!lonlat) throw Error(cat("EPSG:", epsg_, ": the position ", x, ", ", y, " has no latitude and longitude"));
  return {(*lonlat)[1], (*lonlat)[0]};
}

Egm96Geoid::Egm96Geoid() : context_(quiet_context()) {
  // Forward vgridshift adds -1 x the grid value: ellipsoidal height -> EGM96 height. Without the grid,
  // proj_create fails (the grid is not optional here), and available() says so.
  shift_ = proj_create(context_,
                       "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
                       "+step +proj=vgridshift +grids=egm96_15.gtx +multiplier=1 "
                       "+step +proj=unitconvert +xy_in=rad +xy_out=deg");
}

Egm96Geoid::~Egm96Geoid() {
  proj_destroy(shift_);
  proj_context_destroy(context_);
}

std::optional<double> Egm96Geoid::undulation(double latitude, double longitude) const {
  if (!shift_) return std::nullopt;
  const PJ_COORD out = proj_trans(shift_, PJ_FWD, proj_coord(longitude, latitude, 0, 0));
  if (!std::isfinite(out.xyz.z) || out.xyz.z == HUGE_VAL) return std::nullopt;
  return out.xyz.z;  // multiplier +1: z + N
}

CrsToGeocentric::CrsToGeocentric(const std::string& crs, const std::string& geocentric)
    : to_wgs84_(crs, "EPSG:4326", "a position on the globe"),
      to_geocentric_("EPSG:4979", geocentric, "a geocentric frame") {}

std::optional<std::array<double, 3>> CrsToGeocentric::operator()(double x, double y, double z) const {
  const auto lonlat = to_wgs84_.forward(x, y);
  if (!lonlat) return std::nullopt;
  const double h = z + geoid_.undulation((*lonlat)[1], (*lonlat)[0]).value_or(0);
  return to_geocentric_.forward3((*lonlat)[0], (*lonlat)[1], h);
}

GeoidHeights::GeoidHeights(int horizontal_epsg, int vertical_epsg) : context_(quiet_context()) {
  // Geographic 3D WGS 84 -> the compound of the model's horizontal CRS's geographic base and its heights;
  // of PROJ's candidate operations the first that is not a ballpark one and whose grids are all present.
  PJ* source = proj_create(context_, "EPSG:4979");
  PJ* horizontal = proj_create(context_, ("EPSG:" + std::to_string(horizontal_epsg)).c_str());
  PJ* vertical = proj_create(context_, ("EPSG:" + std::to_string(vertical_epsg)).c_str());
  PJ* base = horizontal ? proj_crs_get_geodetic_crs(context_, horizontal) : nullptr;
  PJ* target = base && vertical ? proj_create_compound_crs(context_, "", base, vertical) : nullptr;
  PJ_OPERATION_FACTORY_CONTEXT* factory = target ? proj_create_operation_factory_context(context_, nullptr) : nullptr;
  PJ_OBJ_LIST* operations = nullptr;
  if (factory) {
    proj_operation_factory_context_set_grid_availability_use(context_, factory,
                                                             PROJ_GRID_AVAILABILITY_DISCARD_OPERATION_IF_MISSING_GRID);
    proj_operation_factory_context_set_spatial_criterion(context_, factory, PROJ_SPATIAL_CRITERION_PARTIAL_INTERSECTION);
    operations = proj_create_operations(context_, source, target, factory);
  }
  for (int i = 0; operations && i < proj_list_get_count(operations) && !transform_; ++i) {
    PJ* op = proj_list_get(context_, operations, i);
    if (op && proj_coordoperation_is_instantiable(context_, op) &&
        !proj_coordoperation_has_ballpark_transformation(context_, op) && proj_coordoperation_get_grid_used_count(context_, op) > 0) {
      transform_ = proj_normalize_for_visualization(context_, op);  // longitude, latitude, height
      const char* name = proj_get_name(op);
      operation_ = name ? name : "";
    }
    proj_destroy(op);
  }
  proj_list_destroy(operations);
  proj_operation_factory_context_destroy(factory);
  for (PJ* p : {source, horizontal, vertical, base, target}) proj_destroy(p);
}

GeoidHeights::~GeoidHeights() {
  proj_destroy(transform_);
  proj_context_destroy(context_);
}

std::optional<double> GeoidHeights::height(double latitude, double longitude, double ellipsoidal_height) const {
  if (!transform_) return std::nullopt;
  const PJ_COORD out = proj_trans(transform_, PJ_FWD, proj_coord(longitude, latitude, ellipsoidal_height, 0));
  if (!std::isfinite(out.xyz.z) || out.xyz.z == HUGE_VAL) return std::nullopt;
  return out.xyz.z;
}

}  // namespace cls
