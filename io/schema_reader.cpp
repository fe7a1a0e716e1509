#include "io/schema_reader.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace suspend::io {

namespace {
std::string join_words(const std::vector<std::string>& words) {
  std::string list;
  for (const auto& w : words) {
    if (!list.empty()) list += ", ";
    list += w;
  }
  return list;
}
std::string suggestion(const std::string& guess) {
  return guess.empty() ? std::string() : "; did you mean '" + guess + "'?";
}
}  // namespace

SchemaReader::SchemaReader(YAML::Node node, std::string path) : node_(std::move(node)), path_(std::move(path)) {
  if (node_ && !node_.IsNull() && !node_.IsMap())
    throw InputError((path_.empty() ? std::string("case") : path_) + ": expected a mapping of keys to values");
}

void SchemaReader::fail(const std::string& key, const std::string& what) const {
  throw InputError(key_path(key) + ": " + what);
}

bool SchemaReader::has(const std::string& key) {
  asked_.insert(key);
  return node_ && node_.IsMap() && node_[key] && !node_[key].IsNull();
}

YAML::Node SchemaReader::scalar(const std::string& key) {
  YAML::Node v = node_[key];
  if (!v.IsScalar()) fail(key, "expected a single value, got a " + std::string(v.IsMap() ? "mapping" : "list"));
  return v;
}

double SchemaReader::number_in(const YAML::Node& v, const std::string& key, Range range) const {
  double x = 0.0;
  try {
    x = v.as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "'" + v.Scalar() + "' is not a number (expected " + range.describe() + ")");
  }
  if (!range.contains(x)) fail(key, exact(x) + " is out of range: must be " + range.describe());
  return x;
}

std::optional<double> SchemaReader::optional_number(const std::string& key, Range range) {
  if (!has(key)) return std::nullopt;
  return number_in(scalar(key), key, range);
}

double SchemaReader::number(const std::string& key, double fallback, Range range) {
  return optional_number(key, range).value_or(fallback);
}

double SchemaReader::number(const std::string& key, Range range) {
  if (!has(key)) fail(key, "missing; a number " + range.describe() + " is required");
  return *optional_number(key, range);
}

std::vector<double> SchemaReader::number_list(const std::string& key, Range range) {
  std::vector<double> out;
  if (!has(key)) return out;
  const YAML::Node v = node_[key];
  if (v.IsMap()) fail(key, "expected a number or a list of numbers, got a mapping");
  if (v.IsScalar()) return {*optional_number(key, range)};
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string item = key + "[" + std::to_string(k) + "]";
    if (!v[k].IsScalar()) fail(item, "expected a number");
    out.push_back(number_in(v[k], item, range));
  }
  return out;
}

std::optional<long> SchemaReader::optional_integer(const std::string& key, long lo, long hi) {
  if (!has(key)) return std::nullopt;
  const YAML::Node v = scalar(key);
  long x = 0;
  try {
    x = v.as<long>();
  } catch (const YAML::Exception&) {
    fail(key, "'" + v.Scalar() + "' is not an integer (expected " + std::to_string(lo) + " .. " +
                  std::to_string(hi) + ")");
  }
  if (x < lo || x > hi)
    fail(key, std::to_string(x) + " is out of range: must be in " + std::to_string(lo) + " .. " + std::to_string(hi));
  return x;
}

long SchemaReader::integer(const std::string& key, long fallback, long lo, long hi) {
  return optional_integer(key, lo, hi).value_or(fallback);
}

bool SchemaReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const YAML::Node v = scalar(key);
  try {
    return v.as<bool>();
  } catch (const YAML::Exception&) {
    fail(key, "'" + v.Scalar() + "' is not a boolean (expected true or false)");
  }
}

std::optional<std::string> SchemaReader::optional_text(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return scalar(key).Scalar();
}

std::string SchemaReader::text(const std::string& key, const std::string& fallback) {
  return optional_text(key).value_or(fallback);
}

std::string SchemaReader::choice(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) {
  const std::string v = text(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
  const std::string guess = closest_word(v, allowed);
  fail(key, "'" + v + "' is not allowed (one of: " + join_words(allowed) + ")" + suggestion(guess));
}

SchemaReader SchemaReader::child(const std::string& key) {
  asked_.insert(key);
  YAML::Node v = (node_ && node_.IsMap()) ? node_[key] : YAML::Node();
  if (v && !v.IsNull() && !v.IsMap()) fail(key, "expected a mapping of keys to values");
  return SchemaReader(v, key_path(key));
}

std::vector<SchemaReader> SchemaReader::children(const std::string& key) {
  std::vector<SchemaReader> out;
  if (!has(key)) return out;
  const YAML::Node v = node_[key];
  if (!v.IsSequence()) fail(key, "expected a list");
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (!v[k].IsMap()) fail(key, "entry " + std::to_string(k) + " must be a mapping of keys to values");
    out.emplace_back(v[k], key_path(key) + "[" + std::to_string(k) + "]");
  }
  return out;
}

