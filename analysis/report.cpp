#include "analysis/report.hpp"

#include <array>

#include "analysis/contact_network.hpp"
#include "analysis/contact_stress.hpp"
#include "analysis/distributions.hpp"
#include "analysis/gradient_profile.hpp"

namespace suspend::analysis {

namespace {

using json = nlohmann::ordered_json;

json tensor(const Mat3& m) {  // the column order of run.h5's stress series
  return {{"xx", m(0, 0)}, {"yy", m(1, 1)}, {"zz", m(2, 2)}, {"xy", m(0, 1)}, {"xz", m(0, 2)}, {"yz", m(1, 2)}};
}

json histogram(const Histogram& h) {
  return {{"mean", h.mean}, {"count", h.total}, {"below", h.below}, {"above", h.above}, {"edges", h.edges},
          {"density", h.density}};
}

json axes(const std::array<bool, 3>& a) { return {{"x", a[0]}, {"y", a[1]}, {"z", a[2]}}; }

}  // namespace

json report(const Configuration& c, const ReportOptions& options) {
  json out;
  out["step"] = c.step;
  out["time"] = c.time;
  out["strain"] = c.strain;
  out["particles"] = c.size();
  const ContactNumbers z = contact_numbers(c);
  out["contacts"] = z.contacts;
  out["contacts_per_particle"] = z.contacts_per_particle;
  out["contacts_per_particle_by_species"] = z.contacts_per_particle_of;
  out["rattler_fraction"] = z.rattler_fraction;
  const json unknown;  // null: the file does not record it (Configuration::contact_details)
  out["sliding_fraction"] = c.contact_details ? json(z.sliding_fraction) : unknown;
  const ContactTensors t = contact_tensors(c);
  out["fabric"] = tensor(t.fabric);
  out["contact_stress"] = c.contact_details ? tensor(t.contact_law_stress) : unknown;
  out["contact_pair_stress"] = tensor(t.contact_pair_stress);
  const ClusterStatistics cl = clusters(c);
  json sizes = json::array();
  for (const Cluster& k : cl.clusters) sizes.push_back(k.size);
  json spanning = json::array();
  for (const Cluster& k : cl.clusters)
    if (k.percolates[0] || k.percolates[1] || k.percolates[2]) spanning.push_back({{"size", k.size}, {"percolates", axes(k.percolates)}});
  out["clusters"] = {{"count", cl.clusters.size()}, {"largest", cl.largest},      {"mean", cl.mean_size},
                     {"isolated", cl.isolated},      {"percolates", axes(cl.percolates)}, {"percolating", spanning},
                     {"sizes", sizes}};
  const GradientProfile gp = gradient_profile(c, options.profile_bins);
  out["gradient_profile"] = {{"bins", options.profile_bins}, {"width", gp.width},           {"y", gp.y},
                             {"phi", gp.phi},                {"count", gp.count},           {"mean_y", gp.mean_y},
                             {"velocity", gp.velocity},      {"shear_rate", gp.shear_rate}, {"local_rate", gp.local_rate}};
  if (!options.distributions) return out;
  const ForceDistributions f = force_distributions(c);
  out["force_distribution"] = c.contact_details ? json{{"normal", histogram(f.normal)}, {"tangential", histogram(f.tangential)}}
                                                : unknown;
  const GapDistribution gaps = gap_distribution(c);
  json g = histogram(gaps.gaps);
  g["overlapping"] = gaps.overlapping;
  out["gap_distribution"] = g;
  const PairDistribution pd = pair_distribution(c);
  json rows = json::array();
  const std::size_t bins = pd.xy_centres.size();
  for (std::size_t iy = 0; iy < bins; ++iy)
    rows.push_back(std::vector<double>(pd.g_xy.begin() + iy * bins, pd.g_xy.begin() + (iy + 1) * bins));
  out["pair_distribution"] = {{"dr", pd.dr}, {"r", pd.r}, {"g", pd.g},
                              {"shear_plane", {{"slab", pd.slab}, {"bin", pd.dxy}, {"centres", pd.xy_centres}, {"g", rows}}}};
  return out;
}

}  // namespace suspend::analysis
