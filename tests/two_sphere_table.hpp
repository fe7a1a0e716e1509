// The exact two-sphere resistance tables of tests/data (Townsend / Jeffrey & Onishi; Kim & Karrila normalisation)
// read for the tests: two_sphere_resistance_table.txt (lambda = 0.01 ... 100) and
// two_sphere_resistance_table_lambda1.4.txt (lambda = 1.4 and 1/1.4). Each row: s', lambda, gamma (0: "11", 1: "12"),
// XA YA YB XC YC XG YG YH XM YM ZM.
#pragma once
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace suspend::test {

// s' -> {"11" functions, "12" functions}, each XA YA YB XC YC XG YG YH XM YM ZM, for the rows of `lambda` (to 1e-6).
using TwoSphereRow = std::array<std::array<double, 11>, 2>;
using TwoSphereTable = std::map<double, TwoSphereRow>;

inline TwoSphereTable read_two_sphere_table(const std::string& file, double lambda) {
  std::ifstream in(std::string(SUSPEND_SOURCE_DIR "/tests/data/") + file);
  TwoSphereTable t;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    double sp, lam, gam;
    std::array<double, 11> v{};
    if (!(s >> sp >> lam >> gam)) continue;
    bool ok = true;
    for (double& x : v) ok = ok && static_cast<bool>(s >> x);
    if (ok && std::abs(lam / lambda - 1.0) < 1e-6) t[sp][gam < 0.5 ? 0 : 1] = v;
  }
  return t;
}

inline TwoSphereTable lambda_1_4_table(double lambda) {
  return read_two_sphere_table("two_sphere_resistance_table_lambda1.4.txt", lambda);
}

}  // namespace suspend::test
