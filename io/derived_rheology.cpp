#include "io/derived_rheology.hpp"

#include <cmath>

namespace suspend::io {

namespace {
struct Value {
  double mean = 0.0, sem = 0.0;
};
// JSON has no NaN: a summary writes an undefined mean or error (too few samples) as null.
double number(const nlohmann::ordered_json& v) { return v.is_number() ? v.get<double>() : std::nan(""); }
Value value(const nlohmann::ordered_json& e) { return {number(e["mean"]), number(e["sem"])}; }
nlohmann::ordered_json entry(Value v) { return {{"mean", v.mean}, {"sem", v.sem}}; }
Value ratio(Value a, Value b) {
  return {a.mean / b.mean, std::hypot(a.sem / b.mean, a.mean * b.sem / (b.mean * b.mean))};
}
}  // namespace

nlohmann::ordered_json derived_rheology(const nlohmann::ordered_json& s) {
  // Per contribution, Sigma_22 and Sigma_11 from N1, N2 and Pi: yy = -Pi - (N1 - N2)/3, xx = yy + N1.
  Value c11, c12, c22;
  double c11_var = 0.0, c12_var = 0.0, c22_var = 0.0;
  for (const char* part : {"contact_normal", "contact_tangential", "repulsion", "adhesion"}) {
    const nlohmann::ordered_json& p = s["contributions"][part];
    const Value eta = value(p["eta_r"]), n1 = value(p["N1"]), n2 = value(p["N2"]), pi = value(p["Pi"]);
    const double yy = -pi.mean - (n1.mean - n2.mean) / 3.0;
    c12.mean += eta.mean;
    c12_var += eta.sem * eta.sem;
    c22.mean += yy;
    c22_var += pi.sem * pi.sem + (n1.sem * n1.sem + n2.sem * n2.sem) / 9.0;
    c11.mean += yy + n1.mean;
    c11_var += pi.sem * pi.sem + (4.0 * n1.sem * n1.sem + n2.sem * n2.sem) / 9.0;
  }
  c11.sem = std::sqrt(c11_var), c12.sem = std::sqrt(c12_var), c22.sem = std::sqrt(c22_var);
  const Value eta = value(s["eta_r"]);
  nlohmann::ordered_json o;
  o["eta_r"] = s["eta_r"];
  o["N1"] = s["N1"];
  o["N2"] = s["N2"];
  o["Pi"] = s["Pi"];
  o["Sigma_c12/Sigma_12"] = entry(ratio(c12, eta));
  o["Sigma_c22/Sigma_12"] = entry(ratio(c22, eta));
  o["Sigma_c11/Sigma_c12"] = entry(ratio(c11, c12));
  o["mu"] = entry(ratio(eta, {-c22.mean, c22.sem}));
  o["J"] = entry(ratio({1.0, 0.0}, {-c22.mean, c22.sem}));
  if (s.contains("sigma_star")) o["sigma_star"] = s["sigma_star"];
  if (s.contains("G_adh")) o["G_adh"] = s["G_adh"];
  return o;
}

}  // namespace suspend::io
