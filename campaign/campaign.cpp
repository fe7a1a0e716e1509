#include "campaign/campaign.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "io/case.hpp"
#include "io/schema_reader.hpp"

namespace suspend::campaign {

namespace {
namespace fs = std::filesystem;

std::string yaml_text(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

std::string key_of(const YAML::Node& k, const std::string& where) {
  if (!k.IsScalar() || k.Scalar().empty()) throw InputError(where + ": keys must be dotted case keys (e.g. particles.phi)");
  const std::string key = k.Scalar();
  if (key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos || key.find('=') != std::string::npos)
    throw InputError(where + ": '" + key + "' is not a dotted case key (e.g. particles.phi)");
  return key;
}

std::vector<Assignment> assignments(const YAML::Node& map, const std::string& where) {
  if (!map.IsMap()) throw InputError(where + ": must be a mapping of dotted case keys to values");
  std::vector<Assignment> out;
  for (const auto& kv : map) {  // keys given twice were refused when the file was read
    const std::string key = key_of(kv.first, where);
    if (kv.second.IsNull()) throw InputError(where + "." + key + ": has no value");
    out.push_back({key, yaml_text(kv.second)});
  }
  return out;
}

// A point's name: each parameter as its last key component and its value (the full key where two varied keys
// share a last component), joined by '_'; characters that do not belong in a folder name become '_'.
std::string point_name(const std::vector<Assignment>& parameters, const std::vector<std::string>& varied_keys) {
  auto last = [](const std::string& k) { return k.substr(k.rfind('.') + 1); };
  std::string name;
  for (const Assignment& a : parameters) {
    int sharing = 0;
    for (const std::string& k : varied_keys) sharing += last(k) == last(a.key);
    std::string part = sharing > 1 ? a.key : last(a.key);
    for (char& ch : part)
      if (ch == '.') ch = '_';
    for (char ch : a.value) part += std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-' || ch == '+' ? ch : '_';
    name += (name.empty() ? "" : "_") + part;
  }
  return name.empty() ? "base" : name;
}

constexpr std::size_t max_points = 20'000;  // listing each point loads its case: 20000 take ~12 s

// The points of one `vary` mapping: the product of its lists, first key outermost.
void append_product(const YAML::Node& vary, const std::string& where, std::vector<std::vector<Assignment>>& out) {
  if (!vary.IsMap() || vary.size() == 0)
    throw InputError(where + ": must be a mapping of dotted case keys to lists of values, e.g. particles.phi: [0.4, 0.45]");
  // Counted before it is built: a product too large to list is refused in no time.
  double count = 1.0;
  for (const auto& kv : vary) {
    const std::string key = key_of(kv.first, where);
    if (!kv.second.IsSequence() || kv.second.size() == 0)
      throw InputError(where + "." + key + ": must be a non-empty list of values, e.g. [0.40, 0.45]");
    count *= static_cast<double>(kv.second.size());
  }
  if (count + static_cast<double>(out.size()) > static_cast<double>(max_points))
    throw InputError(where + ": the product of its lists has " + std::to_string(std::llround(std::min(count, 1e18))) +
                     " points; a campaign holds at most " + std::to_string(max_points) + " (split it into several)");
  std::vector<std::vector<Assignment>> product = {{}};
  for (const auto& kv : vary) {
    const std::string key = key_of(kv.first, where);
    std::vector<std::vector<Assignment>> next;
    for (const auto& partial : product)
      for (const auto& v : kv.second) {
        next.push_back(partial);
        next.back().push_back({key, yaml_text(v)});
      }
    product = std::move(next);
  }
  out.insert(out.end(), product.begin(), product.end());
}

Search read_search(const YAML::Node& n) {
  if (!n.IsMap())
    throw InputError("search: must be a mapping {key: particles.phi, lo: 0.40, hi: 0.62, tolerance: 0.01, seeds: 3}");
  const std::vector<std::string> allowed = {"key", "lo", "hi", "tolerance", "seeds", "from_flowing", "flows"};
  for (const auto& kv : n) {
    const std::string k = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      const std::string near = io::closest_word(k, allowed);
      throw InputError("search." + k + ": unknown key" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                       "; allowed: key, lo, hi, tolerance, seeds, from_flowing, flows");
    }
  }
  auto number = [&](const char* k) {
    if (!n[k]) throw InputError(std::string("search.") + k + ": missing");
    try {
      const double v = n[k].as<double>();
      if (!std::isfinite(v)) throw YAML::Exception(YAML::Mark::null_mark(), "");
      return v;
    } catch (const YAML::Exception&) {
      throw InputError(std::string("search.") + k + ": '" + yaml_text(n[k]) + "' is not a finite number");
    }
  };
  Search s;
  s.key = key_of(n["key"] ? n["key"] : YAML::Node(""), "search.key");
  s.lo = number("lo");
  s.hi = number("hi");
  s.tolerance = number("tolerance");
  const double seeds = n["seeds"] ? number("seeds") : 1.0;
  if (!(s.lo < s.hi)) throw InputError("search: lo = " + yaml_text(n["lo"]) + " must be below hi = " + yaml_text(n["hi"]));
  if (!(s.tolerance > 0.0)) throw InputError("search.tolerance: must be > 0, not " + yaml_text(n["tolerance"]));
  if (s.tolerance >= s.hi - s.lo) throw InputError("search.tolerance: must be below hi - lo (nothing to search)");
  if (!(seeds >= 1.0) || seeds != std::floor(seeds) || seeds > 100)
    throw InputError("search.seeds: must be a whole number from 1 to 100, not " + yaml_text(n["seeds"]));
  s.seeds = static_cast<int>(seeds);
  if (n["from_flowing"]) {
    s.from_flowing = number("from_flowing");
    if (!(s.from_flowing >= 0.0)) throw InputError("search.from_flowing: must be >= 0 (0: never)");
  }
  if (n["flows"]) {
    const std::string side = n["flows"].IsScalar() ? n["flows"].Scalar() : yaml_text(n["flows"]);
    if (side != "below" && side != "above")
      throw InputError("search.flows: '" + side + "' is not allowed; allowed: below (the default: values below the "
                       "boundary flow, e.g. particles.phi) or above (e.g. flow.shear_stress against a yield stress)");
    s.flows_above = side == "above";
  }
  if (s.flows_above && s.from_flowing > 0.0)
    throw InputError("search.from_flowing: only with flows: below (it rescales a flowing state to a denser phi)");
  return s;
}

}  // namespace

std::string format_value(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::vector<std::string> Campaign::overrides(const Point& p) const {
  std::vector<std::string> out;
  for (const Assignment& a : set) out.push_back(a.key + "=" + a.value);
  for (const Assignment& a : p.parameters) out.push_back(a.key + "=" + a.value);
  return out;
}

Point Campaign::make_point(const std::vector<Assignment>& parameters, const std::vector<Assignment>& unnamed) const {
  Point p{point_name(parameters, varied_keys), parameters, ""};
  p.parameters.insert(p.parameters.end(), unnamed.begin(), unnamed.end());
  try {
    p.identity = io::result_identity(io::load_case(case_file, overrides(p)));
  } catch (const InputError& e) {
    throw InputError("point " + p.name + ": " + e.what());
  }
  return p;
}

const Point* Campaign::find(const std::string& name) const {
  for (const Point& p : points)
    if (p.name == name) return &p;
  return nullptr;
}

Campaign load_campaign(const std::string& path) {
  const YAML::Node root = io::load_yaml_document(path, "campaign");
  if (!root.IsMap()) throw InputError(path + ": a campaign file is a mapping with keys case, set, vary, points");
  const std::vector<std::string> allowed = {"case", "set", "vary", "points", "search"};
  for (const auto& kv : root) {
    const std::string k = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      const std::string near = io::closest_word(k, allowed);
      throw InputError(k + ": unknown campaign key" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                       "; allowed: case, set, vary, points, search");
    }
  }
  Campaign c;
  c.source = path;
  if (!root["case"] || !root["case"].IsScalar() || root["case"].Scalar().empty())
    throw InputError("case: missing; name the base case file (relative to the campaign file)");
  fs::path case_file(root["case"].Scalar());
  if (case_file.is_relative()) case_file = fs::path(path).parent_path() / case_file;
  c.case_file = case_file.lexically_normal().string();
  if (!fs::is_regular_file(c.case_file)) throw InputError("case: '" + c.case_file + "' does not exist or is not a file");
  if (root["set"]) c.set = assignments(root["set"], "set");

  std::vector<std::vector<Assignment>> parameter_sets;
  if (root["vary"]) {  // one mapping of lists (their product), or a list of such mappings (the union of products)
    const YAML::Node vary = root["vary"];
    if (vary.IsMap()) {
      append_product(vary, "vary", parameter_sets);
    } else if (vary.IsSequence()) {
      if (vary.size() == 0) throw InputError("vary: an empty list; give at least one mapping of keys to lists, or leave vary out");
      for (std::size_t i = 0; i < vary.size(); ++i)
        append_product(vary[i], "vary[" + std::to_string(i) + "]", parameter_sets);
    } else {
      throw InputError("vary: must be a mapping of dotted case keys to lists of values, or a list of such mappings");
    }
  }
  if (root["points"]) {
    const YAML::Node points = root["points"];
    if (!points.IsSequence()) throw InputError("points: must be a list of mappings of dotted case keys to values");
    for (std::size_t i = 0; i < points.size(); ++i)
      parameter_sets.push_back(assignments(points[i], "points[" + std::to_string(i) + "]"));
  }
  if (parameter_sets.empty()) parameter_sets.push_back({});

  for (const auto& ps : parameter_sets)
    for (const Assignment& a : ps)
      if (std::find(c.varied_keys.begin(), c.varied_keys.end(), a.key) == c.varied_keys.end())
        c.varied_keys.push_back(a.key);
  if (root["search"]) {
    c.search = read_search(root["search"]);
    for (const std::string& k : {c.search->key, std::string("run.seed")})
      if (std::find(c.varied_keys.begin(), c.varied_keys.end(), k) != c.varied_keys.end())
        throw InputError("search.key: " + k + " is also varied (vary or points); the search sets it");
    c.varied_keys.push_back(c.search->key);
    c.varied_keys.push_back("run.seed");
  }
  for (const Assignment& a : c.set)
    if (std::find(c.varied_keys.begin(), c.varied_keys.end(), a.key) != c.varied_keys.end())
      throw InputError("set." + a.key + ": also varied (vary, points or search); give each key in one place");
  if (c.search) {
    // The groups are checked as cases at both ends of the range; the points come from the search.
    for (const auto& ps : parameter_sets) {
      for (const double v : {c.search->lo, c.search->hi}) {
        std::vector<Assignment> at = ps;
        at.push_back({c.search->key, format_value(v)});
        at.push_back({"run.seed", "1"});
        c.make_point(at);
      }
      c.groups.push_back(ps);
    }
    return c;
  }
  std::map<std::string, std::size_t> names;
  for (const auto& ps : parameter_sets) {
    Point p{point_name(ps, c.varied_keys), ps, ""};
    if (const auto [at, fresh] = names.emplace(p.name, c.points.size()); !fresh)
      throw InputError("points: two points map to the folder '" + p.name + "' (" +
                       (c.points[at->second].parameters == ps ? std::string("the same parameters given twice")
                                                              : std::string("values that differ only in characters a "
                                                                            "folder name cannot hold")) + ")");
    try {
      p.identity = io::result_identity(io::load_case(c.case_file, c.overrides(p)));
    } catch (const InputError& e) {
      throw InputError("point " + p.name + ": " + e.what());
    }
    c.points.push_back(std::move(p));
  }
  return c;
}

}  // namespace suspend::campaign
