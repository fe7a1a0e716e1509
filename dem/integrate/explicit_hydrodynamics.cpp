// Matrix-free explicit hydrodynamic forces, stress and rate bound; equations and conventions in the header.
#include "dem/integrate/explicit_hydrodynamics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/capacity.hpp"
#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"

namespace suspend {

namespace {
constexpr std::ptrdiff_t chunk_particles = 256;  // reduction chunk: fixed, so sums do not depend on the threads
}

ExplicitHydrodynamics::ExplicitHydrodynamics(std::vector<double> species_radius,
                                             const hydro::LubricationParams& lubrication, LubricationStress stress)
    : law_(std::move(species_radius), lubrication, "explicit hydrodynamics"), stress_form_(stress) {}

std::size_t ExplicitHydrodynamics::memory_bytes() const {
  return start_.capacity() * sizeof(std::uint32_t) + incident_.capacity() * sizeof(std::uint32_t) +
         chunks_.capacity() * sizeof(ChunkSums);
}

void ExplicitHydrodynamics::build_incidence(std::size_t n, const std::vector<int>& species,
                                            const std::vector<ActivePair>& pairs) {
  // Counting sort of the pair ends by particle; filled in pair order, so each particle's list is in pair order.
  start_.assign(n + 1, 0);
  std::size_t ends = 0;
  for (const ActivePair& pr : pairs)
    if (law_.active(pr, species)) {
      ++start_[pr.i + 1];
      ++start_[pr.j + 1];
      ends += 2;
    }
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
  resize_with_headroom(incident_, ends);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ActivePair& pr = pairs[k];
    if (!law_.active(pr, species)) continue;
    incident_[start_[pr.i]++] = static_cast<std::uint32_t>(k);
    incident_[start_[pr.j]++] = static_cast<std::uint32_t>(k);
  }
  // start_[i] now holds the end of row i: shift back by one row.
  for (std::size_t i = n; i > 0; --i) start_[i] = start_[i - 1];
  start_[0] = 0;
}

void ExplicitHydrodynamics::evaluate(const Particles& p, const std::vector<int>& species,
                                     const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                                     const Eigen::VectorXd& dv, const std::vector<double>& mass,
                                     const std::vector<double>& moment, ExplicitHydroResult& out) {
  const std::size_t n = p.size();
  if (species.size() != n || p.position.size() != n || dv.size() != 6 * static_cast<Eigen::Index>(n) ||
      mass.size() != n || moment.size() != n)
    throw InputError("explicit hydrodynamics: species, mass, moment need one entry (dv: six) per particle");
  law_.check(p, species, pairs);

  build_incidence(n, species, pairs);
  out.lubricated_pairs = incident_.size() / 2;
  out.force.resize(6 * static_cast<Eigen::Index>(n));
  const bool dipole = stress_form_ == LubricationStress::force_dipole;
  const std::ptrdiff_t nn = static_cast<std::ptrdiff_t>(n);
  const std::ptrdiff_t nchunks = (nn + chunk_particles - 1) / chunk_particles;
  chunks_.resize(static_cast<std::size_t>(nchunks));

#pragma omp parallel for schedule(dynamic, 4) if (nchunks > 2)
  for (std::ptrdiff_t c = 0; c < nchunks; ++c) {
    Mat3 hydrodynamic = Mat3::Zero(), lubrication = Mat3::Zero();
    double rate = 0.0;
    const std::ptrdiff_t end = std::min(nn, (c + 1) * chunk_particles);
    for (std::ptrdiff_t i = c * chunk_particles; i < end; ++i) {
      const double a = p.radius[i];
      const Vec3& x = p.position[i];
      const hydro::StokesResistance s = hydro::stokes_resistance(a);
      // Diagonal block (Stokes + pair self blocks), strain and Faxen forces, coupling forces and row sums.
      Matrix6 d = Matrix6::Zero();
      d.diagonal() << s.translation, s.translation, s.translation, s.rotation, s.rotation, s.rotation;
      Vector6 b;
      b << s.translation * (a * a / 6.0) * flow.velocity_laplacian(x), Vec3::Zero();
      Vector6 coupled = Vector6::Zero(), coupling_row = Vector6::Zero();
      const Vector6 dv_self = dv.segment<6>(6 * i);
      for (std::uint32_t e = start_[i]; e < start_[i + 1]; ++e) {
        const std::uint32_t k = incident_[e];
        const ActivePair& pr = pairs[k];
        const hydro::PairLubrication& lub = law_(species[pr.i], species[pr.j]);
        const double gap = pr.gap();
        const Mat3 e_i = flow.strain_rate(p.position[pr.i]), e_j = flow.strain_rate(p.position[pr.j]);
        const hydro::Matrix12 r = lub.resistance(pr.geometry().n, gap);
        const hydro::Vector12 strain = lub.strain_forces(pr.geometry().n, gap, e_i, e_j);
        const bool is_i = pr.i == static_cast<std::uint32_t>(i);
        const int self = is_i ? 0 : 6, other = is_i ? 6 : 0;
        const Vector6 dv_other = dv.segment<6>(6 * static_cast<Eigen::Index>(is_i ? pr.j : pr.i));
        d += r.block<6, 6>(self, self);
        b += strain.segment<6>(self);
        const Matrix6 cb = r.block<6, 6>(self, other);
        coupled += cb * dv_other;
        coupling_row += cb.cwiseAbs().rowwise().sum();
        if (dipole && !is_i) {  // force on j, -(R_ji dv_i + R_jj dv_j) + (R_FE : E)_j, as the solver forms it
          const Vector6 f_j = -(cb * dv_other + r.block<6, 6>(6, 6) * dv_self) + strain.segment<6>(6);
          lubrication += -sym_outer(pr.d, Vec3(f_j.head<3>()));
        } else if (!dipole && is_i) {
          hydro::PairMotion m;
          m.du_i = dv_self.head<3>();
          m.dw_i = dv_self.tail<3>();
          m.du_j = dv_other.head<3>();
          m.dw_j = dv_other.tail<3>();
          m.e_i = e_i;
          m.e_j = e_j;
          const hydro::PairHydroForce h = lub.evaluate(pr.geometry().n, gap, m);
          lubrication += h.stresslet_i + h.stresslet_j;
        }
      }
      out.force.segment<6>(6 * i) = b - (d * dv_self + coupled);
      const Vector6 row = d.cwiseAbs().rowwise().sum() + coupling_row;
      rate = std::max({rate, row.head<3>().maxCoeff() / mass[i], row.tail<3>().maxCoeff() / moment[i]});
      hydrodynamic += hydro::stokes_stresslet(a, x, flow);
    }
    chunks_[c] = {hydrodynamic, lubrication, rate};
  }

  out.stress.clear();
  out.relaxation_rate = 0.0;
  for (const ChunkSums& c : chunks_) {
    out.stress[Contribution::hydrodynamic] += c.hydrodynamic;
    out.stress[Contribution::lubrication] += c.lubrication;
    out.relaxation_rate = std::max(out.relaxation_rate, c.rate);
  }
}

}  // namespace suspend
