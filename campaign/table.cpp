#include "campaign/table.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "campaign/point_record.hpp"
#include "io/atomic_file.hpp"
#include "io/derived_rheology.hpp"

namespace suspend::campaign {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {
// A YAML scalar as JSON: numbers and booleans as such, anything else as text.
json json_value(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size()) return v;
  if (text == "true" || text == "false") return text == "true";
  return text;
}

// The point a start from a file (a search's dense value, `particles.initial` naming POINTS/NAME/run.h5) descends
// from, found among the campaign's points by its folder name; null when there is none.
const Point* source_point(const Campaign& c, const Point& p) {
  for (const Assignment& a : p.parameters) {
    if (a.key != "particles.initial") continue;
    const YAML::Node initial = YAML::Load(a.value);
    if (!initial["file"]) return nullptr;
    const std::string name = fs::path(initial["file"].as<std::string>()).parent_path().filename().string();
    for (const Point& q : c.points)
      if (q.name == name && &q != &p) return &q;
  }
  return nullptr;
}

// What the fits group by, read from the point's resolved case.
json case_facts(const Campaign& c, const Point& p, int depth = 0) {
  const YAML::Node n = YAML::Load(p.identity);
  json f;
  f["model"] = n["hydrodynamics"]["model"].as<std::string>();
  f["control"] = n["flow"]["control"].as<std::string>();
  f["phi"] = n["particles"]["phi"].as<double>();
  const YAML::Node contact = n["contact"];
  f["law"] = contact["law"].as<std::string>();
  if (contact["mu_s"])
    f["mu_s"] = contact["mu_s"].as<double>();
  else if (contact["mu"])
    f["mu_s"] = contact["mu"].as<double>();
  else
    f["mu_s"] = 0.0;
  f["g_adh"] = contact["g_adh"] ? contact["g_adh"].as<double>() : 0.0;
  if (n["flow"]["shear_stress"]) f["shear_stress"] = n["flow"]["shear_stress"].as<double>();
  f["strain"] = n["run"]["strain"].as<double>();
  // The near field and the system size, which the boundary campaigns compare (issue 36): the pairwise two-sphere
  // functions (FCM's sub-grid lubrication is exact), and the box edge or the particle count it follows from.
  const YAML::Node lubrication = n["hydrodynamics"]["lubrication"];
  if (f["model"] == "fcm")
    f["functions"] = "fcm";
  else if (lubrication && lubrication["enabled"] && lubrication["enabled"].as<bool>())
    f["functions"] = lubrication["functions"] ? lubrication["functions"].as<std::string>() : "singular";
  else
    f["functions"] = "none";
  // A start from a file (a search's dense value from a seed's flowing state, listed as its particles.initial) has the
  // box and count of the packing it descends from (its own edge is that box compressed by (phi_source / phi)^(1/3),
  // docs/output.md), so the size a campaign compares is named for every point, also in a table restored without runs.
  for (const Assignment& a : p.parameters) {
    if (a.key != "particles.initial") continue;
    const Point* source = depth < 100 ? source_point(c, p) : nullptr;
    if (!source) return f;
    const json s = case_facts(c, *source, depth + 1);
    f["started_from"] = source->name;
    for (const char* key : {"box", "count"})
      if (s.contains(key)) f[key] = s[key];
    return f;
  }
  const YAML::Node box = n["box"];
  if (box && box["length"]) {
    const double x = box["length"]["x"].as<double>(), y = box["length"]["y"].as<double>(),
                 z = box["length"]["z"].as<double>();
    f["box"] = x == y && y == z ? json(x) : json::array({x, y, z});
  } else if (n["particles"]["count"]) {
    f["count"] = n["particles"]["count"].as<long>();
  }
  return f;
}
}  // namespace

