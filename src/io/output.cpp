#include "io/output.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/bolt_output.hpp"
#include "io/contact_output.hpp"
#include "io/input_error.hpp"
#include "io/text_file.hpp"
#include "kinematics/block_matrices.hpp"
#include "solver/energy.hpp"
#include "solver/excavation.hpp"
#include "solver/step.hpp"

namespace dda {

// The shortest text that reads back as the same double, bit for bit (std::to_chars without
// a precision; printf's %.17g gave the same values with more digits, at several times the
// cost: the output of a 30-block run took 45 % of its step).
std::string format_full_precision(double x) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string vtk_frame_name(const char* prefix, int step) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "vtk/%s_%06d.vtp", prefix, step);
  return buf;
}

namespace {

namespace fs = std::filesystem;
// ordered_json keeps the keys in the order written here, which reads better than sorted.
using json = nlohmann::ordered_json;

constexpr const char* kHistoryHeader =
    "step,time,block,xc,yc,rotation,area,exx,eyy,gxy,sxx,syy,sxy,vx,vy,omega,"
    "kinetic,potential,strain_energy,contact_energy,load_work,friction_dissipation,"
    "plastic_dissipation,damping_dissipation,energy_remainder,multiplier_work";

// A contract (docs/output-format.md): these names, in this order (extend, do not rename).
constexpr const char* kMonitorsHeader = "step,time,monitor,x,y,ux,uy,vx,vy";
constexpr const char* kBoltsHeader = "step,time,bolt,force,plastic_extension,broken,length";

std::string num(double x) { return format_full_precision(x); }

[[noreturn]] void fail(const std::string& what, const fs::path& path) {
  throw std::runtime_error("output: " + what + " " + path.string());
}

std::string frame_name(int step) { return vtk_frame_name("step", step); }

// ---- VTK XML PolyData ----

// One cell data array of the blocks: `values(b)` gives block b's components.
template <class Values>
VtkArray block_array(const World& w, VtkType type, const char* name,
                     std::vector<std::string> components, Values values) {
  VtkArray a{name, type, static_cast<int>(components.size()), {}, {}};
  // Component names make ParaView show "sxx" rather than "0" in its menus.
  if (components.size() > 1) a.component_names = std::move(components);
  for (const Block& b : w.blocks) {
    for (double v : values(b)) a.values.push_back(v);
  }
  return a;
}

std::vector<double> flag(bool on) { return {on ? 1.0 : 0.0}; }

VtkPolyData make_blocks_piece(const World& w) {
  VtkPolyData p;
  VtkCells polys;
  polys.index_type = VtkType::Int32;
  polys.ascii_own_line = true;
  for (const Block& b : w.blocks) {
    for (const Vec2& q : b.vertices) {
      polys.connectivity.push_back(static_cast<std::int64_t>(p.points.size()));
      p.points.push_back(q);
    }
    polys.offsets.push_back(static_cast<std::int64_t>(p.points.size()));
  }
  p.polys = std::move(polys);
  std::vector<VtkArray>& cd = p.cell_data;
  std::vector<double> index;
  for (std::size_t i = 0; i < w.blocks.size(); ++i) index.push_back(static_cast<double>(i));
  cd.push_back({"block", VtkType::Int32, 1, {}, index});
  cd.push_back(block_array(w, VtkType::UInt8, "fixed", {"fixed"},
                           [](const Block& b) { return flag(b.fixed); }));
  // A scene with excavation stages: 1 for a block removed (threshold it away in ParaView).
  if (world_excavates(w)) {
    cd.push_back(block_array(w, VtkType::UInt8, "excavated", {"excavated"},
                             [](const Block& b) { return flag(b.excavated); }));
  }
  cd.push_back(block_array(w, VtkType::Float64, "area", {"area"},
                           [](const Block& b) { return std::vector<double>{b.moments.area}; }));
  cd.push_back(block_array(w, VtkType::Float64, "rotation", {"rotation"},
                           [](const Block& b) { return std::vector<double>{b.rotation}; }));
  cd.push_back(block_array(w, VtkType::Float64, "stress", {"sxx", "syy", "sxy"}, [](const Block& b) {
    return std::vector<double>{b.stress[0], b.stress[1], b.stress[2]};
  }));
  cd.push_back(block_array(w, VtkType::Float64, "strain", {"exx", "eyy", "gxy"}, [](const Block& b) {
    return std::vector<double>{b.strain[0], b.strain[1], b.strain[2]};
  }));
  cd.push_back(block_array(w, VtkType::Float64, "velocity", {"vx", "vy", "omega"}, [](const Block& b) {
    return std::vector<double>{b.velocity[kU0], b.velocity[kV0], b.velocity[kR0]};
  }));
  // The material's index in the scene's order (summary.json "materials" names them), and the
  // equivalent plastic strain eps_p of a plastic block (0 for elastic and rigid ones): what
  // dda plot --field material and plastic-strain colour by.
  cd.push_back(block_array(w, VtkType::Int32, "material", {"material"},
                           [](const Block& b) { return std::vector<double>{static_cast<double>(b.material)}; }));
  cd.push_back(block_array(w, VtkType::Float64, "plastic_strain", {"plastic_strain"}, [](const Block& b) {
    return std::vector<double>{b.plastic ? b.material_state.eps_p : 0.0};
  }));
  return p;
}

std::string pvd_text(const std::vector<std::pair<double, std::string>>& frames) {
  std::string s =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [time, file] : frames) {
    s += "    <DataSet timestep=\"" + num(time) + "\" group=\"\" part=\"0\" file=\"" + file +
         "\"/>\n";
  }
  s += "  </Collection>\n</VTKFile>\n";
  return s;
}

