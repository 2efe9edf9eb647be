// io/csv_reader: reading back what io/csv_writer writes (RFC 4180 fields), header checks.

#include "io/csv_reader.h"

#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "io/csv_writer.h"
#include "temp_dir.h"

namespace towsim::io {
namespace {

TEST(CsvReader, SplitsWhatCsvFieldWrites) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "", "[3, 0, 0]"};
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + CsvField(fields[i]);
  EXPECT_EQ(SplitCsvRecord(line), fields);
  EXPECT_EQ(SplitCsvRecord("1,2\r"), (std::vector<std::string>{"1", "2"}));
}

TEST(CsvReader, ChecksTheHeaderAndTheFieldCount) {
  test::TempDir dir;
  const std::string path = (dir.path() / "status.csv").string();
  std::ofstream(path) << kCsvStatusHeader << "\n0,0,0,0,0,10\n\n0.1,2,3,1e-9,40,10\n";
  const CsvTable t = ReadCsvFile(path, kCsvStatusHeader);
  ASSERT_EQ(t.rows.size(), 2u);  // the empty line is skipped
  EXPECT_EQ(t.Column("residual"), 3);
  EXPECT_EQ(t.Column("nope"), -1);
  EXPECT_EQ(t.rows[1][4], "40");
  try {
    ReadCsvFile(path, kCsvBodiesHeader);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ":1: header is " + kCsvStatusHeader + ", expected " + kCsvBodiesHeader);
  }
  std::ofstream(path) << kCsvStatusHeader << "\n0,0,0\n";
  try {
    ReadCsvFile(path);
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path + ":2: 3 fields, the header has 6");
  }
  EXPECT_THROW(ReadCsvFile(path + ".missing"), std::runtime_error);
}

}  // namespace
}  // namespace towsim::io
