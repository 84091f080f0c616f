#include "report/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/metrics_log.h"
#include "core/run_layout.h"
#include "eval/evaluation_tables.h"
#include "report/html.h"
#include "report/svg_chart.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Per-view image grids show the first views only: a page of hundreds of images helps nobody.
constexpr size_t kMaxViews = 12;

// The run's files relative to its directory, as the page links them.
const RunLayout kRun;

// A stage's record: run.json[name], or for a stage run once per method ("train-language/langsplat",
// docs/pipeline.md) run.json["train-language"]["langsplat"]; null when absent.
json stage_record(const json& run, const std::string& name) {
  const size_t slash = name.find('/');
  if (slash == std::string::npos) return run.contains(name) ? run[name] : json();
  const json& group = run.contains(name.substr(0, slash)) ? run[name.substr(0, slash)] : json();
  const std::string method = name.substr(slash + 1);
  return group.is_object() && group.contains(method) ? group[method] : json();
}

const char* const kStyle = R"css(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0;color:#1d232a;background:#fff}
main{max-width:1280px;margin:0 auto;padding:12px 24px 48px}
h1{font-size:24px;margin:8px 0 4px}
h2{font-size:19px;margin:30px 0 8px;padding-bottom:4px;border-bottom:1px solid #d8dee4}
h3{font-size:15px;margin:18px 0 6px}
nav a{margin-right:14px;color:#0b5cad}
.warning{background:#fff4ce;border:1px solid #d4a600;border-radius:6px;padding:10px 14px;margin:12px 0;font-weight:600}
.missing{color:#6a737d;font-style:italic;margin:4px 0}
.note{color:#444;margin:4px 0;max-width:900px}
table{border-collapse:collapse;margin:6px 0 12px}
th,td{border:1px solid #d8dee4;padding:3px 8px;text-align:left;vertical-align:top}
thead th{background:#f3f5f7}
table.results td{text-align:right;font-variant-numeric:tabular-nums}
table.meta th{background:#f8f9fa;font-weight:600}
td.details{font-size:12px;color:#444;max-width:720px;overflow-wrap:anywhere}
.status-ok{color:#1a7f37}.status-skipped{color:#6a737d}.status-stopped{color:#bc4c00;font-weight:600}
.grid{display:flex;flex-wrap:wrap;gap:14px;align-items:flex-start}
.pair{display:flex;gap:4px}
figure{margin:0}
figure img{display:block;width:240px;height:auto;border:1px solid #d8dee4}
figure.wide img{width:320px}
img.labels{image-rendering:pixelated}
img.thumb{width:160px}
figcaption{font-size:12px;color:#444;max-width:320px}
.charts{display:flex;flex-wrap:wrap;gap:16px}
svg.chart{border:1px solid #e1e4e8;border-radius:4px;max-width:100%;height:auto}
.chart-title{font:600 13px sans-serif}
.chart-legend,.chart-tick{font:11px sans-serif;fill:#444}
.chart-axis{font:12px sans-serif;fill:#222}
.chart-empty{font:12px sans-serif;fill:#888}
.chart-frame{fill:none;stroke:#aaa}
.chart-grid{stroke:#eee}
.swatch{display:inline-block;width:12px;height:12px;border:1px solid #888;vertical-align:middle;margin:0 4px 0 10px}
)css";

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string number_text(const json& v) {
  if (v.is_number_integer()) return v.dump();
  if (v.is_number()) {
    std::ostringstream s;
    s.precision(4);
    s << v.get<double>();
    return s.str();
  }
  if (v.is_object()) {  // {"centre": 0.99, "scale": -0.0099} -> "centre 0.99, scale -0.0099"
    std::string s;
    for (const auto& [key, value] : v.items()) s += (s.empty() ? "" : ", ") + key + " " + number_text(value);
    return "(" + s + ")";
  }
  return v.is_string() ? v.get<std::string>() : v.dump();
}

class Page {
 public:
  explicit Page(fs::path run) : run_(std::move(run)) {}
  std::ostringstream html;

  const fs::path& run() const { return run_; }

  bool has(const fs::path& rel) const { return fs::exists(run_ / rel); }

  // An optional JSON file of the run: null when absent; when unreadable the page says so.
  json read_json(const fs::path& rel) {
    if (!has(rel)) return nullptr;
    try {
      return json::parse(read_text_file(run_ / rel));
    } catch (const std::exception& e) {
      missing(rel.generic_string() + ": not readable as JSON (" + e.what() + ")");
      return nullptr;
    }
  }

  std::vector<json> read_rows(const fs::path& rel) const { return read_metrics(run_ / rel); }

  // The sub-directories of `rel`, sorted by name.
  std::vector<std::string> subdirectories(const fs::path& rel) const {
    std::vector<std::string> names;
    if (!fs::is_directory(run_ / rel)) return names;
    for (const auto& e : fs::directory_iterator(run_ / rel))
      if (e.is_directory()) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // The names of the files in `rel` that end in `suffix`, without it, sorted.
  std::vector<std::string> stems_of(const fs::path& rel, const std::string& suffix) const {
    std::vector<std::string> stems;
    if (!fs::is_directory(run_ / rel)) return stems;
    for (const auto& e : fs::directory_iterator(run_ / rel)) {
      const std::string name = e.path().filename().string();
      if (ends_with(name, suffix)) stems.push_back(name.substr(0, name.size() - suffix.size()));
    }
    std::sort(stems.begin(), stems.end());
    return stems;
  }

  void missing(const std::string& text) { html << "<p class=\"missing\">" << html_escape(text) << "</p>\n"; }
  void note(const std::string& text) { html << "<p class=\"note\">" << html_escape(text) << "</p>\n"; }

  // A run-relative path (or an absolute one inside the run) as it reads on the page.
  std::string shown_path(const std::string& p) const {
    const fs::path rel = fs::path(p).lexically_relative(fs::absolute(run_));
    return fs::path(p).is_absolute() && !rel.empty() && *rel.begin() != ".." ? rel.generic_string() : p;
  }

  // A figure of one image of the run (`rel`), or the line that says it is missing. Paths come from the
  // run's JSON files: one that is absolute or leaves the run directory is never shown.
  std::string figure(const fs::path& rel, const std::string& caption, const char* img_class = "") const {
    const fs::path normal = rel.lexically_normal();
    const bool inside = !rel.is_absolute() && !normal.empty() && *normal.begin() != "..";
    if (!inside || !fs::is_regular_file(run_ / rel))
      return "<p class=\"missing\">" + html_escape("no " + rel.generic_string()) + "</p>";
    return "<figure><img class=\"" + std::string(img_class) + "\" src=\"../" + url_of(rel) + "\" alt=\"" +
           html_escape(caption) + "\"><figcaption>" + html_escape(caption) + "</figcaption></figure>";
  }

 private:
  fs::path run_;
};

// One series of a chart from metrics rows: (x_key, y_key) of the rows that have both and pass `keep`.
ChartSeries series_of(const std::vector<json>& rows, const std::string& name, const char* y_key, bool markers = false,
                      const std::function<bool(const json&)>& keep = nullptr) {
  ChartSeries s{name, {}, markers};
  for (const json& r : rows) {
    if (keep && !keep(r)) continue;
    const auto x = r.find("iteration"), y = r.find(y_key);
    if (x != r.end() && y != r.end() && x->is_number() && y->is_number())
      s.points.emplace_back(x->get<double>(), y->get<double>());
  }
  return s;
}

// Class colour swatches ("legend.json" entries: name, color).
std::string swatches(const std::vector<std::pair<std::string, json>>& classes) {
  std::string out;
  for (const auto& [name, colour] : classes) {
    char rgb[16] = "#888888";
    if (colour.is_array() && colour.size() == 3 && colour[0].is_number() && colour[1].is_number() && colour[2].is_number())
      std::snprintf(rgb, sizeof rgb, "#%02x%02x%02x", colour[0].get<int>() & 255, colour[1].get<int>() & 255,
                    colour[2].get<int>() & 255);
    out += "<span class=\"swatch\" style=\"background:" + std::string(rgb) + "\"></span>" + html_escape(name);
  }
  return out;
}

std::string status_class(const std::string& status) {
  if (status == "done" || status == "reused" || status == "imported") return "status-ok";
  if (status.rfind("skipped", 0) == 0) return "status-skipped";
  if (status == "interrupted" || status.rfind("stopped", 0) == 0) return "status-stopped";
  return "";
}

// ---- sections ----------------------------------------------------------------------------------

void header(Page& page, const json& run) {
  page.html << "<h1>CityLangSplat run report</h1>\n";
  if (run.contains("warning") && run["warning"].is_string())
    page.html << "<div class=\"warning\" id=\"warning\">" << html_escape(run["warning"].get<std::string>()) << "</div>\n";
  if (run.contains("interrupted_after"))
    page.html << "<div class=\"warning\">The run was interrupted after " << html_escape(number_text(run["interrupted_after"]))
              << "; run the same command again to continue.</div>\n";
  page.html << "<table class=\"meta\">\n";
  auto row = [&](const char* key, const std::string& value) {
    page.html << "<tr><th>" << key << "</th><td>" << html_escape(value) << "</td></tr>\n";
  };
  for (const auto& [key, label] : {std::pair{"scene", "Scene"}, {"city_model", "City model"}, {"models", "Models"}})
    if (run.contains(key)) row(label, number_text(run[key]));
  if (run.contains("provider")) row("Feature provider", run["provider"].dump());
  if (const auto g = run.find("georef"); g != run.end() && g->is_object() && g->value("status", "") == "done")
    row("Georeferencing", "from the photos' GPS in " + number_text(g->value("crs", json())) + ": " +
                              number_text(g->value("used", json())) + " of " + number_text(g->value("fixes", json())) +
                              " positions used (RMS " + fixed(g->value("gps_rms", NAN), 2) + " m), vertical offset " +
                              fixed(g->value("vertical_offset", NAN), 2) + " m, ICP " +
                              (g->contains("icp_problem") ? "not applied: " + number_text((*g)["icp_problem"])
                                                          : std::string("applied")));
  if (const auto a = run.find("align_check"); a != run.end() && a->is_object())
    row("Alignment check", fixed(100 * a->value("fraction_within", NAN), 1) + "% of the sparse points within " +
                               number_text(a->value("threshold", json())) + " m of the city model (median " +
                               fixed(a->value("median", NAN), 3) + " m)");
  std::time_t now = std::time(nullptr);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M", std::localtime(&now));
  row("Report written", when);
  page.html << "</table>\n<nav><a href=\"#stages\">Stages</a><a href=\"#labels\">Label maps</a>"
               "<a href=\"#rgb\">Photometric model</a><a href=\"#language\">Language fields</a>"
               "<a href=\"#queries\">Queries</a><a href=\"#evaluation\">Evaluation</a></nav>\n";
}

void stages(Page& page, const json& run) {
  // In the order they ran (run_record.h); a run.json without that list (hand-made, or older than it)
  // shows every record that has a status, by name.
  std::vector<std::string> names;
  if (run.contains("stages") && run["stages"].is_array()) {
    for (const json& s : run["stages"])
      if (s.is_string()) names.push_back(s);
  } else {
    const auto has_status = [](const json& v) { return v.is_object() && v.contains("status"); };
    for (const auto& [key, value] : run.items())
      if (has_status(value) || (value.is_object() && !value.empty() && std::all_of(value.begin(), value.end(), has_status)))
        names.push_back(key);
  }
  if (names.empty()) {
    page.missing("run.json records no stage");
  } else {
    page.html << "<table id=\"stages-table\"><thead><tr><th>Stage</th><th>Status</th><th>Time</th><th>Details</th>"
                 "</tr></thead><tbody>\n";
    double total = 0;
    auto row = [&](const std::string& name, const json& stage) {
      const std::string status =
          !stage.is_object() ? "not recorded" : stage.contains("status") ? number_text(stage["status"]) : "-";
      std::string time = "-", details;
      if (stage.is_object()) {
        for (const auto& [key, value] : stage.items()) {
          if (key == "status") continue;
          if (key == "seconds" && value.is_number()) {
            total += value.get<double>();
            time = duration_text(value.get<double>());
            continue;
          }
          const std::string text = value.is_string() ? page.shown_path(value) : number_text(value);
          details += (details.empty() ? "" : "; ") + key + ": " + text;
        }
      }
      page.html << "<tr><td>" << html_escape(name) << "</td><td class=\"" << status_class(status) << "\">"
                << html_escape(status) << "</td><td>" << time << "</td><td class=\"details\">" << html_escape(details)
                << "</td></tr>\n";
    };
    for (const std::string& name : names) {
      const json stage = stage_record(run, name);
      // Per-method stages (train-language, query): {"citylangsplat": {...}, "langsplat": {...}}.
      const bool per_method = stage.is_object() && !stage.empty() && !stage.contains("status") &&
                              std::all_of(stage.begin(), stage.end(), [](const json& v) { return v.is_object(); });
      if (!per_method) row(name, stage);
      else
        for (const auto& [method, s] : stage.items()) row(name + " · " + method, s);
    }
    page.html << "</tbody></table>\n";
    if (total > 0) page.note("Total recorded time: " + duration_text(total) + ".");
  }
  page.html << "<h3>Settings</h3>\n";
  if (!run.contains("settings") || !run["settings"].is_object() || run["settings"].empty()) {
    page.missing("run.json records no settings");
    return;
  }
  page.html << "<table class=\"meta\" id=\"settings\"><tbody>\n";
  for (const auto& [key, value] : run["settings"].items())
    page.html << "<tr><th>" << html_escape(key) << "</th><td>" << html_escape(number_text(value)) << "</td></tr>\n";
  page.html << "</tbody></table>\n";
}

// The class colours of labels/legend.json, by name (empty when absent).
std::vector<std::pair<std::string, json>> legend_classes(Page& page) {
  std::vector<std::pair<std::string, json>> classes;
  const json legend = page.read_json(kRun.labels() / "legend.json");
  if (legend.is_array())
    for (const json& c : legend)
      if (c.is_object() && c.contains("name") && c["name"].is_string())
        classes.emplace_back(c["name"].get<std::string>(), c.value("color", json()));
  return classes;
}

// "showing the first N of M views" when a grid is cut.
void cut_note(Page& page, size_t shown, size_t total) {
  if (shown < total) page.note("Showing the first " + std::to_string(shown) + " of " + std::to_string(total) + " views.");
}

void label_maps(Page& page, const std::vector<std::pair<std::string, json>>& classes) {
  std::vector<std::string> views;
  for (const std::string& v : page.subdirectories(kRun.labels()))
    if (page.has(kRun.labels() / v / "preview.png")) views.push_back(v);
  if (views.empty()) {
    page.missing("no label-map previews (labels/<view>/preview.png)");
    return;
  }
  page.note("Level-1 labels raycast from the city model (finest class per pixel; grey: a surface without a class; dark: "
            "no city surface; black outlines between buildings).");
  if (!classes.empty()) page.html << "<p>" << swatches(classes) << "</p>\n";
  const size_t shown = std::min(views.size(), kMaxViews);
  cut_note(page, shown, views.size());
  page.html << "<div class=\"grid\">\n";
  for (size_t i = 0; i < shown; ++i)
    page.html << page.figure(kRun.labels() / views[i] / "preview.png", views[i], "labels") << "\n";
  page.html << "</div>\n";
}

void charts(Page& page, const std::vector<std::string>& svgs) {
  page.html << "<div class=\"charts\">\n";
  for (const std::string& s : svgs) page.html << s << "\n";
  page.html << "</div>\n";
}

void photometric(Page& page) {
  page.html << "<h3>Training curves</h3>\n";
  const std::vector<json> rows = page.read_rows(kRun.rgb() / "metrics.jsonl");
  if (rows.empty()) {
    page.missing("no training curves (rgb/metrics.jsonl)");
  } else {
    ChartOptions loss{"Photometric loss", "iteration", "loss", true};
    ChartOptions psnr{"PSNR", "iteration", "dB"};
    ChartOptions count{"Gaussians", "iteration", "Gaussians"};
    charts(page, {svg_line_chart({series_of(rows, "loss", "loss"), series_of(rows, "L1", "l1")}, loss),
                  svg_line_chart({series_of(rows, "training view", "psnr"),
                                  series_of(rows, "held-out views", "test_psnr", true)},
                                 psnr),
                  svg_line_chart({series_of(rows, "Gaussians", "gaussians")}, count)});
    page.note("Loss and PSNR of the training view of each logged iteration (one view: noisy); held-out PSNR: mean over "
              "the test views.");
  }

  page.html << "<h3>Test views: photo | render</h3>\n";
  const json render = page.read_json(kRun.render() / "render.json");
  if (!render.is_object()) {
    page.missing("no renders (render/render.json: run `citylangsplat render`)");
    return;
  }
  if (render.contains("mean_psnr"))
    page.note("Mean over the test views: PSNR " + fixed(render.value("mean_psnr", NAN), 2) + " dB, SSIM " +
              fixed(render.value("mean_ssim", NAN), 3) + ".");
  std::vector<json> test;
  if (render.contains("views") && render["views"].is_array())
    for (const json& v : render["views"])
      if (v.is_object() && v.value("split", "") == "test") test.push_back(v);
  if (test.empty()) {
    page.missing((kRun.render() / "render.json").string() + " lists no test view");
    return;
  }
  const size_t shown = std::min(test.size(), kMaxViews);
  cut_note(page, shown, test.size());
  page.html << "<div class=\"grid\">\n";
  for (size_t i = 0; i < shown; ++i) {
    const json& v = test[i];
    const json files = v.value("files", json::object());
    auto file = [&](const char* key) { return kRun.render() / (files.is_object() ? files.value(key, "") : ""); };
    const std::string name = v.value("name", "view");
    page.html << "<div><div class=\"pair\">" << page.figure(file("photo"), "photo") << page.figure(file("rgb"), "render")
              << "</div><p class=\"note\">" << html_escape(name) << ": PSNR " << fixed(v.value("psnr", NAN), 2)
              << " dB, SSIM " << fixed(v.value("ssim", NAN), 3) << "</p></div>\n";
  }
  page.html << "</div>\n";
}

// The methods of a per-method stage ("train-language", "query"): those run.json records for it, so that
// leftovers of an earlier run in the same directory are not shown; the folder's sub-directories when
// run.json records none.
std::vector<std::string> methods_of(const Page& page, const json& run, const char* stage, const fs::path& folder) {
  std::vector<std::string> methods;
  if (run.contains(stage) && run[stage].is_object())
    for (const auto& [method, entry] : run[stage].items())
      if (entry.is_object()) methods.push_back(method);
  return methods.empty() ? page.subdirectories(folder) : methods;
}

void language(Page& page, const json& run) {
  std::vector<std::string> svgs;
  for (const std::string& method : methods_of(page, run, "train-language", kRun.languages())) {
    const std::vector<json> rows = page.read_rows(kRun.language(method) / "metrics.jsonl");
    if (rows.empty()) continue;
    std::vector<ChartSeries> levels;
    for (int l = 1; l <= 3; ++l)
      levels.push_back(series_of(rows, "level " + std::to_string(l), "loss", false,
                                 [l](const json& r) { return r.value("level", 0) == l; }));
    svgs.push_back(svg_line_chart(levels, {"Loss per level: " + method, "iteration (of the level)", "loss", true}));
  }
  if (svgs.empty()) {
    page.missing("no training curves (language/<method>/metrics.jsonl)");
    return;
  }
  charts(page, svgs);
  page.note("The loss of the view trained at each logged iteration; the levels are trained one after the other.");
}

void queries(Page& page, const json& run) {
  std::vector<std::pair<std::string, json>> methods;  // method -> query.json
  for (const std::string& m : methods_of(page, run, "query", kRun.queries())) {
    const json q = page.read_json(kRun.query(m) / "query.json");
    if (q.is_object() && q.contains("queries") && q["queries"].is_array()) methods.emplace_back(m, q);
  }
  if (methods.empty()) {
    page.missing("no queries (query/<method>/query.json)");
    return;
  }
  page.note("LangSplat's relevancy of each class prompt against the canonical phrases, rendered for the first view; "
            "colour map turbo over [0, 1] (dark blue: low, dark red: high).");
  const fs::path legend = kRun.query(methods.front().first) / "maps" / "legend_turbo.png";
  if (page.has(legend)) page.html << page.figure(legend, "relevancy 0 → 1") << "\n";
  std::vector<std::string> texts;  // every class, in first-seen order
  for (const auto& [m, q] : methods)
    for (const json& e : q["queries"])
      if (e.is_object() && e.contains("text") && e["text"].is_string() &&
          std::find(texts.begin(), texts.end(), e["text"].get<std::string>()) == texts.end())
        texts.push_back(e["text"]);
  page.html << "<table id=\"queries-table\"><thead><tr><th>Class</th>";
  for (const auto& [m, q] : methods) page.html << "<th>" << html_escape(m) << "</th>";
  page.html << "</tr></thead><tbody>\n";
  for (const std::string& text : texts) {
    page.html << "<tr><td>" << html_escape(text) << "</td>";
    for (const auto& [m, q] : methods) {
      page.html << "<td>";
      const auto e = std::find_if(q["queries"].begin(), q["queries"].end(),
                                  [&](const json& e) { return e.is_object() && e.value("text", "") == text; });
      std::string maps;
      if (e != q["queries"].end() && e->contains("maps") && (*e)["maps"].is_array())
        for (const json& f : (*e)["maps"]) {
          const std::string file = f.is_string() ? f.get<std::string>() : "";
          if (ends_with(file, "_relevancy.png")) {
            const std::string caption = "level " + number_text(e->value("level", json())) + ", max score " +
                                        fixed(e->value("scores", json::object()).value("max", NAN), 3);
            maps += page.figure(kRun.query(m) / file, caption, "thumb");
          }
        }
      if (maps.empty()) page.html << "<p class=\"missing\">no relevance map</p>";
      page.html << maps << "</td>";
    }
    page.html << "</tr>\n";
  }
  page.html << "</tbody></table>\n";
}

void result_table(Page& page, const ResultTable& t) {
  page.html << "<h3>" << html_escape(t.title) << "</h3>\n";
  if (!t.note.empty()) page.note(t.note);
  page.html << "<table class=\"results\" id=\"" << t.id << "\"><thead><tr>";
  for (const std::string& h : t.header) page.html << "<th>" << html_escape(h) << "</th>";
  page.html << "</tr></thead><tbody>\n";
  for (const auto& [name, cells] : t.rows) {
    page.html << "<tr><th>" << html_escape(name) << "</th>";
    for (const TableCell& c : cells)
      page.html << "<td>" << (c.bold ? "<b>" + html_escape(c.text) + "</b>" : html_escape(c.text)) << "</td>";
    page.html << "</tr>\n";
  }
  page.html << "</tbody></table>\n";
}

// eval.json's methods in order: {"methods": [...], "results": {...}}, or the older layout with the
// methods as top-level keys (reference rows last).
std::vector<std::pair<std::string, json>> evaluated_methods(const json& eval) {
  std::vector<std::pair<std::string, json>> methods;
  if (eval.contains("methods") && eval.contains("results")) {
    for (const json& m : eval["methods"])
      if (m.is_string() && eval["results"].contains(m.get<std::string>()))
        methods.emplace_back(m, eval["results"][m.get<std::string>()]);
    return methods;
  }
  for (const auto& [name, r] : eval.items())
    if (r.is_object()) methods.emplace_back(name, r);
  std::stable_partition(methods.begin(), methods.end(), [](const auto& m) { return !m.second.value("reference", false); });
  return methods;
}

void evaluation(Page& page, const json& run, const std::vector<std::pair<std::string, json>>& legend) {
  const json eval = page.read_json(kRun.eval() / "eval.json");
  if (!eval.is_object()) {
    std::string why = "no evaluation (eval/eval.json)";
    if (run.contains("evaluate") && run["evaluate"].is_object() && run["evaluate"].contains("status"))
      why += ": " + number_text(run["evaluate"]["status"]);
    page.missing(why);
    return;
  }
  if (eval.contains("warning") && eval["warning"].is_string())
    page.html << "<div class=\"warning\">" << html_escape(eval["warning"].get<std::string>()) << "</div>\n";
  const std::vector<std::pair<std::string, json>> methods = evaluated_methods(eval);
  if (methods.empty()) {
    page.missing((kRun.eval() / "eval.json").string() + " holds no method's results");
    return;
  }
  for (const ResultTable& t : evaluation_tables(methods)) result_table(page, t);

  page.html << "<h3>Ground truth and predictions per view</h3>\n";
  std::vector<std::pair<std::string, json>> colours;  // the evaluated classes' legend colours
  for (const auto& [m, r] : methods)
    for (const json& c : r.value("classes", json::array()))
      if (c.is_string() && std::none_of(colours.begin(), colours.end(), [&](const auto& e) { return e.first == c; })) {
        const auto it = std::find_if(legend.begin(), legend.end(), [&](const auto& e) { return e.first == c; });
        colours.emplace_back(c, it == legend.end() ? json() : it->second);
      }
  // The views: those the first method with view images wrote a GT image of.
  std::string gt_method;
  std::vector<std::string> stems;
  for (const auto& [m, r] : methods) {
    stems = page.stems_of(kRun.eval() / m / "views", "_gt.png");
    if (!stems.empty()) {
      gt_method = m;
      break;
    }
  }
  if (stems.empty()) {
    page.missing("no per-view GT/prediction images (eval/<method>/views/)");
    return;
  }
  if (!colours.empty()) page.html << "<p>" << swatches(colours) << " (black: no GT; dark grey: no prediction)</p>\n";
  const size_t shown = std::min(stems.size(), kMaxViews);
  cut_note(page, shown, stems.size());
  page.html << "<table id=\"eval-views\"><thead><tr><th>View</th><th>GT</th>";
  for (const auto& [m, r] : methods) page.html << "<th>" << html_escape(m) << "</th>";
  page.html << "</tr></thead><tbody>\n";
  for (size_t i = 0; i < shown; ++i) {
    const fs::path gt = kRun.eval() / gt_method / "views" / (stems[i] + "_gt.png");
    page.html << "<tr><td>" << html_escape(stems[i]) << "</td><td>" << page.figure(gt, "GT", "labels") << "</td>";
    for (const auto& [m, r] : methods)
      page.html << "<td>" << page.figure(kRun.eval() / m / "views" / (stems[i] + "_pred.png"), m, "labels")
                << "</td>";
    page.html << "</tr>\n";
  }
  page.html << "</tbody></table>\n";
}

// `changes` (docs/export.md): each proposed opening drawn on the photo that sees it most squarely, the
// drawing toggled by a checkbox (CSS only: the page works offline, without scripts), then the tables.
void changes(Page& page) {
  const fs::path dir = RunLayout().changes();
  const json c = page.read_json(dir / "changes.json");
  if (!c.is_object()) return;
  const json& proposals = c.at("proposals");
  const json& contradicted = c.at("contradicted");
  page.html << "<h2 id=\"changes\">What the city model lacks</h2>\n<p>" << proposals.size()
            << " proposed openings (windows and doors the photos show on a surface where the city model has none) and "
            << contradicted.size() << " contradicted surfaces (seen by the cameras, almost no Gaussians on them): "
            << "<code>changes/changes.json</code>, and in the CityJSON <code>changes/enriched.city.json</code>.</p>\n";
  if (!proposals.empty()) {
    page.html << "<style>#show-proposals:not(:checked) ~ .proposals polygon{display:none}"
                 ".proposals svg{max-width:360px;width:100%;height:auto}.proposals polygon{fill:rgba(255,64,32,.25);"
                 "stroke:#ff4020;stroke-width:1.5}</style>\n<input type=\"checkbox\" id=\"show-proposals\" checked>"
                 "<label for=\"show-proposals\"> show the proposals on the photos</label>\n<div class=\"proposals gallery\">\n";
    for (const json& p : proposals) {
      const std::string caption = p.at("id").get<std::string>() + ": " + p.at("class").get<std::string>() + " on " +
                                  p.at("surfaceClass").get<std::string>() + " " + p.at("surface").get<std::string>() + ", " +
                                  fixed(p.at("width").get<double>(), 2) + " x " + fixed(p.at("height").get<double>(), 2) +
                                  " m, confidence " + fixed(p.at("confidence").get<double>(), 2);
      const json& v = p.value("view", json());
      const fs::path image = v.is_object() ? dir / v.at("image").get<std::string>() : fs::path();
      if (!v.is_object() || !page.has(image)) {
        page.html << "<figure><p class=\"missing\">no view sees it</p><figcaption>" << html_escape(caption) << "</figcaption></figure>\n";
        continue;
      }
      std::string points;
      for (const json& q : v.at("polygon")) points += fixed(q.at(0).get<double>(), 1) + "," + fixed(q.at(1).get<double>(), 1) + " ";
      const std::string w = number_text(v.at("width")), h = number_text(v.at("height"));
      page.html << "<figure><svg viewBox=\"0 0 " << w << " " << h << "\" role=\"img\" aria-label=\"" << html_escape(caption)
                << "\"><image href=\"../" << url_of(image) << "\" width=\"" << w << "\" height=\"" << h
                << "\"/><polygon points=\"" << points << "\"/></svg><figcaption>" << html_escape(caption) << " (view "
                << html_escape(v.at("name").get<std::string>()) << ")</figcaption></figure>\n";
    }
    page.html << "</div>\n<table><thead><tr><th>Proposal</th><th>Class</th><th>On</th><th>Building</th><th>Width (m)</th>"
                 "<th>Height (m)</th><th>Votes</th><th>Confidence</th></tr></thead><tbody>\n";
    for (const json& p : proposals)
      page.html << "<tr><td>" << html_escape(p.at("id").get<std::string>()) << "</td><td>" << html_escape(p.at("class").get<std::string>())
                << "</td><td>" << html_escape(p.at("surface").get<std::string>()) << "</td><td>"
                << html_escape(p.at("building").get<std::string>()) << "</td><td>" << fixed(p.at("width").get<double>(), 2)
                << "</td><td>" << fixed(p.at("height").get<double>(), 2) << "</td><td>" << number_text(p.at("votes"))
                << "</td><td>" << fixed(p.at("confidence").get<double>(), 2) << "</td></tr>\n";
    page.html << "</tbody></table>\n";
  }
  if (!contradicted.empty()) {
    page.html << "<table><thead><tr><th>Contradicted surface</th><th>Class</th><th>Seen (m2)</th><th>Gaussians per m2</th>"
                 "<th>Median surface</th></tr></thead><tbody>\n";
    for (const json& s : contradicted)
      page.html << "<tr><td>" << html_escape(s.at("id").get<std::string>()) << "</td><td>" << html_escape(s.at("class").get<std::string>())
                << "</td><td>" << fixed(s.at("seenArea").get<double>(), 1) << "</td><td>" << fixed(s.at("gaussiansPerM2").get<double>(), 2)
                << "</td><td>" << fixed(s.at("medianGaussiansPerM2").get<double>(), 2) << "</td></tr>\n";
    page.html << "</tbody></table>\n";
  }
}

// One section of the page under its heading (none for an empty title). A file of an unexpected shape
// (a JSON field of another type) costs that section only: the page says so instead of the run failing.
void section(Page& page, const char* id, const char* title, const std::function<void(Page&)>& write) {
  Page part(page.run());
  try {
    write(part);
  } catch (const std::exception& e) {
    part.html.str("");
    part.missing(std::string("this section could not be written: ") + e.what());
  }
  if (*title) page.html << "<h2 id=\"" << id << "\">" << title << "</h2>\n";
  page.html << part.html.str();
}

}  // namespace

fs::path write_report(const fs::path& run_dir) {
  const fs::path run_json = RunLayout(run_dir).run_json();
  if (!fs::exists(run_json)) fail(run_json.string(), "not found: not a run directory (`citylangsplat run` writes it)");
  json run;
  try {
    run = json::parse(read_text_file(run_json));
  } catch (const json::exception& e) {
    fail(run_json.string(), std::string("not valid JSON: ") + e.what());
  }
  if (!run.is_object()) fail(run_json.string(), "expected a JSON object");

  Page page(run_dir);
  const std::string title = "CityLangSplat report: " + fs::path(run.value("scene", run_dir.string())).filename().string();
  page.html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title)
            << "</title>\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<style>" << kStyle
            << "</style>\n</head>\n<body>\n<main>\n";
  section(page, "", "", [&](Page& p) { header(p, run); });
  section(page, "stages", "Stages", [&](Page& p) { stages(p, run); });
  std::vector<std::pair<std::string, json>> legend;  // the class colours, for the label maps and the evaluation
  section(page, "labels", "Label maps", [&](Page& p) {
    legend = legend_classes(p);
    label_maps(p, legend);
  });
  section(page, "rgb", "Photometric model", photometric);
  section(page, "language", "Language fields", [&](Page& p) { language(p, run); });
  section(page, "queries", "Queries: relevance maps", [&](Page& p) { queries(p, run); });
  section(page, "evaluation", "Evaluation", [&](Page& p) { evaluation(p, run, legend); });
  section(page, "", "", changes);  // only when `changes` ran: its own heading
  page.html << "</main>\n</body>\n</html>\n";
  const fs::path out = RunLayout(run_dir).report_page();
  write_text_atomic(out, page.html.str());
  return out;
}

}  // namespace cls