json gather_table(const Campaign& c, const fs::path& dir) {
  json points = json::array();
  for (const Point& p : c.points) {
    const fs::path pd = point_dir(dir, p);
    PointRecord r = read_record(pd);
    if (r.status == "running" && !locked_elsewhere(pd)) r.status = "pending";  // its sweep was stopped
    json e;
    e["name"] = p.name;
    e["status"] = r.status;
    e["parameters"] = json::object();
    for (const Assignment& a : p.parameters) e["parameters"][a.key] = json_value(a.value);
    e["case"] = case_facts(c, p);
    e["wall_seconds"] = r.wall_seconds;
    if (r.cpu_seconds > 0.0) e["cpu_seconds"] = r.cpu_seconds;  // absent: run before the sweep recorded it
    if (!r.message.empty()) e["message"] = r.message;
    e["summary"] = nullptr;
    if (r.status == "done" || r.status == "jammed") {
      std::ifstream in(pd / "summary.json");
      json s = json::parse(in, nullptr, false);
      if (!s.is_discarded()) {
        // The point's own wall_seconds (every invocation) replaces the last invocation's, so that a table does not
        // depend on how the points were interrupted; the resolved case is kept once per point, in the run's folder.
        s.erase("wall_seconds");
        s.erase("case");
        e["summary"] = s;
        e["derived"] = io::derived_rheology(s);
      }
    }
    points.push_back(std::move(e));
  }
  return {{"campaign", c.source}, {"case", c.case_file}, {"points", points}};
}

std::string table_csv(const Campaign& c, const json& table) {
  const std::vector<std::string> derived = {"eta_r", "Sigma_c12/Sigma_12", "Sigma_c22/Sigma_12", "Sigma_c11/Sigma_c12",
                                            "N1", "N2", "Pi", "mu", "J", "sigma_star", "G_adh"};
  std::ostringstream out;
  out << "name,status";
  for (const std::string& k : c.varied_keys) out << ',' << k;
  out << ",phi,mu_s,g_adh";
  for (const std::string& k : derived) out << ',' << k << ',' << k << "_sem";
  out << ",contacts_per_particle,contacts_per_particle_sem,window_from,window_to,wall_seconds\n";
  auto number = [&](const json& v) {  // null (an undefined mean or error) stays an empty cell
    char b[32] = "";
    if (v.is_number()) std::snprintf(b, sizeof b, "%.8g", v.get<double>());
    out << ',' << b;
  };
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const json& e = table["points"][i];
    out << e["name"].get<std::string>() << ',' << e["status"].get<std::string>();
    for (const std::string& k : c.varied_keys) {  // as written in the campaign file
      out << ',';
      for (const Assignment& a : c.points[i].parameters)
        if (a.key == k) out << (a.value.find(',') == std::string::npos ? a.value : '"' + a.value + '"');
    }
    const json& s = e["summary"];
    if (s.is_null()) {
      out << ',' << ',' << e["case"]["mu_s"].dump() << ',' << e["case"]["g_adh"].dump();
      for (std::size_t k = 0; k < 2 * derived.size() + 4; ++k) out << ',';
      number(e["wall_seconds"]);
      out << '\n';
      continue;
    }
    number(s["phi"]);
    number(e["case"]["mu_s"]);
    number(e["case"]["g_adh"]);
    for (const std::string& k : derived) {
      if (e["derived"].contains(k)) {
        number(e["derived"][k]["mean"]);
        number(e["derived"][k]["sem"]);
      } else {
        out << ",,";
      }
    }
    // Z = 2 contacts / particles (summaries written before contacts_per_particle existed: from contacts)
    const double n = s["particles"].get<double>();
    const json& pairs = s["contacts"];
    const json z = s.contains("contacts_per_particle")
                       ? s["contacts_per_particle"]
                       : json{{"mean", pairs["mean"].is_number() ? json(2.0 * pairs["mean"].get<double>() / n) : json()},
                              {"sem", pairs["sem"].is_number() ? json(2.0 * pairs["sem"].get<double>() / n) : json()}};
    number(z["mean"]);
    number(z["sem"]);
    number(s["window"]["from_strain"]);
    number(s["window"]["to_strain"]);
    number(e["wall_seconds"]);
    out << '\n';
  }
  return out.str();
}

void write_table(const Campaign& c, const fs::path& dir) {
  const json table = gather_table(c, dir);
  io::write_text_atomically((dir / "campaign.json").string(), table.dump(2) + "\n");
  io::write_text_atomically((dir / "campaign.csv").string(), table_csv(c, table));
}

}  // namespace suspend::campaign
