#include "io/run_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "common/printf_text.hpp"
#include "io/colour_maps.hpp"
#include "io/vtk_reader.hpp"
#include "kinematics/polygon.hpp"

namespace dda {
namespace {

namespace fs = std::filesystem;

constexpr Rgb kFixedGrey{190, 190, 190};
constexpr Rgb kFreePale{235, 235, 235};
constexpr Rgb kStart{246, 246, 246};  // a block's place at the start, under it now
constexpr Rgb kArrowRed{200, 0, 0};
// Joint states: blue locked, red sliding, light grey-blue open, green bonded (tab10's).
constexpr Rgb kLocked{31, 119, 180};
constexpr Rgb kSliding{214, 39, 40};
constexpr Rgb kOpen{170, 190, 210};
constexpr Rgb kBonded{44, 160, 44};
constexpr Rgb kChain{60, 60, 60};

// Every picture plot_run may write.
constexpr const char* kPictureNames[] = {"blocks.png", "joint_states.png", "force_chains.png", "energy.png",
                                         "monitors.png"};

// How many blocks get an arrow: beyond this a large slope's picture is a smear.
constexpr std::size_t kArrowsDrawn = 80;

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
  throw std::runtime_error("plot: " + file.string() + ": " + what);
}

std::string read_whole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The (timestep, file) pairs of a .pvd collection, as io/output writes them.
std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& file) {
  const std::string text = read_whole(file);
  static const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)")re");
  std::vector<std::pair<double, std::string>> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset); it != std::sregex_iterator(); ++it) {
    try {
      out.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
    } catch (const std::exception&) {
      fail(file, "a timestep is not a number: \"" + (*it)[1].str() + "\"");
    }
  }
  return out;
}

// Per block: fixed, excavated, and the polygon. Cell arrays by name, or a clear error.
const VtkArray& cell_array(const VtkPolyData& d, const std::string& name, const std::string& what) {
  const VtkArray* a = d.find_cell_array(name);
  if (a == nullptr) throw std::invalid_argument("plot: the run's block frames carry no \"" + name + "\" array" + what);
  return *a;
}

bool flag(const VtkPolyData& d, const char* name, std::size_t i) {
  const VtkArray* a = d.find_cell_array(name);
  return a != nullptr && a->at(i) != 0.0;
}

// A polygon's centroid, as polygon_moments gives it but safe for what a file may hold:
// a polygon of fewer than three points or of no area gives a point of its own (its first)
// rather than an assertion or a division by zero.
Vec2 centroid(const std::vector<Vec2>& p) {
  double a = 0.0;
  Vec2 c = Vec2::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    const double cross = u.x() * v.y() - v.x() * u.y();
    a += cross;
    c += cross * (u + v);
  }
  if (std::abs(a) < 1e-300) return p.empty() ? Vec2::Zero() : p.front();
  return c / (3.0 * a);
}

// The square root of the median area of the free blocks still there (of all, if none is
// free): the typical block size the exaggeration and the arrows are scaled to.
double typical_size(const VtkPolyData& d) {
  std::vector<double> areas, all;
  const std::size_t n = d.polys ? d.polys->size() : 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (flag(d, "excavated", i)) continue;
    const double a = std::abs(signed_area(d.polygon(i)));
    all.push_back(a);
    if (!flag(d, "fixed", i)) areas.push_back(a);
  }
  std::vector<double>& use = areas.empty() ? all : areas;
  if (use.empty()) return 1.0;
  std::nth_element(use.begin(), use.begin() + static_cast<std::ptrdiff_t>(use.size() / 2), use.end());
  return std::sqrt(use[use.size() / 2]);
}

// The round number (1, 2 or 5 x 10^k) nearest `x` on a log scale.
double round_number(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  double best = p;
  for (double k : {1.0, 2.0, 5.0, 10.0})
    if (std::abs(std::log(k * p / x)) < std::abs(std::log(best / x))) best = k * p;
  return best;
}

std::string time_text(double t) { return printf_text(t, "%.4g"); }

