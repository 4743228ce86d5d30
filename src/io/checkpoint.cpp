#include "io/checkpoint.hpp"

#include <algorithm>
#include <concepts>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "io/input_error.hpp"
#include "io/output_file.hpp"
#include "io/scene_reader.hpp"

namespace dda {
namespace {

// ---- the file: header, payload, checksum ----
//
//   8 bytes  magic "DDA2DCK\n"
//   4 bytes  format version (kCheckpointVersion), in the writer's byte order
//   4 bytes  0x01020304 in the writer's byte order (another order is refused)
//   8 bytes  the double 1.5 (another size or representation of doubles is refused)
//   8 bytes  payload length
//   payload  (below)
//   8 bytes  FNV-1a digest of the payload (continue_digest)
//
// The payload begins with what the file is ("run" or "fos consolidation").
// The payload is the fields in the order the visitors below list them: integers as 8-byte
// signed, bools as one byte, doubles as their 8 bytes, strings and vectors as an 8-byte
// count and their elements (64-bit unsigned integers as their bits), optionals as a byte (0 absent, 1 present) and the value.
constexpr char kMagic[8] = {'D', 'D', 'A', '2', 'D', 'C', 'K', '\n'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;
constexpr double kDoubleMark = 1.5;
constexpr std::size_t kHeaderSize = 8 + 4 + 4 + 8 + 8;

// A struct the serializer must list field by field: adding a field to one of these changes
// its size, and the build stops here until the visitor below (and kCheckpointVersion) takes
// it in. The sizes are those of the one platform the project builds on (x86-64, GCC's
// libstdc++).
static_assert(sizeof(void*) != 8 || sizeof(Block) == 576, "Block changed: update visit(Block)");
static_assert(sizeof(void*) != 8 || sizeof(Contact) == 304, "Contact changed: update visit(Contact)");
// World less the members taken from the scene (whose own fields may change freely).
static_assert(sizeof(void*) != 8 || sizeof(World) - sizeof(World::water) - sizeof(World::base_motion) == 936,
              "World changed: update visit(World)");
static_assert(sizeof(void*) != 8 || sizeof(EnergyLedger) == 120, "EnergyLedger changed");
static_assert(sizeof(void*) != 8 || sizeof(RunStats) == 296, "RunStats changed: update visit(RunStats)");
static_assert(sizeof(void*) != 8 || sizeof(ControlSettings) == 152, "ControlSettings changed");
static_assert(sizeof(void*) != 8 || sizeof(StagePlan) == 304, "StagePlan changed");
static_assert(sizeof(void*) != 8 || sizeof(Bolt) == 88, "Bolt changed: update visit(Bolt)");
static_assert(sizeof(void*) != 8 || sizeof(JointLaw) == 80, "JointLaw changed");
static_assert(sizeof(void*) != 8 || sizeof(MaterialParameters) == 104, "MaterialParameters changed");
static_assert(sizeof(void*) != 8 || sizeof(Settling) == 368, "Settling changed: update visit(Settling)");
static_assert(sizeof(void*) != 8 || sizeof(LinearSolveStats) == 40, "LinearSolveStats changed");
static_assert(sizeof(void*) != 8 || sizeof(FactorRecord) == 112, "FactorRecord changed");
static_assert(sizeof(void*) != 8 || sizeof(CholmodSolver::Record) == 176, "CholmodSolver::Record changed");
static_assert(sizeof(void*) != 8 || sizeof(WorkspaceRecord) == 200, "WorkspaceRecord changed");

template <class B, class T>
concept Is = std::same_as<std::remove_const_t<B>, T>;

// ---- what is stored: one visitor per struct, for writing (B const) and reading ----
//
// From the scene (never changed by a run, rebuilt by make_world from the stored scene
// text): World::water, World::base_motion and StagePlan::stages. Everything else in the
// world is stored, cold fields included, so that nothing a run or a study changed is lost.

template <class A, Is<Moments> B>
void visit(A& a, B& m) {
  a(m.area), a(m.centroid), a(m.sxx), a(m.syy), a(m.sxy);
}

template <class A, Is<MaterialState> B>
void visit(A& a, B& s) {
  a(s.plastic_strain), a(s.eps_p);
}

template <class A, Is<BlockSpec::EdgeBridge> B>
void visit(A& a, B& e) {
  a(e.material), a(e.share);
}

template <class A, Is<Block> B>
void visit(A& a, B& b) {
  a(b.initial_vertices), a(b.initial_centroid), a(b.material), a(b.fixed), a(b.edge_joints);
  a(b.edge_bridges), a(b.initial_stress), a(b.initial_area), a(b.material_inertia);
  a(b.first_dof), a(b.excavated), a(b.step_limit), a(b.reach), a(b.size), a(b.rigid);
  a(b.plastic);
  a(b.vertices), a(b.moments), a(b.translation), a(b.rotation), a(b.strain), a(b.local_strain);
  a(b.stress), a(b.velocity), a(b.local_strain_rate), a(b.last_rotation_increment);
  a(b.last_local_increment), a(b.material_state), a(b.szz), a(b.branch);
}

template <class A, Is<HardeningPoint> B>
void visit(A& a, B& h) {
  a(h.eps_p), a(h.cohesion);
}

template <class A, Is<FrictionalStrength> B>
void visit(A& a, B& f) {
  a(f.cohesion), a(f.friction_angle), a(f.dilation_angle), a(f.hardening);
}

template <class A, Is<MaterialParameters> B>
void visit(A& a, B& p) {
  a(p.young), a(p.poisson), a(p.density), a(p.plane);
  std::int64_t model = static_cast<std::int64_t>(p.model_parameters.index());
  a(model);
  if constexpr (!std::is_const_v<B>) {
    switch (model) {
      case 0: p.model_parameters = ElasticOnly{}; break;
      case 1: p.model_parameters = DruckerPragerParameters{}; break;
      case 2: p.model_parameters = MohrCoulombParameters{}; break;
      default: a.garbage("a material model that does not exist");
    }
  }
  if (auto* dp = std::get_if<DruckerPragerParameters>(&p.model_parameters)) {
    visit(a, static_cast<std::conditional_t<std::is_const_v<B>, const FrictionalStrength&,
                                            FrictionalStrength&>>(*dp));
    a(dp->match);
  }
  if (auto* mc = std::get_if<MohrCoulombParameters>(&p.model_parameters)) {
    visit(a, static_cast<std::conditional_t<std::is_const_v<B>, const FrictionalStrength&,
                                            FrictionalStrength&>>(*mc));
    a(mc->tensile_strength);
  }
}

template <class A, Is<WorldMaterial> B>
void visit(A& a, B& m) {
  a(m.parameters), a(m.elastic);
}

template <class A, Is<Pin> B>
void visit(A& a, B& p) {
  a(p.block), a(p.anchor), a(p.initial), a(p.current);
}

template <class A, Is<PointLoad> B>
void visit(A& a, B& p) {
  a(p.block), a(p.initial), a(p.current), a(p.force);
}

template <class A, Is<Monitor> B>
void visit(A& a, B& m) {
  a(m.name), a(m.block), a(m.initial), a(m.current);
}

template <class A, Is<BoltEnd> B>
void visit(A& a, B& e) {
  a(e.block), a(e.initial), a(e.current);
}

template <class A, Is<BoltLaw> B>
void visit(A& a, B& l) {
  a(l.stiffness), a(l.yield_force);
}

template <class A, Is<Bolt> B>
void visit(A& a, B& b) {
  a(b.name), a(b.law), a(b.rupture_extension), a(b.force), a(b.plastic_extension), a(b.broken);
  a(b.broken_at);
}

template <class A, Is<ControlSettings> B>
void visit(A& a, B& c) {
  a(c.time_steps), a(c.steps), a(c.end_time), a(c.max_displacement_ratio);
  a(c.dynamic_coefficient), a(c.rotation_update), a(c.penalty), a(c.output_every);
  a(c.vtk_binary), a(c.max_open_close), a(c.max_augmentations), a(c.reuse_factor);
  a(c.allowed_penetration), a(c.energy_tolerance), a(c.stop_on_energy_loss);
  a(c.contact_solver), a(c.inertia);
}

template <class A, Is<JointLaw> B>
void visit(A& a, B& l) {
  a(l.tan_phi), a(l.cohesion), a(l.tensile_strength), a(l.kind), a(l.residual_tan_phi);
  a(l.residual_cohesion), a(l.residual_slip), a(l.jrc), a(l.jcs), a(l.friction_divisor);
}

template <class A, Is<ContactKey> B>
void visit(A& a, B& k) {
  a(k.vertex_block), a(k.vertex), a(k.edge_block), a(k.edge);
}

template <class A, Is<ModeChange> B>
void visit(A& a, B& m) {
  a(m.mode), a(m.slide_sign), a(m.relock), a(m.lock_offset);
}

template <class A, Is<ContactState> B>
void visit(A& a, B& s) {
  a(s.mode), a(s.slide_sign), a(s.t_lock), a(s.bonded), a(s.predicted_slip), a(s.normal_force);
  a(s.deferred), a(s.rest_shift), a(s.spring_energy), a(s.slip_sum);
}

template <class A, Is<ContactIterate> B>
void visit(A& a, B& i) {
  a(i.new_gap), a(i.shear_force), a(i.slip), a(i.mode_changes), a(i.start_mode);
  a(i.start_t_lock);
}

template <class A, Is<Contact> B>
void visit(A& a, B& c) {
  a(c.key), a(c.joint), a(c.bridge_joint), a(c.bridge_share), a(c.start_normal_force);
  a(c.vertex), a(c.edge_start), a(c.edge_end), a(c.tangent), a(c.normal), a(c.gap), a(c.t);
  a(c.length), a(c.allowed_penetration), a(c.state), a(c.iterate);
}

template <class A, Is<EnergyLedger> B>
void visit(A& a, B& e) {
  a(e.load_work), a(e.multiplier_work), a(e.friction_dissipation), a(e.plastic_dissipation);
  a(e.damping_dissipation), a(e.friction_gain), a(e.contact_energy), a(e.excavation);
  a(e.initial_total), a(e.remainder), a(e.remainder_max), a(e.remainder_max_step);
  a(e.remainder_min), a(e.remainder_min_step), a(e.scale);
}

template <class A, Is<StepSizeMemory> B>
void visit(A& a, B& s) {
  a(s.next);
}

// The stages' specs come from the scene; what the run made of them is stored.
template <class A, Is<StagePlan> B>
void visit(A& a, B& p) {
  a(p.end_times), a(p.gravity), a(p.control), a(p.joint_laws), a(p.current), a(p.start_steps);
  a(p.bonds_formed);
}

template <class A, Is<World> B>
void visit(A& a, B& w) {
  a(w.materials), a(w.blocks), a(w.pins), a(w.loads), a(w.monitors), a(w.bolts), a(w.bolt_ends);
  a(w.gravity), a(w.pseudo_rigid), a(w.plane), a(w.control), a(w.penalty), a(w.w0);
  a(w.allowed_penetration), a(w.search_distance), a(w.joint_laws);
  // The pair table in key order, so that the bytes do not depend on the hash table's.
  std::vector<std::pair<std::uint64_t, int>> pairs(w.pair_joint.begin(), w.pair_joint.end());
  std::sort(pairs.begin(), pairs.end());
  a(pairs);
  if constexpr (!std::is_const_v<B>) {
    w.pair_joint.clear();
    w.pair_joint.insert(pairs.begin(), pairs.end());
  }
  a(w.dof_count), a(w.contacts), a(w.time), a(w.step), a(w.step_size), a(w.energy), a(w.stages);
}

template <class A, Is<StageTimes> B>
void visit(A& a, B& t) {
  a(t.detect), a(t.assemble), a(t.solve), a(t.contact_update), a(t.update);
}

template <class A, Is<BrokenBond> B>
void visit(A& a, B& b) {
  a(b.step), a(b.time), a(b.vertex_block), a(b.edge_block), a(b.at);
}

template <class A, Is<RunStats> B>
void visit(A& a, B& s) {
  a(s.steps), a(s.cut_steps), a(s.cuts_for_displacement), a(s.cuts_for_open_close);
  a(s.cuts_for_penetration), a(s.cuts_for_material), a(s.cuts_for_overshoot);
  a(s.smallest_time_step), a(s.largest_time_step), a(s.steps_below_schedule), a(s.iterations);
  a(s.wall_time_s), a(s.open_close_total), a(s.open_close_max), a(s.contacts_total);
  a(s.contacts_max), a(s.contacts_final), a(s.candidate_pairs_max), a(s.interrupted);
  a(s.deepest_penetration), a(s.largest_normal_force), a(s.augmentations);
  a(s.line_searches_shortened), a(s.newton_unconverged_mismatch);
  a(s.newton_accepted_unconverged), a(s.newton_held_open), a(s.bonds_broken);
  a(s.broken_bonds), a(s.local_secant_settles), a(s.stage_times), a(s.diverged), a(s.message);
}

template <class A, Is<StreamProgress> B>
void visit(A& a, B& s) {
  a(s.bytes), a(s.digest);
}

template <class A, Is<OutputProgress> B>
void visit(A& a, B& o) {
  a(o.frames), a(o.contact_frames), a(o.bolt_frames), a(o.history), a(o.monitors), a(o.bolts);
}

template <class A, Is<Settling> B>
void visit(A& a, B& s) {
  a(s.steps), a(s.at_rest), a(s.unbalanced_start), a(s.unbalanced_end), a(s.relaxation_steps);
  a(s.stopped), a(s.kept), a(s.stats);
}

template <class A, Is<RankOneTerm> B>
void visit(A& a, B& t) {
  a(t.entries);
}

template <class A, Is<FactorModification> B>
void visit(A& a, B& m) {
  a(m.update), a(m.terms);
}

template <class A, Is<FactorRecord> B>
void visit(A& a, B& f) {
  a(f.analysed), a(f.outer), a(f.inner), a(f.values), a(f.factored), a(f.analyses);
  a(f.modifications);
}

template <class A, Is<LinearSolveStats> B>
void visit(A& a, B& s) {
  a(s.factorisations), a(s.analyses), a(s.modifications), a(s.reused), a(s.cg_iterations);
  a(s.cg_failures), a(s.largest_difference_from_plain);
}

template <class A, Is<CholmodSolver::Record> B>
void visit(A& a, B& r) {
  a(r.factor), a(r.factored_rows), a(r.refresh), a(r.since_factor_cost), a(r.since_factor_solves);
  a(r.last_path), a(r.stats);
}

template <class A, Is<WorkspaceRecord> B>
void visit(A& a, B& w) {
  a(w.solver), a(w.factor_springs);
}

template <class A, Is<ConsolidationSettings> B>
void visit(A& a, B& s) {
  a(s.factor), a(s.seismic_coefficient);
}

template <class T>
struct IsEigen : std::false_type {};
template <int R, int C, int O, int MR, int MC>
struct IsEigen<Eigen::Matrix<double, R, C, O, MR, MC>> : std::true_type {};

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <class T>
struct IsPair : std::false_type {};
template <class T, class U>
struct IsPair<std::pair<T, U>> : std::true_type {};

// Writes the fields it is shown.
class Writer {
 public:
  std::string bytes;

  template <class T>
  void operator()(const T& x) {
    if constexpr (std::is_same_v<T, bool>) {
      bytes.push_back(x ? '\1' : '\0');
    } else if constexpr (std::is_enum_v<T>) {
      integer(static_cast<std::int64_t>(x));
    } else if constexpr (std::is_integral_v<T>) {
      integer(static_cast<std::int64_t>(x));
    } else if constexpr (std::is_same_v<T, double>) {
      raw(&x, sizeof x);
    } else if constexpr (std::is_same_v<T, std::string>) {
      integer(static_cast<std::int64_t>(x.size()));
      bytes += x;
    } else if constexpr (IsEigen<T>::value) {
      for (Eigen::Index i = 0; i < x.size(); ++i) (*this)(x.data()[i]);
    } else if constexpr (IsVector<T>::value) {
      integer(static_cast<std::int64_t>(x.size()));
      for (const auto& e : x) (*this)(e);
    } else if constexpr (IsOptional<T>::value) {
      (*this)(x.has_value());
      if (x) (*this)(*x);
    } else if constexpr (IsPair<T>::value) {
      (*this)(x.first), (*this)(x.second);
    } else {
      visit(*this, x);
    }
  }
  [[noreturn]] void garbage(const char*) { throw std::logic_error("checkpoint: writer"); }

  void raw(const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); }
  void integer(std::int64_t v) { raw(&v, sizeof v); }
};

// Reads them back, every count and value checked against what is left.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  template <class T>
  void operator()(T& x) {
    if constexpr (std::is_same_v<T, bool>) {
      const char c = byte();
      if (c != '\0' && c != '\1') garbage("a flag that is neither 0 nor 1");
      x = c == '\1';
    } else if constexpr (std::is_enum_v<T>) {
      x = static_cast<T>(ranged<std::underlying_type_t<T>>());
    } else if constexpr (std::is_integral_v<T>) {
      x = ranged<T>();
    } else if constexpr (std::is_same_v<T, double>) {
      raw(&x, sizeof x);
    } else if constexpr (std::is_same_v<T, std::string>) {
      const std::size_t n = count(1);
      x.assign(bytes_.substr(at_, n));
      at_ += n;
    } else if constexpr (IsEigen<T>::value) {
      for (Eigen::Index i = 0; i < x.size(); ++i) (*this)(x.data()[i]);
    } else if constexpr (IsVector<T>::value) {
      x.clear();
      x.resize(count(1));
      for (auto& e : x) (*this)(e);
    } else if constexpr (IsOptional<T>::value) {
      bool present = false;
      (*this)(present);
      if (present) {
        x.emplace();
        (*this)(*x);
      } else {
        x.reset();
      }
    } else if constexpr (IsPair<T>::value) {
      (*this)(x.first), (*this)(x.second);
    } else {
      visit(*this, x);
    }
  }