void SchemaReader::finish() const {
  if (!node_ || !node_.IsMap()) return;
  std::vector<std::string> allowed(asked_.begin(), asked_.end());
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
    if (asked_.count(key)) continue;
    // `{from:file}` in YAML is the key "from:file" with no value: a colon without its space, never a key left out.
    if (const auto colon = key.find(':'); colon != std::string::npos)
      throw InputError(key_path(key) + ": not a key; write '" + key.substr(0, colon) + ": " + key.substr(colon + 1) +
                       "' (YAML needs a space after the colon)");
    if (kv.second.IsNull()) continue;  // `key: null` (--set key=null) is the key left out
    throw InputError(key_path(key) + ": unknown key" + suggestion(closest_word(key, allowed)) +
                     " (allowed here: " + join_words(allowed) + ")");
  }
}

std::string closest_word(const std::string& word, const std::vector<std::string>& candidates) {
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      std::swap(prev, cur);
    }
    return prev[b.size()];
  };
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

namespace {

// yaml-cpp accepts a quoted scalar that runs to the end of the text unclosed (and swallows the rest of the file
// into it), so a quoted scalar's closing quote is looked for in the source text it was parsed from.
void check_closing_quote(const YAML::Node& n, const std::string& source, const std::string& where) {
  if (source.empty() || n.Tag() != "!") return;
  const YAML::Mark m = n.Mark();
  if (m.pos < 0 || static_cast<std::size_t>(m.pos) >= source.size()) return;
  const char q = source[static_cast<std::size_t>(m.pos)];
  if (q != '"' && q != '\'') return;
  for (std::size_t k = static_cast<std::size_t>(m.pos) + 1; k < source.size(); ++k) {
    if (q == '"' && source[k] == '\\') {
      ++k;
    } else if (source[k] == q) {
      if (q == '\'' && k + 1 < source.size() && source[k + 1] == '\'') {
        ++k;  // '' inside single quotes is a quote
      } else {
        return;
      }
    }
  }
  throw InputError(where + ": the quoted text opened at line " + std::to_string(m.line + 1) + ", column " +
                   std::to_string(m.column + 1) + " is never closed (add the closing " + q + ")");
}

}  // namespace

YAML::Node load_yaml_document(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) throw InputError(path + ": " + what + " file not found");
  if (fs::is_directory(path)) throw InputError(path + ": is a directory, not a " + what + " file");
  if (!fs::is_regular_file(path)) throw InputError(path + ": not a regular file; a " + what + " file is YAML text");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be read (permissions?)");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path + ": not valid YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (docs.size() > 1)
    throw InputError(path + ": holds " + std::to_string(docs.size()) + " YAML documents (separated by ---); a " + what +
                     " file is one");
  YAML::Node root = docs.empty() || !docs[0] || docs[0].IsNull() ? YAML::Node(YAML::NodeType::Map) : docs[0];
  check_yaml_structure(root, "", text);
  return root;
}

void check_yaml_structure(const YAML::Node& n, const std::string& path, const std::string& source) {
  const std::string where = path.empty() ? "case file" : path;
  if (n.IsScalar()) check_closing_quote(n, source, where);
  const std::string& tag = n.Tag();
  if (!tag.empty() && tag != "?" && tag != "!")
    throw InputError(where + ": YAML tags (" + tag + ") are not read; remove the tag and give the plain value");
  if (n.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : n) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      const std::string child = path.empty() ? key : path + "." + key;
      if (!kv.first.IsScalar()) throw InputError(where + ": a key must be a plain word, not a list or mapping");
      check_closing_quote(kv.first, source, where);
      if (!seen.insert(key).second)
        throw InputError(child + ": given twice in one mapping (YAML keeps only one; give it once)");
      check_yaml_structure(kv.second, child, source);
    }
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i)
      check_yaml_structure(n[i], path + "[" + std::to_string(i) + "]", source);
  }
}

void apply_override(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + assignment + ": expected KEY=VALUE, e.g. --set particles.phi=0.52");
  const std::string path = assignment.substr(0, eq);
  if (path.front() == '.' || path.back() == '.')
    throw InputError("--set " + assignment + ": '" + path + "' starts or ends with a dot; give a dotted key such as particles.phi");
  const std::string value = assignment.substr(eq + 1);
  std::vector<std::string> keys;
  std::stringstream ss(path);
  for (std::string k; std::getline(ss, k, '.');) {
    if (k.empty()) throw InputError("--set " + assignment + ": empty key in '" + path + "'");
    keys.push_back(k);
  }
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + path + ": cannot parse value '" + value + "' (" + e.msg + ")");
  }
  check_yaml_structure(parsed, path, value);
  // yaml-cpp nodes are references: walk by building the chain of nodes explicitly.
  if (root.IsScalar() || root.IsSequence()) throw InputError("case file: expected a mapping of sections");
  std::vector<YAML::Node> chain{root};
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    YAML::Node cur = chain.back();
    YAML::Node next = cur[keys[k]];
    if (next.IsScalar() || next.IsSequence())
      throw InputError("--set " + path + ": '" + keys[k] + "' holds a value, not a mapping");
    chain.push_back(next);
  }
  YAML::Node parent = chain.back();
  parent[keys.back()] = parsed;
}

}  // namespace suspend::io
