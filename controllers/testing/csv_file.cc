#include "testing/csv_file.h"

#include <sstream>

#include "testing/process.h"

namespace towsim::testing {

std::vector<std::string> SplitCsvRow(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) f.push_back(cell);
  return f;
}

std::string JoinCsvRow(const std::vector<std::string>& fields) {
  std::string s;
  for (size_t i = 0; i < fields.size(); ++i) s += (i ? "," : "") + fields[i];
  return s;
}

CsvTable ReadCsv(const std::string& path) {
  CsvTable table;
  std::stringstream in(ReadFile(path));
  std::string line;
  if (std::getline(in, line)) table.header = SplitCsvRow(line);
  while (std::getline(in, line)) table.rows.push_back(SplitCsvRow(line));
  return table;
}

}  // namespace towsim::testing
