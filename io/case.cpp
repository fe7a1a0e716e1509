#include "io/case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

#include "dem/integrate/pairwise_models.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "io/contact_case.hpp"
#include "io/hydrodynamic_models.hpp"
#include "io/initial_configuration.hpp"
#include "io/schema_reader.hpp"

namespace suspend::io {

namespace {

// Where FCM pair-resistance tables are cached: $XDG_CACHE_HOME/suspend, else ~/.cache/suspend, else none.
std::string default_fcm_cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/suspend";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/suspend";
  return "";
}

void read_particles(SchemaReader r, Case& c) {
  ParticlesCase& p = c.particles;
  p.phi = r.number("phi", Range::open(0.0, 0.74));
  if (auto n = r.optional_integer("count", 2, 100'000'000)) p.count = *n;
  const bool has_species = r.has("species"), has_bidisperse = r.has("bidisperse");
  if (has_species && has_bidisperse)
    r.fail("bidisperse", "give either 'species' or 'bidisperse', not both");
  if (has_species) {
    for (SchemaReader s : r.children("species")) {
      Species sp{s.number("radius", Range::positive()), s.number("volume_share", Range::open_closed(0.0, 1.0))};
      s.finish();
      p.species.push_back(sp);
    }
    if (p.species.empty()) r.fail("species", "the list is empty; give at least one {radius, volume_share}");
  } else if (has_bidisperse) {
    SchemaReader b = r.child("bidisperse");
    const double ratio = b.number("size_ratio", Range::closed(1.0, 100.0));
    const double large = b.number("large_volume_share", 0.5, Range::open(0.0, 1.0));
    b.finish();
    p.species = {{1.0, 1.0 - large}, {ratio, large}};
  } else {
    p.species = {{1.0, 1.0}};
  }
  double share = 0.0, a_min = INFINITY;
  for (const Species& s : p.species) share += s.volume_share, a_min = std::min(a_min, s.radius);
  if (std::abs(share - 1.0) > 1e-9)
    r.fail(has_species ? "species" : "bidisperse",
           "volume shares sum to " + exact(share) + "; they must sum to 1");
  if (std::abs(a_min - 1.0) > 1e-12)
    r.fail(has_species ? "species" : "bidisperse",
           "the smallest radius is the length unit a_1 and must be 1 (got " + exact(a_min) + ")");

  SchemaReader init = r.child("initial");
  p.initial = init.choice("from", "random", {"random", "file"});
  if (p.initial == "file") {
    p.initial_file = init.text("file", "");
    if (p.initial_file.empty()) init.fail("file", "missing; initial.from = file needs a file path");
    std::filesystem::path f(p.initial_file);
    if (f.is_relative() && !c.source.empty())
      f = std::filesystem::path(c.source).parent_path() / f;
    if (!std::filesystem::is_regular_file(f))
      init.fail("file", "'" + p.initial_file + "' does not exist or is not a file");
    p.initial_file = f.lexically_normal().string();
    p.compress = init.boolean("compress", false);
  }
  p.min_gap = init.number("min_gap", p.min_gap, Range::closed(0.0, 0.5));
  init.finish();
  r.finish();
}

}  // namespace