  [[noreturn]] void garbage(const std::string& what) const {
    throw InputError(name_ + ": not a checkpoint dda can read (" + what + ")");
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void raw(void* p, std::size_t n) {
    if (bytes_.size() - at_ < n) garbage("it ends early");
    std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
  }
  char byte() {
    char c = 0;
    raw(&c, 1);
    return c;
  }
  template <class T>
  T ranged() {
    std::int64_t v = 0;
    raw(&v, sizeof v);
    // 64-bit unsigned values (digests, hash keys) are stored as their bits.
    if constexpr (std::is_unsigned_v<T> && sizeof(T) == sizeof v) return static_cast<T>(v);
    if (v < static_cast<std::int64_t>(std::numeric_limits<T>::min()) ||
        (std::is_signed_v<T> && v > static_cast<std::int64_t>(std::numeric_limits<T>::max()))) {
      garbage("a number out of range");
    }
    return static_cast<T>(v);
  }
  // A count of items of at least `least` bytes each: no more than the bytes left can hold.
  std::size_t count(std::size_t least) {
    const std::int64_t n = ranged<std::int64_t>();
    if (n < 0 || static_cast<std::uint64_t>(n) > (bytes_.size() - at_) / least) {
      garbage("a count larger than the file");
    }
    return static_cast<std::size_t>(n);
  }

  std::string_view bytes_;
  std::size_t at_ = 0;
  const std::string& name_;
};

template <class T>
void put(std::string& out, const T& x) {
  out.append(reinterpret_cast<const char*>(&x), sizeof x);
}

template <class T>
T take(const std::string& in, std::size_t at) {
  T x;
  std::memcpy(&x, in.data() + at, sizeof x);
  return x;
}

// What a file is: a run's checkpoint or a fos consolidation (the payload's first field).
constexpr const char* kRunKind = "run";
constexpr const char* kConsolidationKind = "fos consolidation";

// The whole file around a payload.
std::string frame_payload(const std::string& payload) {
  std::string out(kMagic, sizeof kMagic);
  put(out, kCheckpointVersion);
  put(out, kByteOrderMark);
  put(out, kDoubleMark);
  put(out, static_cast<std::uint64_t>(payload.size()));
  out += payload;
  put(out, continue_digest(kDigestStart, payload));
  return out;
}

// The payload of a file, its header and checksum checked.
std::string_view payload_of(const std::string& bytes, const std::string& name) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(name + ": not a checkpoint dda can read (" + why + ")");
  };
  if (bytes.size() < kHeaderSize || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    refuse("it does not begin as a dda checkpoint does");
  }
  if (take<std::uint32_t>(bytes, 12) != kByteOrderMark) refuse("written with another byte order");
  if (take<double>(bytes, 16) != kDoubleMark) refuse("written with another representation of doubles");
  const auto version = take<std::uint32_t>(bytes, 8);
  if (version != kCheckpointVersion) {
    refuse("format version " + std::to_string(version) + "; this dda reads version " +
           std::to_string(kCheckpointVersion));
  }
  const auto length = take<std::uint64_t>(bytes, 24);
  if (bytes.size() - kHeaderSize < 8 || length != bytes.size() - kHeaderSize - 8) {
    refuse("its length is not what its header says: cut short or damaged");
  }
  const std::string_view payload(bytes.data() + kHeaderSize, length);
  if (continue_digest(kDigestStart, payload) != take<std::uint64_t>(bytes, kHeaderSize + length)) {
    refuse("its checksum does not match: damaged");
  }
  return payload;
}