// ---- summary.json ----

json vec(const Vec2& v) { return json::array({v.x(), v.y()}); }
json vec(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }

template <class T>
json optional_value(const std::optional<T>& x) {
  return x ? json(*x) : json(nullptr);
}

// A staged run's stages as the run used them (durations, coefficients, gravity, time steps,
// joint overrides, bonding).
json stages_json(const StagePlan& plan) {
  json out = json::array();
  for (const StageSpec& st : plan.stages) {
    json joints = json::object();
    for (const StageJoint& j : st.joint_materials) {
      joints[j.material.name] = {{"friction_angle", j.material.friction_angle},
                                 {"cohesion", j.material.cohesion},
                                 {"tensile_strength", j.material.tensile_strength}};
    }
    json stage = {{"duration", st.duration}, {"dynamic_coefficient", st.dynamic_coefficient}};
    if (st.gravity_ramp) {
      stage["gravity_ramp"] = {st.gravity_from, st.gravity_to};
    } else {
      stage["gravity_factor"] = st.gravity_from;
    }
    stage["time_step"] = st.time_steps;
    stage["joint_materials"] = joints;
    stage["bond_closed_contacts"] = st.bond_closed_contacts;
    out.push_back(stage);
  }
  return out;
}

json settings_json(const World& w) {
  // With stages, the world's gravity and control are the last stage's: report the scene's.
  const bool staged = !w.stages.stages.empty();
  const ControlSettings& c = staged ? w.stages.control : w.control;
  json settings = {
      {"gravity", vec(staged ? w.stages.gravity : w.gravity)},
      {"plane", w.plane == PlaneMode::Strain ? "strain" : "stress"},
      {"time_step", c.time_steps},
      {"steps", optional_value(c.steps)},
      {"end_time", optional_value(c.end_time)},
      {"max_displacement_ratio", c.max_displacement_ratio},
      {"dynamic_coefficient", c.dynamic_coefficient},
      {"rotation_update", rotation_update_name(c.rotation_update)},
      {"penalty", w.penalty},
      {"penalty_rule", c.penalty ? "user" : "auto"},
      {"output_every", c.output_every},
      {"vtk_format", c.vtk_binary ? "binary" : "ascii"},
      {"w0", w.w0},
      {"max_open_close", c.max_open_close},
      {"contact_solver", name_in(kContactSolverNames, c.contact_solver)},
      {"max_augmentations", c.max_augmentations},
      {"allowed_penetration", w.allowed_penetration},
      {"allowed_penetration_rule", c.allowed_penetration ? "user" : "auto"},
      {"search_distance", w.search_distance},
      // Blocks the run solves for; 0 when every block is fixed (then nothing moves).
      {"free_blocks", std::count_if(w.blocks.begin(), w.blocks.end(),
                                    [](const Block& b) { return !b.fixed; })},
      {"energy_tolerance", c.energy_tolerance},
      {"energy_losses", c.stop_on_energy_loss ? "stop" : "report"},
      {"linear_solver", c.reuse_factor ? "reuse" : "factorise"},
      {"inertia", name_in(kInertiaNames, w.pseudo_rigid ? Inertia::PseudoRigid : Inertia::Shi)},
      {"inertia_rule", c.inertia ? "user" : "auto"},
  };
  if (staged) settings["stages"] = stages_json(w.stages);
  return settings;
}

