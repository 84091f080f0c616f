#include "citymodel/cityjson_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "citymodel/mesh_builder.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"

namespace cls {
namespace {

using json = nlohmann::json;
using Point = std::array<double, 3>;

// A LoD as written ("2", "2.2"; a number in CityJSON 1.0): integer part and decimal part.
struct Lod {
  int major = 0;
  int minor = 0;
  bool operator<(const Lod& o) const { return major != o.major ? major < o.major : minor < o.minor; }
  bool operator==(const Lod& o) const { return major == o.major && minor == o.minor; }
};

// "transform": source coordinate = integer vertex * scale + translate.
struct VertexTransform {
  std::array<double, 3> scale{1, 1, 1};
  std::array<double, 3> translate{0, 0, 0};
};

// nlohmann's messages start with "[json.exception.parse_error.101] "; the tag means nothing to a user.
std::string without_json_tag(const std::string& what) {
  if (what.rfind("[json.exception.", 0) != 0) return what;
  const auto end = what.find("] ");
  return end == std::string::npos ? what : what.substr(end + 2);
}

json parse_json(const std::string& text, const std::string& name, const std::string& where) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers like 1e999
    fail(name, where + "malformed JSON: " + without_json_tag(e.what()));
  }
}

// Geometry types with surfaces, by how many array levels sit above the surfaces.
int surface_depth(const std::string& type) {
  if (type == "MultiSurface" || type == "CompositeSurface") return 0;
  if (type == "Solid") return 1;
  if (type == "MultiSolid" || type == "CompositeSolid") return 2;
  return -1;
}

// Reads one CityJSON document, or the header and features of a CityJSONSeq stream, into a
// MeshBuilder. Errors are prefixed with `where_` (the line of a CityJSONSeq feature).
class CityJsonReader {
 public:
  CityJsonReader(const std::string& name, const Taxonomy& taxonomy, int lod)
      : name_(name), taxonomy_(taxonomy), lod_(lod), builder_(taxonomy) {
    if (lod < 0 || lod > 3) fail(name, "LoD must be 1, 2, 3 or 0 (highest), got " + std::to_string(lod));
  }

  void set_where(const std::string& where) { where_ = where; }

  // The root object (a document or the first line of a sequence): version, CRS, transform, templates.
  void read_header(const json& doc) {
    if (!doc.is_object()) error("top level is not a JSON object");
    if (!doc.contains("type")) error("not a CityJSON file: no \"type\" member");
    const std::string type = string_member(doc, "type", "top level");
    if (type != "CityJSON") error("\"type\" is '" + type + "', expected 'CityJSON'");
    version_ = string_member(doc, "version", "top level");
    if (doc.contains("metadata") && doc["metadata"].is_object()) {
      const json& rs = doc["metadata"].value("referenceSystem", json());
      if (rs.is_string()) crs_ = rs.get<std::string>();
    }
    read_transform(doc);
    read_templates(doc);
  }

  // "CityObjects" with their "vertices" (the document's, or one CityJSONFeature's).
  // `progress` (optional) advances once per CityObject.
  void add_objects(const json& container, Progress* progress) {
    const json& objects = member(container, "CityObjects", "top level");
    if (!objects.is_object()) error("\"CityObjects\" is not an object");
    const std::vector<Point> vertices = read_vertices(member(container, "vertices", "top level"));
    for (const auto& [id, object] : objects.items()) {
      add_object(objects, id, object, vertices);
      if (progress) progress->advance();
    }
  }