// The kind a payload says it is; refused when it is not `want`.
void expect_kind(Reader& r, const char* want, const std::string& name) {
  std::string kind;
  r(kind);
  if (kind != want) {
    throw InputError(name + ": a " + kind + " checkpoint, not the " + want + " one asked for");
  }
}

std::string read_whole_file(const std::filesystem::path& path) {
  // Not read_input_file: a checkpoint of a large scene may pass the input files' size limit.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string() + ": no checkpoint there (not a regular file)");
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw InputError(path.string() + ": cannot read the checkpoint");
  return bytes;
}

}  // namespace

std::string encode_checkpoint(const CheckpointSource& source) {
  Writer w;
  w(std::string(kRunKind));
  w(source.scene_text);
  w(source.scene.source);
  w(source.scene.control.vtk_binary);
  w(source.world);
  w(source.stats);
  w(source.output);
  std::optional<WorkspaceRecord> workspace;
  if (source.workspace != nullptr) workspace = record_workspace(*source.workspace);
  w(workspace);
  return frame_payload(w.bytes);
}

std::string encode_consolidation(const std::string& scene_text, const Scene& scene,
                                 const ConsolidationSettings& settings,
                                 const Consolidation& consolidation) {
  Writer w;
  w(std::string(kConsolidationKind));
  w(scene_text);
  w(scene.source);
  w(settings);
  w(consolidation.world);
  w(consolidation.stats);
  w(consolidation.settling);
  return frame_payload(w.bytes);
}

