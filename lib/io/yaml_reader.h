// Reading a case file's mappings (README.md, "The case file"). Every key a reader asks for is marked; a key
// left over at any level is an error, so a typo never becomes a silent default. Every error throws
// CaseError with the file, the line and column (1-based) and the key path:
//   cases/paper.yaml:12:5: friction.mu: must be in [0, 10], got -1
// A section is a few lines:
//   m.section("friction", [&](YamlMap& s) { s.required("mu", c.friction.mu, in_closed(0, 10)); });
// Values: double (.inf, -.inf, .nan as YAML spells them), int (decimal), bool, std::string. A check
// returns "" when the value is fine, else what is required ("must be > 0 and finite"); the reader
// appends the value as written. A value of a form of its own (a time history: a number or a
// mapping; a list) is read from a YamlValue, which fails at its own node:
//   s.required_value("normal_load_N", [&](const YamlValue& v) { c.load.normal_load_N = read_load(v); });
#pragma once

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <yaml-cpp/yaml.h>

#include "lib/errors.h"
#include "lib/io/key_locations.h"

namespace contact {

// "FILE:LINE:COL" of a mark (1-based); "FILE:1:1" when yaml-cpp has none (an empty document)
inline std::string yaml_location(const std::string& file, const YAML::Mark& mark) {
  if (mark.is_null()) return file + ":1:1";
  return fmt::format("{}:{}:{}", file, mark.line + 1, mark.column + 1);
}

// the same place as data (errors.h InputLocation), for CaseError
inline InputLocation yaml_input_location(const std::string& file, const YAML::Mark& mark, const std::string& key) {
  if (mark.is_null()) return {file, 1, 1, key};
  return {file, mark.line + 1, mark.column + 1, key};
}

// a document's text parsed, `file` naming it in the messages; CaseError "FILE:LINE:COL: YAML syntax error: ..."
inline YAML::Node parse_yaml_text(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw CaseError(yaml_location(file, e.mark) + ": YAML syntax error: " + e.msg, yaml_input_location(file, e.mark, ""));
  }
}

// the whole file parsed; CaseError "FILE: cannot read: reason" or "FILE:LINE:COL: YAML syntax error: ..."
inline YAML::Node load_yaml_file(const std::string& file) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) throw CaseError(file + ": cannot read: " + std::strerror(errno), InputLocation{file, 0, 0, ""});
  std::string text;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) text.append(buffer, n);
  if (std::ferror(f.get())) throw CaseError(file + ": cannot read: " + std::strerror(errno), InputLocation{file, 0, 0, ""});
  return parse_yaml_text(text, file);
}

// how a node reads in a message: 'text' for a scalar (cut, errors.h clipped), else its kind
inline std::string yaml_describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:  // a quoted scalar is a string, never a number or a bool
      return node.Tag() == "!" ? "the quoted string '" + clipped(node.Scalar()) + "'"
                               : "'" + clipped(node.Scalar()) + "'";
    case YAML::NodeType::Sequence: return "a sequence";
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Null: return "nothing (null)";
    case YAML::NodeType::Undefined: break;
  }
  return "nothing";
}

// scalar conversions: false when the node is not a value of the type
namespace yaml_detail {

// a quoted scalar is a string, never a number or a bool
inline bool is_plain_scalar(const YAML::Node& n) { return n.IsScalar() && n.Tag() != "!"; }

inline const char* expected(const double*) { return "a number"; }
inline const char* expected(const int*) { return "an integer"; }
inline const char* expected(const bool*) { return "true or false"; }
inline const char* expected(const std::string*) { return "a string"; }

inline bool parse(const YAML::Node& n, double& v) {
  return is_plain_scalar(n) && YAML::convert<double>::decode(n, v);
}
inline bool parse(const YAML::Node& n, int& v) {  // decimal only: 010 is not 8
  if (!is_plain_scalar(n)) return false;
  const std::string& s = n.Scalar();
  const char* first = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const char* last = s.data() + s.size();
  const auto [end, ec] = std::from_chars(first, last, v);
  return ec == std::errc() && end == last && first != last;
}
inline bool parse(const YAML::Node& n, bool& v) {
  return is_plain_scalar(n) && YAML::convert<bool>::decode(n, v);
}
inline bool parse(const YAML::Node& n, std::string& v) {
  if (!n.IsScalar()) return false;
  v = n.Scalar();
  return true;
}

// the value as written (cut, errors.h clipped), quoted for strings
template <class T>
std::string shown(const YAML::Node& n) {
  if constexpr (std::is_same_v<T, std::string>) return "'" + clipped(n.Scalar()) + "'";
  else return clipped(n.Scalar());
}

struct NoCheck {
  template <class T>
  std::string operator()(const T&) const { return {}; }
};

}  // namespace yaml_detail