  SemanticMesh finish() {
    for (const auto& [type, count] : skipped_types_)
      log_verbose(cat(name_, ": skipped ", count, " CityObject(s) of type ", type, " (not in the taxonomy)"));
    if (surfaces_seen_ == 0) {
      if (lods_present_.empty() || lod_ == 0) fail(name_, "contains no building geometry with surfaces");
      std::string present;
      for (int l : lods_present_) present += (present.empty() ? "" : ", ") + std::to_string(l);
      fail(name_, "no building geometry at LoD " + std::to_string(lod_) + " (the file has LoD " + present + ")");
    }
    if (builder_.degenerate_polygons() > 0)
      log_verbose(cat(name_, ": ", builder_.degenerate_polygons(), " degenerate polygon(s) skipped"));
    SemanticMesh mesh = builder_.finish();
    mesh.source_path = name_;
    mesh.format = "CityJSON";
    mesh.version = version_;
    mesh.crs = crs_;
    mesh.lod = lod_ != 0 ? lod_ : max_lod_used_;
    return mesh;
  }

 private:
  // What one selected geometry of one CityObject contributes to, with entities made on first use
  // so that objects and surfaces without polygons at the chosen LoD leave no entities behind.
  struct GeometryScope {
    const json* objects = nullptr;
    std::string object_id;
    int object_class = -1;
    int geometry_index = 0;
    const json* surfaces = nullptr;     // semantics "surfaces", or nullptr
    std::vector<int> semantic_entity;   // per semantic surface, -1 until made
    int plain_entity = -1;              // the "surface" entity for faces without semantics
  };

  [[noreturn]] void error(const std::string& what) const { fail(name_, where_ + what); }
  [[noreturn]] void object_error(const std::string& id, const std::string& what) const {
    error("object '" + id + "': " + what);
  }

  const json& member(const json& obj, const char* key, const std::string& context) const {
    auto it = obj.find(key);
    if (it == obj.end()) error(context + ": missing \"" + key + "\"");
    return *it;
  }
  std::string string_member(const json& obj, const char* key, const std::string& context) const {
    const json& v = member(obj, key, context);
    if (!v.is_string()) error(context + ": \"" + key + "\" is not a string");
    return v.get<std::string>();
  }