void write_checkpoint_file(const std::filesystem::path& path, const std::string& bytes) {
  write_file_whole(path, bytes);
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& name) {
  Reader r(payload_of(bytes, name), name);
  expect_kind(r, kRunKind, name);
  Checkpoint c;
  std::string source;
  bool vtk_binary = true;
  r(c.scene_text), r(source), r(vtk_binary);
  try {
    c.scene = parse_scene_text(c.scene_text, source);
  } catch (const InputError& e) {
    throw InputError(name + ": the scene it holds does not read: " + e.what());
  }
  c.scene.control.vtk_binary = vtk_binary;
  c.world = make_world(c.scene);
  const std::size_t blocks = c.world.blocks.size();
  r(c.world);
  if (c.world.blocks.size() != blocks) r.garbage("a world that is not its scene's");
  r(c.stats), r(c.output), r(c.workspace);
  if (!r.done()) r.garbage("bytes after its end");
  return c;
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  return decode_checkpoint(read_whole_file(path), path.string());
}

Consolidation read_consolidation(const std::filesystem::path& path, const std::string& scene_text,
                                 const Scene& scene, const ConsolidationSettings& settings) {
  const std::string name = path.string();
  const std::string bytes = read_whole_file(path);
  Reader r(payload_of(bytes, name), name);
  expect_kind(r, kConsolidationKind, name);
  std::string text, source;
  ConsolidationSettings stored;
  r(text), r(source), r(stored);
  if (text != scene_text) {
    throw InputError(name + ": the consolidation of another scene (" + source + "), not of " +
                     scene.source + " as it is now");
  }
  if (stored.factor != settings.factor || stored.seismic_coefficient != settings.seismic_coefficient) {
    throw InputError(name + ": consolidated at --consolidation-factor " + std::to_string(stored.factor) +
                     " and --seismic-coefficient " + std::to_string(stored.seismic_coefficient) +
                     ", not at the " + std::to_string(settings.factor) + " and " +
                     std::to_string(settings.seismic_coefficient) + " asked for");
  }
  Consolidation c;
  c.world = make_world(scene);
  const std::size_t blocks = c.world.blocks.size();
  r(c.world);
  if (c.world.blocks.size() != blocks) r.garbage("a world that is not its scene's");
  r(c.stats), r(c.settling);
  if (!r.done()) r.garbage("bytes after its end");
  return c;
}

}  // namespace dda
