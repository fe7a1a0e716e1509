// A dilute suspension (phi 0.05) for the flow-protocol tests: no contacts engage, lubrication pairs are rare, so
// it is Newtonian (Einstein's 1 + 2.5 phi plus the O(phi^2) the model carries) in either hydrodynamic model.
#pragma once
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/integration/cli_support.hpp"

namespace suspend::test {

inline std::string dilute_case(const std::string& model, double box) {
  return "particles: {phi: 0.05}\nbox: {cube: " + std::to_string(box) +
         "}\nhydrodynamics: {model: " + model +
         ", lubrication: {enabled: true, inner_cutoff: 1.0e-3, outer_cutoff: 0.25}, fcm: {grid_spacing: 0.5}}\n"
         "contact: {law: soft_repulsion, k_hat: 1.0e4}\nrun: {seed: 4, output: {checkpoint_every: 100}}\n";
}

// Runs case_file into `out` with --set assignments (one thread) and returns its summary.json.
inline nlohmann::json run_summary_in(const std::string& case_file, const std::string& out,
                                     const std::vector<std::string>& sets) {
  std::vector<std::string> args = {"run", case_file, "--out", out, "--threads", "1", "--quiet"};
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  const Result r = run(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return nlohmann::json::parse(read_text(out + "/summary.json"));
}

}  // namespace suspend::test
