#pragma once
// Reading back CSV files: those of a run (csv_writer.h, docs/contract.md §5) and the sweep's results.csv
// (docs/sweeps.md). Fields follow RFC 4180 as CsvField() writes them: quoted when they hold a
// comma, quote or line break, a quote inside doubled. One record per line.

#include <string>
#include <vector>

namespace towsim::io {

struct CsvTable {
  std::vector<std::string> columns;            // the header's names
  std::vector<std::vector<std::string>> rows;  // each with columns.size() fields

  // the index of column `name`; -1 if there is none
  int Column(const std::string& name) const;
};

// the fields of one CSV record (a line without its line break)
std::vector<std::string> SplitCsvRecord(const std::string& line);

// Reads the CSV file at `path`. If `expected_header` is given (e.g. kCsvBodiesHeader) the
// header line must equal it. Throws std::runtime_error naming the file and line: unreadable,
// a different header, a row with another number of fields.
CsvTable ReadCsvFile(const std::string& path, const char* expected_header = nullptr);

}  // namespace towsim::io
