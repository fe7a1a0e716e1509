// The per-pair state a frictional contact carries from one step to the next (paper 000 eq. 5 and Appendix B).
//
//  * tangential_stretch xi: integral of the tangential contact velocity of j relative to i since the contact began,
//    kept on the current tangent plane and capped at the Coulomb limit (force on j is -k_t xi).
//  * rolling_stretch xi_r: the same for the rolling velocity u_r = a_ij n x (omega_i - omega_j).
//  * in_contact: false once the pair separates; a new contact then starts from zero stretch (xi(t_0) = 0).
//  * normal_state: what a normal law with hysteresis keeps (a law declaring `keeps_history`, contact_model.hpp;
//    JKR: the contact radius of the neck, > 0 while the pair is bonded); 0 for the others. Carried by the contact
//    store and checkpoints like the stretches; unchanged by the swap.
//  * twisting_stretch xi_o: the signed stretch of the twisting spring along n (twisting_resistance.hpp); unchanged by
//    the swap (u_o is symmetric under it).
// The scalar slots are listed in scalar_slots: the contact store and checkpoints carry each one by that list (a
// dataset contacts/<name>, absent in checkpoints written before the slot existed and then read as 0).
// Orientation: stored for the ordered pair (i, j), d = r_j - r_i. Seen as (j, i) the tangential stretch changes
// sign and the rolling stretch does not (u_r is symmetric under the swap); oriented_for_swap() applies this.
// Units: lengths in a_1.
#pragma once
#include <array>
#include <string_view>

#include "core/vec.hpp"

namespace suspend {

struct PairHistory {
  Vec3 tangential_stretch = Vec3::Zero();
  Vec3 rolling_stretch = Vec3::Zero();
  bool in_contact = false;
  double normal_state = 0.0;
  double twisting_stretch = 0.0;

  void reset() { *this = PairHistory{}; }
  PairHistory swapped() const {
    PairHistory h = *this;
    h.tangential_stretch = -tangential_stretch;
    return h;
  }
};

// The per-pair scalars a sub-model keeps, by the name their checkpoint dataset has.
struct PairHistorySlot {
  std::string_view name;
  double PairHistory::*member;
};
inline constexpr std::array<PairHistorySlot, 2> scalar_slots{{{"normal_state", &PairHistory::normal_state},
                                                              {"twisting_stretch", &PairHistory::twisting_stretch}}};

}  // namespace suspend
