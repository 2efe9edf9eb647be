#include "scene/csv_data_file.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "scene/config_error.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {
namespace {

std::string Join(const std::vector<std::string>& fields) {
  std::string s;
  for (size_t i = 0; i < fields.size(); ++i) s += (i == 0 ? "" : ",") + fields[i];
  return s;
}

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(Trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

std::string FileLocation(const CsvDataFile& file, int line) {
  return file.name + ":" + std::to_string(line);
}

bool ParseFiniteNumber(const std::string& field, double* x) {
  errno = 0;
  char* end = nullptr;
  *x = std::strtod(field.c_str(), &end);
  return !field.empty() && end == field.c_str() + field.size() && errno != ERANGE &&
         std::isfinite(*x);
}

CsvDataFile ReadCsvDataFile(const std::string& path, const std::string& key,
                            const std::vector<std::string>& header) {
  CsvDataFile file;
  file.name = std::filesystem::path(path).filename().string();
  std::string text, why;
  if (!ReadTextFile(path, &text, &why)) {
    throw ConfigError(key, path, file.name, "cannot read the file: " + why);
  }
  const std::string expected = Join(header);
  std::istringstream in(text);
  std::string raw;
  for (int number = 1; std::getline(in, raw); ++number) {
    const size_t hash = raw.find('#');
    if (hash != std::string::npos) raw.resize(hash);
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string line = Trim(raw);
    if (line.empty()) continue;
    std::vector<std::string> fields = SplitFields(line);
    if (file.header_line == 0) {
      if (fields != header) {
        throw ConfigError(key, line, FileLocation(file, number), "the header must be " + expected);
      }
      file.header_line = number;
      continue;
    }
    if (fields.size() != header.size()) {
      throw ConfigError(key, line, FileLocation(file, number),
                        "must have " + std::to_string(header.size()) + " fields (" + expected +
                            "), it has " + std::to_string(fields.size()));
    }
    file.rows.push_back({number, std::move(fields)});
  }
  if (file.header_line == 0) {
    throw ConfigError(key, path, file.name,
                      "holds no header line: the first line that is not blank or a comment "
                      "must be " +
                          expected);
  }
  return file;
}

}  // namespace towsim::scene::internal
