// `suspend crossval CASE.yaml --out DIR [--set KEY=VALUE]... [--threads N] [--quiet]`: the same case with pairwise
// lubrication-DEM and with FCM + sub-grid lubrication, from the same initial configuration (same seed or file) and
// the same contact law, then a side-by-side table of the steady-state rheology, also written to DIR/crossval.json.
// A finished method is not rerun, an interrupted one continues from its checkpoint; a folder that holds a run of
// another case is refused (exit 2, naming the keys that differ).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"
#include "io/derived_rheology.hpp"
#include "io/hdf5.hpp"
#include "io/output_folder.hpp"
#include "io/runner.hpp"

namespace suspend::app {

namespace {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// A method's run that reached run.strain (summaries of stopped, jammed or failed runs say so in `status`).
bool finished(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  const json s = json::parse(in, nullptr, false);
  return !s.is_discarded() && s.is_object() && s.value("status", "done") == "done";
}

// The table's rows, from one summary.json.
json observables(const json& summary) {
  const json all = io::derived_rheology(summary);
  json o;
  for (const char* key : {"eta_r", "Sigma_c12/Sigma_12", "Sigma_c22/Sigma_12", "N1", "N2", "Pi", "sigma_star"})
    if (all.contains(key)) o[key] = all[key];
  return o;
}
}  // namespace

void add_crossval_command(CLI::App& app) {
  struct Options {
    std::string case_file;
    std::vector<std::string> overrides;
    io::RunOptions run;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "crossval", "Run a case with pairwise lubrication-DEM and with FCM; compare their rheology (DIR/crossval.json)");
  cmd->add_option("case", opt->case_file, "case file (YAML, see docs/cases.md)")->required();
  cmd->add_option("--out,-o", opt->run.out_dir, "output directory (DIR/pairwise, DIR/fcm, DIR/crossval.json)")
      ->required();
  cmd->add_option("--set,-s", opt->overrides, "override a case key by its dotted path")->take_all();
  cmd->add_option("--threads,-t", opt->run.threads, "OpenMP threads (default: run.threads, else all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--quiet,-q", opt->run.quiet, "no progress output");
  cmd->callback([opt] {
    const fs::path dir(opt->run.out_dir);
    io::refuse_foreign_folder(dir, io::FolderKind::crossval);
    json summaries;
    // Both cases are read (and so validated) before anything runs.
    std::vector<std::pair<std::string, io::Case>> cases;
    for (const char* model : {"pairwise", "fcm"}) {
      std::vector<std::string> o = opt->overrides;
      o.push_back(std::string("hydrodynamics.model=") + model);
      cases.emplace_back(model, io::load_case(opt->case_file, o));
    }
    // A method's folder is reused (finished, or continued from its checkpoint) only for exactly the same case.
    for (const auto& [model, c] : cases) {
      const fs::path run_file = dir / model / "run.h5";
      if (!fs::is_regular_file(run_file)) continue;
      std::string before;
      try {
        io::h5::File f = io::h5::File::open(run_file.string(), false);
        before = io::h5::string_attribute(f.id(), ".", "case");
      } catch (const std::exception&) {
        before = "unreadable: true";
      }
      const std::string changes = io::case_changes(before, io::result_identity(c), io::result_identity);
      if (!changes.empty())
        throw InputError("--out: " + (dir / model).string() + " holds a run of another case (" + changes +
                         "); give another --out or remove it");
    }
    for (const auto& [model, c] : cases) {
      const fs::path out = dir / model;
      if (!finished(out)) {
        if (!opt->run.quiet) std::printf("== %s ==\n", model.c_str());
        io::RunOptions r = opt->run;
        r.out_dir = out.string();
        if (fs::is_regular_file(out / "checkpoint.h5")) r.restart = (out / "checkpoint.h5").string();
        const int code = io::run_case(c, r);
        if (code != 0) std::exit(code);
      }
      std::ifstream in(out / "summary.json");
      summaries[model] = json::parse(in);
    }
    json result;
    result["pairwise"] = observables(summaries["pairwise"]);
    result["fcm"] = observables(summaries["fcm"]);
    result["phi"] = summaries["pairwise"]["phi"];
    std::printf("\n%-20s %24s %24s %10s\n", "", "pairwise", "fcm", "rel. diff");
    for (const auto& [key, p] : result["pairwise"].items()) {
      const json& f = result["fcm"][key];
      const double a = p["mean"].get<double>(), b = f["mean"].get<double>();
      const double diff = a != 0.0 ? (b - a) / std::abs(a) : NAN;
      result["relative_difference"][key] = diff;
      std::printf("%-20s %12.5g +- %-9.2g %12.5g +- %-9.2g ", key.c_str(), a, p["sem"].get<double>(), b,
                  f["sem"].get<double>());
      // undefined where the pairwise value is zero (no contact stress in a dilute case): null in the JSON
      if (std::isfinite(diff))
        std::printf("%+9.1f%%\n", 100.0 * diff);
      else
        std::printf("%10s\n", "n/a");
    }
    std::printf("phi = %.4g; written to %s\n", result["phi"].get<double>(), (dir / "crossval.json").c_str());
    io::write_text_atomically((dir / "crossval.json").string(), result.dump(2) + "\n");
  });
}

}  // namespace suspend::app