// The largest strain a step can take is known before the run: refuse a case that would need more steps than any
// machine can take (a time step of 1e-300, an explicit contact stiffness of 1e308, a shear rate of 1e-12 with a
// fixed step...). Imposed stress: the rate is at most Sigma / eta_0 (eta_r >= 1).
namespace {
void refuse_runs_without_progress(const Case& c) {
  constexpr double max_steps = max_run_steps;
  const SimulationParams& s = c.simulation;
  const TimeStepParams& ts = s.time_step;
  const Flow& fl = s.flow;
  const bool stress = fl.control == FlowControl::stress;
  // The largest rate the protocol imposes (an oscillation's amplitude).
  const double rate = fl.protocol->largest_target(fl);
  const std::string rate_key = stress ? "flow.shear_stress (or sigma_star)" : "flow.shear_rate";
  double step = 0.0;  // largest strain per step
  std::string why;
  if (ts.mode == TimeStepParams::Mode::fixed) {
    step = rate * ts.fixed;
    why = "run.time_step.fixed = " + exact(ts.fixed) + " at " + rate_key + " = " + exact(rate);
  } else if (s.integrator == Integrator::overdamped && !ts.implicit_contacts) {
    double a_min = 1.0;
    for (const Species& sp : c.particles.species) a_min = std::min(a_min, sp.radius);
    const double bound = explicit_contact_time_step(ts, s.contact, a_min);
    step = std::min(ts.max, rate * bound);
    const std::string keys = std::visit(
        [](const auto& l) { return std::string(std::decay_t<decltype(l.contact.normal)>::stiffness_keys); }, s.contact);
    why = "explicit contacts of stiffness " + exact(stiffness_scale(s.contact)) + " (set by " + keys +
          ") limit a step to " +
          exact(bound) + " time units (run.time_step.stability x 6 pi a_min / stiffness) at " + rate_key + " = " +
          exact(rate);
  } else {
    return;
  }
  if (c.run.strain <= step * max_steps) return;
  std::ostringstream m;
  m << "run.strain = " << exact(c.run.strain) << " cannot be reached: with " << why
    << ", a step advances the strain by at most " << step << ", so the run needs more than " << c.run.strain / step << " steps (allowed: at most "
    << max_steps << "); raise the time step"
    << (ts.mode == TimeStepParams::Mode::fixed ? "" : ", use run.time_step.contacts = implicit or softer contacts");
  throw InputError(m.str());
}
}  // namespace