std::vector<PictureBlock> pale_blocks(const VtkPolyData& d) {
  std::vector<PictureBlock> out;
  const std::size_t n = d.polys ? d.polys->size() : 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (flag(d, "excavated", i)) continue;
    out.push_back({d.polygon(i), flag(d, "fixed", i) ? kFixedGrey : kFreePale});
  }
  return out;
}

std::vector<std::string> material_names_of(const fs::path& summary) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::exists(summary, ec)) return names;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_whole(summary));
    if (j.contains("materials") && j["materials"].is_array())
      for (const auto& m : j["materials"]) names.push_back(m.is_string() ? m.get<std::string>() : m.dump());
  } catch (const nlohmann::json::exception& e) {
    fail(summary, std::string("is not valid JSON: ") + e.what());
  }
  return names;
}

}  // namespace

PlotField plot_field_from_name(const std::string& name) {
  static const std::map<std::string, PlotField> names = {
      {"displacement", PlotField::Displacement}, {"velocity", PlotField::Velocity},
      {"stress", PlotField::Stress}, {"plastic-strain", PlotField::PlasticStrain},
      {"material", PlotField::Material}};
  const auto it = names.find(name);
  if (it == names.end())
    throw std::invalid_argument("plot: unknown field \"" + name +
                                "\"; the fields are displacement, velocity, stress, plastic-strain, material");
  return it->second;
}

std::vector<RunFrame> run_frames(const fs::path& run_dir) {
  const fs::path blocks = run_dir / "blocks.pvd";
  std::error_code ec;
  if (!fs::exists(blocks, ec)) fail(blocks, "not found (is this the output directory of dda run?)");
  std::vector<RunFrame> frames;
  for (const auto& [t, file] : pvd_entries(blocks)) frames.push_back({t, file, ""});
  if (frames.empty()) fail(blocks, "lists no frame");
  const fs::path contacts = run_dir / "contacts.pvd";
  if (fs::exists(contacts, ec)) {
    const auto entries = pvd_entries(contacts);
    for (RunFrame& f : frames)
      for (const auto& [t, file] : entries)
        if (t == f.time) f.contacts_file = file;
  }
  return frames;
}

