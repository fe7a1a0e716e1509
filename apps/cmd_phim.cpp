// `suspend phim CAMPAIGN_DIR_OR_campaign.json [--json] [--min-phi X] [--sigma-star S,...] [--out DIR]`:
// Maron-Pierce fits of phi_m(sigma*) per (model, mu_s, sigma*) group (campaign/phim.hpp), printed as a table
// (or JSON) and written to phim.json and phim.csv beside campaign.json (or in --out).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/commands.hpp"
#include "campaign/phim.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"

namespace suspend::app {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

void add_phim_command(CLI::App& app) {
  struct Options {
    std::string input, out;
    bool json_output = false;
    campaign::PhimOptions fit;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("phim", "Fit phi_m(sigma*) (Maron-Pierce, paper 004 eq. 23) to a campaign table");
  cmd->add_option("campaign", opt->input, "campaign directory or its campaign.json")->required();
  cmd->add_flag("--json", opt->json_output, "print the fits as JSON");
  cmd->add_option("--min-phi", opt->fit.min_phi, "fit only points at phi >= this (paper 004: 0.45 for mu_s <= 0.1)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--sigma-star", opt->fit.sigma_stars,
                  "sigma* values at which rate-controlled points are interpolated (default 0.7,1,2,5,10)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cmd->add_option("--out,-o", opt->out, "where to write phim.json and phim.csv (default: beside campaign.json)");
  cmd->callback([opt] {
    fs::path table_file(opt->input);
    if (fs::is_directory(table_file)) table_file /= "campaign.json";
    if (!fs::is_regular_file(table_file))
      throw InputError("campaign: '" + table_file.string() + "' not found; give a campaign directory or campaign.json");
    std::ifstream in(table_file);
    const json table = json::parse(in, nullptr, false);
    if (table.is_discarded() || !table.contains("points"))
      throw InputError("campaign: " + table_file.string() + " is not a campaign table (suspend sweep writes it)");
    json result;
    try {
      result = campaign::fit_phim(table, opt->fit);
    } catch (const json::exception& e) {  // a hand-edited or foreign table: name it, not the JSON library
      throw InputError("campaign: " + table_file.string() + " has a point with a missing or mistyped field (" +
                       e.what() + ")");
    }
    const fs::path out = opt->out.empty() ? table_file.parent_path() : fs::path(opt->out);
    io::refuse_foreign_folder(out.empty() ? fs::path(".") : out, io::FolderKind::phim);
    fs::create_directories(out.empty() ? fs::path(".") : out);
    io::write_text_atomically((out / "phim.json").string(), result.dump(2) + "\n");
    io::write_text_atomically((out / "phim.csv").string(), campaign::phim_csv(result));
    if (opt->json_output) {
      std::printf("%s\n", result.dump(2).c_str());
      return;
    }
    std::printf("%-9s %5s %9s %18s %16s %6s %8s %26s %7s  %s\n", "model", "mu_s", "sigma*", "phi_m", "alpha", "points",
                "chi2/dof", "bracket (flowed/seeds)", "result", "note");
    for (const json& f : result["fits"]) {
      char sigma[16], phim[40] = "-", alpha[40] = "-", chi[16] = "-";
      if (f["sigma_star"].is_null()) std::snprintf(sigma, sizeof sigma, "inf");
      else std::snprintf(sigma, sizeof sigma, "%.3g", f["sigma_star"].get<double>());
      if (!f["phi_m"].is_null()) {
        std::snprintf(phim, sizeof phim, "%.4f +- %.4f", f["phi_m"].get<double>(), f["phi_m_err"].get<double>());
        std::snprintf(alpha, sizeof alpha, "%.3f +- %.3f", f["alpha"].get<double>(), f["alpha_err"].get<double>());
        std::snprintf(chi, sizeof chi, "%.2f", f["chi2_reduced"].get<double>());
      }
      char bracket[64] = "-";
      if (f["bracket"].is_array()) {
        const json &b = f["bracket"], &n = f["bracket_seeds"], &q = f["bracket_flowing_fraction"];
        std::snprintf(bracket, sizeof bracket, "[%.4g, %.4g] (%.0f/%d, %.0f/%d)", b[0].get<double>(), b[1].get<double>(),
                      q[0].get<double>() * n[0].get<int>(), n[0].get<int>(), q[1].get<double>() * n[1].get<int>(),
                      n[1].get<int>());
      }
      std::printf("%-9s %5.2g %9s %18s %16s %6d %8s %26s %7s  %s\n", f["model"].get<std::string>().c_str(),
                  f["mu_s"].get<double>(), sigma, phim, alpha, f["points"].get<int>(), chi, bracket,
                  f["result"].is_string() ? f["result"].get<std::string>().c_str() : "-",
                  f.contains("note") ? f["note"].get<std::string>().c_str() : "");
    }
    std::printf("written to %s and %s\n", (out / "phim.json").c_str(), (out / "phim.csv").c_str());
  });
}

}  // namespace suspend::app