  std::array<double, 3> number_triple(const json& v, const std::string& what) const {
    if (!v.is_array() || v.size() != 3) error(what + " must be an array of 3 numbers");
    std::array<double, 3> r{};
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number()) error(what + " must be an array of 3 numbers, got " + v.dump());
      r[i] = v[i].get<double>();
      if (!std::isfinite(r[i])) error(what + " is not finite");
    }
    return r;
  }

  void read_transform(const json& doc) {
    auto it = doc.find("transform");
    if (it == doc.end()) return;  // optional in CityJSON 1.0: vertices are real coordinates
    if (!it->is_object()) error("\"transform\" is not an object");
    auto scale = it->find("scale");
    auto translate = it->find("translate");
    if (scale == it->end()) error("\"transform\" has no \"scale\"");
    if (translate == it->end()) error("\"transform\" has no \"translate\"");
    transform_.scale = number_triple(*scale, "transform.scale");
    transform_.translate = number_triple(*translate, "transform.translate");
    for (double s : transform_.scale)
      if (s == 0) error("transform.scale has a zero component: " + scale->dump());
  }

  std::vector<Point> read_vertices(const json& list) const {
    if (!list.is_array()) error("\"vertices\" is not an array");
    std::vector<Point> out;
    out.reserve(list.size());
    for (size_t i = 0; i < list.size(); ++i) {
      const json& v = list[i];
      if (!v.is_array() || v.size() != 3) error("vertex " + std::to_string(i) + " is not an array of 3 numbers");
      Point p{};
      for (int k = 0; k < 3; ++k) {
        if (v[k].is_null()) error("vertex " + std::to_string(i) + " has a null coordinate");
        if (!v[k].is_number()) error("vertex " + std::to_string(i) + " has a non-numeric coordinate " + v[k].dump());
        p[k] = v[k].get<double>() * transform_.scale[k] + transform_.translate[k];
        if (!std::isfinite(p[k])) error("vertex " + std::to_string(i) + " has a non-finite coordinate");
      }
      out.push_back(p);
    }
    return out;
  }

  // "geometry-templates": template geometries with their own real-coordinate vertices.
  void read_templates(const json& doc) {
    auto it = doc.find("geometry-templates");
    if (it == doc.end()) return;
    if (!it->is_object()) error("\"geometry-templates\" is not an object");
    templates_ = &member(*it, "templates", "geometry-templates");
    if (!templates_->is_array()) error("geometry-templates.templates is not an array");
    const json& tv = member(*it, "vertices-templates", "geometry-templates");
    if (!tv.is_array()) error("geometry-templates.vertices-templates is not an array");
    template_vertices_.reserve(tv.size());
    for (size_t i = 0; i < tv.size(); ++i)
      template_vertices_.push_back(number_triple(tv[i], "template vertex " + std::to_string(i)));
  }

  Lod parse_lod(const json& v, const std::string& id) const {
    if (v.is_number()) {  // CityJSON 1.0: 2 or 2.2
      const double d = v.get<double>();
      if (!(d >= 0 && d < 10)) object_error(id, "LoD " + v.dump() + " is out of range");
      const int major = static_cast<int>(d);
      return {major, static_cast<int>(std::lround((d - major) * 10))};
    }
    if (!v.is_string()) object_error(id, "geometry has no valid \"lod\"");
    const std::string s = v.get<std::string>();
    Lod lod;
    size_t i = 0;
    auto digits = [&](int& out) {
      const size_t start = i;
      out = 0;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && i - start < 3) out = out * 10 + (s[i++] - '0');
      return i > start;
    };
    bool ok = digits(lod.major);
    if (ok && i < s.size() && s[i] == '.') {
      ++i;
      ok = digits(lod.minor);
    }
    if (!ok || i != s.size()) object_error(id, "invalid LoD '" + s + "'");
    return lod;
  }

  // The template a GeometryInstance refers to, or nullptr (with a warning) if it cannot be used.
  const json* instance_template(const json& g, const std::string& id) const {
    const json& t = member(g, "template", "object '" + id + "' GeometryInstance");
    if (!templates_ || !t.is_number_unsigned() || t.get<size_t>() >= templates_->size())
      object_error(id, "GeometryInstance refers to a missing template " + t.dump());
    const json& tmpl = (*templates_)[t.get<size_t>()];
    if (!tmpl.is_object() || !tmpl.contains("type") || !tmpl["type"].is_string() ||
        surface_depth(tmpl["type"].get<std::string>()) < 0) {
      log_warn(cat(name_, ": object '", id, "': skipping a GeometryInstance whose template has no surfaces"));
      return nullptr;
    }
    return &tmpl;
  }

  // The geometry's LoD, or nothing for geometries without surfaces (points, lines).
  std::optional<Lod> geometry_lod(const json& g, const std::string& id) const {
    if (!g.is_object()) object_error(id, "a geometry is not an object");
    const std::string type = string_member(g, "type", "object '" + id + "' geometry");
    if (type == "MultiPoint" || type == "MultiLineString") return std::nullopt;
    if (type == "GeometryInstance") {
      const json* tmpl = instance_template(g, id);
      if (!tmpl) return std::nullopt;
      return parse_lod(member(*tmpl, "lod", "object '" + id + "' template"), id);
    }
    if (surface_depth(type) < 0) object_error(id, "unknown geometry type '" + type + "'");
    return parse_lod(member(g, "lod", "object '" + id + "' geometry"), id);
  }

  // The nearest object up the "parents" chain of `id` whose type is a level-3 class (the Building or
  // BuildingPart that a BuildingPart or BuildingInstallation lies in); "" if there is none.
  std::string enclosing_building(const json& objects, const std::string& id) const {
    std::string current = id;
    for (size_t steps = 0; steps <= objects.size(); ++steps) {  // bounded: parents may form a cycle
      auto it = objects.find(current);
      if (it == objects.end() || !it->is_object()) return "";
      const json& parents = it->value("parents", json());
      if (!parents.is_array() || parents.empty() || !parents[0].is_string()) return "";
      current = parents[0].get<std::string>();
      auto parent = objects.find(current);
      if (parent == objects.end() || !parent->is_object()) return "";
      const json& type = parent->value("type", json());
      if (!type.is_string()) continue;
      const auto c = taxonomy_.class_of_type(type.get<std::string>());
      if (c && taxonomy_.classes[*c].level == 3) return current;
    }
    return "";
  }

  void add_object(const json& objects, const std::string& id, const json& object,
                  const std::vector<Point>& vertices) {
    if (!object.is_object()) object_error(id, "is not a JSON object");
    const std::string type = string_member(object, "type", "object '" + id + "'");
    const auto object_class = taxonomy_.class_of_type(type);
    if (!object_class) {
      ++skipped_types_[type];
      return;
    }
    auto git = object.find("geometry");
    if (git == object.end()) return;
    if (!git->is_array()) object_error(id, "\"geometry\" is not an array");
    const json& geometries = *git;

    // LoD selection: of the geometries at the wanted integer LoD (or at the highest one for
    // lod 0), only those with the highest full LoD, so 1.2 and 1.3 copies do not overlap.
    std::vector<std::optional<Lod>> lods;
    std::optional<Lod> best;
    for (const json& g : geometries) {
      lods.push_back(geometry_lod(g, id));
      if (!lods.back()) continue;
      lods_present_.insert(lods.back()->major);
      if ((lod_ == 0 || lods.back()->major == lod_) && (!best || *best < *lods.back())) best = lods.back();
    }
    if (!best) return;
    max_lod_used_ = std::max(max_lod_used_, best->major);
    for (size_t gi = 0; gi < geometries.size(); ++gi) {
      if (!lods[gi] || !(*lods[gi] == *best)) continue;
      GeometryScope scope;
      scope.objects = &objects;
      scope.object_id = id;
      scope.object_class = *object_class;
      scope.geometry_index = static_cast<int>(gi);
      add_geometry(scope, geometries[gi], vertices);
    }
  }

  void add_geometry(GeometryScope& scope, const json& g, const std::vector<Point>& vertices) {
    const std::string& id = scope.object_id;
    const std::string type = g["type"].get<std::string>();
    if (type != "GeometryInstance") {
      add_surfaces(scope, g, vertices);
      return;
    }
    // An instance: template vertices mapped by the 4x4 matrix, then moved to the reference point.
    const json& tmpl = *instance_template(g, id);
    const json& ref = member(g, "boundaries", "object '" + id + "' GeometryInstance");
    if (!ref.is_array() || ref.size() != 1) object_error(id, "GeometryInstance boundaries must hold one vertex index");
    const Point& anchor = vertices.at(vertex_index(ref[0], vertices.size(), id));
    const json& m = member(g, "transformationMatrix", "object '" + id + "' GeometryInstance");
    if (!m.is_array() || m.size() != 16) object_error(id, "transformationMatrix must hold 16 numbers");
    double M[16];
    for (int i = 0; i < 16; ++i) {
      if (!m[i].is_number()) object_error(id, "transformationMatrix must hold 16 numbers");
      M[i] = m[i].get<double>();
    }
    std::vector<Point> placed;
    placed.reserve(template_vertices_.size());
    for (const Point& v : template_vertices_) {
      Point p{};
      for (int r = 0; r < 3; ++r)
        p[r] = M[4 * r] * v[0] + M[4 * r + 1] * v[1] + M[4 * r + 2] * v[2] + M[4 * r + 3] + anchor[r];
      for (double c : p)
        if (!std::isfinite(c)) object_error(id, "GeometryInstance gives a non-finite coordinate");
      placed.push_back(p);
    }
    add_surfaces(scope, tmpl, placed);
  }

  size_t vertex_index(const json& v, size_t count, const std::string& id) const {
    if (!v.is_number_unsigned()) object_error(id, "vertex index " + v.dump() + " is not a non-negative integer");
    const auto i = v.get<uint64_t>();
    if (i >= count)
      object_error(id, "vertex index " + std::to_string(i) + " out of range (" + std::to_string(count) + " vertices)");
    return static_cast<size_t>(i);
  }

  // Walks boundaries and semantics "values" together down to the surfaces.
  void add_surfaces(GeometryScope& scope, const json& g, const std::vector<Point>& vertices) {
    const std::string& id = scope.object_id;
    const json& boundaries = member(g, "boundaries", "object '" + id + "' geometry");
    const json* values = nullptr;
    scope.surfaces = nullptr;
    auto sem = g.find("semantics");
    if (sem != g.end() && !sem->is_null()) {
      if (!sem->is_object()) object_error(id, "\"semantics\" is not an object");
      scope.surfaces = &member(*sem, "surfaces", "object '" + id + "' semantics");
      if (!scope.surfaces->is_array()) object_error(id, "semantics \"surfaces\" is not an array");
      values = &member(*sem, "values", "object '" + id + "' semantics");
      if (values->is_null()) values = nullptr;
      scope.semantic_entity.assign(scope.surfaces->size(), -1);
    }
    int surface_index = 0;
    walk(scope, boundaries, values, surface_depth(g["type"].get<std::string>()), vertices, surface_index);
  }

  void walk(GeometryScope& scope, const json& boundaries, const json* values, int depth,
            const std::vector<Point>& vertices, int& surface_index) {
    const std::string& id = scope.object_id;
    if (!boundaries.is_array()) object_error(id, "geometry boundaries are not nested arrays");
    if (values && (!values->is_array() || values->size() != boundaries.size()))
      object_error(id, "semantics \"values\" do not match the boundaries");
    for (size_t i = 0; i < boundaries.size(); ++i) {
      const json* v = values ? &(*values)[i] : nullptr;
      if (depth > 0) {
        walk(scope, boundaries[i], v && !v->is_null() ? v : nullptr, depth - 1, vertices, surface_index);
      } else {
        add_surface(scope, boundaries[i], v, vertices, surface_index++);
      }
    }
  }

  void add_surface(GeometryScope& scope, const json& surface, const json* value,
                   const std::vector<Point>& vertices, int surface_index) {
    const std::string& id = scope.object_id;
    if (!surface.is_array()) object_error(id, "a surface is not an array of rings");
    if (surface.empty()) return;
    std::vector<Ring> rings;
    rings.reserve(surface.size());
    for (const json& ring : surface) {
      if (!ring.is_array()) object_error(id, "a ring is not an array of vertex indices");
      Ring r;
      r.reserve(ring.size());
      for (const json& v : ring) r.push_back(vertices[vertex_index(v, vertices.size(), id)]);
      rings.push_back(std::move(r));
    }
    int semantic = -1;
    if (value && !value->is_null()) {
      if (!value->is_number_unsigned() || value->get<uint64_t>() >= scope.surfaces->size())
        object_error(id, "semantics value " + value->dump() + " is not an index of \"surfaces\"");
      semantic = static_cast<int>(value->get<uint64_t>());
    }
    ++surfaces_seen_;
    const auto [face_class, entity] = classify(scope, semantic);
    const std::string polygon_id = id + "/" + std::to_string(scope.geometry_index) + "/" + std::to_string(surface_index);
    try {
      builder_.add_polygon(rings, face_class, entity, polygon_id);
    } catch (const Error& e) {  // the builder's message names the polygon, not the file
      error(e.what());
    }
  }

  // Class of a semantic surface's type, or nothing (no semantics, or a type the taxonomy lacks).
  std::optional<int> semantic_class(const GeometryScope& scope, int semantic) {
    if (semantic < 0) return std::nullopt;
    const json& s = (*scope.surfaces)[semantic];
    if (!s.is_object() || !s.contains("type") || !s["type"].is_string())
      object_error(scope.object_id, "semantic surface " + std::to_string(semantic) + " has no \"type\"");
    const std::string type = s["type"].get<std::string>();
    const auto c = taxonomy_.class_of_type(type);
    if (!c && warned_semantic_types_.insert(type).second)
      log_warn(cat(name_, ": semantic surface type '", type, "' is not in the taxonomy; its faces get class 'surface'"));
    if (c && taxonomy_.classes[*c].level == 3) return std::nullopt;  // a "building" face means nothing
    return c;
  }

  int surface_class() const {
    const int c = taxonomy_.find("surface");
    if (c < 0) fail(name_, "the taxonomy has no class 'surface' for faces without semantics");
    return c;
  }

  bool is_building_object(const GeometryScope& scope) const {
    return taxonomy_.classes[scope.object_class].level == 3;
  }

  // The entity of a CityObject: a root building at level 3 without parent; a BuildingPart (level 3)
  // or an installation (level 2) under the entity of the building or part it lies in (building ->
  // part -> part ...), made first so that a parent always precedes its children.
  int object_entity(const json& objects, const std::string& id, int object_class) {
    if (auto it = object_entity_.find(id); it != object_entity_.end()) return it->second;
    std::vector<std::string> chain;  // the enclosing buildings and parts without an entity yet, innermost first
    std::set<std::string> seen = {id};
    int parent = -1;
    for (std::string up = enclosing_building(objects, id); !up.empty(); up = enclosing_building(objects, up)) {
      if (auto it = object_entity_.find(up); it != object_entity_.end()) {
        parent = it->second;
        break;
      }
      if (!seen.insert(up).second) object_error(id, "its \"parents\" chain comes back to \"" + up + "\"");
      chain.push_back(up);
    }
    for (auto up = chain.rbegin(); up != chain.rend(); ++up) {
      const int c = *taxonomy_.class_of_type(objects[*up]["type"].get<std::string>());
      parent = builder_.add_entity(taxonomy_.classes[c].level, c, parent, *up);
      object_entity_.emplace(*up, parent);
    }
    const int e = builder_.add_entity(taxonomy_.classes[object_class].level, object_class, parent, id);
    object_entity_.emplace(id, e);
    return e;
  }
  int object_entity(const GeometryScope& scope) {
    return object_entity(*scope.objects, scope.object_id, scope.object_class);
  }

  // The level-2 entity of a building's faces that carry no semantics.
  int plain_entity(GeometryScope& scope) {
    if (scope.plain_entity < 0) {
      const int parent = object_entity(scope);
      scope.plain_entity = builder_.add_entity(2, surface_class(), parent,
                                               scope.object_id + "/" + std::to_string(scope.geometry_index));
    }
    return scope.plain_entity;
  }

  std::string semantic_source_id(const GeometryScope& scope, int semantic) const {
    const json& s = (*scope.surfaces)[semantic];
    const json& sid = s.value("id", json());
    if (sid.is_string()) return sid.get<std::string>();
    return scope.object_id + "/" + std::to_string(scope.geometry_index) + "/semantics/" + std::to_string(semantic);
  }

  // The entity of semantic surface `semantic` with class `c`: a surface under the building, or an
  // opening under the surface its "parent" names.
  int semantic_entity(GeometryScope& scope, int semantic, int c) {
    int& e = scope.semantic_entity[semantic];
    if (e >= 0) return e;
    const int level = taxonomy_.classes[c].level;
    int parent = -1;
    if (!is_building_object(scope) || level != 1) {
      parent = object_entity(scope);
    } else {
      const json& p = (*scope.surfaces)[semantic].value("parent", json());
      if (!p.is_null()) {
        if (!p.is_number_unsigned() || p.get<uint64_t>() >= scope.surfaces->size())
          object_error(scope.object_id, "semantic surface " + std::to_string(semantic) + " has an invalid parent " + p.dump());
        const int pi = static_cast<int>(p.get<uint64_t>());
        const auto pc = semantic_class(scope, pi);
        if (pi != semantic && pc && taxonomy_.classes[*pc].level == 2) parent = semantic_entity(scope, pi, *pc);
      }
      if (parent < 0) parent = plain_entity(scope);  // an opening without a wall still sits on a surface
    }
    e = builder_.add_entity(level, c, parent, semantic_source_id(scope, semantic));
    return e;
  }

  // Face class and innermost entity of a face with semantic surface `semantic` (-1: none).
  std::pair<int, int> classify(GeometryScope& scope, int semantic) {
    const auto c = semantic_class(scope, semantic);
    if (!is_building_object(scope)) {
      // An installation: its own entity, openings in it below that.
      if (c && taxonomy_.classes[*c].level == 1) return {*c, semantic_entity(scope, semantic, *c)};
      return {c ? *c : scope.object_class, object_entity(scope)};
    }
    if (!c) return {surface_class(), plain_entity(scope)};
    return {*c, semantic_entity(scope, semantic, *c)};
  }

  const std::string name_;
  const Taxonomy& taxonomy_;
  const int lod_;
  MeshBuilder builder_;
  std::string where_;

  std::string version_, crs_;
  VertexTransform transform_;
  const json* templates_ = nullptr;  // points into the header document, which outlives the reader's use
  std::vector<Point> template_vertices_;

  std::map<std::string, int> object_entity_;  // CityObject id -> its entity
  std::map<std::string, size_t> skipped_types_;
  std::set<std::string> warned_semantic_types_;
  std::set<int> lods_present_;
  int max_lod_used_ = 0;
  size_t surfaces_seen_ = 0;
};

