#include "citymodel/citygml_reader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "citymodel/gml_coordinates.h"
#include "citymodel/gml_vocabulary.h"
#include "citymodel/mesh_builder.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"

namespace cls {

namespace {

// Deeper element nesting or xlink chains are no real city model; refusing them keeps the
// recursive walks below far from the stack limit on hostile input.
constexpr int kMaxDepth = 256;

bool is_polygon_element(std::string_view name) {
  return name == "Polygon" || name == "PolygonPatch" || name == "Triangle" || name == "Rectangle";
}

// xs:ID is an NCName: a letter or '_' first (non-ASCII UTF-8 is accepted as letters), then letters,
// digits, '.', '-', '_'; no ':'.
bool is_ncname(std::string_view s) {
  const auto letter = [](unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; };
  if (s.empty() || !letter(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [&](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return letter(c) || std::isdigit(c) || c == '.' || c == '-';
  });
}

// "http://www.opengis.net/citygml/building/2.0" -> "2.0"; "" for other namespaces.
std::string citygml_version_of_namespace(std::string_view uri) {
  constexpr std::string_view kPrefix = "http://www.opengis.net/citygml/";
  if (uri.substr(0, kPrefix.size()) != kPrefix) return "";
  const std::string_view last = uri.substr(uri.find_last_of('/') + 1);
  for (std::string_view v : {"1.0", "2.0", "3.0"})
    if (last == v) return std::string(v);
  return "";
}

class CityGmlReader {
 public:
  CityGmlReader(const char* data, size_t size, const std::string& name, const Taxonomy& taxonomy, int lod)
      : data_(data), size_(size), name_(name), taxonomy_(taxonomy), requested_lod_(lod), builder_(taxonomy) {}

  SemanticMesh read();

 private:
  [[noreturn]] void fail_at(pugi::xml_node node, const std::string& what) const;
  std::string element_id(pugi::xml_node node) const;
  void index_document();
  void find_buildings(pugi::xml_node node, std::vector<pugi::xml_node>& buildings,
                      std::map<std::string, int>& skipped) const;
  std::set<int> surface_lods(pugi::xml_node building) const;
  pugi::xml_node resolve_local_href(pugi::xml_node node, pugi::xml_attribute href) const;
  int entity_level(std::string_view type) const;
  int class_of(std::string_view type, pugi::xml_node node) const;
  int surface_class(pugi::xml_node node, std::string_view why) const;

  void visit_feature(pugi::xml_node feature, int parent, int depth);
  void walk_feature_content(pugi::xml_node node, int entity, int depth, std::vector<pugi::xml_node>& geometry);
  void add_geometry(pugi::xml_node node, int entity, int face_class, bool flip, int depth);
  void add_polygon(pugi::xml_node polygon, int entity, int face_class, bool flip);
  Ring read_ring(pugi::xml_node boundary, pugi::xml_node polygon, const std::string& polygon_id) const;
  void read_positions(pugi::xml_node node, Ring& ring, int depth) const;
  int srs_dimension(pugi::xml_node node) const;

  const char* data_;
  size_t size_;
  std::string name_;
  const Taxonomy& taxonomy_;
  int requested_lod_;
  pugi::xml_document doc_;
  std::unordered_map<std::string_view, pugi::xml_node> ids_;  // views into doc_'s strings
  std::string version_, crs_;
  MeshBuilder builder_;
  int lod_ = 0;  // LoD of the building being read
  // Features and geometry reached both in place and by xlink are read once: later visits would
  // add nothing (polygons are deduplicated) and could repeat exponentially in hostile files.
  std::unordered_set<const void*> visited_features_, expanded_geometry_;
};

void CityGmlReader::fail_at(pugi::xml_node node, const std::string& what) const {
  const ptrdiff_t offset = node.offset_debug();
  if (offset < 0 || static_cast<size_t>(offset) > size_) fail(name_, what);
  fail(name_, cat("line ", 1 + std::count(data_, data_ + offset, '\n'), ": ", what));
}

// gml:id, or "@<byte offset>" for elements without one (unique per element, for tracing).
std::string CityGmlReader::element_id(pugi::xml_node node) const {
  if (pugi::xml_attribute id = prefixed_attribute(node, "id")) return id.value();
  return cat("@", node.offset_debug());
}

// One pass over all elements: gml:id index, CityGML version, CRS, nesting depth.
void CityGmlReader::index_document() {
  struct Walker : pugi::xml_tree_walker {
    CityGmlReader& r;
    explicit Walker(CityGmlReader& reader) : r(reader) {}
    bool for_each(pugi::xml_node& n) override {
      if (n.type() != pugi::node_element) return true;
      if (depth() > kMaxDepth) r.fail_at(n, cat("elements nested deeper than ", kMaxDepth, " levels"));
      for (pugi::xml_attribute a : n.attributes()) {
        const std::string_view name = a.name();
        if (name.substr(0, 6) == "xmlns:" || name == "xmlns") {
          if (r.version_.empty()) r.version_ = citygml_version_of_namespace(a.value());
        } else if (r.crs_.empty() && name == "srsName") {
          r.crs_ = a.value();
        }
      }
      if (pugi::xml_attribute id = prefixed_attribute(n, "id")) {
        if (!is_ncname(id.value()))
          r.fail_at(n, cat("gml:id \"", id.value(), "\" is not a valid XML ID (it must start with a letter or '_' "
                                                     "and contain only letters, digits, '.', '-', '_')"));
        if (!r.ids_.emplace(id.value(), n).second) r.fail_at(n, cat("duplicate gml:id \"", id.value(), "\""));
      }
      return true;
    }
  } walker(*this);
  doc_.traverse(walker);
  if (version_.empty()) fail(name_, "not a CityGML file (no http://www.opengis.net/citygml/ namespace)");
}

// Root Building elements (BuildingParts are read with their Building); other city objects are counted.
// (Recursion is safe: index_document() has bounded the nesting depth.)
void CityGmlReader::find_buildings(pugi::xml_node node, std::vector<pugi::xml_node>& buildings,
                                   std::map<std::string, int>& skipped) const {
  const std::string_view name = local_name(node);
  if (name == "Building") {
    buildings.push_back(node);
    return;
  }
  const bool member = name == "cityObjectMember" || name == "featureMember" || name == "member";
  for_each_element_child(node, [&](pugi::xml_node c) {
    if (member && local_name(c) != "Building") ++skipped[std::string(local_name(c))];
    find_buildings(c, buildings, skipped);
  });
}

std::set<int> CityGmlReader::surface_lods(pugi::xml_node building) const {
  struct Walker : pugi::xml_tree_walker {
    std::set<int> lods;
    bool for_each(pugi::xml_node& n) override {
      if (n.type() == pugi::node_element && surface_lod(local_name(n)) >= 1) lods.insert(surface_lod(local_name(n)));
      return true;
    }
  } walker;
  building.traverse(walker);
  return walker.lods;
}

// The element an xlink:href="#id" names; an empty node for references outside the file.
pugi::xml_node CityGmlReader::resolve_local_href(pugi::xml_node node, pugi::xml_attribute href) const {
  const std::string_view ref = href.value();
  if (ref.empty() || ref[0] != '#') return {};
  const auto it = ids_.find(ref.substr(1));
  if (it == ids_.end()) fail_at(node, cat("dangling xlink:href \"", ref, "\": no element has gml:id \"", ref.substr(1), "\""));
  return it->second;
}

int CityGmlReader::entity_level(std::string_view type) const {
  if (const int level = structural_level(type)) return level;
  const std::optional<int> c = taxonomy_.class_of_type(std::string(type));
  return c ? taxonomy_.classes[*c].level : 0;
}

// Taxonomy class of a feature type; types the taxonomy does not map are generic "surface".
int CityGmlReader::class_of(std::string_view type, pugi::xml_node node) const {
  if (const std::optional<int> c = taxonomy_.class_of_type(std::string(type))) return *c;
  return surface_class(node, cat("the taxonomy maps no class to ", type));
}

int CityGmlReader::surface_class(pugi::xml_node node, std::string_view why) const {
  const int surface = taxonomy_.find("surface");
  if (surface < 0) fail_at(node, cat(why, " and has no \"surface\" class"));
  return surface;
}

void CityGmlReader::visit_feature(pugi::xml_node feature, int parent, int depth) {
  if (!visited_features_.insert(feature.internal_object()).second) return;
  const std::string_view type = local_name(feature);
  const int level = entity_level(type);
  const int feature_class = class_of(type, feature);
  int entity = -1;
  try {
    entity = builder_.add_entity(level, feature_class, parent, element_id(feature));
  } catch (const Error& e) {  // e.g. a BuildingPart inside a wall: named here at its element
    fail_at(feature, cat(type, ": ", e.what()));
  }
  // Nested features first: a polygon shared by a boundary surface and the building's solid gets
  // the surface's class, whatever the order in the file.
  std::vector<pugi::xml_node> geometry;
  for_each_element_child(feature, [&](pugi::xml_node c) { walk_feature_content(c, entity, depth + 1, geometry); });
  if (geometry.empty()) return;
  // A building's own geometry (outside its semantic surfaces) is a generic surface.
  const int face_class =
      level == 3 ? surface_class(feature, cat(type, " has geometry outside semantic surfaces, the taxonomy")) : feature_class;
  for (pugi::xml_node g : geometry) add_geometry(g, entity, face_class, false, depth + 1);
}

// Below a feature: nested features are visited, geometry properties of the LoD being read are
// collected into `geometry`, everything else (attributes, addresses, envelopes) is searched through.
void CityGmlReader::walk_feature_content(pugi::xml_node node, int entity, int depth,
                                         std::vector<pugi::xml_node>& geometry) {
  if (depth > kMaxDepth) fail_at(node, cat("elements nested deeper than ", kMaxDepth, " levels"));
  const std::string_view name = local_name(node);
  if (entity_level(name) > 0) {
    visit_feature(node, entity, depth);
    return;
  }
  if (const int lod = surface_lod(name); lod >= 0) {
    if (lod == lod_) geometry.push_back(node);
    return;
  }
  if (pugi::xml_attribute href = prefixed_attribute(node, "href")) {
    // A feature by reference (an opening or surface defined elsewhere); never another building.
    const pugi::xml_node target = resolve_local_href(node, href);
    const std::string_view target_type = target ? local_name(target) : std::string_view();
    if (target && target_type != "Building" && entity_level(target_type) > 0) visit_feature(target, entity, depth + 1);
    return;
  }
  for_each_element_child(node, [&](pugi::xml_node c) { walk_feature_content(c, entity, depth + 1, geometry); });
}

void CityGmlReader::add_geometry(pugi::xml_node node, int entity, int face_class, bool flip, int depth) {
  if (depth > kMaxDepth) fail_at(node, cat("geometry nested or referenced deeper than ", kMaxDepth, " levels"));
  if (!expanded_geometry_.insert(node.internal_object()).second) return;
  if (pugi::xml_attribute href = prefixed_attribute(node, "href")) {
    const pugi::xml_node target = resolve_local_href(node, href);
    if (!target) fail_at(node, cat("geometry xlink:href \"", href.value(), "\" points outside the file (not supported)"));
    add_geometry(target, entity, face_class, flip, depth + 1);
    return;
  }
  const std::string_view name = local_name(node);
  if (is_polygon_element(name)) {
    add_polygon(node, entity, face_class, flip);
    return;
  }
  if (name == "OrientableSurface" && std::string_view(node.attribute("orientation").value()) == "-") flip = !flip;
  for_each_element_child(node, [&](pugi::xml_node c) { add_geometry(c, entity, face_class, flip, depth + 1); });
}

void CityGmlReader::add_polygon(pugi::xml_node polygon, int entity, int face_class, bool flip) {
  const std::string id = element_id(polygon);
  std::vector<Ring> rings(1);  // rings[0]: exterior
  bool has_exterior = false;
  for_each_element_child(polygon, [&](pugi::xml_node c) {
    const std::string_view name = local_name(c);
    if (name == "exterior" || name == "outerBoundaryIs") {
      if (has_exterior) fail_at(c, cat("polygon \"", id, "\" has two exterior rings"));
      rings[0] = read_ring(c, polygon, id);
      has_exterior = true;
    } else if (name == "interior" || name == "innerBoundaryIs") {
      rings.push_back(read_ring(c, polygon, id));
    }
  });
  if (!has_exterior) fail_at(polygon, cat("polygon \"", id, "\" has no exterior ring"));
  if (flip)
    for (Ring& r : rings) std::reverse(r.begin(), r.end());
  try {
    builder_.add_polygon(rings, face_class, entity, id);
  } catch (const Error& e) {
    fail_at(polygon, e.what());
  }
}

Ring CityGmlReader::read_ring(pugi::xml_node boundary, pugi::xml_node polygon, const std::string& polygon_id) const {
  Ring ring;
  read_positions(boundary, ring, 0);
  size_t points = ring.size();
  if (points >= 2 && ring.front() == ring.back()) --points;  // the closing repetition of the first point
  if (points < 3)
    fail_at(boundary.empty() ? polygon : boundary,
            cat("a ring of polygon \"", polygon_id, "\" has ", points, " point(s); a ring needs at least 3"));
  return ring;
}

// Positions below `node` in document order: gml:posList, gml:pos and gml:coordinates (a gml:Ring
// of several curves yields its curves' points in sequence).
void CityGmlReader::read_positions(pugi::xml_node node, Ring& ring, int depth) const {
  if (depth > kMaxDepth) fail_at(node, cat("ring nested deeper than ", kMaxDepth, " levels"));
  for_each_element_child(node, [&](pugi::xml_node c) {
    const std::string_view name = local_name(c);
    if (name == "posList" || name == "pos") {
      std::vector<double> values;
      if (std::string err = parse_double_list(c.child_value(), values); !err.empty())
        fail_at(c, cat("gml:", name, ": ", err));
      const size_t dim = name == "pos" && (values.size() == 2 || values.size() == 3) ? values.size() : srs_dimension(c);
      if (values.size() % dim != 0 || (name == "pos" && values.size() != dim))
        fail_at(c, cat("gml:", name, " has ", values.size(), " numbers, not a multiple of its dimension ", dim));
      for (size_t i = 0; i < values.size(); i += dim) ring.push_back({values[i], values[i + 1], dim == 3 ? values[i + 2] : 0.0});
    } else if (name == "coordinates") {
      const auto sep = [&](const char* attr, char fallback) {
        const char* v = c.attribute(attr).value();
        return v[0] != 0 && v[1] == 0 ? v[0] : fallback;  // single-character separators only
      };
      if (std::string err = parse_gml_coordinates(c.child_value(), sep("decimal", '.'), sep("cs", ','), sep("ts", ' '), ring);
          !err.empty())
        fail_at(c, "gml:coordinates: " + err);
    } else {
      read_positions(c, ring, depth + 1);
    }
  });
}

// srsDimension of a position list: on the element or inherited from an enclosing geometry; 3 by default.
int CityGmlReader::srs_dimension(pugi::xml_node node) const {
  for (pugi::xml_node n = node; n; n = n.parent()) {
    if (pugi::xml_attribute a = n.attribute("srsDimension")) {
      const std::string_view v = a.value();
      if (v == "2" || v == "3") return v[0] - '0';
      fail_at(n, cat("srsDimension \"", v, "\" is not 2 or 3"));
    }
  }
  return 3;
}

SemanticMesh CityGmlReader::read() {
  if (requested_lod_ < 0 || requested_lod_ > 4) fail(name_, cat("LoD ", requested_lod_, " requested; use 1..4 or 0 (highest)"));
  const pugi::xml_parse_result parsed = doc_.load_buffer(data_, size_);
  if (!parsed) {
    const auto offset = static_cast<size_t>(std::clamp<ptrdiff_t>(parsed.offset, 0, static_cast<ptrdiff_t>(size_)));
    fail(name_, cat("malformed XML: ", parsed.description(), " at line ", 1 + std::count(data_, data_ + offset, '\n'),
                    " (byte offset ", parsed.offset, ")"));
  }
  index_document();

  std::vector<pugi::xml_node> buildings;
  std::map<std::string, int> skipped;
  find_buildings(doc_.document_element(), buildings, skipped);
  for (const auto& [type, n] : skipped) log_verbose(cat(name_, ": skipped ", n, " ", type, " (not a building)"));

  std::set<int> available, used;
  {
    Progress progress("reading CityGML buildings", buildings.size(), "buildings");
    for (pugi::xml_node b : buildings) {
      const std::set<int> lods = surface_lods(b);
      available.insert(lods.begin(), lods.end());
      lod_ = requested_lod_ != 0 ? requested_lod_ : (lods.empty() ? -1 : *lods.rbegin());
      if (lods.count(lod_)) used.insert(lod_);
      visit_feature(b, -1, 0);
      progress.advance();
    }
  }
  if (builder_.degenerate_polygons() > 0)
    log_info(cat(name_, ": skipped ", builder_.degenerate_polygons(), " degenerate polygon(s) (zero area)"));

  SemanticMesh mesh = builder_.finish();
  if (mesh.num_triangles() == 0) {
    std::string have;
    for (int l : available) have += cat(have.empty() ? "" : ", ", l);
    fail(name_, cat("no building geometry", requested_lod_ ? cat(" at LoD ", requested_lod_) : "",
                    " (building LoDs in the file: ", have.empty() ? "none" : have, ")"));
  }
  if (used.size() > 1) log_info(cat(name_, ": buildings read at different LoDs; the mesh records the highest"));
  mesh.source_path = name_;
  mesh.format = "CityGML";
  mesh.version = version_;
  mesh.crs = crs_;
  mesh.lod = used.empty() ? requested_lod_ : *used.rbegin();
  return mesh;
}

}  // namespace

SemanticMesh read_citygml_buffer(const char* data, size_t size, const std::string& name, const Taxonomy& taxonomy,
                                 int lod) {
  return CityGmlReader(data, size, name, taxonomy, lod).read();
}

SemanticMesh read_citygml(const std::string& path, const Taxonomy& taxonomy, int lod) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "cannot read file");
  const std::string data = text.str();
  return read_citygml_buffer(data.data(), data.size(), path, taxonomy, lod);
}

}  // namespace cls
