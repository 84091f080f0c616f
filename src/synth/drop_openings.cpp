#include "synth/drop_openings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "citymodel/city_model.h"
#include "citymodel/gml_vocabulary.h"
#include "core/error.h"
#include "synth/random.h"

namespace cls::synth {

namespace {

// Which `count` of `total` openings to drop: a seeded Fisher-Yates shuffle's first `count`.
std::vector<bool> choose(int total, int count, uint64_t seed) {
  std::vector<int> order(total);
  std::iota(order.begin(), order.end(), 0);
  Rng rng(seed, Stream::DropOpenings);
  for (int i = total - 1; i > 0; --i) std::swap(order[i], order[rng.below(i + 1)]);
  std::vector<bool> chosen(total, false);
  for (int i = 0; i < count; ++i) chosen[order[i]] = true;
  return chosen;
}

int count_of(double fraction, int total) { return static_cast<int>(std::lround(fraction * total)); }

// An opening as the reader sees one: a level-1 feature defined here, not a reference to one elsewhere.
bool is_opening(pugi::xml_node n) {
  return n.type() == pugi::node_element && structural_level(local_name(n)) == 1 && !prefixed_attribute(n, "href");
}

pugi::xml_node first_element_child(pugi::xml_node n) {
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) return c;
  return {};
}

// GML's naming rule: features are UpperCamelCase, properties lowerCamelCase. The feature an opening
// sits in is its nearest UpperCamelCase ancestor (WallSurface <- opening / fillingSurface <- Window).
pugi::xml_node host_feature(pugi::xml_node opening) {
  for (pugi::xml_node a = opening.parent(); a && a.type() == pugi::node_element; a = a.parent()) {
    const std::string_view name = local_name(a);
    if (!name.empty() && std::isupper(static_cast<unsigned char>(name[0]))) return a;
  }
  return {};
}

// Moves the opening's surface geometry (the lodN properties the reader reads) into the host: into the
// host's aggregate of the same property where it has one (a MultiSurface gains the opening's surface
// members), else as a property of its own. (Nodes are collected first: moving them while walking a
// sibling list would end the walk.)
void merge_into(pugi::xml_node opening, pugi::xml_node host) {
  std::vector<pugi::xml_node> properties;
  for_each_element_child(opening, [&](pugi::xml_node c) {
    if (surface_lod(local_name(c)) >= 0) properties.push_back(c);
  });
  for (pugi::xml_node property : properties) {
    pugi::xml_node target;
    for_each_element_child(host, [&](pugi::xml_node c) {
      if (!target && local_name(c) == local_name(property)) target = first_element_child(c);
    });
    const pugi::xml_node source = first_element_child(property);
    if (target && source && local_name(target) == local_name(source)) {
      std::vector<pugi::xml_node> members;
      for_each_element_child(source, [&](pugi::xml_node m) { members.push_back(m); });
      for (pugi::xml_node m : members) target.append_move(m);
    } else {
      host.append_move(property);
    }
  }
}

DroppedOpenings drop_in_citygml(const std::string& path, const std::string& text, double fraction, uint64_t seed) {
  pugi::xml_document doc;
  const unsigned options = pugi::parse_default | pugi::parse_declaration | pugi::parse_ws_pcdata | pugi::parse_comments;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), options);
  if (!parsed) fail(path, std::string("not well-formed XML: ") + parsed.description());
  std::vector<pugi::xml_node> openings;
  struct Collect : pugi::xml_tree_walker {
    std::vector<pugi::xml_node>* out;
    bool for_each(pugi::xml_node& n) override {
      if (is_opening(n)) out->push_back(n);
      return true;
    }
  } collect;
  collect.out = &openings;
  doc.traverse(collect);

  DroppedOpenings result;
  result.total = static_cast<int>(openings.size());
  const std::vector<bool> chosen = choose(result.total, count_of(fraction, result.total), seed);
  for (int i = 0; i < result.total; ++i) {
    if (!chosen[i]) continue;
    const pugi::xml_node opening = openings[i];
    const pugi::xml_node host = host_feature(opening);
    if (!host)
      fail(path, std::string("opening \"") + opening.attribute("gml:id").value() + "\" (" + opening.name() +
                     ") is in no surface to merge it into");
    merge_into(opening, host);
    // The opening leaves with the property that holds it (bldg:opening, con:fillingSurface).
    const pugi::xml_node holder = opening.parent() == host ? opening : opening.parent();
    holder.parent().remove_child(holder);
    ++result.dropped;
  }
  std::ostringstream out;
  doc.save(out, "", pugi::format_raw);
  result.text = out.str();
  return result;
}

