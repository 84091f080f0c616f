// The HTML report: helpers (escaping, URLs, ticks, SVG charts), the evaluation tables' model, the
// metrics log, and pages of a complete and of a partial run directory: every image the page references
// exists, by a relative path; the tables, charts and the warning banner are there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/metrics_log.h"
#include "models/temp_dir.h"
#include "eval/evaluation_tables.h"
#include "report/html.h"
#include "report/report.h"
#include "report/sample_run.h"
#include "report/svg_chart.h"

namespace cls {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempDir;

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
  return n;
}

std::string url_decode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size()) {
      out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

// Every src= and href= of the page: relative, local, and (src) an existing file.
void expect_local_references_resolve(const fs::path& page) {
  const std::string html = read_text_file(page);
  const std::regex ref(R"re((src|href)="([^"]*)")re");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ref); it != std::sregex_iterator(); ++it) {
    const std::string kind = (*it)[1], url = (*it)[2];
    if (kind == "href" && url.rfind("#", 0) == 0) continue;  // an anchor on the page
    EXPECT_EQ(url.find(':'), std::string::npos) << "not a relative local path: " << url;
    EXPECT_NE(url.rfind("/", 0), 0u) << "absolute path: " << url;
    if (kind == "src") {
      ++images;
      EXPECT_TRUE(fs::is_regular_file(page.parent_path() / url_decode(url))) << "missing image: " << url;
    }
  }
  EXPECT_EQ(count_of(html, "<img "), size_t(images));
}

TEST(ReportHtml, EscapesTextAndEncodesUrls) {
  EXPECT_EQ(html_escape("<a href=\"x\">Tom & Jerry's</a>"), "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
  EXPECT_EQ(url_of("labels/view 002 #b/preview.png"), "labels/view%20002%20%23b/preview.png");
  EXPECT_EQ(url_of("a/b%c?.png"), "a/b%25c%3F.png");
  EXPECT_EQ(fixed(1.23456, 2), "1.23");
  EXPECT_EQ(fixed(NAN, 2), "-");
  EXPECT_EQ(duration_text(0.42), "0.4 s");
  EXPECT_EQ(duration_text(185), "3 min 05 s");
  EXPECT_EQ(duration_text(7620), "2 h 07 min");
}

TEST(ReportChart, NiceTicksCoverTheRange) {
  EXPECT_EQ(nice_ticks(1, 100, 5), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  const std::vector<double> t = nice_ticks(0.13, 0.87, 4);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_DOUBLE_EQ(t.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.back(), 1.0);
  const std::vector<double> one = nice_ticks(5, 5, 4);  // one value: widened by 10% each way
  EXPECT_LE(one.front(), 4.5);
  EXPECT_GE(one.back(), 5.5);
  EXPECT_EQ(log_ticks(0.02, 0.05), (std::vector<double>{0.02, 0.05}));
  EXPECT_EQ(log_ticks(0.003, 20), (std::vector<double>{0.001, 0.01, 0.1, 1, 10, 100}));
}

TEST(ReportChart, SeriesLegendGapsAndEmptyCharts) {
  ChartOptions o{"Loss <total>", "iteration", "loss", true};
  const std::string svg = svg_line_chart({{"a&b", {{1, 0.5}, {2, 0.2}, {3, -1}, {4, 0.1}, {5, 0.05}}},
                                          {"held-out", {{5, 0.3}}, true}},
                                         o);
  EXPECT_EQ(svg.rfind("<svg class=\"chart\"", 0), 0u);
  EXPECT_NE(svg.find("Loss &lt;total&gt;"), std::string::npos);
  EXPECT_NE(svg.find(">a&amp;b<"), std::string::npos);
  EXPECT_EQ(count_of(svg, "<polyline"), 3u) << "y <= 0 on a log axis breaks the line; one point makes none";
  EXPECT_EQ(count_of(svg, "<circle"), 1u);
  EXPECT_NE(svg.find(">0.01<"), std::string::npos) << "log ticks";
  EXPECT_NE(svg_line_chart({{"none", {}}}, o).find(">no data<"), std::string::npos);
}

TEST(ReportTables, BestValuesBoldReferenceRowsNeverCompared) {
  const json a = {{"classes", {"wall"}},
                  {"2d", {{"miou", 0.25}, {"per_class", {{"wall", {{"iou", 0.5}, {"precision", 0.6}, {"recall", 0.7}}}}}}}};
  json b = a;
  b["2d"]["miou"] = 0.3;
  json ref = {{"reference", true}, {"classes", {"wall"}}, {"2d", a["2d"]}};
  ref["2d"]["miou"] = 0.9;
  const std::vector<ResultTable> tables = evaluation_tables({{"A", a}, {"B", b}, {"labels", ref}});
  std::set<std::string> ids;
  for (const ResultTable& t : tables) ids.insert(t.id);
  EXPECT_EQ(ids, (std::set<std::string>{"table-1", "table-3"})) << "no 2d_covered: no Table 1b; no 3d: no Table 2";
  json with_3d = a;
  with_3d["3d"] = {{"miou", 0.4}};
  std::set<std::string> ids_3d;
  for (const ResultTable& t : evaluation_tables({{"A", with_3d}, {"labels", ref}})) ids_3d.insert(t.id);
  EXPECT_EQ(ids_3d, (std::set<std::string>{"table-1", "table-2", "table-2b", "table-3"}));
  const ResultTable& t1 = tables[0];
  ASSERT_EQ(t1.rows.size(), 3u);
  EXPECT_EQ(t1.header[3], "mIoU");
  EXPECT_EQ(t1.rows[1].second[2].text, "30.00");
  EXPECT_TRUE(t1.rows[1].second[2].bold);
  EXPECT_FALSE(t1.rows[2].second[2].bold) << "a reference row is never bold";
  EXPECT_EQ(t1.rows[0].second[0].text, "-") << "no gt_coverage";
  const ResultTable& t3 = tables.back();
  EXPECT_EQ(t3.header.size(), 1u + 3 * 3);
  EXPECT_FALSE(t3.rows[0].second[0].bold) << "A and B tie on wall IoU";
  EXPECT_NE(tables_markdown(tables).find("| B | - | - | **30.00** |"), std::string::npos) << tables_markdown(tables);
}

TEST(MetricsLog, AppendsRowsAndAResumeDropsThoseAfterTheCheckpoint) {
  EXPECT_EQ(metrics_interval(30000), 100);
  EXPECT_EQ(metrics_interval(100), 1);
  TempDir dir;
  const fs::path path = dir.path / "m.jsonl";
  {
    MetricsLog log = MetricsLog::start(path);
    for (int it = 1; it <= 5; ++it) log.append({{"iteration", it}, {"seconds", 0.5 * it}});
  }
  std::ofstream(path, std::ios::app) << "{\"iteration\": 6, \"sec";  // a line cut short by a kill
  EXPECT_EQ(read_metrics(path).size(), 5u);
  MetricsLog resumed = MetricsLog::resume(path, [](const json& r) { return r.value("iteration", 0) <= 3; });
  EXPECT_EQ(resumed.last()["seconds"], 1.5) << "the clock continues from the last row kept";
  resumed.append({{"iteration", 4}});
  const std::vector<json> rows = read_metrics(path);
  ASSERT_EQ(rows.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(rows[size_t(i)]["iteration"], i + 1);
  EXPECT_TRUE(MetricsLog::start(path).last().is_null());
  EXPECT_TRUE(read_metrics(path).empty()) << "a fresh start empties the file";
  EXPECT_TRUE(read_metrics(dir.path / "absent.jsonl").empty());
}

TEST(Report, CompleteRunShowsEverySectionWithResolvingImages) {
  TempDir dir;
  test::write_sample_run(dir.path, "synthetic");
  const fs::path page = write_report(dir.path);
  EXPECT_EQ(page, dir.path / "report" / "index.html");
  const std::string html = read_text_file(page);
  expect_local_references_resolve(page);
  EXPECT_NE(html.find("<div class=\"warning\" id=\"warning\">mechanics: synthetic features, not CLIP</div>"),
            std::string::npos);
  for (const char* id : {"stages-table", "settings", "table-1", "table-1b", "table-2", "table-2b", "table-3",
                         "queries-table", "eval-views"})
    EXPECT_NE(html.find(std::string("id=\"") + id + "\""), std::string::npos) << id;
  EXPECT_EQ(count_of(html, "<svg class=\"chart\""), 5u) << "loss, PSNR, Gaussians and one per language method";
  EXPECT_NE(html.find("src=\"../labels/view%20002%20%23b/preview.png\""), std::string::npos);
  EXPECT_NE(html.find("<td><b>70.00</b></td>"), std::string::npos) << "Table 1b: langsplat's 2D mIoU is best";
  EXPECT_NE(html.find("<td>train-language/langsplat</td><td class=\"status-ok\">done</td><td>1 min 00 s</td>"), std::string::npos)
      << "a per-method stage is found under run.json[\"train-language\"][\"langsplat\"]";
  EXPECT_EQ(html.find("not recorded"), std::string::npos);
  EXPECT_NE(html.find("14 min 54 s"), std::string::npos) << "the total of the stages' times";
  EXPECT_NE(html.find("dir: labels"), std::string::npos) << "paths inside the run shown relative to it";
  EXPECT_EQ(html.find("class=\"missing\""), std::string::npos) << "nothing is missing in a complete run";
  // Test views only: the train view of render.json is not shown.
  EXPECT_NE(html.find("../render/views/view_000/photo.png"), std::string::npos);
  EXPECT_EQ(html.find("../render/views/view_001/"), std::string::npos);

  // A run with real models has no banner.
  TempDir real;
  test::write_sample_run(real.path, "clip");
  EXPECT_EQ(read_text_file(write_report(real.path)).find("class=\"warning\""), std::string::npos);
}

// Leftovers of an earlier run in the same directory (a method that this run did not train) are not
// shown, and image paths from the run's JSON files never point outside the run directory.
TEST(Report, ShowsOnlyTheRunsMethodsAndNoImageOutsideTheRun) {
  TempDir dir;
  const fs::path run = dir.path / "run", outside = dir.path / "outside.png";
  test::write_sample_run(run, "synthetic");
  test::sample::write_png(outside, 7);
  for (const char* d : {"language", "query"})
    fs::copy(run / d / "langsplat", run / d / "stale", fs::copy_options::recursive);
  test::sample::write_json(run / "render" / "render.json",
                           {{"views", {{{"name", "a.png"}, {"split", "test"},
                                        {"files", {{"photo", "../outside.png"}, {"rgb", outside.string()}}}}}}});
  const std::string html = read_text_file(write_report(run));
  EXPECT_EQ(html.find("stale"), std::string::npos) << "only the methods run.json records";
  EXPECT_NE(html.find("<th>langsplat</th>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"../render/../outside.png\""), std::string::npos);
  EXPECT_EQ(html.find("src=\"" + outside.string()), std::string::npos);
  EXPECT_NE(html.find("no render/../outside.png"), std::string::npos) << "said missing instead";
}

TEST(Report, PartialRunSaysWhatIsMissingInsteadOfBrokenImages) {
  TempDir dir;
  test::write_sample_run(dir.path, "clip-tiny");
  // A run stopped before the features (no weights): run.json and the label maps only.
  for (const char* d : {"rgb", "language", "render", "eval", "query"}) fs::remove_all(dir.path / d);
  fs::remove(dir.path / "labels" / "view_001" / "preview.png");
  write_text_atomic(dir.path / "run.json",
                    json{{"scene", "/s"},
                         {"models", "clip"},
                         {"georef", {{"status", "done"}, {"crs", "EPSG:25832"}, {"used", 22}, {"fixes", 24},
                                     {"gps_rms", 5.187}, {"vertical_offset", -2.25}}},
                         {"labels", {{"status", "done"}}},
                         {"features", {{"status", "stopped: no model weights"}, {"reason", "no CLIP weights"}}}}
                            .dump());
  const fs::path page = write_report(dir.path);
  expect_local_references_resolve(page);
  const std::string html = read_text_file(page);
  EXPECT_EQ(count_of(html, "<img "), 2u) << "the two label previews that exist";
  for (const char* line : {"no training curves (rgb/metrics.jsonl)", "no renders (render/render.json",
                           "no training curves (language/&lt;method&gt;/metrics.jsonl)", "no queries",
                           "no evaluation (eval/eval.json)", "run.json records no settings"})
    EXPECT_NE(html.find(line), std::string::npos) << line;
  EXPECT_NE(html.find("status-stopped\">stopped: no model weights"), std::string::npos);
  EXPECT_NE(html.find("from the photos&#39; GPS in EPSG:25832: 22 of 24 positions used (RMS 5.19 m), vertical offset "
                      "-2.25 m, ICP applied"),
            std::string::npos);

  // An unreadable optional file is said on the page, a field of another type costs its section only;
  // a missing or broken run.json is an error naming it.
  write_text_atomic(dir.path / "eval" / "eval.json", "{\"methods\": [");
  write_text_atomic(dir.path / "language" / "langsplat" / "metrics.jsonl", R"({"level": "one", "iteration": 1})");
  test::sample::write_json(dir.path / "render" / "render.json", {{"views", {{{"name", "a.png"}, {"split", "test"}}}}});
  const std::string odd = read_text_file(write_report(dir.path));
  EXPECT_NE(odd.find("no render/</p>"), std::string::npos) << "a view without files: no image of a directory";
  EXPECT_NE(odd.find("a.png: PSNR - dB"), std::string::npos);
  EXPECT_NE(odd.find("eval/eval.json: not readable as JSON"), std::string::npos);
  EXPECT_NE(odd.find("<h2 id=\"language\">Language fields</h2>\n<p class=\"missing\">this section could not be written"),
            std::string::npos);
  EXPECT_NE(odd.find("<h2 id=\"queries\">"), std::string::npos) << "the sections after it are written";
  write_text_atomic(dir.path / "run.json", "[1, 2]");
  try {
    write_report(dir.path);
    ADD_FAILURE() << "accepted a run.json that is not an object";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("run.json"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_report(dir.path / "absent"), Error);
}

TEST(ReportCli, WritesThePageAndPrintsItsPath) {
  TempDir dir;
  test::write_sample_run(dir.path, "synthetic");
  const auto r = test::run_cli("report " + dir.path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, (dir.path / "report" / "index.html").string() + "\n");
  EXPECT_TRUE(fs::exists(dir.path / "report" / "index.html"));
  const auto missing = test::run_cli("report " + (dir.path / "absent").string());
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("run.json"), std::string::npos) << missing.err;
  EXPECT_EQ(test::run_cli("report").status, 2);
}

}  // namespace
}  // namespace cls
