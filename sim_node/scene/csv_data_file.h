#pragma once
// The common reader of the scene's CSV data files (scene/rao_file.h, scene/time_history_file.h):
// plain text, one record per line, fields separated by commas (no quoting: the files hold
// numbers and names). Text after '#' is a comment; blank lines are skipped; blanks around a
// field are ignored. The first remaining line is the header, which must name exactly the
// expected columns in order. Every other line must have as many fields as the header.
// Errors are ConfigError(key, value, "<file>:<line>", rule), <file> the file's name without
// its folder, e.g.
//   bodies.ship.raos = 4,0,heave,1 (ship_raos.csv:7): must have 5 fields ... (it has 4)

#include <string>
#include <vector>

namespace towsim::scene::internal {

struct CsvDataRow {
  int line = 0;                     // 1-based line number in the file
  std::vector<std::string> fields;  // trimmed, header.size() of them
};

struct CsvDataFile {
  std::string name;  // the file name without its folder, for messages
  int header_line = 0;
  std::vector<CsvDataRow> rows;
};

// Reads the file at `path` (scene/yaml_reader.h ReadTextFile: at most 16 MB). Throws
// ConfigError with key `key`: the file cannot be read (value: path), it has no header line or
// another header, a row has another number of fields.
CsvDataFile ReadCsvDataFile(const std::string& path, const std::string& key,
                            const std::vector<std::string>& header);

// `field` as a finite number (the whole field; "nan", "inf" and overflow are not)
bool ParseFiniteNumber(const std::string& field, double* x);

// "<name>:<line>"
std::string FileLocation(const CsvDataFile& file, int line);

}  // namespace towsim::scene::internal
