// The contact springs inside CholmodSolver's kept factor. The factor is
// kept from step to step; between its matrix and the present one lie (a) the springs of
// contacts whose mode changed, which appeared or which went (tens a step on a settled
// 1000-brick wall: deferred changes, chatter between lock and slide), and (b) the small drift
// of everything else (geometry, T). CG on the kept factor needs about one iteration per
// changed spring, so (a) is taken out of the factor by rank-one updates before CG: this
// ledger records, per contact, the mode whose springs the factor holds. A changed contact's
// old springs are taken out as they are now (its geometry and T of this iteration), not as
// the factor holds them, so the factor is left with that spring's drift, which (b) covers:
// recording every contact's terms at each factorisation took 12 % of a 1000-brick step.
#pragma once

#include <unordered_map>
#include <utility>
#include <vector>

#include "contact/contact.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/sparse_cholesky.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

class FactorSprings {
 public:
  // After a factorisation of a system assembled with `contacts` as they are now: the factor
  // holds their present springs.
  void record_all(const std::vector<Contact>& contacts);

  // The terms that turn the factor's springs into the contacts' present ones: `removed`
  // (the recorded mode's springs) and `added` (the present mode's), both at the present
  // geometry and T. Both vectors are cleared first. Kept as pending until commit().
  void differences(const World& world, const std::vector<Contact>& contacts, const StepContext& ctx,
                   std::vector<RankOneTerm>& added, std::vector<RankOneTerm>& removed);

  // The pending differences were applied to the factor.
  void commit();

  // Nothing recorded (no factor yet, or it was dropped).
  void clear();

  // The ledger as a checkpoint keeps it (sorted by key, so that its bytes do not depend on
  // the hash table's order), and put back. Pending differences are not kept: the next
  // differences() makes them afresh.
  using Entry = std::pair<ContactKey, ContactMode>;
  std::vector<Entry> entries() const;
  void restore(const std::vector<Entry>& entries);

 private:
  struct KeyHash {
    std::size_t operator()(const ContactKey& k) const;
  };
  // Contacts whose springs the factor holds (closed ones), with the mode they had.
  using Ledger = std::unordered_map<ContactKey, ContactMode, KeyHash>;

  Ledger recorded_;
  std::vector<std::pair<ContactKey, ContactMode>> pending_;  // new modes (Open: gone)
};

}  // namespace dda