// Replaces semantic indices in a (nested) CityJSON "values" array.
void remap_values(nlohmann::ordered_json& values, const std::vector<nlohmann::ordered_json>& replacement) {
  if (values.is_array()) {
    for (auto& v : values) remap_values(v, replacement);
  } else if (values.is_number_integer()) {
    const auto s = values.get<int64_t>();
    if (s >= 0 && s < static_cast<int64_t>(replacement.size())) values = replacement[s];
  }
}

DroppedOpenings drop_in_cityjson(const std::string& path, const std::string& text, double fraction, uint64_t seed) {
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("CityObjects") || !doc["CityObjects"].is_object())
    fail(path, "not a CityJSON document (no \"CityObjects\" object)");
  // Every Window / Door semantic surface, as (semantics object, surface index).
  std::vector<std::pair<nlohmann::ordered_json*, size_t>> openings;
  for (auto& [id, object] : doc["CityObjects"].items()) {
    if (!object.contains("geometry") || !object["geometry"].is_array()) continue;
    for (auto& g : object["geometry"]) {
      if (!g.is_object() || !g.contains("semantics") || !g["semantics"].is_object()) continue;
      auto& semantics = g["semantics"];
      if (!semantics.contains("surfaces") || !semantics["surfaces"].is_array()) continue;
      for (size_t s = 0; s < semantics["surfaces"].size(); ++s) {
        const std::string type = semantics["surfaces"][s].value("type", "");
        if (type == "Window" || type == "Door") openings.emplace_back(&semantics, s);
      }
    }
  }
  DroppedOpenings result;
  result.total = static_cast<int>(openings.size());
  const std::vector<bool> chosen = choose(result.total, count_of(fraction, result.total), seed);
  for (int i = 0; i < result.total; ++i) {
    if (!chosen[i]) continue;
    auto& [semantics, s] = openings[i];
    auto& surfaces = (*semantics)["surfaces"];
    const nlohmann::ordered_json parent = surfaces[s].value("parent", nlohmann::ordered_json());
    const bool has_parent = parent.is_number_unsigned() && parent.get<size_t>() < surfaces.size();
    std::vector<nlohmann::ordered_json> replacement;
    for (size_t k = 0; k < surfaces.size(); ++k) replacement.emplace_back(k);
    replacement[s] = has_parent ? parent : nullptr;
    if (semantics->contains("values")) remap_values((*semantics)["values"], replacement);
    // The object stays in "surfaces" (indices of the others do not move) but no longer belongs to its parent.
    if (has_parent) {
      auto& siblings = surfaces[parent.get<size_t>()];
      if (siblings.contains("children") && siblings["children"].is_array()) {
        auto& children = siblings["children"];
        children.erase(std::remove(children.begin(), children.end(), nlohmann::ordered_json(s)), children.end());
      }
    }
    ++result.dropped;
  }
  result.text = doc.dump() + "\n";
  return result;
}

}  // namespace

DroppedOpenings drop_openings(const std::string& path, const std::string& text, double fraction, uint64_t seed) {
  if (!(fraction >= 0 && fraction <= 1))
    throw UsageError("--drop-openings: expected a fraction in [0, 1], got " + std::to_string(fraction));
  switch (detect_city_format(text)) {
    case CityFormat::CityGML: return drop_in_citygml(path, text, fraction, seed);
    case CityFormat::CityJSON: return drop_in_cityjson(path, text, fraction, seed);
    case CityFormat::CityJSONSeq: throw UsageError(path + ": --drop-openings reads CityGML and CityJSON documents, not CityJSONSeq");
    case CityFormat::Unknown: break;
  }
  fail(path, "neither CityGML nor CityJSON");
}

}  // namespace cls::synth
