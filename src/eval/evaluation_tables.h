#pragma once
// The paper's Tables 1-3 (section 4) as data: the evaluation writes them as Markdown (eval.md), the
// report as HTML, from this one definition of their columns and of which value is best.
#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace cls {

struct TableCell {
  std::string text;   // formatted value; "-" where the method has no such score
  bool bold = false;  // strictly the best of the compared methods in its column
};

struct ResultTable {
  std::string id;                   // "table-1", "table-1b", ...: anchors and tests
  std::string title, note;          // note: what the columns mean (may be empty)
  std::vector<std::string> header;  // the row-name column first
  std::vector<std::pair<std::string, std::vector<TableCell>>> rows;  // row name, one cell per column after it
};

// The tables for several methods (name -> evaluate_model's JSON, in display order). A method whose JSON
// has "reference": true (the label maps) is shown but neither bold nor compared against. Table 1b only
// when some method has "2d_covered" scores.
std::vector<ResultTable> evaluation_tables(const std::vector<std::pair<std::string, nlohmann::json>>& methods);

// "### title", the note and a Markdown table per table, separated by blank lines; best values in **bold**.
std::string tables_markdown(const std::vector<ResultTable>& tables);

}  // namespace cls
