#include "io/csv_reader.h"

#include <fstream>
#include <stdexcept>

namespace towsim::io {

int CsvTable::Column(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<std::string> SplitCsvRecord(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';  // "" inside quotes
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

CsvTable ReadCsvFile(const std::string& path, const char* expected_header) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty, no header line");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (expected_header != nullptr && line != expected_header) {
    throw std::runtime_error(path + ":1: header is " + line + ", expected " + expected_header);
  }
  CsvTable table;
  table.columns = SplitCsvRecord(line);
  for (size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::vector<std::string> fields = SplitCsvRecord(line);
    if (fields.size() != table.columns.size()) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": " +
                               std::to_string(fields.size()) + " fields, the header has " +
                               std::to_string(table.columns.size()));
    }
    table.rows.push_back(std::move(fields));
  }
  return table;
}

}  // namespace towsim::io
