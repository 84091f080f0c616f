#pragma once
// Coordinate reference systems through PROJ (Debian's libproj-dev and its EPSG database): the
// photos' WGS 84 GPS positions, and a photogrammetry project's output CRS, in a city model's CRS.
#include <array>
#include <optional>
#include <string>

// PROJ's handles, declared here so that only proj_crs.cpp includes <proj.h>.
struct pj_ctx;
struct PJconsts;

namespace cls {

// Whether EPSG:`code` is a vertical CRS (true) or one with horizontal axes (false: projected,
// geographic, compound); nullopt for a code PROJ's database does not hold.
std::optional<bool> is_vertical_crs(int code);
// Whether a CRS (as PROJ reads it) is geocentric (ECEF, e.g. EPSG:4978); nullopt for one PROJ does not know.
std::optional<bool> is_geocentric_crs(const std::string& definition);

// x, y of one CRS -> x, y of another through PROJ (of compound CRSs their horizontal parts), in the
// axis order a GIS shows (longitude first; easting first). Heights are not converted: which vertical
// datum a height is in is for the georeferencing to find out.
class CrsTransform {
 public:
  // `from`, `to`: as PROJ reads them (EPSG:N, WKT, PROJJSON). cls::Error for a CRS PROJ does not
  // know, a vertical CRS (`purpose` says what needed a horizontal one), or no transformation.
  CrsTransform(const std::string& from, const std::string& to, const std::string& purpose);
  ~CrsTransform();
  CrsTransform(const CrsTransform&) = delete;
  CrsTransform& operator=(const CrsTransform&) = delete;

  // nullopt for a position the target cannot represent (PROJ returns infinity there).
  std::optional<std::array<double, 2>> forward(double x, double y) const;
  std::optional<std::array<double, 2>> inverse(double x, double y) const;
  // x, y, z through: between CRSs with heights (geographic 3D, geocentric), where z is converted too.
  std::optional<std::array<double, 3>> forward3(double x, double y, double z) const;

 private:
  pj_ctx* context_ = nullptr;
  PJconsts* transform_ = nullptr;
};

// WGS 84 latitude / longitude (degrees) -> easting / northing (or the CRS's own x, y in the order a
// GIS shows them) of EPSG:`epsg`; of a compound CRS its horizontal part.
class GpsProjection {
 public:
  // cls::Error for a code PROJ does not know, a vertical CRS, or no transformation from WGS 84.
  explicit GpsProjection(int epsg);

  // cls::Error for a position the CRS cannot represent (PROJ returns infinity there).
  std::array<double, 2> project(double latitude, double longitude) const;
  // The inverse: x, y of the CRS -> WGS 84 latitude, longitude (what synth --gps writes into photos).
  std::array<double, 2> unproject(double x, double y) const;
  int epsg() const { return epsg_; }

 private:
  int epsg_;
  CrsTransform wgs84_to_crs_;
};

// The EGM96 geoid's height above the WGS 84 ellipsoid (N, metres) at a position, through PROJ's
// vgridshift with the grid proj-data installs (egm96_15.gtx): orthometric height ~ ellipsoidal height - N.
// nullopt when the grid is not installed. EGM96 is a global model: national geoids (GCG2016 in Germany)
// differ from it by decimetres to a metre, which georeferencing's vertical search takes up.
class Egm96Geoid {
 public:
  Egm96Geoid();
  ~Egm96Geoid();
  Egm96Geoid(const Egm96Geoid&) = delete;
  Egm96Geoid& operator=(const Egm96Geoid&) = delete;

  bool available() const { return shift_ != nullptr; }
  // nullopt when the grid is not available or does not cover the position.
  std::optional<double> undulation(double latitude, double longitude) const;

 private:
  pj_ctx* context_ = nullptr;
  PJconsts* shift_ = nullptr;
};

// Points of a CRS with heights above the geoid (a city model's: easting, northing, orthometric height) in
// a geocentric CRS (ECEF, EPSG:4978 unless told): PROJ to WGS 84 longitude / latitude, the EGM96
// undulation added to the heights where its grid is installed (else they pass as ellipsoidal: metres off,
// geoid_available() says so), then PROJ to geocentric. What a projected frame needs to sit on the globe:
// a model_aligner ECEF frame, a 3D Tiles tileset's transform.
class CrsToGeocentric {
 public:
  // cls::Error as CrsTransform's for a CRS PROJ does not know or cannot transform.
  CrsToGeocentric(const std::string& crs, const std::string& geocentric = "EPSG:4978");
  // nullopt for a position PROJ cannot place.
  std::optional<std::array<double, 3>> operator()(double x, double y, double z) const;
  bool geoid_available() const { return geoid_.available(); }

 private:
  CrsTransform to_wgs84_;
  CrsTransform to_geocentric_;
  Egm96Geoid geoid_;
};

// WGS 84 ellipsoidal heights -> heights of a city model's vertical CRS (DHHN2016, NAP, EGM96 height, ...)
// through PROJ's own transformation with that datum's geoid grid, where the grid is installed: Debian's
// proj-data holds EGM96 and none of the national ones (GCG2016, NLGEO2018, ...), which users add to
// ~/.local/share/proj or $PROJ_DATA (projsync, or the agency's file). Only operations that use a grid are
// taken: PROJ's ballpark fallback (heights unchanged) is what georeferencing's vertical search already does.
class GeoidHeights {
 public:
  GeoidHeights(int horizontal_epsg, int vertical_epsg);
  ~GeoidHeights();
  GeoidHeights(const GeoidHeights&) = delete;
  GeoidHeights& operator=(const GeoidHeights&) = delete;

  bool available() const { return transform_ != nullptr; }
  const std::string& operation() const { return operation_; }  // PROJ's name of the transformation
  // The height in the vertical CRS; nullopt when not available or the grid does not cover the position.
  std::optional<double> height(double latitude, double longitude, double ellipsoidal_height) const;

 private:
  pj_ctx* context_ = nullptr;
  PJconsts* transform_ = nullptr;
  std::string operation_;
};

}  // namespace cls
