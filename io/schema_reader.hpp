// Reading a YAML case with validation: every value is read through a SchemaReader that knows its dotted key path,
// so every error names the key, the value and what is allowed, in one line. Keys that nothing asked for are
// reported as unknown, with a "did you mean" suggestion among the keys that are allowed at that place.
#pragma once
#include <yaml-cpp/yaml.h>

#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/range.hpp"

namespace suspend::io {

class SchemaReader {
 public:
  SchemaReader(YAML::Node node, std::string path);

  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }  // the mapping read (to merge it with another)
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key);

  double number(const std::string& key, double fallback, Range range = {});
  double number(const std::string& key, Range range);  // required
  std::optional<double> optional_number(const std::string& key, Range range = {});
  // One number or a list of numbers, each in range (absent: empty).
  std::vector<double> number_list(const std::string& key, Range range = {});
  long integer(const std::string& key, long fallback, long lo, long hi);
  std::optional<long> optional_integer(const std::string& key, long lo, long hi);
  bool boolean(const std::string& key, bool fallback);
  std::string text(const std::string& key, const std::string& fallback);
  std::optional<std::string> optional_text(const std::string& key);
  // One of a fixed set of words.
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed);

  // A nested mapping (absent -> an empty mapping, so every key inside takes its default).
  SchemaReader child(const std::string& key);
  // A sequence of mappings.
  std::vector<SchemaReader> children(const std::string& key);

  // Throws for any key in this mapping that was never asked for. Call after reading every key.
  void finish() const;

  // Raises an InputError about one key of this mapping.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  YAML::Node scalar(const std::string& key);
  // The scalar v as a number in range; InputError naming `key` otherwise.
  double number_in(const YAML::Node& v, const std::string& key, Range range) const;
  YAML::Node node_;
  std::string path_;
  std::set<std::string> asked_;
};

// Reads a YAML file that must hold one document (an empty file is an empty mapping), checked with
// check_yaml_structure. `what` names the file in messages ("case", "campaign"). InputError on any problem.
YAML::Node load_yaml_document(const std::string& path, const std::string& what);

// Refuses what YAML allows but a case cannot mean: a key given twice in one mapping (yaml-cpp would keep the first
// silently), explicit tags (!!str 0.4), non-scalar keys, and, given the `source` text n was parsed from, a quoted
// scalar never closed (yaml-cpp runs it to the end of the text). InputError names the key path.
void check_yaml_structure(const YAML::Node& n, const std::string& path = "", const std::string& source = "");

// Applies `--set a.b.c=VALUE` (VALUE parsed as YAML) to a case tree, creating mappings as needed.
void apply_override(YAML::Node& root, const std::string& assignment);

// The closest word to `word` among `candidates` (edit distance), or "" if none is close.
std::string closest_word(const std::string& word, const std::vector<std::string>& candidates);

// The same as a YAML scalar (0.1, not 0.10000000000000001), still read back as a number.
inline YAML::Node number_node(double v) { return YAML::Node(exact(v)); }

}  // namespace suspend::io