// the edit distance of two keys (insertions, deletions, substitutions and swaps of neighbours each 1),
// for the "did you mean" of an unknown key
inline std::size_t key_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
// close enough to be a typo of the other: at most a third of the longer key's letters wrong, at least 1
inline bool is_typo_of(const std::string& typed, const std::string& meant) {
  if (typed.size() > 200 || meant.size() > 200) return false;  // no quadratic work on a pasted value
  const std::size_t d = key_distance(typed, meant);
  return d > 0 && d <= std::max<std::size_t>(1, std::max(typed.size(), meant.size()) / 3);
}

// checks shared by the sections
inline std::string positive_finite(double v) { return v > 0 && std::isfinite(v) ? "" : "must be > 0 and finite"; }
inline std::string nonnegative_finite(double v) { return v >= 0 && std::isfinite(v) ? "" : "must be >= 0 and finite"; }
inline std::string finite(double v) { return std::isfinite(v) ? "" : "must be finite"; }
inline auto in_closed(double lo, double hi) {  // [lo, hi]
  return [lo, hi](double v) -> std::string {
    return v >= lo && v <= hi ? "" : fmt::format("must be in [{}, {}]", lo, hi);
  };
}
inline auto in_half_open(double lo, double hi) {  // [lo, hi)
  return [lo, hi](double v) -> std::string {
    return v >= lo && v < hi ? "" : fmt::format("must be in [{}, {})", lo, hi);
  };
}

// Plausibility bounds on lengths, forces, moduli and masses: far wider than any machine element's, to catch
// a unit slip (40 m for a 40 mm radius), not to judge a design. The refusal gives the range and the likely
// slip; the reader adds what it got. Each key's bounds are listed with the case keys (README.md, docs/).
enum class Quantity { Length, Force, Modulus, Mass, Stiffness };
inline auto plausible(Quantity q, double lo, double hi) {
  return [q, lo, hi](double v) -> std::string {
    // a sign or a non-number first, as positive_finite and nonnegative_finite say it
    if (!std::isfinite(v) || (lo > 0 && v <= 0) || (lo >= 0 && v < 0))
      return lo > 0 ? "must be > 0 and finite" : "must be >= 0 and finite";
    if (v >= lo && v <= hi) return "";
    const bool high = v > hi;
    const char* unit = "m";
    const char* slip = "a slip in the exponent?";
    switch (q) {
      case Quantity::Length:
        slip = high ? (v / 1e3 >= lo && v / 1e3 <= hi ? "millimetres written as metres?" : "a slip in the exponent?")
                    : (v * 1e3 >= lo && v * 1e3 <= hi ? "millimetres converted to metres twice?"
                                                      : "a slip in the exponent (e-12 for e-3)?");
        break;
      case Quantity::Force:
        unit = "N";
        break;
      case Quantity::Modulus:
        unit = "Pa";
        if (!high) slip = "GPa or MPa written as Pa (steel: 2.1e11 Pa)?";
        break;
      case Quantity::Mass:
        unit = "kg";
        if (high && v / 1e3 >= lo && v / 1e3 <= hi) slip = "grams written as kilograms?";
        break;
      case Quantity::Stiffness:
        unit = "N/m";
        break;
    }
    return fmt::format("is not plausible: must be in [{:g}, {:g}] {} ({})", lo, hi, unit, slip);
  };
}

class YamlMap;