// Per-step means are over accepted steps; a run of zero steps reports zeros.
json per_step(long total, int max, int steps) {
  return {{"mean", steps > 0 ? static_cast<double>(total) / steps : 0.0}, {"max", max}};
}

json block_json(const Block& b, int index) {
  json vertices = json::array();
  for (const Vec2& p : b.vertices) vertices.push_back(vec(p));
  json out = {
      {"index", index},
      {"fixed", b.fixed},
      {"vertices", vertices},
      {"centroid", vec(b.moments.centroid)},
      {"rotation", b.rotation},
      {"area", b.moments.area},
      {"strain", vec(b.strain)},
      {"local_strain", vec(b.local_strain)},
      {"frame_angle", b.rotation},  // the block frame is turned by the total rotation
      {"stress", vec(b.stress)},
      {"velocity", json::array({b.velocity[kU0], b.velocity[kV0], b.velocity[kR0]})},
  };
  if (b.plastic) {
    out["plastic"] = {{"szz", b.szz},
                      {"eps_p", b.material_state.eps_p},
                      {"plastic_strain", json::array({b.material_state.plastic_strain[0],
                                                      b.material_state.plastic_strain[1],
                                                      b.material_state.plastic_strain[2],
                                                      b.material_state.plastic_strain[3]})},
                      {"branch", branch_name(b.branch)}};
  }
  if (b.excavated) out["excavated"] = true;  // removed by an excavation stage
  return out;
}

}  // namespace

VtkPolyData blocks_piece(const World& world) { return make_blocks_piece(world); }

namespace {

// A reused output directory: the files of the kinds a run writes (docs/output-format.md) are
// removed first, so that an earlier, longer run's VTK frames or a monitors.csv this scene
// would not write are not taken for this run's. Nothing else in the directory is touched.
// Only regular files and symbolic links (whose targets stay) are removed: a name of the
// run's that holds anything else (a directory, a device, a FIFO) stops the run before
// anything is removed or written.
void remove_earlier_run(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> earlier;
  const auto take = [&](const fs::path& path) {
    const fs::file_status st = fs::symlink_status(path, ec);
    if (ec || st.type() == fs::file_type::not_found) return;
    if (st.type() != fs::file_type::regular && st.type() != fs::file_type::symlink) {
      fail("a file of the run's is in the way and not a regular file; dda does not replace it:",
           path);
    }
    earlier.push_back(path);
  };
  for (const char* name : {"summary.json", "history.csv", "monitors.csv", "bolts.csv",
                           "blocks.pvd", "contacts.pvd", "bolts.pvd"}) {
    take(dir / name);
  }
  if (fs::exists(fs::symlink_status(dir / "vtk", ec)) && !fs::is_directory(dir / "vtk", ec)) {
    fail("the run's frame directory is in the way and not a directory; dda does not replace it:",
         dir / "vtk");
  }
  if (fs::is_directory(dir / "vtk", ec)) {
    for (const fs::directory_entry& entry : fs::directory_iterator(dir / "vtk", ec)) {
      const std::string name = entry.path().filename().string();
      const bool frame = (name.rfind("step_", 0) == 0 || name.rfind("contacts_", 0) == 0 ||
                          name.rfind("bolts_", 0) == 0) &&
                         entry.path().extension() == ".vtp";
      if (frame) take(entry.path());
    }
  }
  for (const fs::path& path : earlier) {
    fs::remove(path, ec);
    if (ec) fail("cannot remove an earlier run's file (" + ec.message() + ")", path);
  }
}

}  // namespace