BlocksPicture blocks_picture(const VtkPolyData& start, const VtkPolyData& now, double time,
                             const PlotOptions& options, const std::vector<std::string>& material_names) {
  if (!now.polys || !start.polys || now.polys->size() != start.polys->size())
    throw std::invalid_argument("plot: the first and the chosen frame hold different blocks");
  const std::size_t n = now.polys->size();
  // Per block: the vertices' displacements and the centroid's.
  std::vector<std::vector<Vec2>> from(n), to(n);
  std::vector<Vec2> u(n, Vec2::Zero());
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    from[i] = start.polygon(i);
    to[i] = now.polygon(i);
    if (from[i].size() != to[i].size())
      throw std::invalid_argument("plot: block " + std::to_string(i) + " has a different vertex count in the first frame");
    u[i] = centroid(to[i]) - centroid(from[i]);
    if (flag(now, "excavated", i)) continue;
    for (std::size_t k = 0; k < to[i].size(); ++k) largest = std::max(largest, (to[i][k] - from[i][k]).norm());
  }
  const double size = typical_size(start);
  BlocksPicture p;
  p.exaggeration = options.exaggeration ? *options.exaggeration
                   : (largest > 0.0 && largest < 0.05 * size) ? round_number(0.25 * size / largest)
                                                              : 1.0;
  const double x = p.exaggeration;

  // The colouring: a value per block and its bar, or a category per block.
  std::vector<double> value(n, 0.0);
  std::string bar_label;
  switch (options.field) {
    case PlotField::Displacement:
      for (std::size_t i = 0; i < n; ++i) value[i] = u[i].norm();
      bar_label = "displacement of the centroid since the start (m)";
      break;
    case PlotField::Velocity: {
      const VtkArray& v = cell_array(now, "velocity", "");
      for (std::size_t i = 0; i < n; ++i) value[i] = std::hypot(v.at(i, 0), v.at(i, 1));
      bar_label = "speed of the centroid (m/s)";
      break;
    }
    case PlotField::Stress: {
      const VtkArray& s = cell_array(now, "stress", "");
      // The in-plane maximum shear stress, an invariant of the plane stress state:
      // sqrt(((sxx - syy) / 2)^2 + sxy^2).
      for (std::size_t i = 0; i < n; ++i) value[i] = std::hypot(0.5 * (s.at(i, 0) - s.at(i, 1)), s.at(i, 2));
      bar_label = "in-plane maximum shear stress (Pa)";
      break;
    }
    case PlotField::PlasticStrain: {
      const VtkArray& e = cell_array(now, "plastic_strain", " (frames written by an earlier version)");
      for (std::size_t i = 0; i < n; ++i) value[i] = e.at(i);
      bar_label = "equivalent plastic strain";
      break;
    }
    case PlotField::Material:
      cell_array(now, "material", " (frames written by an earlier version)");
      break;
  }
  double top = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (!flag(now, "fixed", i) && !flag(now, "excavated", i)) top = std::max(top, value[i]);

  // Where the free blocks started, pale under the blocks now, when the drawn motion is
  // large enough to take a block off its place (half a typical block): a newcomer sees
  // where things came from.
  const bool ghosts = x * largest > 0.5 * size;
  if (ghosts)
    for (std::size_t i = 0; i < n; ++i)
      if (!flag(now, "fixed", i) && !flag(now, "excavated", i)) p.blocks.push_back({from[i], kStart});
  std::vector<int> materials_seen;
  for (std::size_t i = 0; i < n; ++i) {
    if (flag(now, "excavated", i)) continue;
    std::vector<Vec2> drawn(to[i].size());
    for (std::size_t k = 0; k < drawn.size(); ++k) drawn[k] = from[i][k] + x * (to[i][k] - from[i][k]);
    Rgb colour = kFixedGrey;
    if (options.field == PlotField::Material) {
      const int m = static_cast<int>(now.find_cell_array("material")->at(i));
      colour = category_colour(m);
      if (std::find(materials_seen.begin(), materials_seen.end(), m) == materials_seen.end()) materials_seen.push_back(m);
    } else if (!flag(now, "fixed", i)) {
      colour = sequential_colour(top > 0.0 ? value[i] / top : 0.0);
    }
    p.blocks.push_back({std::move(drawn), colour});
  }

  PictureOptions& o = p.options;
  o.width_px = options.width_px;
  o.axes = true;
  // Arrows along the largest displacements, from the drawn centroid, the largest 0.8 of a
  // typical block long; only blocks that moved more than a tenth of the largest.
  std::vector<std::size_t> order;
  double u_top = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (!flag(now, "fixed", i) && !flag(now, "excavated", i)) order.push_back(i), u_top = std::max(u_top, u[i].norm());
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return u[a].norm() > u[b].norm(); });
  for (std::size_t k = 0; k < order.size() && k < kArrowsDrawn && u_top > 0.0; ++k) {
    const std::size_t i = order[k];
    if (u[i].norm() <= 0.1 * u_top) break;
    const Vec2 c = centroid(from[i]) + x * u[i];
    o.arrows.push_back({c, c + 0.8 * size * u[i] / u_top, kArrowRed});
  }
  const char* field_name = options.field == PlotField::Displacement ? "displacement"
                           : options.field == PlotField::Velocity    ? "speed"
                           : options.field == PlotField::Stress      ? "maximum shear stress"
                           : options.field == PlotField::PlasticStrain ? "plastic strain"
                                                                       : "material";
  o.title = "blocks at t = " + time_text(time) + " s, coloured by " + field_name + "; displacement drawn x" +
            printf_text(x, "%g") + ", largest at a vertex " + printf_text(largest, "%.3g") + " m";
  if (options.field == PlotField::Material) {
    std::sort(materials_seen.begin(), materials_seen.end());
    for (int m : materials_seen) {
      const std::string name = m >= 0 && static_cast<std::size_t>(m) < material_names.size()
                                   ? material_names[static_cast<std::size_t>(m)]
                                   : "material " + std::to_string(m);
      o.legend.push_back({name, category_colour(m)});
    }
  } else {
    o.legend.push_back({"fixed block", kFixedGrey});
    o.colour_bar = ColourBar{bar_label, 0.0, top};
  }
  if (ghosts) o.legend.push_back({"start position", kStart});
  if (!o.arrows.empty()) o.legend.push_back({"displacement direction", kArrowRed});
  return p;
}