// One value of a case file with the key path that names it, for values that are more than a plain
// scalar (a time history, a list). Errors throw CaseError at this node: "FILE:LINE:COL: path: what".
class YamlValue {
 public:
  YamlValue(YAML::Node node, std::string file, std::string path, KeyLocations* locations)
      : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)), locations_(locations) {}

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string location() const { return yaml_location(file_, node_.Mark()); }

  [[noreturn]] void fail(const std::string& what) const {
    throw CaseError(location() + ": " + path_ + ": " + what, yaml_input_location(file_, node_.Mark(), path_));
  }

  // the node read as a T and checked; `label` names the part of a larger value in the messages
  // ("row 3: t_s must be finite, got .nan")
  template <class T, class Check = yaml_detail::NoCheck>
  T as(Check check = {}, const std::string& label = "") const {
    T parsed{};
    if (!yaml_detail::parse(node_, parsed))
      fail((label.empty() ? "" : label + ": ") + "expected " + yaml_detail::expected(&parsed) + ", got " +
           yaml_describe(node_));
    const std::string complaint = check(parsed);
    if (!complaint.empty())
      fail((label.empty() ? "" : label + " ") + complaint + ", got " + yaml_detail::shown<T>(node_));
    return parsed;
  }

  // the elements of a sequence, each under this key path (the caller's labels name the element);
  // `what` says what was expected when the node is not a sequence ("a list of times")
  std::vector<YamlValue> elements(const std::string& what = "a sequence") const {
    if (!node_.IsSequence()) fail("expected " + what + ", got " + yaml_describe(node_));
    std::vector<YamlValue> out;
    for (const YAML::Node& element : node_) out.emplace_back(element, file_, path_, locations_);
    return out;
  }

  // the node as a mapping under this key path, read by read_body(YamlMap&); its keys left over are errors
  template <class ReadBody>
  void mapping(ReadBody read_body) const;

 private:
  YAML::Node node_;
  std::string file_;
  std::string path_;
  KeyLocations* locations_ = nullptr;
};

