#pragma once
// Whole text files for towsim_sweep's folders: read at once, written atomically (a temporary
// file "<path>.tmp" renamed over the path), so a reader or a killed writer never leaves or
// sees half a file.

#include <string>

namespace towsim::app {

// the whole file; empty if it cannot be read
std::string ReadTextFile(const std::string& path);

// writes `text` to `path` by way of path.tmp and a rename; throws std::runtime_error naming
// the path when it cannot be written (e.g. disk full)
void WriteTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace towsim::app