// Converts what nlohmann throws on an unexpected value type into an error naming the file; the
// reader checks types itself, this only keeps a missed check from becoming an internal error.
template <class F>
SemanticMesh guarded(const std::string& name, F&& read) {
  try {
    return read();
  } catch (const json::exception& e) {
    fail(name, "invalid CityJSON: " + without_json_tag(e.what()));
  }
}

}  // namespace

SemanticMesh parse_cityjson(const std::string& text, const std::string& name, const Taxonomy& taxonomy, int lod) {
  return guarded(name, [&] {
    const json doc = parse_json(text, name, "");
    CityJsonReader reader(name, taxonomy, lod);
    reader.read_header(doc);
    const json& objects = doc.value("CityObjects", json());
    Progress progress("reading CityJSON objects", objects.is_object() ? objects.size() : 0, "objects");
    reader.add_objects(doc, &progress);
    return reader.finish();
  });
}

SemanticMesh parse_cityjson_seq(const std::string& text, const std::string& name, const Taxonomy& taxonomy,
                                int lod) {
  return guarded(name, [&] {
    CityJsonReader reader(name, taxonomy, lod);
    json header;
    bool have_header = false;
    const size_t lines = std::count(text.begin(), text.end(), '\n') + (text.empty() || text.back() == '\n' ? 0 : 1);
    Progress progress("reading CityJSONSeq lines", lines, "lines");
    std::istringstream in(text);
    std::string line;
    for (size_t line_no = 1; std::getline(in, line); ++line_no, progress.advance()) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string where = "line " + std::to_string(line_no) + ": ";
      reader.set_where(where);
      json doc = parse_json(line, name, where);
      if (!have_header) {
        header = std::move(doc);  // kept alive: the reader refers to its templates
        reader.read_header(header);
        have_header = true;
        continue;
      }
      if (!doc.is_object() || doc.value("type", json()) != "CityJSONFeature")
        fail(name, where + "expected a CityJSONFeature object");
      reader.add_objects(doc, nullptr);
    }
    reader.set_where("");
    if (!have_header) fail(name, "empty CityJSONSeq file");
    return reader.finish();
  });
}

bool is_cityjson_seq(const std::string& text) {
  const size_t after_bom = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  const size_t start = text.find_first_not_of(" \t\r\n", after_bom);
  if (start == std::string::npos || text[start] != '{') return false;
  const size_t end = text.find('\n', start);
  if (end == std::string::npos || text.find_first_not_of(" \t\r\n", end) == std::string::npos) return false;
  return json::accept(text.substr(start, end - start));
}

SemanticMesh read_cityjson(const std::string& path, const Taxonomy& taxonomy, int lod) {
  const std::string text = read_text_file(path);
  return is_cityjson_seq(text) ? parse_cityjson_seq(text, path, taxonomy, lod) : parse_cityjson(text, path, taxonomy, lod);
}

}  // namespace cls
