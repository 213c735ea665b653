#include "io/AtomicFile.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace ondine {

std::string temporary_name(const std::string& path) { return path + ".tmp"; }

std::string system_reason(int error) { return error != 0 ? std::string(": ") + std::strerror(error) : std::string(); }

void commit_file(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + " (renaming " + tmp + " onto it)" + system_reason(e));
  }
}

void write_text_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = temporary_name(path);
  int e = 0;
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::trunc);
    if (out) {
      out << text;
      out.flush();
      if (out) out.close();
    }
    if (!out) e = errno != 0 ? errno : EIO;
  }
  if (e != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + system_reason(e));
  }
  commit_file(tmp, path);
}

}  // namespace ondine
