#pragma once
// towsim_export --info: a summary of a recording in the layout of `ros2 bag info` (file, size,
// storage, duration, start and end, message count, per topic: type, count, serialization
// format), plus what MCAP adds (profile, library, chunks, metadata records).

#include <string>

#include "io/mcap_reader.h"

namespace towsim::app {

// the summary text of `mcap_path` (McapReader::Open, or Recover if `recover`); throws
// mcap::McapError for a bad file (the message names the offset)
std::string RecordingInfo(const std::string& mcap_path, bool recover);
// the same from a reader opened (Open, or Recover if `recover`) by the caller
std::string RecordingInfo(const io::McapReader& reader, const std::string& mcap_path, bool recover);

}  // namespace towsim::app
