#include "georef/proj_crs.h"

#include <proj.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/log.h"

namespace cls {
namespace {

// The CRS object of EPSG:`code` from PROJ's database, nullptr when it has none.
PJ* create_epsg(PJ_CONTEXT* context, int code) {
  return proj_create(context, ("EPSG:" + std::to_string(code)).c_str());
}

// PROJ logs failed look-ups to stderr; our errors say what went wrong instead.
PJ_CONTEXT* quiet_context() {
  PJ_CONTEXT* context = proj_context_create();
  proj_log_level(context, PJ_LOG_NONE);
  return context;
}

}  // namespace

std::optional<bool> is_vertical_crs(int code) {
  PJ_CONTEXT* context = quiet_context();
  PJ* crs = create_epsg(context, code);
  std::optional<bool> vertical;
  if (crs && proj_is_crs(crs)) vertical = proj_get_type(crs) == PJ_TYPE_VERTICAL_CRS;
  proj_destroy(crs);
  proj_context_destroy(context);
  return vertical;
}

GpsProjection::GpsProjection(int epsg) : epsg_(epsg), context_(quiet_context()) {
  const std::string name = "EPSG:" + std::to_string(epsg);
  PJ* target = create_epsg(context_, epsg);
  if (!target || !proj_is_crs(target)) {
    proj_destroy(target);
    proj_context_destroy(context_);
    throw Error(cat(name, ": PROJ's database (proj-data) has no such coordinate reference system"));
  }
  if (proj_get_type(target) == PJ_TYPE_COMPOUND_CRS) {  // e.g. 7415: RD New + NAP height
    PJ* horizontal = proj_crs_get_sub_crs(context_, target, 0);
    proj_destroy(target);
    target = horizontal;
  }
  if (!target || proj_get_type(target) == PJ_TYPE_VERTICAL_CRS) {
    proj_destroy(target);
    proj_context_destroy(context_);
    throw Error(cat(name, " is a vertical CRS: the photos' positions need one with horizontal axes"));
  }
  PJ* wgs84 = create_epsg(context_, 4326);
  PJ* raw = proj_create_crs_to_crs_from_pj(context_, wgs84, target, nullptr, nullptr);
  // The axis order a GIS shows (longitude first; easting first): what project() hands in and out.
  transform_ = raw ? proj_normalize_for_visualization(context_, raw) : nullptr;
  proj_destroy(raw);
  proj_destroy(wgs84);
  proj_destroy(target);
  if (!transform_) {
    proj_context_destroy(context_);
    throw Error(cat(name, ": PROJ has no transformation from WGS 84 (EPSG:4326) to it"));
  }
}

GpsProjection::~GpsProjection() {
  proj_destroy(transform_);
  proj_context_destroy(context_);
}

std::array<double, 2> GpsProjection::project(double latitude, double longitude) const {
  const PJ_COORD out = proj_trans(transform_, PJ_FWD, proj_coord(longitude, latitude, 0, 0));
  if (!std::isfinite(out.xy.x) || !std::isfinite(out.xy.y))
    throw Error(cat("EPSG:", epsg_, ": the GPS position ", latitude, ", ", longitude, " lies outside what it can represent"));
  return {out.xy.x, out.xy.y};
}

std::array<double, 2> GpsProjection::unproject(double x, double y) const {
  const PJ_COORD out = proj_trans(transform_, PJ_INV, proj_coord(x, y, 0, 0));
  if (!std::isfinite(out.lp.lam) || !std::isfinite(out.lp.phi))
    throw Error(cat("EPSG:", epsg_, ": the position ", x, ", ", y, " has no latitude and longitude"));
  return {out.lp.phi, out.lp.lam};  // normalized for visualization: longitude first, in degrees
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

}  // namespace cls