OutputWriter::OutputWriter(std::filesystem::path dir, const Scene& scene)
    : dir_(std::move(dir)), scene_(scene) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) fail("cannot create directory (" + ec.message() + ")", dir_);
  remove_earlier_run(dir_);
  fs::create_directories(dir_ / "vtk", ec);
  if (ec) fail("cannot create directory (" + ec.message() + ")", dir_ / "vtk");
  history_.emplace(dir_ / "history.csv", std::string(kHistoryHeader) + "\n");
  if (!scene.monitors.empty()) {
    monitors_.emplace(dir_ / "monitors.csv", std::string(kMonitorsHeader) + "\n");
  }
  if (!scene.bolts.empty()) bolts_.emplace(dir_ / "bolts.csv", std::string(kBoltsHeader) + "\n");
}

namespace {

// The run's frame files in dir/vtk that `keep` does not list: a restarted run's directory
// loses the frames written after its checkpoint's step.
void remove_frames_not_in(const fs::path& dir, const OutputProgress& keep) {
  std::vector<std::string> listed;
  for (const OutputProgress::Frames* frames : {&keep.frames, &keep.contact_frames, &keep.bolt_frames}) {
    for (const auto& frame : *frames) listed.push_back(fs::path(frame.second).filename().string());
  }
  std::error_code ec;
  std::vector<fs::path> gone;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir / "vtk", ec)) {
    const std::string name = entry.path().filename().string();
    const bool frame = (name.rfind("step_", 0) == 0 || name.rfind("contacts_", 0) == 0 ||
                        name.rfind("bolts_", 0) == 0) &&
                       entry.path().extension() == ".vtp";
    if (frame && std::find(listed.begin(), listed.end(), name) == listed.end()) {
      gone.push_back(entry.path());
    }
  }
  for (const fs::path& path : gone) {
    fs::remove(path, ec);
    if (ec) fail("cannot remove a frame written after the checkpoint (" + ec.message() + ")", path);
  }
}

}  // namespace

OutputWriter::OutputWriter(std::filesystem::path dir, const Scene& scene, const OutputProgress& from)
    : dir_(std::move(dir)), scene_(scene) {
  const fs::path history = dir_ / "history.csv";
  std::error_code ec;
  if (!fs::exists(history, ec)) {
    // Another directory: the continuation alone, from fresh files.
    fs::create_directories(dir_, ec);
    if (ec) fail("cannot create directory (" + ec.message() + ")", dir_);
    remove_earlier_run(dir_);
    fs::create_directories(dir_ / "vtk", ec);
    if (ec) fail("cannot create directory (" + ec.message() + ")", dir_ / "vtk");
    history_.emplace(history, std::string(kHistoryHeader) + "\n");
    if (!scene.monitors.empty()) {
      monitors_.emplace(dir_ / "monitors.csv", std::string(kMonitorsHeader) + "\n");
    }
    if (!scene.bolts.empty()) bolts_.emplace(dir_ / "bolts.csv", std::string(kBoltsHeader) + "\n");
    return;
  }
  // The run's own directory: every streamed file must be the one the checkpoint counted.
  const auto check = [&](const fs::path& path, const StreamProgress& at) {
    if (!file_begins_with(path, at)) {
      throw InputError(path.string() +
                       ": not the file of the run this checkpoint continues (it does not begin "
                       "with the rows the checkpoint counted); restart into that run's own "
                       "directory or into one without a history.csv");
    }
  };
  check(history, from.history);
  if (!scene.monitors.empty()) check(dir_ / "monitors.csv", from.monitors);
  if (!scene.bolts.empty()) check(dir_ / "bolts.csv", from.bolts);
  fs::create_directories(dir_ / "vtk", ec);
  if (ec) fail("cannot create directory (" + ec.message() + ")", dir_ / "vtk");
  remove_frames_not_in(dir_, from);
  history_.emplace(history, from.history);
  if (!scene.monitors.empty()) monitors_.emplace(dir_ / "monitors.csv", from.monitors);
  if (!scene.bolts.empty()) bolts_.emplace(dir_ / "bolts.csv", from.bolts);
  frames_ = from.frames;
  contact_frames_ = from.contact_frames;
  bolt_frames_ = from.bolt_frames;
}

