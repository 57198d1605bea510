// The rulebook's page (docs/auto-rules.md) against the rulebook itself
// (rulebook.h, option_table.h): every number the methods decide by has one
// row there, whose number is the code's.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "edge_sharpener/option_table.h"
#include "edge_sharpener/rulebook.h"

namespace es = edge_sharpener;

namespace {

/// The cells of a Markdown table row, trimmed; empty for any other line.
std::vector<std::string> cellsOf(const std::string &line) {
  std::vector<std::string> cells;
  if (line.size() < 2 || line[0] != '|') return cells;
  std::stringstream s(line.substr(1));
  std::string cell;
  while (std::getline(s, cell, '|')) {
    const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

/// The page's rows whose first cell is a name in backticks: name -> number.
std::multimap<std::string, std::string> pageRules(const std::string &path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::multimap<std::string, std::string> rules;
  for (std::string line; std::getline(in, line);) {
    const auto cells = cellsOf(line);
    if (cells.size() < 3 || cells[0].size() < 3 || cells[0].front() != '`' ||
        cells[0].back() != '`')
      continue;
    rules.emplace(cells[0].substr(1, cells[0].size() - 2), cells[2]);
  }
  return rules;
}

/// Every number of the code: each option's default (in the unit its row
/// gives) and each fixed rule.
std::map<std::string, double> codeRules() {
  std::map<std::string, double> rules;
  for (const es::OptionSpec &spec : es::optionTable())
    rules[std::string(spec.key)] = spec.defaultValue();
  for (const es::FixedRule &rule : es::fixedRules()) rules[std::string(rule.name)] = rule.value;
  return rules;
}

}  // namespace

TEST(Rulebook, EveryRuleHasOneRowOnItsPageWithTheCodesNumber) {
  const auto page = pageRules(EDGE_SHARPENER_SOURCE_DIR "/docs/auto-rules.md");
  const auto code = codeRules();
  for (const auto &[name, value] : code) {
    const auto rows = page.count(name);
    EXPECT_EQ(rows, 1u) << name << " has " << rows << " rows in docs/auto-rules.md";
    if (rows != 1) continue;
    const std::string written = page.find(name)->second;
    char *end = nullptr;
    const double number = std::strtod(written.c_str(), &end);
    EXPECT_TRUE(end != written.c_str() && *end == '\0')
        << name << ": '" << written << "' is not a number";
    EXPECT_NEAR(number, value, 1e-9 * std::max(1.0, std::abs(value)))
        << name << " reads " << written << " on the page, " << value << " in the code";
  }
  for (const auto &[name, number] : page)
    EXPECT_EQ(code.count(name), 1u)
        << "docs/auto-rules.md names `" << name << "`, which is no rule of the code";
}

TEST(Rulebook, FixedRulesAreNamedOnce) {
  std::map<std::string, int> seen;
  for (const es::FixedRule &rule : es::fixedRules()) ++seen[std::string(rule.name)];
  for (const auto &[name, count] : seen) EXPECT_EQ(count, 1) << name;
  EXPECT_GE(seen.size(), 20u);
}
