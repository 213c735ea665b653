#pragma once
#include <stdexcept>
#include <string>

namespace ondine {

// A case file (or --set override) that cannot be run; what() names the file,
// the line and the key, and what was expected.
class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ondine