OutputProgress OutputWriter::progress() const {
  OutputProgress p;
  p.frames = frames_;
  p.contact_frames = contact_frames_;
  p.bolt_frames = bolt_frames_;
  p.history = history_->progress();
  if (monitors_) p.monitors = monitors_->progress();
  if (bolts_) p.bolts = bolts_->progress();
  return p;
}

bool OutputWriter::due(const World& world) const {
  return world.step % scene_.control.output_every == 0 || is_finished(world);
}

void OutputWriter::record_if_due(const World& world) {
  if (due(world)) record(world);
}

void OutputWriter::record_last(const World& world) {
  if (!due(world)) record(world);
}

void OutputWriter::record(const World& world) {
  // Scene totals, repeated on every block's row of the step (see docs/output-format.md).
  const EnergyTotals energy = scene_energy(world);
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    const double values[] = {b.moments.centroid.x(), b.moments.centroid.y(), b.rotation,
                             b.moments.area,         b.strain[0],            b.strain[1],
                             b.strain[2],            b.stress[0],            b.stress[1],
                             b.stress[2],            b.velocity[kU0],        b.velocity[kV0],
                             b.velocity[kR0],        energy.kinetic,         energy.potential,
                             energy.strain_energy,   energy.contact_energy,
                             world.energy.load_work, world.energy.friction_dissipation,
                             world.energy.plastic_dissipation, world.energy.damping_dissipation,
                             world.energy.remainder, world.energy.multiplier_work};
    history_->append(std::to_string(world.step));
    history_->append(',');
    history_->append(num(world.time));
    history_->append(',');
    history_->append(std::to_string(i));
    for (double v : values) {
      history_->append(',');
      history_->append(num(v));
    }
    history_->append('\n');
  }
  // Written every time, the step's rows at once: a run that dies keeps every whole step
  // written so far, and a write that fails leaves the file at the end of the last one.
  history_->commit();
  if (!world.monitors.empty()) record_monitors(world);
  if (!world.bolts.empty()) record_bolts(world);

  const VtkEncoding encoding = scene_.control.vtk_binary ? VtkEncoding::Binary : VtkEncoding::Ascii;
  const std::string name = frame_name(world.step);
  write_text_file((dir_ / name).string(), vtp_file(blocks_piece(world), encoding));
  // Recording the same step twice (e.g. the final step is also an output step) overwrites
  // the frame; the index lists it once.
  if (frames_.empty() || frames_.back().second != name) frames_.emplace_back(world.time, name);
  write_text_file((dir_ / "blocks.pvd").string(), pvd_text(frames_));

  const std::string contacts = contact_frame_name(world.step);
  write_text_file((dir_ / contacts).string(), contacts_vtp_text(world, encoding));
  if (contact_frames_.empty() || contact_frames_.back().second != contacts) {
    contact_frames_.emplace_back(world.time, contacts);
  }
  write_text_file((dir_ / "contacts.pvd").string(), pvd_text(contact_frames_));

  if (!world.bolts.empty()) {
    const std::string bolts = bolt_frame_name(world.step);
    write_text_file((dir_ / bolts).string(), bolts_vtp_text(world, encoding));
    if (bolt_frames_.empty() || bolt_frames_.back().second != bolts) {
      bolt_frames_.emplace_back(world.time, bolts);
    }
    write_text_file((dir_ / "bolts.pvd").string(), pvd_text(bolt_frames_));
  }
}

Vec2 monitor_velocity(const World& world, const Monitor& monitor) {
  const Block& b = world.blocks[static_cast<std::size_t>(monitor.block)];
  if (b.fixed) return Vec2::Zero();
  return shi_t().at(monitor.current - b.moments.centroid) * b.velocity;
}

