// Definitions of every number: docs/evaluation.md.
#include "eval/evaluation_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

namespace cls {
namespace {

using Methods = std::vector<std::pair<std::string, nlohmann::json>>;

std::string pct(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", 100.0 * v);
  return buf;
}

std::string fixed2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// A reference row (the label maps) is shown but neither bolded nor compared against.
bool is_reference(const nlohmann::json& j) { return j.is_object() && j.value("reference", false); }

// Whether methods[m]'s value v is strictly better than every other (non-reference) method's; ties stay plain.
bool strictly_best(const Methods& methods, size_t m, double v, const std::function<double(size_t)>& value_of,
                   bool higher_better) {
  if (is_reference(methods[m].second) || std::isnan(v)) return false;
  int compared = 0;
  for (size_t o = 0; o < methods.size(); ++o) {
    if (o == m || is_reference(methods[o].second)) continue;
    const double w = value_of(o);
    if (std::isnan(w)) continue;
    ++compared;
    if (!(higher_better ? v > w + 1e-12 : v < w - 1e-12)) return false;
  }
  return compared > 0;
}

// One column of a per-method table; NaN = the method has no such score (the label maps have no 3D).
struct Column {
  std::string header;
  std::function<double(const nlohmann::json&)> value;
  bool percent = true;
  bool higher_better = true;
  bool compared = true;  // false: a reference value, never bold
};

double get(const nlohmann::json& j, const std::string& a, const std::string& b) {
  return j.contains(a) && j[a].is_object() && j[a].contains(b) && j[a][b].is_number() ? j[a][b].get<double>()
                                                                                     : std::nan("");
}

// The mIoU of the best labelling of the Gaussians (`group`.best_labelling.miou).
double best_labelling(const nlohmann::json& j, const std::string& group) {
  return j.contains(group) ? get(j[group], "best_labelling", "miou") : std::nan("");
}

TableCell cell(double v, bool best, bool percent) {
  if (std::isnan(v)) return {"-", false};
  return {percent ? pct(v) : fixed2(v), best};
}

// One row per method, one cell per column; the best value of each column among the methods in bold.
ResultTable method_table(std::string id, std::string title, std::string note, const Methods& methods,
                         const std::vector<Column>& cols) {
  ResultTable t{std::move(id), std::move(title), std::move(note), {"Method"}, {}};
  for (const Column& c : cols) t.header.push_back(c.header);
  for (size_t m = 0; m < methods.size(); ++m) {
    std::vector<TableCell> cells;
    for (const Column& c : cols) {
      const double v = c.value(methods[m].second);
      const bool best =
          c.compared && strictly_best(methods, m, v, [&](size_t o) { return c.value(methods[o].second); }, c.higher_better);
      cells.push_back(cell(v, best, c.percent));
    }
    t.rows.emplace_back(methods[m].first, std::move(cells));
  }
  return t;
}

// The columns of Tables 1 and 1b: 2D scores of `group`.
std::vector<Column> columns_2d(const std::string& group) {
  auto of = [group](const char* field) { return [group, field](const nlohmann::json& j) { return get(j, group, field); }; };
  return {{"Cov. GT", of("gt_coverage")}, {"Cov.", of("coverage")}, {"mIoU", of("miou")}, {"wIoU", of("wiou")},
          {"Acc", of("accuracy")}};
}

// The columns of Tables 2 and 2b: 3D scores of `group`.
std::vector<Column> columns_3d(const std::string& group) {
  auto of = [group](const char* field) { return [group, field](const nlohmann::json& j) { return get(j, group, field); }; };
  return {{"Cov.", of("coverage")},
          {"Dist.", of("mean_distance"), false, false},
          {"mIoU", of("miou")},
          {"wIoU", of("wiou")},
          {"mIoU, best labelling", [group](const nlohmann::json& j) { return best_labelling(j, group); }, true, true,
           false}};
}

// Table 3: per class (of every method, in first-seen order) IoU, precision and recall of each method.
ResultTable per_class_table(const Methods& methods) {
  ResultTable t{"table-3",
                "Table 3: per class, 2D (per image, averaged over the images that contain the class; percentages)",
                "",
                {"Class"},
                {}};
  for (const auto& m : methods) {
    t.header.push_back(m.first + " IoU");
    t.header.push_back("Precision");
    t.header.push_back("Recall");
  }
  std::vector<std::string> classes;
  for (const auto& m : methods)
    if (m.second.contains("classes") && m.second["classes"].is_array())
      for (const auto& c : m.second["classes"])
        if (c.is_string() && std::find(classes.begin(), classes.end(), c.get<std::string>()) == classes.end())
          classes.push_back(c);
  for (const std::string& c : classes) {
    auto score = [&](size_t m, const char* metric) {
      const nlohmann::json& j = methods[m].second;
      return j.contains("2d") && j["2d"].contains("per_class") && j["2d"]["per_class"].contains(c)
                 ? get(j["2d"]["per_class"], c, metric)
                 : std::nan("");
    };
    std::vector<TableCell> cells;
    for (size_t m = 0; m < methods.size(); ++m)
      for (const char* metric : {"iou", "precision", "recall"}) {
        const double v = score(m, metric);
        cells.push_back(cell(v, strictly_best(methods, m, v, [&](size_t o) { return score(o, metric); }, true), true));
      }
    t.rows.emplace_back(c, std::move(cells));
  }
  return t;
}

}  // namespace

std::vector<ResultTable> evaluation_tables(const Methods& methods) {
  std::vector<ResultTable> tables;
  tables.push_back(method_table("table-1", "Table 1: 2D (the GT cloud projected, or label images; percentages)",
                                "Cov. GT: pixels with a valid GT label; Cov.: valid GT pixels with a prediction above "
                                "the threshold; scores over those.",
                                methods, columns_2d("2d")));
  if (std::any_of(methods.begin(), methods.end(), [](const auto& m) { return m.second.contains("2d_covered"); }))
    tables.push_back(method_table("table-1b", "Table 1b: 2D on the GT pixels the city model covers (coverage M = 1)",
                                  "", methods, columns_2d("2d_covered")));
  if (std::any_of(methods.begin(), methods.end(), [](const auto& m) { return m.second.contains("2d_train"); }))
    tables.push_back(method_table("table-1c", "Table 1c: 2D on the training views (Tables 1 and 1b: the held-out views)",
                                  "The views the photometric and language training saw; reported apart, not the result.",
                                  methods, columns_2d("2d_train")));
  if (std::any_of(methods.begin(), methods.end(), [](const auto& m) { return m.second.contains("2d_relevancy"); }))
    tables.push_back(method_table(
        "table-1d", "Table 1d: 2D with LangSplat's relevancy (Table 1: the plain cosine, the default)",
        "The held-out views of Table 1, each class's map LangSplat's relevancy against its canonical phrases "
        "(object, things, stuff, texture) instead of the cosine, then the same normalisation, argmax and threshold.",
        methods, columns_2d("2d_relevancy")));
  // No 3D tables without a labelled cloud (label images alone).
  if (std::any_of(methods.begin(), methods.end(), [](const auto& m) { return m.second.contains("3d"); })) {
    tables.push_back(method_table(
        "table-2", "Table 2: 3D (nearest Gaussian centre)",
        "Cov.: GT points with a Gaussian centre within the radius (%); Dist.: mean match distance (scene units); "
        "best labelling: the mIoU when every Gaussian holds the majority class of the GT points matched to it (the "
        "labelling with the highest accuracy these Gaussians allow; a reference, not compared).",
        methods, columns_3d("3d")));
    tables.push_back(method_table("table-2b", "Table 2b: 3D over the GT points visible in some view", "", methods,
                                  columns_3d("3d_visible")));
  }
  tables.push_back(per_class_table(methods));
  return tables;
}

std::string tables_markdown(const std::vector<ResultTable>& tables) {
  std::ostringstream md;
  for (size_t i = 0; i < tables.size(); ++i) {
    const ResultTable& t = tables[i];
    md << (i ? "\n" : "") << "### " << t.title << "\n\n";
    if (!t.note.empty()) md << t.note << "\n\n";
    md << "|";
    for (const std::string& h : t.header) md << " " << h << " |";
    md << "\n|---|";
    for (size_t c = 1; c < t.header.size(); ++c) md << "---:|";
    md << "\n";
    for (const auto& [name, cells] : t.rows) {
      md << "| " << name << " |";
      for (const TableCell& c : cells) md << " " << (c.bold ? "**" + c.text + "**" : c.text) << " |";
      md << "\n";
    }
  }
  return md.str();
}

}  // namespace cls
