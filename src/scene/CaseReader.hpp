#pragma once
// Internal to the case-file parser (src/scene/Case*.cpp); nothing outside src/scene
// includes it. The public entry points are in scene/CaseFile.hpp.
#include <yaml-cpp/yaml.h>

#include <array>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>

#include "scene/CaseError.hpp"
#include "scene/Scene.hpp"

namespace ondine::case_file {

// Schema-driven reading of one YAML document, with messages that point at the
// offending line and key. Nodes created by --set carry no mark; messages name
// the override instead.
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden)
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& what) const;

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  static std::string shown(const YAML::Node& n);

  void only_keys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> keys) const;
  YAML::Node required(const YAML::Node& map, const std::string& path, const char* key) const;
  double number(const YAML::Node& n, const std::string& key, const std::string& expect = "a number") const;
  double positive(const YAML::Node& n, const std::string& key, const std::string& unit) const;
  double non_negative(const YAML::Node& n, const std::string& key, const std::string& unit) const;
  long long integer(const YAML::Node& n, const std::string& key, long long lo, long long hi) const;
  bool boolean(const YAML::Node& n, const std::string& key) const;
  std::string word(const YAML::Node& n, const std::string& key, std::initializer_list<const char*> choices) const;
  Vec3 vector(const YAML::Node& n, const std::string& key, int dim, const std::string& unit) const;
  std::array<bool, 3> flags(const YAML::Node& n, const std::string& key, int dim) const;
  std::string text(const YAML::Node& n, const std::string& key, const std::string& expect) const;

 private:
  std::string file_;
  std::set<std::string> overridden_;
};

// Applies "dotted.key=value" overrides (--set) to the document; returns the keys set.
std::set<std::string> apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides);

// yaml-cpp keeps both entries of a key written twice in a mapping and reads the
// first: a second `dx:` further down would be silently ignored. Refused instead.
void reject_duplicate_keys(const YAML::Node& n, const std::string& path, const std::string& where);

// A number as a stream writes it by default (messages).
std::string fmt(double v);

}  // namespace ondine::case_file
