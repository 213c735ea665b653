#include "scene/CaseReader.hpp"

#include <cmath>
#include <sstream>

namespace ondine::case_file {

namespace {
// a key path in the overrides' dotted form (list items as key.N, where the reader writes key[N])
std::string dotted(const std::string& key) {
  std::string d;
  for (const char c : key) {
    if (c == '[') d += '.';
    else if (c != ']') d += c;
  }
  return d;
}
}  // namespace

void Reader::fail(const YAML::Node& at, const std::string& key, const std::string& what) const {
  std::ostringstream m;
  // a key that an override made (no place in the file), below which an override wrote: that override
  std::string via;
  const bool from_file = at.IsDefined() && at.Mark().line >= 0;
  if (!from_file)
    for (const std::string& o : overridden_)
      if (o.rfind(dotted(key) + ".", 0) == 0) {
        via = o;
        break;
      }
  if (overridden_.count(key)) {
    m << "--set " << key << ": " << what;
  } else if (!via.empty()) {
    m << "--set " << via << ": key '" << key << "': " << what;
  } else {
    m << file_;
    const YAML::Mark mk = at.IsDefined() ? at.Mark() : YAML::Mark::null_mark();
    if (mk.line >= 0) m << ":" << mk.line + 1 << ":" << mk.column + 1;
    m << ": key '" << key << "': " << what;
  }
  throw CaseError(m.str());
}

std::string Reader::shown(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}

void Reader::only_keys(const YAML::Node& map, const std::string& path, std::initializer_list<const char*> keys) const {
  if (!map.IsMap()) fail(map, path.empty() ? "(top level)" : path, "expected a mapping, got " + shown(map));
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    bool ok = false;
    for (const char* a : keys) ok = ok || k == a;
    if (!ok) {
      std::string list;
      for (const char* a : keys) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(it->first, join(path, k), "unknown key; expected one of: " + list);
    }
  }
}

YAML::Node Reader::required(const YAML::Node& map, const std::string& path, const char* key) const {
  const YAML::Node n = map[key];
  if (!n.IsDefined() || n.IsNull()) fail(map, join(path, key), "required key is missing");
  return n;
}

double Reader::number(const YAML::Node& n, const std::string& key, const std::string& expect) const {
  if (!n.IsScalar()) fail(n, key, "expected " + expect + ", got " + shown(n));
  double v;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    fail(n, key, "expected " + expect + ", got " + shown(n));
  }
  if (!std::isfinite(v)) fail(n, key, "expected " + expect + ", got " + shown(n));
  return v;
}

double Reader::positive(const YAML::Node& n, const std::string& key, const std::string& unit) const {
  const double v = number(n, key, "a positive number" + unit);
  if (!(v > 0)) fail(n, key, "expected a positive number" + unit + ", got " + shown(n));
  return v;
}

double Reader::non_negative(const YAML::Node& n, const std::string& key, const std::string& unit) const {
  const double v = number(n, key, "a number >= 0" + unit);
  if (v < 0) fail(n, key, "expected a number >= 0" + unit + ", got " + shown(n));
  return v;
}

long long Reader::integer(const YAML::Node& n, const std::string& key, long long lo, long long hi) const {
  const std::string expect = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!n.IsScalar()) fail(n, key, "expected " + expect + ", got " + shown(n));
  long long v;
  try {
    v = n.as<long long>();
  } catch (const YAML::Exception&) {
    fail(n, key, "expected " + expect + ", got " + shown(n));
  }
  if (v < lo || v > hi) fail(n, key, "expected " + expect + ", got " + shown(n));
  return v;
}

bool Reader::boolean(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected true or false, got " + shown(n));
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    fail(n, key, "expected true or false, got " + shown(n));
  }
}

std::string Reader::word(const YAML::Node& n, const std::string& key, std::initializer_list<const char*> choices) const {
  std::string list;
  for (const char* a : choices) list += (list.empty() ? "" : " | ") + std::string(a);
  if (!n.IsScalar()) fail(n, key, "expected one of " + list + ", got " + shown(n));
  const std::string s = n.Scalar();
  for (const char* a : choices)
    if (s == a) return s;
  fail(n, key, "expected one of " + list + ", got " + shown(n));
}

