#include "solver/factor_springs.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <functional>
#include <unordered_set>

namespace dda {

std::size_t FactorSprings::KeyHash::operator()(const ContactKey& k) const {
  // Block indices below 2^20 and vertex/edge indices below 2^12 make the packing exact for
  // any scene this code runs; beyond, it is still a hash (collisions only cost lookups).
  const auto u = [](int v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)); };
  const std::uint64_t packed =
      (u(k.vertex_block) << 44) ^ (u(k.vertex) << 32) ^ (u(k.edge_block) << 12) ^ u(k.edge);
  return std::hash<std::uint64_t>{}(packed);
}

void FactorSprings::record_all(const std::vector<Contact>& contacts) {
  recorded_.clear();
  pending_.clear();
  recorded_.reserve(contacts.size());
  for (const Contact& c : contacts) {
    if (c.state.mode != ContactMode::Open) recorded_.emplace(c.key, c.state.mode);
  }
}

// Only a change of mode changes a contact's springs by a whole spring. A moved anchor
// (t_lock) or a sliding contact's new slip (predicted_slip) moves where its springs act by
// a share of an edge, like any other drift of the geometry, which CG makes up in the same
// few iterations; counting them as changes would ask for ~200 updates an iteration on a
// 100-brick wall, where a handful of modes change.
void FactorSprings::differences(const World& world, const std::vector<Contact>& contacts,
                                const StepContext& ctx, std::vector<RankOneTerm>& added,
                                std::vector<RankOneTerm>& removed) {
  added.clear();
  removed.clear();
  pending_.clear();
  // Contacts present now: changed or new ones. Recorded contacts seen are counted so that the
  // ones that went (in the factor, no longer detected) are found below.
  std::size_t seen = 0;
  for (const Contact& c : contacts) {
    const auto it = recorded_.find(c.key);
    const ContactMode held = it == recorded_.end() ? ContactMode::Open : it->second;
    if (it != recorded_.end()) ++seen;
    if (held == c.state.mode) continue;
    if (held != ContactMode::Open) {
      Contact then = c;
      then.state.mode = held;
      contact_spring_terms(world, then, ctx, removed);
    }
    contact_spring_terms(world, c, ctx, added);  // none when open
    pending_.emplace_back(c.key, c.state.mode);
  }
  if (seen == recorded_.size()) return;
  // Some recorded contacts are no longer detected (their vertex left the search distance).
  // Their terms cannot be made without the contact, so their springs stay in the factor as
  // drift for CG, like any other; the ledger forgets them.
  std::unordered_set<ContactKey, KeyHash> present;
  present.reserve(contacts.size());
  for (const Contact& c : contacts) present.insert(c.key);
  for (const auto& [key, mode] : recorded_) {
    if (present.count(key) == 0) pending_.emplace_back(key, ContactMode::Open);
  }
}

void FactorSprings::commit() {
  for (const auto& [key, mode] : pending_) {
    if (mode == ContactMode::Open) {
      recorded_.erase(key);
    } else {
      recorded_[key] = mode;
    }
  }
  pending_.clear();
}

void FactorSprings::clear() {
  recorded_.clear();
  pending_.clear();
}

std::vector<FactorSprings::Entry> FactorSprings::entries() const {
  std::vector<Entry> out(recorded_.begin(), recorded_.end());
  const auto tied = [](const ContactKey& k) { return std::tie(k.vertex_block, k.vertex, k.edge_block, k.edge); };
  std::sort(out.begin(), out.end(), [&](const Entry& a, const Entry& b) { return tied(a.first) < tied(b.first); });
  return out;
}

void FactorSprings::restore(const std::vector<Entry>& entries) {
  recorded_.clear();
  pending_.clear();
  recorded_.insert(entries.begin(), entries.end());
}

}  // namespace dda
