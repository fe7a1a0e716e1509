#include "analysis/contact_stress.hpp"

namespace suspend::analysis {

ContactTensors contact_tensors(const Configuration& c) {
  ContactTensors out;
  for (const Contact& k : c.contacts) {
    const Vec3 d = c.box.minimum_image(c.position[k.i], c.position[k.j]).d;
    const double r = d.norm();
    if (r <= 0.0) continue;
    const Vec3 n = d / r;
    out.fabric += n * n.transpose();
    const Vec3 law = k.normal_force * n + k.tangential_force;
    out.contact_law_stress -= sym_outer(d, law);
    out.contact_pair_stress -= sym_outer(d, k.force_on_j);
  }
  if (!c.contacts.empty()) out.fabric /= static_cast<double>(c.contacts.size());
  const double v = c.box.volume();
  out.contact_law_stress /= v;
  out.contact_pair_stress /= v;
  return out;
}

}  // namespace suspend::analysis
