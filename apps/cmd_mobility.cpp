// `suspend mobility`: one FCM mobility solve for a sphere (or the spheres of a file) in a periodic box.
// Prints velocities, angular velocities and stresslets (eta = 1, lengths in the units of the input), and for a
// single sphere the drag ratio 6 pi eta a U.F / |F|^2 that Hasimoto's expansion predicts (docs/fcm.md).
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/commands.hpp"
#include "io/initial_configuration.hpp"
#include "core/error.hpp"
#include "fcm/solver.hpp"

namespace suspend::app {
namespace {

struct MobilityArgs {
  double box = 16.0;
  int grid = 32;
  double radius = 1.0;
  std::string positions_file;
  std::vector<double> force{1.0, 0.0, 0.0};
  std::vector<double> torque{0.0, 0.0, 0.0};
  double shear_rate = 0.0;
  double shear_offset = 0.0;
  bool json = false;
};

Vec3 vec3_of(const std::vector<double>& v, const char* name) {
  if (v.size() != 3) throw InputError(std::string("--") + name + " needs three comma-separated numbers");
  for (double x : v)
    if (!std::isfinite(x)) throw InputError(std::string("--") + name + " needs three finite numbers");
  return {v[0], v[1], v[2]};
}

nlohmann::json json_of(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
nlohmann::json json_of(const Mat3& m) {
  return {json_of(Vec3(m.row(0).transpose())), json_of(Vec3(m.row(1).transpose())), json_of(Vec3(m.row(2).transpose()))};
}

void run_mobility(const MobilityArgs& args) {
  if (!(args.box > 0.0) || !std::isfinite(args.box)) throw InputError("--box must be a positive number");
  if (args.grid < 8 || args.grid > 1024) throw InputError("--grid must be between 8 and 1024 nodes per side");
  // Three grids of doubles and their transforms, and the envelopes' tables: about 100 bytes a node.
  const double bytes = 100.0 * std::pow(static_cast<double>(args.grid), 3);
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  if (memory > 0.0 && bytes > 0.8 * memory)
    throw InputError("--grid " + std::to_string(args.grid) + ": needs about " + std::to_string(bytes / 1e9).substr(0, 5) +
                     " GB, more than this machine's memory allows");
  const double h = args.box / args.grid;
  if (!(args.radius >= 0.5 * h) || !(args.radius <= 0.25 * args.box))
    throw InputError("--radius must be between h/2 = " + std::to_string(0.5 * h) + " (the FCM envelopes must span grid "
                     "nodes; paper 004 uses h = a/2) and a quarter of --box");
  for (double v : {args.shear_rate, args.shear_offset})
    if (!std::isfinite(v)) throw InputError("--shear-rate and --shear-offset must be finite numbers");
  std::vector<Vec3> pos;
  std::vector<double> rad;
  if (args.positions_file.empty()) {
    pos.push_back(Vec3::Constant(0.5 * args.box));
    rad.push_back(args.radius);
  } else {
    const Particles p = io::read_particle_table(args.positions_file);
    pos = p.position;
    rad = p.radius;
  }
  const Vec3 f = vec3_of(args.force, "force"), t = vec3_of(args.torque, "torque");
  const std::vector<Vec3> forces(pos.size(), f), torques(pos.size(), t);
  fcm::Solver solver(Vec3::Constant(args.box), {args.grid, args.grid, args.grid}, fcm::SolverOptions{});
  fcm::MobilityProblem pb{.positions = pos, .radii = rad, .forces = forces, .torques = torques,
                          .flow = AmbientFlow::simple_shear(args.shear_rate), .shear_offset = args.shear_offset};
  const fcm::MobilityResult r = solver.solve(pb);
  const bool single = pos.size() == 1 && f.squaredNorm() > 0.0;
  const double drag = single ? 6.0 * std::numbers::pi * rad[0] * r.velocities[0].dot(f) / f.squaredNorm() : 0.0;
  if (args.json) {
    nlohmann::json j = {{"box", args.box}, {"grid", args.grid}, {"shear_rate", args.shear_rate},
                        {"shear_offset", args.shear_offset}, {"rigidity_iterations", r.iterations}};
    for (std::size_t i = 0; i < pos.size(); ++i)
      j["particles"].push_back({{"position", json_of(pos[i])}, {"radius", rad[i]},
                                {"velocity", json_of(r.velocities[i])},
                                {"angular_velocity", json_of(r.angular_velocities[i])},
                                {"stresslet", json_of(r.stresslets[i])}});
    if (single) j["drag_ratio"] = drag;
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << std::setprecision(8) << "FCM mobility: box " << args.box << "^3, grid " << args.grid << "^3 (h = "
            << args.box / args.grid << "), shear rate " << args.shear_rate << ", offset " << args.shear_offset << ", "
            << pos.size() << " particle(s), rigidity iterations " << r.iterations << "\n";
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const Mat3& s = r.stresslets[i];
    std::cout << "particle " << i << ": U = " << r.velocities[i].transpose()
              << "  Omega = " << r.angular_velocities[i].transpose() << "  S (xx xy xz yy yz) = " << s(0, 0) << " "
              << s(0, 1) << " " << s(0, 2) << " " << s(1, 1) << " " << s(1, 2) << "\n";
  }
  if (single) std::cout << "drag ratio 6 pi eta a U.F/|F|^2 = " << drag << "\n";
}

}  // namespace

void add_mobility_command(CLI::App& app) {
  auto args = std::make_shared<MobilityArgs>();
  CLI::App* cmd = app.add_subcommand("mobility", "FCM mobility of spheres in a periodic (Lees-Edwards) box");
  cmd->add_option("--box", args->box, "cube side L (lengths in a_1)")->capture_default_str();
  cmd->add_option("--grid", args->grid, "grid nodes per direction")->capture_default_str();
  cmd->add_option("--radius", args->radius, "radius of the single sphere")->capture_default_str();
  cmd->add_option("--positions", args->positions_file, "file with one 'x y z radius' line per particle");
  cmd->add_option("--force", args->force, "force FX,FY,FZ on every particle")->delimiter(',')->capture_default_str();
  cmd->add_option("--torque", args->torque, "torque TX,TY,TZ on every particle")->delimiter(',')->capture_default_str();
  cmd->add_option("--shear-rate", args->shear_rate, "imposed shear rate gammadot")->capture_default_str();
  cmd->add_option("--shear-offset", args->shear_offset, "Lees-Edwards offset D")->capture_default_str();
  cmd->add_flag("--json", args->json, "print JSON");
  cmd->callback([args] { run_mobility(*args); });
}

}  // namespace suspend::app