class YamlMap {
 public:
  // node must be a mapping (checked); path is its key path, "" for the document
  YamlMap(const YAML::Node& node, std::string file, std::string path, KeyLocations* locations)
      : node_(node), file_(std::move(file)), path_(std::move(path)), locations_(locations) {
    if (!node_.IsMap()) fail_here("expected a mapping, got " + yaml_describe(node_));
    std::map<std::string, YAML::Mark> seen;
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string();
      if (!it->first.IsScalar())
        throw CaseError(yaml_location(file_, it->first.Mark()) + ": " + key_path("?") +
                        ": a key must be a plain name, got " + yaml_describe(it->first),
                        yaml_input_location(file_, it->first.Mark(), key_path("?")));
      const auto [first, inserted] = seen.emplace(key, it->first.Mark());
      if (!inserted)
        throw CaseError(yaml_location(file_, it->first.Mark()) + ": " + key_path(key) +
                        ": duplicate key (first at line " + std::to_string(first->second.line + 1) + ")",
                        yaml_input_location(file_, it->first.Mark(), key_path(key)));
      entries_.push_back({key, it->first, it->second});
    }
  }

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  std::string location() const { return yaml_location(file_, node_.Mark()); }

  // a value; a required key that is absent is an error at this mapping's position
  template <class T, class Check = yaml_detail::NoCheck>
  void required(const std::string& key, T& value, Check check = {}) { read(key, value, check, true); }
  // a value; an absent key leaves the default
  template <class T, class Check = yaml_detail::NoCheck>
  void optional(const std::string& key, T& value, Check check = {}) { read(key, value, check, false); }

  // a value of a form of its own, read by read_value(const YamlValue&); optional_value returns
  // whether the key is present
  template <class ReadValue>
  void required_value(const std::string& key, ReadValue read_value) { read_value_at(key, read_value, true); }
  template <class ReadValue>
  bool optional_value(const std::string& key, ReadValue read_value) { return read_value_at(key, read_value, false); }

  // a nested mapping, read by read_body(YamlMap&); its keys left over are errors
  template <class ReadBody>
  void section(const std::string& key, ReadBody read_body) { read_section(key, read_body, true); }
  template <class ReadBody>
  void optional_section(const std::string& key, ReadBody read_body) { read_section(key, read_body, false); }

  // an error at the key's value (at this mapping when the key is absent)
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const Entry* e = find(key);
    const YAML::Mark mark = e ? e->value.Mark() : node_.Mark();
    throw CaseError(yaml_location(file_, mark) + ": " + key_path(key) + ": " + what,
                    yaml_input_location(file_, mark, key_path(key)));
  }
  // an error about this mapping as a whole
  [[noreturn]] void fail_here(const std::string& what) const {
    throw CaseError(location() + ": " + (path_.empty() ? "" : path_ + ": ") + what,
                    yaml_input_location(file_, node_.Mark(), path_));
  }

  // every key present must have been asked for; an unknown key is named with the closest valid one
  void check_all_read() const {
    for (const Entry& e : entries_) {
      if (asked_.count(e.key)) continue;
      std::string valid, closest;
      std::size_t closest_distance = 0;
      for (const std::string& k : asked_) {
        valid += (valid.empty() ? "" : ", ") + k;
        if (!is_typo_of(e.key, k)) continue;
        const std::size_t d = key_distance(e.key, k);
        if (closest.empty() || d < closest_distance) closest = k, closest_distance = d;
      }
      unknown_key(e, closest.empty() ? std::string() : "did you mean '" + closest + "'?",
                  valid.empty() ? std::string("this mapping takes no keys") : "valid: " + valid);
    }
  }

 private:
  struct Entry {
    std::string key;
    YAML::Node key_node, value;
  };

  // marks the key as known whether present or not
  const Entry* ask(const std::string& key) {
    asked_.insert(key);
    return find(key);
  }
  const Entry* find(const std::string& key) const {
    for (const Entry& e : entries_)
      if (e.key == key) return &e;
    return nullptr;
  }

  template <class T, class Check>
  void read(const std::string& key, T& value, const Check& check, bool is_required) {
    const Entry* e = ask(key);
    if (!e) {
      if (is_required) fail_here_missing(key, "required key is missing");
      return;
    }
    value = YamlValue(e->value, file_, key_path(key), locations_).as<T>(check);
    if (locations_) (*locations_)[key_path(key)] = yaml_location(file_, e->value.Mark());
  }

  template <class ReadValue>
  bool read_value_at(const std::string& key, ReadValue& read_value, bool is_required) {
    const Entry* e = ask(key);
    if (!e) {
      if (is_required) fail_here_missing(key, "required key is missing");
      return false;
    }
    if (locations_) (*locations_)[key_path(key)] = yaml_location(file_, e->value.Mark());
    read_value(YamlValue(e->value, file_, key_path(key), locations_));
    return true;
  }

  template <class ReadBody>
  void read_section(const std::string& key, ReadBody& read_body, bool is_required) {
    const Entry* e = ask(key);
    if (!e) {
      if (is_required) fail_here_missing(key, "required section is missing");
      return;
    }
    if (!e->value.IsMap()) fail(key, "expected a mapping, got " + yaml_describe(e->value));
    YamlMap sub(e->value, file_, key_path(key), locations_);
    if (locations_) (*locations_)[sub.path()] = sub.location();
    read_body(sub);
    sub.check_all_read();
  }

  // a required key that is absent: if a key not (yet) asked for is a typo of it, the error is that key's,
  // at its line ("frction: unknown key, did you mean 'friction'?"), else at this mapping
  [[noreturn]] void fail_here_missing(const std::string& key, const std::string& what) const {
    for (const Entry& e : entries_)
      if (!asked_.count(e.key) && is_typo_of(e.key, key))
        unknown_key(e, "did you mean '" + key + "'?", key_path(key) + ": " + what);
    throw CaseError(location() + ": " + key_path(key) + ": " + what, yaml_input_location(file_, node_.Mark(), key_path(key)));
  }
  [[noreturn]] void unknown_key(const Entry& e, const std::string& suggestion, const std::string& note) const {
    throw CaseError(yaml_location(file_, e.key_node.Mark()) + ": " + key_path(clipped(e.key)) + ": unknown key" +
                        (suggestion.empty() ? "" : ", " + suggestion) + " (" + note + ")",
                    yaml_input_location(file_, e.key_node.Mark(), key_path(e.key)));
  }

  YAML::Node node_;
  std::string file_;
  std::string path_;
  KeyLocations* locations_ = nullptr;
  std::vector<Entry> entries_;
  std::set<std::string> asked_;
};

template <class ReadBody>
void YamlValue::mapping(ReadBody read_body) const {
  YamlMap m(node_, file_, path_, locations_);
  read_body(m);
  m.check_all_read();
}

// a parsed document as a mapping, `file` naming it, read by read_body(YamlMap&); its keys left over are errors
template <class ReadBody>
void read_yaml_document(const YAML::Node& doc, const std::string& file, KeyLocations* locations, ReadBody read_body) {
  if (!doc.IsMap())
    throw CaseError(yaml_location(file, doc.Mark()) + ": expected a mapping of sections, got " + yaml_describe(doc),
                    yaml_input_location(file, doc.Mark(), ""));
  YamlMap root(doc, file, "", locations);
  read_body(root);
  root.check_all_read();
}

// the document of a file as a mapping, read by read_body(YamlMap&); its keys left over are errors
template <class ReadBody>
void read_yaml_file(const std::string& file, KeyLocations* locations, ReadBody read_body) {
  read_yaml_document(load_yaml_file(file), file, locations, read_body);
}

}  // namespace contact
