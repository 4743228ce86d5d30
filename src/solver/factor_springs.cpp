#include "solver/factor_springs.hpp"

#include <cstdint>
#include <functional>

namespace dda {

std::size_t FactorSprings::KeyHash::operator()(const ContactKey& k) const {
  // Block indices below 2^20 and vertex/edge indices below 2^12 make the packing exact for
  // any scene this code runs; beyond, it is still a hash (collisions only cost lookups).
  const auto u = [](int v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)); };
  const std::uint64_t packed =
      (u(k.vertex_block) << 44) ^ (u(k.vertex) << 32) ^ (u(k.edge_block) << 12) ^ u(k.edge);
  return std::hash<std::uint64_t>{}(packed);
}

bool FactorSprings::same_springs(const SpringState& a, const SpringState& b) {
  // Only a change of mode changes a contact's springs by a whole spring. A moved anchor
  // (t_lock) or a sliding contact's new slip (predicted_slip) moves where its springs act by
  // a share of an edge, like any other drift of the geometry, which CG makes up in the same
  // few iterations; counting them as changes would ask for ~200 updates an iteration on a
  // 100-brick wall, where a handful of modes change.
  return a.mode == b.mode;
}

namespace {

SpringState springs_of(const Contact& c) {
  return {c.state.mode, c.state.t_lock, c.state.predicted_slip};
}

}  // namespace

void FactorSprings::record_all(const World& world, const std::vector<Contact>& contacts,
                               const StepContext& ctx) {
  recorded_.clear();
  pending_.clear();
  recorded_.reserve(contacts.size());
  for (const Contact& c : contacts) {
    if (c.state.mode == ContactMode::Open) continue;  // no springs
    Entry e{springs_of(c), {}};
    contact_spring_terms(world, c, ctx, e.terms);
    recorded_.emplace(c.key, std::move(e));
  }
}

void FactorSprings::differences(const World& world, const std::vector<Contact>& contacts,
                                const StepContext& ctx, std::vector<RankOneTerm>& added,
                                std::vector<RankOneTerm>& removed) {
  added.clear();
  removed.clear();
  pending_.clear();
  // Contacts present now: changed or new ones. Recorded contacts seen are counted so that the
  // ones that went (in the factor, no longer present or now open) are found below.
  std::size_t seen = 0;
  for (const Contact& c : contacts) {
    const auto it = recorded_.find(c.key);
    const bool open = c.state.mode == ContactMode::Open;
    if (it == recorded_.end()) {
      if (open) continue;
      Entry e{springs_of(c), {}};
      contact_spring_terms(world, c, ctx, e.terms);
      added.insert(added.end(), e.terms.begin(), e.terms.end());
      pending_.emplace_back(c.key, std::move(e));
      continue;
    }
    ++seen;
    if (!open && same_springs(it->second.state, springs_of(c))) continue;
    removed.insert(removed.end(), it->second.terms.begin(), it->second.terms.end());
    Entry e{springs_of(c), {}};
    if (!open) contact_spring_terms(world, c, ctx, e.terms);
    added.insert(added.end(), e.terms.begin(), e.terms.end());
    pending_.emplace_back(c.key, std::move(e));
  }
  if (seen == recorded_.size()) return;
  // Some recorded contacts are no longer detected: their springs go.
  std::unordered_map<ContactKey, bool, KeyHash> present;
  present.reserve(contacts.size());
  for (const Contact& c : contacts) present.emplace(c.key, true);
  for (const auto& [key, entry] : recorded_) {
    if (present.count(key) != 0) continue;
    removed.insert(removed.end(), entry.terms.begin(), entry.terms.end());
    pending_.emplace_back(key, Entry{entry.state, {}});
  }
}

void FactorSprings::commit() {
  for (auto& [key, entry] : pending_) {
    if (entry.terms.empty()) {
      recorded_.erase(key);
    } else {
      recorded_[key] = std::move(entry);
    }
  }
  pending_.clear();
}

void FactorSprings::clear() {
  recorded_.clear();
  pending_.clear();
}

}  // namespace dda
