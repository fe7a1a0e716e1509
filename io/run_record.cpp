#include "io/run_record.hpp"

#include <filesystem>
#include <iostream>

#include "core/version.hpp"
#include "io/hydrodynamic_models.hpp"
#include "io/atomic_file.hpp"
#include "io/summary.hpp"
#include "io/xdmf.hpp"
#include "io/yaml_json.hpp"

namespace suspend::io {

double progress_strain(const Flow& flow, const SimulationState& st) {
  return flow.counts_signed_strain() ? st.strain : st.accumulated_strain;
}

Snapshot snapshot_of(const Simulation& sim) {
  Snapshot s;
  const SimulationState& st = sim.state();
  s.step = st.step;
  s.time = st.time;
  s.strain = st.strain;
  s.accumulated_strain = st.accumulated_strain;
  s.box = sim.box();
  s.particles = &st.particles;
  const std::vector<Vec3>& f = sim.pair_forces();
  const auto& pairs = sim.active_pairs();
  const ContactRecords records = sim.contact_records();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ContactRecord r = records[k];
    if (!r.contact) continue;  // lubrication-range pairs without contact force are not contacts
    const PairGeometry& g = pairs[k].geometry();
    s.contact_pairs.push_back(pairs[k].i);
    s.contact_pairs.push_back(pairs[k].j);
    for (int a = 0; a < 3; ++a) s.contact_force.push_back(f[k][a]);
    s.contact_gap.push_back(g.gap());
    s.contact_normal_force.push_back(r.normal.dot(g.n));
    for (int a = 0; a < 3; ++a) s.contact_tangential_force.push_back(r.tangential[a]);
    s.contact_sliding.push_back(r.sliding ? 1 : 0);
  }
  return s;
}

RunRecord::RunRecord(const Case& c, const Simulation& sim, RunFile file, const std::string& dir, OutputClock& clock,
                     const Rng& rng, std::string fingerprint, int threads,
                     std::chrono::steady_clock::time_point started, double checkpoint_strain)
    : case_(c),
      sim_(sim),
      file_(std::move(file)),
      run_path_((std::filesystem::path(dir) / "run.h5").string()),
      checkpoint_path_((std::filesystem::path(dir) / "checkpoint.h5").string()),
      summary_path_((std::filesystem::path(dir) / "summary.json").string()),
      xdmf_path_((std::filesystem::path(dir) / "run.xdmf").string()),
      clock_(clock),
      rng_(rng),
      fingerprint_(std::move(fingerprint)),
      threads_(threads),
      started_(started),
      checkpoint_strain_(checkpoint_strain) {}

void RunRecord::save() {
  file_.flush();
  clock_.series_rows = static_cast<std::int64_t>(file_.series_rows());
  clock_.snapshots = static_cast<std::int64_t>(file_.snapshot_count());
  write_checkpoint(checkpoint_path_, {sim_.state_with_contacts(), clock_, fingerprint_, serialize(rng_), threads_});
  checkpoint_strain_ = strain();
}

void RunRecord::remember_step_start() {
  // A copy per step: small beside the step itself.
  std::swap(previous_step_, this_step_);
  this_step_.state = sim_.state_with_contacts();
  this_step_.clock = clock_;
  this_step_.clock.series_rows = static_cast<std::int64_t>(file_.series_rows());
  this_step_.clock.snapshots = static_cast<std::int64_t>(file_.snapshot_count());
  this_step_.valid = true;
}

// The checkpoint of a step's start (the output clock as it was then: continued, the step is taken again).
void RunRecord::save_step_start(const StepStart& s) {
  file_.flush();
  write_checkpoint(checkpoint_path_, {s.state, s.clock, fingerprint_, serialize(rng_), threads_});
}

const SimulationState& RunRecord::save_state_before_failure(bool found_evaluating) {
  // evaluate() found the state it was given bad: the step that made it is the failing one.
  const StepStart& good = found_evaluating && previous_step_.valid ? previous_step_ : this_step_;
  save_step_start(good);
  return good.state;
}

void RunRecord::save_final(bool last_step_clipped) {
  if (last_step_clipped)
    save_step_start(previous_step_);
  else
    save();
}

void RunRecord::finish_outputs() {
  file_.flush();
  write_text_atomically(xdmf_path_, xdmf_text("run.h5", file_.snapshots()));
}

nlohmann::json RunRecord::write_summary(double average_from, const nlohmann::json& extra) {
  const Flow& flow = case_.simulation.flow;
  nlohmann::json summary =
      summarize(file_.id(), {sim_.state().particles.volume() / sim_.box().volume(), sim_.state().particles.size(),
                             average_from, flow.control == FlowControl::stress,
                             adhesion_force(case_.simulation.contact), flow, case_.protocol.get()});
  summary.update(extra);
  // What produced it: the resolved case, the program and this invocation's wall time and threads.
  summary["case"] = yaml_to_json(to_yaml(case_));
  summary["version"] = std::string(suspend::version);
  summary["git_commit"] = std::string(suspend::git_commit);
  summary["threads"] = threads_;
  summary["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  hydrodynamic_model(case_.hydrodynamics).summarise(sim_, summary);
  write_text_atomically(summary_path_, summary.dump(2) + "\n");
  return summary;
}

double RunRecord::write_partial_summary(const char* status, nlohmann::json extra) {
  const double from = std::min(case_.run.average_from, 0.5 * strain());
  extra["status"] = status;
  try {
    write_summary(from, extra);
  } catch (const std::exception& e) {
    std::cerr << "warning: no summary.json: " << e.what() << "\n";
  }
  return from;
}

}  // namespace suspend::io
