#include "io/rank_messages.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace dda {
namespace {

class Writer {
 public:
  template <typename T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.append(p, sizeof(T));
  }
  void put(const std::string& s) {
    put(s.size());
    bytes_.append(s);
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  void get(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
  }
  void get(std::string& s) {
    std::size_t n = 0;
    get(n);
    need(n);
    s.assign(bytes_.data() + at_, n);
    at_ += n;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - at_ < n) throw std::runtime_error("a message between ranks ends early");
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

// The same field list both ways: `io` is a Writer (put) or a Reader (get).
template <typename IO, typename Stats>
void stats_fields(IO& io, Stats& s) {
  io.field(s.steps, s.cut_steps, s.cuts_for_displacement, s.cuts_for_open_close,
           s.cuts_for_penetration, s.cuts_for_material, s.cuts_for_overshoot,
           s.smallest_time_step, s.largest_time_step, s.steps_below_schedule, s.iterations,
           s.wall_time_s, s.open_close_total, s.open_close_max, s.contacts_total, s.contacts_max,
           s.contacts_final, s.candidate_pairs_max, s.interrupted, s.deepest_penetration,
           s.largest_normal_force, s.augmentations, s.line_searches_shortened,
           s.newton_unconverged_mismatch, s.newton_accepted_unconverged, s.newton_held_open,
           s.bonds_broken, s.local_secant_settles, s.stage_times.detect, s.stage_times.assemble,
           s.stage_times.solve, s.stage_times.contact_update, s.stage_times.update, s.diverged,
           s.message);
  io.count(s.broken_bonds);
  for (auto& b : s.broken_bonds) io.field(b.step, b.time, b.vertex_block, b.edge_block, b.at.x(), b.at.y());
}

template <typename IO, typename Trial>
void trial_fields(IO& io, Trial& t) {
  io.field(t.factor, t.stable, t.verdict, t.largest_displacement, t.end_speed, t.end_speed_limit,
           t.kinetic_peak, t.kinetic_end, t.steps, t.simulated_time, t.wall_time_s, t.watched_point,
           t.interrupted);
  io.optional(t.predicted_displacement);
  stats_fields(io, t.stats);
}

template <typename IO, typename Sample>
void sample_fields(IO& io, Sample& o) {
  io.field(o.index, o.done, o.failing, o.verdict, o.factor_found, o.factor, o.last_stable,
           o.first_failing, o.message, o.above_range, o.below_range, o.trials, o.steps,
           o.wall_time_s);
  io.count(o.values);
  for (auto& v : o.values) io.field(v);
}

struct Packing {
  Writer w;
  template <typename... T>
  void field(const T&... v) { (w.put(v), ...); }
  template <typename V>
  void count(const std::vector<V>& v) { w.put(v.size()); }
  void optional(const std::optional<double>& v) {
    w.put(v.has_value());
    w.put(v.value_or(0.0));
  }
};

struct Unpacking {
  explicit Unpacking(const std::string& bytes) : r(bytes) {}
  Reader r;
  template <typename... T>
  void field(T&... v) { (r.get(v), ...); }
  template <typename V>
  void count(std::vector<V>& v) {
    std::size_t n = 0;
    r.get(n);
    v.resize(n);
  }
  void optional(std::optional<double>& v) {
    bool has = false;
    double value = 0.0;
    r.get(has);
    r.get(value);
    v = has ? std::optional<double>(value) : std::nullopt;
  }
};

// One field list serves both directions and names its fields as lvalues, so packing takes the
// items as non-const; it only reads them.
template <typename T, typename Each>
std::string pack_all(const std::vector<T>& items, Each each) {
  Packing p;
  p.w.put(items.size());
  for (const T& item : items) each(p, const_cast<T&>(item));
  return p.w.take();
}

template <typename T, typename Each>
std::vector<T> unpack_all(const std::string& bytes, Each each) {
  Unpacking u(bytes);
  std::size_t n = 0;
  u.r.get(n);
  std::vector<T> items(n);
  for (T& item : items) each(u, item);
  if (!u.r.done()) throw std::runtime_error("a message between ranks is longer than its contents");
  return items;
}

}  // namespace

std::string pack_trials(const std::vector<TrialResult>& trials) {
  return pack_all(trials, [](Packing& p, TrialResult& t) { trial_fields(p, t); });
}

std::vector<TrialResult> unpack_trials(const std::string& bytes) {
  return unpack_all<TrialResult>(bytes, [](Unpacking& u, TrialResult& t) { trial_fields(u, t); });
}

std::string pack_samples(const std::vector<SampleOutcome>& samples) {
  return pack_all(samples, [](Packing& p, SampleOutcome& o) { sample_fields(p, o); });
}

std::vector<SampleOutcome> unpack_samples(const std::string& bytes) {
  return unpack_all<SampleOutcome>(bytes, [](Unpacking& u, SampleOutcome& o) { sample_fields(u, o); });
}

}  // namespace dda
