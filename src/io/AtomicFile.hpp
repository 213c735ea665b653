#pragma once
// Outputs are written to "<path>.tmp" and renamed into place, so that an
// interrupted run never leaves a truncated file under its final name.
#include <string>

namespace ondine {

std::string temporary_name(const std::string& path);
// Renames tmp -> path (atomic on one file system); throws std::runtime_error.
void commit_file(const std::string& tmp, const std::string& path);
// Writes `text` to path through a temporary file.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace ondine