namespace {

// The blocks of `now`, pale (fixed ones grey), with axes: what the contacts are drawn over.
BlocksPicture pale_picture(const VtkPolyData& now, int width_px) {
  BlocksPicture p;
  p.blocks = pale_blocks(now);
  p.options.width_px = width_px;
  p.options.axes = true;
  return p;
}

}  // namespace

BlocksPicture joint_states_picture(const VtkPolyData& now, const VtkPolyData& contacts, double time,
                                   int width_px) {
  BlocksPicture p = pale_picture(now, width_px);
  PictureOptions& o = p.options;
  const VtkArray* mode = contacts.find_point_array("mode");
  const VtkArray* bonded = contacts.find_point_array("bonded");
  if (mode == nullptr || bonded == nullptr)
    throw std::invalid_argument("plot: the contacts frame carries no mode or bonded array");
  int counts[4] = {0, 0, 0, 0};  // open, sliding, locked, bonded
  // A square of 5 px (a third of a percent of the width, at least) at each contact.
  const double half = std::max(2.0, width_px / 600.0 + 1.0);
  for (std::size_t i = 0; i < contacts.points.size(); ++i) {
    const int state = bonded->at(i) != 0.0 ? 3 : static_cast<int>(mode->at(i)) == 0 ? 0
                                              : static_cast<int>(mode->at(i)) == 1 ? 1
                                                                                   : 2;
    ++counts[state];
    const Rgb colour = state == 0 ? kOpen : state == 1 ? kSliding : state == 2 ? kLocked : kBonded;
    // A line of no length: only its end squares, 2 half wide, are drawn.
    o.lines.push_back({contacts.points[i], contacts.points[i], colour, 2.0 * half});
  }
  o.title = "joint states at t = " + time_text(time) + " s: " + std::to_string(contacts.points.size()) + " contacts";
  o.legend = {{"open " + std::to_string(counts[0]), kOpen},
              {"sliding " + std::to_string(counts[1]), kSliding},
              {"locked " + std::to_string(counts[2]), kLocked},
              {"bonded " + std::to_string(counts[3]), kBonded},
              {"fixed block", kFixedGrey}};
  return p;
}

BlocksPicture force_chain_picture(const VtkPolyData& now, const VtkPolyData& contacts, double time,
                                  int width_px) {
  BlocksPicture p = pale_picture(now, width_px);
  PictureOptions& o = p.options;
  const VtkArray* normal = contacts.find_point_array("normal_force");
  const VtkArray* a = contacts.find_point_array("vertex_block");
  const VtkArray* b = contacts.find_point_array("edge_block");
  if (normal == nullptr || a == nullptr || b == nullptr)
    throw std::invalid_argument("plot: the contacts frame carries no normal_force, vertex_block or edge_block array");
  std::map<std::pair<int, int>, double> pairs;  // (lower, higher block) -> sum of N
  for (std::size_t i = 0; i < contacts.points.size(); ++i) {
    if (normal->at(i) <= 0.0) continue;  // compression positive
    const int i0 = static_cast<int>(a->at(i)), i1 = static_cast<int>(b->at(i));
    pairs[{std::min(i0, i1), std::max(i0, i1)}] += normal->at(i);
  }
  double top = 0.0;
  for (const auto& [key, n] : pairs) top = std::max(top, n);
  const std::size_t blocks = now.polys ? now.polys->size() : 0;
  std::vector<std::pair<double, std::pair<int, int>>> by_force;
  for (const auto& [key, n] : pairs) by_force.push_back({n, key});
  std::sort(by_force.begin(), by_force.end());  // the strongest drawn last, on top
  for (const auto& [n, key] : by_force) {
    if (key.first < 0 || static_cast<std::size_t>(key.second) >= blocks) continue;
    const Vec2 c0 = centroid(now.polygon(static_cast<std::size_t>(key.first)));
    const Vec2 c1 = centroid(now.polygon(static_cast<std::size_t>(key.second)));
    o.lines.push_back({c0, c1, kChain, 1.0 + 9.0 * n / top});
  }
  o.title = "force chains at t = " + time_text(time) + " s: line width by the normal force between two blocks, " +
            "the largest " + printf_text(top, "%.3g") + " N/m (10 px)";
  o.legend = {{"fixed block", kFixedGrey}, {"compression between two blocks", kChain}};
  return p;
}

