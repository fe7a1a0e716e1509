// `suspend sweep CAMPAIGN.yaml --out DIR [--jobs N] [--threads T] [--retry-failed] [--point-seconds S] [--quiet]`,
// `suspend sweep CAMPAIGN.yaml --list [--out DIR]`, `suspend sweep CAMPAIGN.yaml --out DIR --status [--jobs N]`, `suspend sweep CAMPAIGN.yaml --out DIR --point NAME`,
// `mpirun -n K suspend sweep CAMPAIGN.yaml --out DIR` (rank 0 hands points to ranks 1..K-1).
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "apps/commands.hpp"
#include "campaign/campaign.hpp"
#include "campaign/mpi_sweep.hpp"
#include "campaign/point_record.hpp"
#include "campaign/search.hpp"
#include "campaign/status.hpp"
#include "campaign/sweep.hpp"
#include "campaign/table.hpp"
#include "core/error.hpp"
#include "io/output_folder.hpp"

namespace suspend::app {

void add_sweep_command(CLI::App& app) {
  struct Options {
    std::string campaign_file;
    std::string out;
    campaign::SweepOptions sweep;
    bool list = false;
    bool status = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Run every point of a campaign (DIR/points/NAME, DIR/campaign.json, DIR/campaign.csv); resumable");
  cmd->add_option("campaign", opt->campaign_file, "campaign file (YAML, see docs/campaigns.md)")->required();
  cmd->add_option("--out,-o", opt->out, "campaign directory");
  cmd->add_option("--jobs,-j", opt->sweep.jobs, "points run at once (default: cores / threads)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--threads,-t", opt->sweep.threads, "OpenMP threads of each point (default 1)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--retry-failed", opt->sweep.retry_failed, "run failed points again (from their checkpoints)");
  cmd->add_option("--point-seconds", opt->sweep.point_seconds,
                  "wall-clock budget of one run of a point; over it the point checkpoints and is marked failed")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--point", opt->sweep.only_point, "run this point only (one scheduler job per point)");
  cmd->add_flag("--list", opt->list, "print the points (with their status when --out is given) and exit");
  cmd->add_flag("--status", opt->status,
                "print each point's state (running ones with their strain and rate) and the time left; starts nothing");
  cmd->add_flag("--quiet,-q", opt->sweep.quiet, "no progress lines");
  cmd->callback([opt, cmd] {
    const campaign::Campaign base = campaign::load_campaign(opt->campaign_file);
    campaign::Campaign c = base;
    std::vector<campaign::GroupSearch> plan;
    if (c.search) {  // the points the search has decided on so far, from the records under --out
      plan = campaign::plan_search(c, opt->out.empty() ? fs::path("/nonexistent") : fs::path(opt->out));
      c = campaign::with_search_points(c, plan);
    }
    if (opt->list) {
      for (const campaign::Point& p : c.points) {
        if (opt->out.empty())
          std::printf("%s\n", p.name.c_str());
        else
          std::printf("%-40s %s\n", p.name.c_str(),
                      campaign::read_record(campaign::point_dir(opt->out, p)).status.c_str());
      }
      if (c.search) std::printf("# search of %s:\n%s", c.search->key.c_str(), campaign::describe_search(c, plan).c_str());
      return;
    }
    if (opt->out.empty()) throw InputError("--out: missing; give the campaign directory");
    opt->sweep.out_dir = opt->out;
    io::refuse_foreign_folder(opt->out, io::FolderKind::campaign);
    if (cmd->count("--jobs") == 0) opt->sweep.jobs = std::max(1, omp_get_num_procs() / opt->sweep.threads);
    if (opt->status) {
      campaign::check_points(c, opt->out);  // a campaign the sweep would refuse is refused here too
      campaign::print_status(c, opt->out, opt->sweep.jobs, campaign::points_to_come(c, plan));
      return;
    }
    // Once, before any point: every round of a search runs the same program, even if it is replaced meanwhile.
    if (opt->sweep.executable.empty()) opt->sweep.executable = campaign::own_executable();
    const int code = campaign::launched_by_mpi()                   ? campaign::run_sweep_mpi(base, opt->sweep)
                     : c.search && opt->sweep.only_point.empty() ? campaign::run_search_sweep(base, opt->sweep)
                                                                 : campaign::run_sweep(c, opt->sweep);
    if (code != 0) std::exit(code);
  });
}

}  // namespace suspend::app
