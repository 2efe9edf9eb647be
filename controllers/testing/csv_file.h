#pragma once
// CSV files as the node writes them (docs/contract.md §5: a header line, then rows of comma-separated
// fields; names are never quoted in the files tests compare), read as text.

#include <string>
#include <vector>

namespace towsim::testing {

struct CsvTable {
  std::vector<std::string> header;             // the first line's fields
  std::vector<std::vector<std::string>> rows;  // every further line's fields
};

// the fields of one line
std::vector<std::string> SplitCsvRow(const std::string& line);

// the fields joined by commas again (for messages)
std::string JoinCsvRow(const std::vector<std::string>& fields);

// the file at `path` (an empty table if it cannot be read)
CsvTable ReadCsv(const std::string& path);

}  // namespace towsim::testing