std::vector<fs::path> plot_run(const fs::path& run_dir, const fs::path& out_dir, const PlotOptions& options) {
  const std::vector<RunFrame> frames = run_frames(run_dir);
  // The frames chosen: the last at or before each time asked, in the order asked.
  std::vector<std::size_t> chosen;
  for (double t : options.times) {
    if (t < frames.front().time)
      throw std::invalid_argument("plot: --time " + printf_text(t, "%g") + " s is before the first frame (" +
                                  printf_text(frames.front().time, "%g") + " s)");
    std::size_t k = frames.size() - 1;
    while (k > 0 && frames[k].time > t) --k;
    chosen.push_back(k);
  }
  if (chosen.empty()) chosen.push_back(frames.size() - 1);
  const VtkPolyData start = read_vtp(run_dir / frames.front().blocks_file);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) fail(out_dir, "cannot be created: " + ec.message());
  // An earlier plot's pictures go first: a monitors.png this run would not draw is not
  // taken for this run's. Only these names (and theirs at a time), only regular files.
  for (const fs::directory_entry& e : fs::directory_iterator(out_dir, ec)) {
    const std::string name = e.path().filename().string();
    bool ours = false;
    for (const char* p : kPictureNames) {
      const std::string stem = fs::path(p).stem().string();
      ours = ours || name == p || (name.rfind(stem + "_t", 0) == 0 && e.path().extension() == ".png");
    }
    if (ours && fs::is_regular_file(fs::symlink_status(e.path(), ec))) fs::remove(e.path(), ec);
  }

  std::vector<fs::path> written;
  const auto blocks = [&](const std::string& name, const BlocksPicture& p) {
    const fs::path path = out_dir / name;
    write_block_picture(path.string(), p.blocks, p.options);
    written.push_back(path);
  };
  const std::vector<std::string> materials = material_names_of(run_dir / "summary.json");
  PlotOptions each = options;
  if (chosen.size() > 1 && !each.exaggeration) {  // one scale for all: the last frame's
    const std::size_t last = chosen.back();
    each.exaggeration = blocks_picture(start, last == 0 ? start : read_vtp(run_dir / frames[last].blocks_file),
                                       frames[last].time, options, materials).exaggeration;
  }
  for (std::size_t k : chosen) {
    const RunFrame& f = frames[k];
    const std::string suffix = chosen.size() > 1 ? "_t" + printf_text(f.time, "%g") : "";
    const VtkPolyData now = k == 0 ? start : read_vtp(run_dir / f.blocks_file);
    blocks("blocks" + suffix + ".png", blocks_picture(start, now, f.time, each, materials));
    if (!f.contacts_file.empty()) {
      const VtkPolyData contacts = read_vtp(run_dir / f.contacts_file);
      blocks("joint_states" + suffix + ".png", joint_states_picture(now, contacts, f.time, options.width_px));
      blocks("force_chains" + suffix + ".png", force_chain_picture(now, contacts, f.time, options.width_px));
    }
  }
  const fs::path history = run_dir / "history.csv";
  if (fs::exists(history, ec)) {
    write_chart((out_dir / "energy.png").string(), energy_chart(history));
    written.push_back(out_dir / "energy.png");
  }
  const fs::path monitors = run_dir / "monitors.csv";
  if (fs::exists(monitors, ec)) {
    write_chart((out_dir / "monitors.png").string(), monitors_chart(monitors));
    written.push_back(out_dir / "monitors.png");
  }
  return written;
}

}  // namespace dda