Vec3 Reader::vector(const YAML::Node& n, const std::string& key, int dim, const std::string& unit) const {
  const std::string expect = "a list of " + std::to_string(dim) + " numbers" + unit;
  if (!n.IsSequence() || static_cast<int>(n.size()) != dim) fail(n, key, "expected " + expect + ", got " + shown(n) + (n.IsSequence() ? " of " + std::to_string(n.size()) : ""));
  Vec3 v{0, 0, 0};
  for (int k = 0; k < dim; ++k) v[k] = number(n[k], key + "[" + std::to_string(k) + "]", "a number" + unit);
  return v;
}

std::array<bool, 3> Reader::flags(const YAML::Node& n, const std::string& key, int dim) const {
  if (!n.IsSequence() || static_cast<int>(n.size()) != dim)
    fail(n, key, "expected a list of " + std::to_string(dim) + " booleans, got " + shown(n));
  std::array<bool, 3> v{false, false, false};
  for (int k = 0; k < dim; ++k) v[k] = boolean(n[k], key + "[" + std::to_string(k) + "]");
  return v;
}

std::string Reader::text(const YAML::Node& n, const std::string& key, const std::string& expect) const {
  if (!n.IsScalar() || n.Scalar().empty()) fail(n, key, "expected " + expect + ", got " + shown(n));
  return n.Scalar();
}

std::set<std::string> apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides) {
  std::set<std::string> keys;
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CaseError("--set " + o + ": expected key=value (e.g. --set discretisation.dx=0.01)");
    const std::string key = o.substr(0, eq);
    YAML::Node value;
    try {
      value = YAML::Load(o.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw CaseError("--set " + o + ": the value is not valid YAML (" + e.msg + ")");
    }
    // Walk the dotted path, creating mappings as needed; list items are addressed as key.N.
    std::vector<std::string> parts;
    std::stringstream ss(key);
    for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
    std::vector<YAML::Node> chain{root};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      YAML::Node cur = chain.back();
      const bool index = !parts[i].empty() && parts[i].find_first_not_of("0123456789") == std::string::npos;
      if (cur.IsSequence() && index) {
        const std::size_t k = std::stoul(parts[i]);
        if (k >= cur.size()) throw CaseError("--set " + key + ": list index " + parts[i] + " is out of range");
        chain.push_back(cur[k]);
      } else {
        if (cur.IsScalar() || cur.IsSequence())
          throw CaseError("--set " + key + ": '" + (i == 0 ? std::string("(top level)") : parts[i - 1]) +
                          "' is not a mapping");
        chain.push_back(cur[parts[i]]);
      }
    }
    YAML::Node parent = chain.back();
    const std::string& last = parts.back();
    if (parent.IsScalar())
      throw CaseError("--set " + key + ": '" + (parts.size() > 1 ? parts[parts.size() - 2] : std::string("(top level)")) +
                      "' is not a mapping");
    if (parent.IsSequence() && last.find_first_not_of("0123456789") == std::string::npos) {
      const std::size_t k = std::stoul(last);
      if (k >= parent.size()) throw CaseError("--set " + key + ": list index " + last + " is out of range");
      parent[k] = value;
    } else {
      parent[last] = value;
    }
    keys.insert(key);
  }
  return keys;
}

void reject_duplicate_keys(const YAML::Node& n, const std::string& path, const std::string& where) {
  if (n.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : n) {
      const std::string key = kv.first.Scalar();
      const std::string full = where.empty() ? key : where + "." + key;
      if (!seen.insert(key).second) {
        const YAML::Mark mk = kv.first.Mark();
        throw CaseError(path + ":" + std::to_string(mk.line + 1) + ":" + std::to_string(mk.column + 1) + ": key '" + full +
                        "': written twice in the same mapping; keep one");
      }
      reject_duplicate_keys(kv.second, path, full);
    }
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) reject_duplicate_keys(n[i], path, where + "[" + std::to_string(i) + "]");
  }
}

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace ondine::case_file