// One row per monitor: where its material point is, how far it has moved since the start,
// and its velocity, Shi's first-order T at the point times the block's velocity (u0, v0,
// r0 and the strain rates, end of step; zero for a fixed block).
void OutputWriter::record_monitors(const World& world) {
  for (const Monitor& m : world.monitors) {
    const Vec2 u = m.current - m.initial;
    const Vec2 v = monitor_velocity(world, m);
    monitors_->append(std::to_string(world.step));
    monitors_->append(',');
    monitors_->append(num(world.time));
    monitors_->append(',');
    monitors_->append(m.name);
    for (double x : {m.current.x(), m.current.y(), u.x(), u.y(), v.x(), v.y()}) {
      monitors_->append(',');
      monitors_->append(num(x));
    }
    monitors_->append('\n');
  }
  monitors_->commit();
}

// One row per bolt: its axial force (tension positive), the plastic extension it has
// yielded, whether it has broken, and the distance between its ends now.
void OutputWriter::record_bolts(const World& world) {
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    const Bolt& bolt = world.bolts[i];
    const double length = (world.bolt_ends[2 * i + 1].current - world.bolt_ends[2 * i].current).norm();
    bolts_->append(std::to_string(world.step));
    bolts_->append(',');
    bolts_->append(num(world.time));
    bolts_->append(',');
    bolts_->append(bolt.name);
    bolts_->append(',');
    bolts_->append(num(bolt.force));
    bolts_->append(',');
    bolts_->append(num(bolt.plastic_extension));
    bolts_->append(bolt.broken ? ",1," : ",0,");
    bolts_->append(num(length));
    bolts_->append('\n');
  }
  bolts_->commit();
}

namespace {
// The bolts at the end (empty without bolts): each one's force, yield and rupture.
json bolts_json(const World& world) {
  json out = json::array();
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    const Bolt& b = world.bolts[i];
    json entry = {{"name", b.name},
                  {"force", b.force},
                  {"plastic_extension", b.plastic_extension},
                  {"yielding", bolt_yielding(b)},
                  {"broken", b.broken}};
    if (b.broken) entry["broken_at"] = b.broken_at;
    out.push_back(entry);
  }
  return out;
}

// The stages entered (empty without stages): where each began and the bonds it formed.
json stages_run_json(const World& world) {
  const StagePlan& plan = world.stages;
  json out = json::array();
  for (std::size_t k = 0; k < plan.start_steps.size(); ++k) {
    out.push_back({{"index", k},
                   {"start_step", plan.start_steps[k]},
                   {"start_time", k == 0 ? 0.0 : plan.end_times[k - 1]},
                   {"bonds_formed", k < plan.bonds_formed.size() ? plan.bonds_formed[k] : 0}});
  }
  return out;
}

// The energy account at the end (docs/output-format.md, docs/energy-balance.md).
json energy_json(const World& world) {
  const EnergyTotals e = scene_energy(world);
  const EnergyLedger& led = world.energy;
  json out = {{"scale", led.scale},
          {"initial_total", led.initial_total},
          {"kinetic", e.kinetic},
          {"potential", e.potential},
          {"strain_energy", e.strain_energy},
          {"contact_energy", e.contact_energy},
          {"load_work", led.load_work},
          {"multiplier_work", led.multiplier_work},
          {"friction_dissipation", led.friction_dissipation},
          {"plastic_dissipation", led.plastic_dissipation},
          {"damping_dissipation", led.damping_dissipation},
          {"friction_gain", led.friction_gain},
          {"remainder", led.remainder},
          {"remainder_max", led.remainder_max},
          {"remainder_max_step", led.remainder_max_step},
          {"remainder_max_share", led.scale > 0.0 ? led.remainder_max / led.scale : 0.0},
          {"remainder_min", led.remainder_min},
          {"remainder_min_step", led.remainder_min_step},
          {"remainder_min_share", led.scale > 0.0 ? led.remainder_min / led.scale : 0.0},
          {"losses_beyond_tolerance", energy_lost_beyond(led, world.control.energy_tolerance)}};
  // What excavated blocks took away (a scene with excavation stages only).
  if (world_excavates(world)) out["excavation"] = led.excavation;
  return out;
}
}  // namespace