Case parse_case(const YAML::Node& root, const std::string& source) {
  check_yaml_structure(root);
  Case c;
  c.source = source;
  SchemaReader top(root, "");
  c.title = top.text("title", "");
  // The resolved case is an HDF5 attribute of run.h5 (64 kB at most, with every other key).
  if (c.title.size() > 1000)
    throw InputError("title: " + std::to_string(c.title.size()) + " characters; at most 1000 are allowed");
  read_particles(top.child("particles"), c);

  {
    SchemaReader b = top.child("box");
    const bool has_cube = b.has("cube"), has_length = b.has("length");
    if (has_cube && has_length) b.fail("cube", "give either 'cube' or 'length', not both");
    if (has_cube) {
      const double l = b.number("cube", Range::positive());
      c.box = Vec3(l, l, l);
    } else if (has_length) {
      SchemaReader l = b.child("length");
      c.box = Vec3(l.number("x", Range::positive()), l.number("y", Range::positive()), l.number("z", Range::positive()));
      l.finish();
    }
    b.finish();
  }
  if (c.particles.compress && (c.box || c.particles.count))
    throw InputError("particles.initial.compress: the file's particles are rescaled to particles.phi, so their count "
                     "and box follow from the file; leave particles.count and box out");
  if (c.box && c.particles.count)
    throw InputError("particles.count and box are both given; give one of them (the other follows from phi)");
  if (!c.box && !c.particles.count && c.particles.initial != "file")
    throw InputError("particles.count: missing; give particles.count or box (the other follows from phi)");

  std::optional<double> sigma_star;  // flow.sigma_star, resolved into shear_stress once the contact law is known
  {
    SchemaReader f = top.child("flow");
    SimulationParams& s = c.simulation;
    const std::string type = f.choice("type", "simple_shear", protocol_types());
    ProtocolKeys keys{f, s.flow, sigma_star};
    c.protocol = read_protocol(type, keys);
    s.flow.protocol = c.protocol;
    s.flow.validate();
    f.finish();
  }
  {
    SchemaReader h = top.child("hydrodynamics");
    c.hydrodynamics = h.choice("model", "pairwise", hydrodynamic_model_names());
    {  // read for either model, so one case file serves `suspend crossval`; used by model fcm only
      SchemaReader m = h.child("fcm");
      FcmParams& f = c.fcm;
      f.grid_spacing = m.number("grid_spacing", 0.5, Range::positive());
      f.truncation_widths = m.number("truncation_widths", f.truncation_widths, Range::closed(2.0, 8.0));
      f.krylov_tolerance = m.number("tolerance", f.krylov_tolerance, Range::open(0.0, 1.0));
      f.max_iterations = static_cast<int>(m.integer("max_iterations", f.max_iterations, 1, 100'000));
      f.far_field_every = static_cast<int>(m.integer("far_field_every", f.far_field_every, 1, 1000));
      f.lagged_predictor =
          m.choice("predictor", f.lagged_predictor ? "lagged_far_field" : "extrapolated",
                   {"extrapolated", "lagged_far_field"}) == "lagged_far_field";
      f.preconditioner_iterations =
          static_cast<int>(m.integer("preconditioner_iterations", f.preconditioner_iterations, 1, 1000));
      f.lagged_cutoff = m.number("lagged_cutoff", f.lagged_cutoff, Range::closed(2.0, 10.0));
      f.lagged_tolerance = m.number("lagged_tolerance", f.lagged_tolerance, Range::open(0.0, 1.0));
      f.subgrid = m.boolean("subgrid", f.subgrid);
      f.subgrid_cutoff = m.number("subgrid_cutoff", f.subgrid_cutoff, Range::open(2.0, 10.0));
      f.cache_dir = m.text("cache_dir", default_fcm_cache_dir());
      m.finish();
    }
    ResistanceSolverParams& rs = c.simulation.resistance;
    SchemaReader l = h.child("lubrication");
    c.simulation.lubrication = l.boolean("enabled", true);
    rs.lubrication.inner_cutoff = l.number("inner_cutoff", rs.lubrication.inner_cutoff, Range::non_negative());
    rs.lubrication.outer_cutoff = l.number("outer_cutoff", rs.lubrication.outer_cutoff, Range::positive());
    rs.lubrication.regularization = l.number("regularization", rs.lubrication.regularization, Range::non_negative());
    rs.lubrication.exact_relative =
        l.choice("functions", "singular", {"singular", "exact_relative"}) == "exact_relative";
    rs.lubrication_stress = l.choice("stress", "force_dipole", {"force_dipole", "stresslet"}) == "stresslet"
                                ? LubricationStress::stresslet
                                : LubricationStress::force_dipole;
    l.finish();
    SchemaReader v = h.child("solver");
    rs.solver = v.choice("method", "cg", {"cg", "cholesky"}) == "cholesky" ? LinearSolver::cholesky
                                                                           : LinearSolver::conjugate_gradient;
    rs.preconditioner = v.choice("preconditioner", "gauss_seidel", {"gauss_seidel", "jacobi"}) == "jacobi"
                            ? Preconditioner::block_jacobi
                            : Preconditioner::symmetric_gauss_seidel;
    rs.tolerance = v.number("tolerance", rs.tolerance, Range::open(0.0, 1.0));
    rs.max_iterations = static_cast<int>(v.integer("max_iterations", rs.max_iterations, 1, 1'000'000));
    const std::string storage = v.choice("storage", "auto", {"auto", "dense", "pair_form"});
    if (storage != "auto")
      rs.storage = storage == "pair_form" ? CouplingStorage::pair_form : CouplingStorage::dense;
    v.finish();
    h.finish();
  }
  c.simulation.contact = read_contact(top.child("contact"), static_cast<int>(c.particles.species.size()));
  if (sigma_star) {
    // paper 004 eq. 20: sigma* = 6 pi Sigma_12 a_1^2 / F_adh
    const double f_adh = adhesion_force(c.simulation.contact);
    if (!(f_adh > 0.0))
      throw InputError("flow.sigma_star: needs an adhesive contact law (contact.law = hertz_adhesive with g_adh > 0), "
                       "since sigma* = 6 pi Sigma_12 a_1^2 / F_adh; give flow.shear_stress instead");
    c.simulation.flow.shear_stress = *sigma_star * f_adh / (6.0 * std::numbers::pi);
  }
  {
    SchemaReader r = top.child("run");
    c.run.strain = r.number("strain", c.run.strain, Range::positive());
    c.run.average_from = r.number("average_from", std::min(c.run.average_from, 0.2 * c.run.strain),
                                  Range::non_negative());
    if (c.run.average_from >= c.run.strain)
      r.fail("average_from", exact(c.run.average_from) + " must be below run.strain = " + exact(c.run.strain));
    c.run.seed = r.integer("seed", 1, 0, 2'000'000'000);
    c.run.threads = r.integer("threads", 0, 0, 4096);
    {
      SchemaReader j = r.child("jammed");
      c.run.jammed_viscosity = j.number("viscosity", c.run.jammed_viscosity, Range::positive());
      c.run.jammed_strain = j.number("strain", c.run.jammed_strain, Range::positive());
      j.finish();
    }
    c.simulation.max_overlap = r.number("max_overlap", c.simulation.max_overlap, Range::open_closed(0.0, 1.0));
    c.simulation.skin = r.number("skin", c.simulation.skin, Range::positive());
    c.simulation.integrator = r.choice("integrator", "overdamped", {"overdamped", "inertial"}) == "inertial"
                                  ? Integrator::inertial
                                  : Integrator::overdamped;
    if (c.simulation.integrator == Integrator::inertial) {
      c.simulation.stokes_number = r.number("stokes_number", c.simulation.stokes_number, Range::positive());
      if (c.simulation.flow.control == FlowControl::stress)
        r.fail("integrator", "inertial is not available with flow.control = stress (use overdamped)");
    } else if (r.has("stokes_number")) {
      r.fail("stokes_number", "applies to run.integrator = inertial only");
    }

    SchemaReader t = r.child("time_step");
    TimeStepParams& ts = c.simulation.time_step;
    ts.mode = t.choice("mode", "adaptive", {"adaptive", "fixed"}) == "fixed" ? TimeStepParams::Mode::fixed
                                                                             : TimeStepParams::Mode::adaptive;
    ts.fixed = t.number("fixed", ts.fixed, Range::positive());
    ts.max_displacement = t.number("max_displacement", ts.max_displacement, Range::positive());
    ts.max = t.number("max", ts.max, Range::positive());
    ts.stability = t.number("stability", ts.stability, Range::open_closed(0.0, 1.0));
    // Implicit contacts wherever the model has its overdamped solve (docs/overdamped.md 4b): the pairwise resistance
    // solve (lubrication enabled) or FCM's sub-grid pair terms.
    const bool can_be_implicit = c.simulation.integrator == Integrator::overdamped &&
                                 hydrodynamic_model(c.hydrodynamics).takes_implicit_contacts(c);
    ts.implicit_contacts =
        t.choice("contacts", can_be_implicit ? "implicit" : "explicit", {"explicit", "implicit"}) == "implicit";
    ts.bound = t.choice("bound", "pairs", {"pairs", "particles"}) == "particles" ? TimeStepParams::Bound::particles
                                                                               : TimeStepParams::Bound::pairs;
    ts.gap_change = t.number("gap_change", ts.gap_change, Range::open_closed(0.0, 1.0));
    ts.fastest_of = static_cast<int>(t.integer("fastest_of", ts.fastest_of, 0, 1'000'000'000));
    ts.growth = t.number("growth", ts.growth, Range::open_closed(1.0, 10.0));
    ts.displacement_per_compliance =
        t.number("displacement_per_compliance", ts.displacement_per_compliance, Range::positive());
    // An oscillation stops the flow twice a cycle: floor the compliance bound there (time_step_control.hpp).
    ts.min_displacement = t.number("min_displacement", c.simulation.flow.periodic() ? 0.01 * ts.max_displacement : 0.0,
                                   Range::non_negative());
    t.finish();

    SchemaReader o = r.child("output");
    OutputCase& out = c.run.output;
    out.series_every = o.number("series_every", out.series_every, Range::positive());
    if (c.simulation.flow.periodic())
      out.series_per_cycle = static_cast<int>(o.integer("series_per_cycle", out.series_per_cycle, 8, 1'000'000));
    else if (o.has("series_per_cycle"))
      o.fail("series_per_cycle", "applies to flow.type = oscillatory only (the others write every series_every)");
    out.snapshot_every = o.number("snapshot_every", out.snapshot_every, Range::positive());
    out.snapshot_every_steps = o.integer("snapshot_every_steps", out.snapshot_every_steps, 0, 1'000'000'000);
    out.checkpoint_every = o.number("checkpoint_every", out.checkpoint_every, Range::positive());
    out.checkpoint_seconds = o.number("checkpoint_seconds", out.checkpoint_seconds, Range::positive());
    o.finish();
    r.finish();
  }
  top.finish();
  // The rules of the hydrodynamic model, where the model states them.
  hydrodynamic_model(c.hydrodynamics).check(c);
  refuse_runs_without_progress(c);
  return c;
}

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {

  YAML::Node root = load_yaml_document(path, "case");
  for (const std::string& o : overrides) apply_override(root, o);
  Case c = parse_case(root, path);
  c.overrides = overrides;
  return c;
}

YAML::Node to_yaml(const Case& c) {
  YAML::Node n;
  if (!c.title.empty()) n["title"] = c.title;
  YAML::Node p = n["particles"];
  p["phi"] = number_node(c.particles.phi);
  if (c.particles.count) p["count"] = *c.particles.count;
  for (const Species& s : c.particles.species) {
    YAML::Node sp;
    sp["radius"] = number_node(s.radius);
    sp["volume_share"] = number_node(s.volume_share);
    p["species"].push_back(sp);
  }
  p["initial"]["from"] = c.particles.initial;
  if (c.particles.initial == "file") {
    p["initial"]["file"] = c.particles.initial_file;
    if (c.particles.compress) p["initial"]["compress"] = true;
  }
  p["initial"]["min_gap"] = number_node(c.particles.min_gap);
  if (c.box) {
    n["box"]["length"]["x"] = number_node(c.box->x());
    n["box"]["length"]["y"] = number_node(c.box->y());
    n["box"]["length"]["z"] = number_node(c.box->z());
  }
  const Flow& fl = c.simulation.flow;
  n["flow"]["type"] = c.protocol->name();
  n["flow"]["control"] = fl.control == FlowControl::stress ? "stress" : "rate";
  YAML::Node flow_keys = n["flow"];
  c.protocol->write(fl, flow_keys);
  n["hydrodynamics"]["model"] = c.hydrodynamics;
  {
    YAML::Node h = n["hydrodynamics"];
    hydrodynamic_model(c.hydrodynamics).write(c, h);
  }
  {
    const ResistanceSolverParams& rs = c.simulation.resistance;
    YAML::Node l = n["hydrodynamics"]["lubrication"];
    l["enabled"] = c.simulation.lubrication;
    l["inner_cutoff"] = number_node(rs.lubrication.inner_cutoff);
    l["outer_cutoff"] = number_node(rs.lubrication.outer_cutoff);
    l["regularization"] = number_node(rs.lubrication.regularization);
    l["functions"] = rs.lubrication.exact_relative ? "exact_relative" : "singular";
    l["stress"] = rs.lubrication_stress == LubricationStress::stresslet ? "stresslet" : "force_dipole";
    YAML::Node v = n["hydrodynamics"]["solver"];
    v["method"] = rs.solver == LinearSolver::cholesky ? "cholesky" : "cg";
    v["preconditioner"] = rs.preconditioner == Preconditioner::block_jacobi ? "jacobi" : "gauss_seidel";
    v["tolerance"] = number_node(rs.tolerance);
    v["max_iterations"] = rs.max_iterations;
    v["storage"] = !rs.storage ? "auto" : *rs.storage == CouplingStorage::pair_form ? "pair_form" : "dense";
  }
  n["contact"] = contact_to_yaml(c.simulation.contact);
  YAML::Node r = n["run"];
  r["strain"] = number_node(c.run.strain);
  r["average_from"] = number_node(c.run.average_from);
  r["seed"] = c.run.seed;
  r["threads"] = c.run.threads;
  if (c.simulation.flow.control == FlowControl::stress) {
    r["jammed"]["viscosity"] = number_node(c.run.jammed_viscosity);
    r["jammed"]["strain"] = number_node(c.run.jammed_strain);
  }
  r["max_overlap"] = number_node(c.simulation.max_overlap);
  r["skin"] = number_node(c.simulation.skin);
  r["integrator"] = c.simulation.integrator == Integrator::inertial ? "inertial" : "overdamped";
  if (c.simulation.integrator == Integrator::inertial) r["stokes_number"] = number_node(c.simulation.stokes_number);
  const TimeStepParams& ts = c.simulation.time_step;
  r["time_step"]["mode"] = ts.mode == TimeStepParams::Mode::fixed ? "fixed" : "adaptive";
  r["time_step"]["fixed"] = number_node(ts.fixed);
  r["time_step"]["max_displacement"] = number_node(ts.max_displacement);
  r["time_step"]["max"] = number_node(ts.max);
  r["time_step"]["stability"] = number_node(ts.stability);
  r["time_step"]["contacts"] = ts.implicit_contacts ? "implicit" : "explicit";
  r["time_step"]["growth"] = number_node(ts.growth);
  r["time_step"]["displacement_per_compliance"] = number_node(ts.displacement_per_compliance);
  r["time_step"]["bound"] = ts.bound == TimeStepParams::Bound::pairs ? "pairs" : "particles";
  r["time_step"]["gap_change"] = number_node(ts.gap_change);
  r["time_step"]["fastest_of"] = ts.fastest_of;
  if (ts.min_displacement > 0.0) r["time_step"]["min_displacement"] = number_node(ts.min_displacement);
  r["output"]["series_every"] = number_node(c.run.output.series_every);
  if (c.simulation.flow.periodic()) r["output"]["series_per_cycle"] = c.run.output.series_per_cycle;
  r["output"]["snapshot_every"] = number_node(c.run.output.snapshot_every);
  if (c.run.output.snapshot_every_steps > 0) r["output"]["snapshot_every_steps"] = c.run.output.snapshot_every_steps;
  r["output"]["checkpoint_every"] = number_node(c.run.output.checkpoint_every);
  r["output"]["checkpoint_seconds"] = number_node(c.run.output.checkpoint_seconds);
  return n;
}

namespace {
// The iteration caps of the linear solvers: when a run gives up, not what it computes (a solve that converges
// gives the same result under any cap; one that does not stops the run with a numerical failure).
void remove_solver_caps(YAML::Node& n) {
  if (n["hydrodynamics"]["fcm"]) n["hydrodynamics"]["fcm"].remove("max_iterations");
  if (n["hydrodynamics"]["solver"]) n["hydrodynamics"]["solver"].remove("max_iterations");
}
}  // namespace

std::string result_identity(const Case& c) {
  YAML::Node n = to_yaml(c);
  n["run"].remove("threads");  // how many, not what
  if (n["hydrodynamics"]["fcm"]) n["hydrodynamics"]["fcm"].remove("cache_dir");  // where, not what
  remove_solver_caps(n);
  YAML::Emitter e;
  e << n;
  return e.c_str();
}

std::string physics_fingerprint(const Case& c) {
  YAML::Node n = to_yaml(c);
  n["run"].remove("strain");
  n["run"].remove("average_from");
  n["run"].remove("threads");
  n["run"].remove("output");
  n["run"].remove("jammed");  // when to give up, not what is simulated
  n.remove("title");
  if (n["hydrodynamics"]["fcm"]) n["hydrodynamics"]["fcm"].remove("cache_dir");  // where, not what
  remove_solver_caps(n);
  YAML::Emitter e;
  e << n;
  return e.c_str();
}

namespace {
// Every scalar of a YAML tree by dotted key.
void flatten(const YAML::Node& n, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (n.IsMap()) {
    for (const auto& kv : n)
      flatten(kv.second, prefix.empty() ? kv.first.Scalar() : prefix + "." + kv.first.Scalar(), out);
  } else if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) flatten(n[i], prefix + "[" + std::to_string(i) + "]", out);
  } else {
    out[prefix] = n.IsScalar() ? n.Scalar() : "~";
  }
}

// Equal text, or numbers equal to 1e-12 relative (the last digit of a recomputed value is no change).
bool same_value(const std::string& a, const std::string& b) {
  if (a == b) return true;
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a), y = std::strtod(b.c_str(), &end_b);
  return !a.empty() && !b.empty() && *end_a == '\0' && *end_b == '\0' && std::isfinite(x) && std::isfinite(y) &&
         std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
}
}  // namespace

std::string yaml_differences(const std::string& old_yaml, const std::string& new_yaml) {
  std::map<std::string, std::string> a, b;
  flatten(YAML::Load(old_yaml), "", a);
  flatten(YAML::Load(new_yaml), "", b);
  std::string out;
  int shown = 0;
  auto show = [&](const std::string& k, const std::string& from, const std::string& to) {
    if (shown++ < 4) out += (out.empty() ? "" : ", ") + k + " " + from + " -> " + to;
  };
  for (const auto& [k, v] : a) {
    auto it = b.find(k);
    if (it == b.end()) show(k, v, "(absent)");
    else if (!same_value(it->second, v)) show(k, v, it->second);
  }
  for (const auto& [k, v] : b)
    if (!a.count(k)) show(k, "(absent)", v);
  if (shown > 4) out += " and " + std::to_string(shown - 4) + " more";
  return out.empty() ? "nothing" : out;
}

namespace {
// A case recorded by an older version omits keys that did not exist then; what it meant is their value then, not
// today's default. FCM cases: far_field_every (every step, 1) and predictor (extrapolated) became the fast setting's
// defaults on 2026-12-05, and until then predictor was recorded only when it was lagged_far_field.
YAML::Node with_former_defaults(YAML::Node recorded) {
  const YAML::Node& view = recorded;  // reads do not add keys
  // Recorded before issue 35: every particle's non-affine displacement bounded by the contact displacement.
  const YAML::Node run = view.IsMap() ? view["run"] : YAML::Node();
  if (run.IsMap() && run["time_step"].IsMap() && !run["time_step"]["bound"])
    recorded["run"]["time_step"]["bound"] = "particles";
  // Recorded before 2026-12-07: the displacement bound on the fastest particle of all.
  if (run.IsMap() && run["time_step"].IsMap() && !run["time_step"]["fastest_of"])
    recorded["run"]["time_step"]["fastest_of"] = 0;
  const YAML::Node hydro = view.IsMap() ? view["hydrodynamics"] : YAML::Node();
  if (!hydro.IsMap() || !hydro["model"].IsScalar() || hydro["model"].Scalar() != "fcm" || !hydro["fcm"].IsMap())
    return recorded;
  YAML::Node fcm = recorded["hydrodynamics"]["fcm"];
  if (!hydro["fcm"]["far_field_every"]) fcm["far_field_every"] = 1;
  if (!hydro["fcm"]["predictor"]) fcm["predictor"] = "extrapolated";
  return recorded;
}
}  // namespace

namespace {
// run.time_step.fastest_of acts through the rank k = N / fastest_of (at least 1; 1 for 0) of the particle and pair
// the motion bounds apply to (bound_rank): two values of the same rank for the case's N give the same steps bit for
// bit, e.g. 0 (the rule recorded before 2026-12-07) and the default 500 below 1000 particles. The recorded value
// takes the present one's then. N is that of a random packing of the case (composition_of); a case whose count
// cannot be formed so keeps its recorded value.
void same_rank_fastest_of(Case& recorded, const std::string& now) {
  try {
    const Case present = parse_case(YAML::Load(now), "the present case");
    int& old_value = recorded.simulation.time_step.fastest_of;
    const int new_value = present.simulation.time_step.fastest_of;
    if (old_value == new_value) return;
    const std::size_t n = composition_of(present).radius.size();
    if (bound_rank(n, old_value) == bound_rank(n, new_value)) old_value = new_value;
  } catch (const std::exception&) {
  }
}
}  // namespace

std::string case_changes(const std::string& recorded, const std::string& now, std::string (*resolve)(const Case&)) {
  if (recorded == now) return "";
  std::string again;
  try {
    Case old = parse_case(with_former_defaults(YAML::Load(recorded)), "the recorded case");
    same_rank_fastest_of(old, now);
    again = resolve(old);
  } catch (const std::exception&) {
    try {
      return yaml_differences(recorded, now);
    } catch (const std::exception&) {
      return "the recorded case is unreadable";
    }
  }
  const std::string d = yaml_differences(again, now);
  return d == "nothing" ? "" : d;
}

std::string to_yaml_text(const Case& c) {
  YAML::Emitter e;
  e << to_yaml(c);
  return e.c_str();
}

}  // namespace suspend::io
