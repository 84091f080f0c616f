#pragma once
// A SemanticMesh as a CityJSON 2.0 document (issue 35 §2), so that a run on any city model (CityGML
// 1/2/3, CityJSON, CityJSONSeq) can go out enriched in the format cjio and 3DCityDB read. Hand-written:
// Debian has no CityJSON library for C++ (cjio is Python, outside Debian), and the document is plain JSON.
//
// Every source polygon becomes one surface again: its rings are the boundary of the triangles the
// reader made of it (polygon_rings), so the geometry is the city model's own polygons, not a
// triangulation. Buildings and building parts become CityObjects (parts with "parents"/"children"),
// installations BuildingInstallation objects; boundary surfaces and openings become semantic surfaces of
// their object's one MultiSurface, openings with "parent" on their wall. What is lost on the way: the
// attributes and other LoDs of the source (the reader keeps one LoD's geometry) and the distinction
// between InteriorWall/Ceiling/FloorSurface (the taxonomy folds them into "interior").
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"

namespace cls {

// The rings of one planar polygon from its triangles (vertex indices, counter-clockwise about the
// polygon's normal as the mesh builder's tessellation makes them): the edges that belong to one
// triangle only, chained. The ring with the largest area comes first (the exterior, counter-clockwise);
// the others are holes (clockwise). Empty when the triangles leave no closed boundary.
std::vector<std::vector<uint32_t>> polygon_rings(const std::vector<std::array<uint32_t, 3>>& triangles,
                                                 const std::vector<std::array<double, 3>>& vertices);

// Where the attributes of a mesh entity go in the document: its CityObject, and the index of its
// semantic surface in that object's geometry (-1: the entity is the CityObject itself, or a plain
// surface without semantics, which has no place of its own).
struct CityJsonPlace {
  std::string object;
  int surface = -1;
  bool is_object = false;  // the entity is the CityObject itself
};

struct CityJsonDocument {
  nlohmann::json document;
  std::vector<CityJsonPlace> places;  // per SemanticMesh entity
};

// The mesh (vertices in the source CRS minus mesh.origin) as CityJSON 2.0: vertices in millimetres
// ("transform" scale 0.001, translate = origin), "metadata.referenceSystem" = `reference_system` when
// not empty (an OGC CRS URL). std::logic_error (a bug, exit 3) for a mesh whose entities break the
// builder's rules.
CityJsonDocument semantic_mesh_cityjson(const SemanticMesh& mesh, const Taxonomy& taxonomy,
                                        const std::string& reference_system);

// A CityJSON document as CityJSONSeq (CityJSON 2.0, section "CityJSON Text Sequences"), for models too
// large to read whole: the first line the document without its objects and vertices (its transform,
// metadata, extensions and root attributes stay there, as the specification asks), then one
// CityJSONFeature per top-level object (one without "parents") holding it and all its descendants
// ("children", recursively) with only the vertices they use, renumbered in order of first use.
std::vector<nlohmann::json> cityjson_sequence(const nlohmann::json& document);

// The OGC URL CityJSON 2.0 asks for ("https://www.opengis.net/def/crs/EPSG/0/25832") of a CRS name
// parse_crs_name knows; a compound name gives its horizontal CRS. "" when the name is unknown.
std::string cityjson_reference_system(const std::string& crs_name);

}  // namespace cls
