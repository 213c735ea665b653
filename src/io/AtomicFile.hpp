#pragma once
// Outputs are written to "<path>.tmp" and renamed into place, so that an
// interrupted run never leaves a truncated file under its final name.
#include <string>

namespace ondine {

std::string temporary_name(const std::string& path);
// ": <strerror(error)>", or nothing for 0: the system's reason in a failed write's message
std::string system_reason(int error);
// Renames tmp -> path (atomic on one file system); throws std::runtime_error naming path and the
// system's reason, the temporary removed.
void commit_file(const std::string& tmp, const std::string& path);
// Writes `text` to path through a temporary file; on failure the same message, no temporary left.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace ondine