void OutputWriter::finish(const World& world, const RunStats& stats) {
  write_text_file((dir_ / "blocks.pvd").string(), pvd_text(frames_));
  write_text_file((dir_ / "contacts.pvd").string(), pvd_text(contact_frames_));
  if (!world.bolts.empty()) write_text_file((dir_ / "bolts.pvd").string(), pvd_text(bolt_frames_));
  json modes = json::object();
  const std::vector<ContactModeCounts> counts =
      contact_modes_by_joint(world, scene_.joint_materials.size());
  for (std::size_t j = 0; j < counts.size(); ++j) {
    modes[scene_.joint_materials[j].name] = {{"open", counts[j].open},
                                             {"slide", counts[j].slide},
                                             {"lock", counts[j].lock},
                                             {"bonded", counts[j].bonded}};
  }

  json blocks = json::array();
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    blocks.push_back(block_json(world.blocks[i], static_cast<int>(i)));
  }
  json settings = settings_json(world);
  json laws = json::object();  // which joint law each joint material uses
  for (const JointMaterial& j : scene_.joint_materials) {
    laws[j.name] = joint_law_name(j.law);
  }
  settings["joint_laws"] = laws;
  json summary = {
      {"scene", scene_.source},
      {"settings", settings},
      {"wall_time_s", stats.wall_time_s},
      {"steps", stats.steps},
      {"cut_steps", stats.cut_steps},
      {"cuts", {{"displacement", stats.cuts_for_displacement},
                {"open_close", stats.cuts_for_open_close},
                {"penetration", stats.cuts_for_penetration},
                {"material", stats.cuts_for_material},
                {"overshoot", stats.cuts_for_overshoot}}},
      // The accepted steps' lengths (RunStats): after a cut the step size remembers the step
      // that worked (solver/step.cpp), so a schedule too long for the scene shows here.
      {"time_steps_taken", {{"smallest", stats.smallest_time_step},
                            {"largest", stats.largest_time_step},
                            {"below_schedule", stats.steps_below_schedule}}},
      {"iterations", stats.iterations},
      {"open_close_iterations", per_step(stats.open_close_total, stats.open_close_max, stats.steps)},
      {"contacts", {{"final", stats.contacts_final},
                    {"mean", per_step(stats.contacts_total, stats.contacts_max, stats.steps)["mean"]},
                    {"max", stats.contacts_max},
                    {"deepest_penetration", stats.deepest_penetration},
                    {"largest_normal_force", stats.largest_normal_force},
                    {"candidate_pairs_max", stats.candidate_pairs_max},
                    {"modes_by_joint_material", modes}}},
      // The penalty stays as the scene sets it (raising it while contacts were loaded put
      // energy into them); the key stays in the format for the scripts that read it.
      {"penalty_raises", 0},
      {"augmentations", stats.augmentations},
      {"bonds_broken", stats.bonds_broken},
      {"contact_solver", {{"line_searches_shortened", stats.line_searches_shortened},
                          {"unconverged_mismatch", stats.newton_unconverged_mismatch},
                          {"accepted_unconverged", stats.newton_accepted_unconverged},
                          {"held_open", stats.newton_held_open},
                          {"local_secant_settles", stats.local_secant_settles}}},
      {"energy", energy_json(world)},
      {"stages_run", stages_run_json(world)},
      {"end_time", world.time},
      {"diverged", stats.diverged},
      {"message", stats.message},
      // Stopped by SIGINT or SIGTERM before its end (then also "message" says so).
      {"interrupted", stats.interrupted},
      {"blocks", blocks},
  };
  // The block materials' names in the scene's order: the VTK frames' "material" indices.
  json materials = json::array();
  for (const Material& m : scene_.materials) materials.push_back(m.name);
  summary["materials"] = materials;
  // The bolts' end state: only for a scene that has bolts (as bolts.csv).
  if (!world.bolts.empty()) summary["bolts"] = bolts_json(world);
  // Replace rather than throw on invalid UTF-8 (a scene path or message from the system).
  write_text_file((dir_ / "summary.json").string(),
                  summary.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace dda
