#include "io/fos_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "common/printf_text.hpp"
#include "io/block_picture.hpp"
#include "io/chart.hpp"
#include "kinematics/polygon.hpp"
#include "studies/trial_mechanism.hpp"

namespace dda {
namespace {

constexpr Rgb kFixedGrey{190, 190, 190};
constexpr Rgb kFreePale{235, 235, 235};
constexpr Rgb kMovingOutline{120, 0, 0};  // dark red: apart from viridis and the grey blocks
constexpr Rgb kArrowRed{200, 0, 0};

// The block's polygon moved rigidly by the displacement u of its centroid and the small
// rotation theta about it: each vertex p to p + u + theta x (p - c). The pictures draw
// motions multiplied to be seen with it.
Polygon moved_rigidly(const Block& b, const Vec2& u, double theta) {
  Polygon p = b.vertices;
  for (Vec2& v : p) {
    const Vec2 r = v - b.moments.centroid;
    v += u + theta * Vec2(-r.y(), r.x());
  }
  return p;
}

// How many of a trial's moving blocks get an arrow, and how many a number: beyond these the
// picture of a 2000-block slope is a smear; the report lists them all.
constexpr std::size_t kArrowsDrawn = 60;
constexpr std::size_t kNumbersDrawn = 25;

// Every block that is still there where `world` has it: fixed grey, free pale.
std::vector<PictureBlock> slope_blocks(const World& world) {
  std::vector<PictureBlock> blocks;
  for (const Block& b : world.blocks) {
    if (b.excavated) continue;  // gone
    blocks.push_back({b.vertices, b.fixed ? kFixedGrey : kFreePale});
  }
  return blocks;
}

// The bolts not broken, as lines between their ends where `world` has them.
void add_bolt_lines(const World& world, PictureOptions& options) {
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    if (world.bolts[i].broken) continue;
    options.lines.push_back({world.bolt_ends[2 * i].current, world.bolt_ends[2 * i + 1].current});
  }
}

// The sizes shared by the slope pictures: 1600 px wide with axes, block numbers at the
// title's size so that they read on a 2000-block slope.
PictureOptions slope_options() {
  PictureOptions options;
  options.width_px = 1600;
  options.axes = true;
  options.label_scale = 2;
  return options;
}

// The box of both, and whether a point lies in a box (kinematics/polygon's Box).
Box joined(const Box& a, const Box& b) { return {a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)}; }
bool inside(const Box& b, const Vec2& p) {
  return (p.array() >= b.min.array()).all() && (p.array() <= b.max.array()).all();
}

Vec2 vertex_mean(const Polygon& p) {
  Vec2 m = Vec2::Zero();
  for (const Vec2& v : p) m += v;
  return p.empty() ? m : Vec2(m / static_cast<double>(p.size()));
}

// NAME_close.png beside NAME.png, when there is a close-up to draw.
void write_close_up(const std::filesystem::path& path, const SlopePicture& whole) {
  std::filesystem::path out = path;
  out.replace_filename(path.stem().string() + "_close" + path.extension().string());
  const std::optional<SlopePicture> close = close_up(whole);
  if (close) {
    write_block_picture(out.string(), close->blocks, close->options);
  } else {  // an earlier search's close-up is not this one's
    std::error_code ec;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(out, ec))) std::filesystem::remove(out, ec);
  }
}

}  // namespace

std::optional<SlopePicture> close_up(const SlopePicture& whole) {
  if (whole.moving_from >= whole.blocks.size()) return std::nullopt;
  const Box none{Vec2::Constant(INFINITY), Vec2::Constant(-INFINITY)};
  Box slope = none, moving = none;
  for (std::size_t i = 0; i < whole.blocks.size(); ++i) {
    Box& b = i < whole.moving_from ? slope : moving;
    b = joined(b, bounding_box(whole.blocks[i].polygon));
  }
  const Vec2 slope_size = slope.max - slope.min, moving_size = moving.max - moving.min;
  if (moving_size.x() >= 0.4 * slope_size.x() || moving_size.y() >= 0.4 * slope_size.y()) return std::nullopt;
  const double grow = std::max({moving_size.x(), moving_size.y(), 3.0 * whole.typical_size});
  const Box region{moving.min - Vec2::Constant(grow), moving.max + Vec2::Constant(grow)};
  SlopePicture close;
  close.typical_size = whole.typical_size;
  close.options = whole.options;
  close.options.arrows.clear();
  close.options.labels.clear();
  for (std::size_t i = 0; i < whole.moving_from; ++i)
    if (inside(region, vertex_mean(whole.blocks[i].polygon))) close.blocks.push_back(whole.blocks[i]);
  close.moving_from = close.blocks.size();
  close.blocks.insert(close.blocks.end(), whole.blocks.begin() + static_cast<std::ptrdiff_t>(whole.moving_from),
                      whole.blocks.end());
  for (const PictureArrow& a : whole.options.arrows)
    if (inside(region, a.from)) close.options.arrows.push_back(a);
  for (const PictureLabel& l : whole.options.labels)
    if (inside(region, l.at)) close.options.labels.push_back(l);
  std::erase_if(close.options.lines, [&](const PictureLine& l) { return !inside(region, l.from) && !inside(region, l.to); });
  close.options.title = "close-up: " + whole.options.title;
  return close;
}

SlopePicture mechanism_picture(const World& consolidated, const TrialResult& t, const std::string& what) {
  const std::vector<BlockMotion> moved = moved_blocks(consolidated, t.world);
  const double largest = moved.empty() ? 0.0 : moved.front().displacement.norm();
  const double typical = std::sqrt(median_free_block_area(consolidated));
  const double shown = 0.25 * typical;
  const double x = largest > 0.0 ? shown / largest : 0.0;
  std::vector<PictureBlock> blocks = slope_blocks(consolidated);
  const std::size_t moving_from = blocks.size();
  PictureOptions options = slope_options();
  add_bolt_lines(t.world, options);
  for (auto it = moved.rbegin(); it != moved.rend(); ++it) {  // the largest on top
    const Block& b = consolidated.blocks[static_cast<std::size_t>(it->block)];
    blocks.push_back({moved_rigidly(b, x * it->displacement, x * it->rotation),
                      sequential_colour(it->displacement.norm() / largest), kMovingOutline, 3.0});
  }
  // The arrows are longer than the drawn displacement (the largest 0.8 of a typical block)
  // so that their direction reads at a slope's scale.
  for (std::size_t k = 0; k < moved.size() && k < kArrowsDrawn; ++k) {
    const Vec2 c = consolidated.blocks[static_cast<std::size_t>(moved[k].block)].moments.centroid;
    options.arrows.push_back({c, c + 3.2 * x * moved[k].displacement, kArrowRed});
  }
  for (std::size_t k = 0; k < moved.size() && k < kNumbersDrawn; ++k) {  // on the moved block
    const Vec2 c = consolidated.blocks[static_cast<std::size_t>(moved[k].block)].moments.centroid;
    options.labels.push_back({c + x * moved[k].displacement, std::to_string(moved[k].block), Rgb{0, 0, 0}});
  }
  options.title = what + ": F = " + printf_text(t.factor, "%.4f") + ", " +
                  (t.stable ? "stable" : "failing") + " (" + t.verdict + "); " +
                  std::to_string(moved.size()) + " blocks moved, drawn x" + printf_text(x, "%.3g") +
                  (moved.empty() ? std::string()
                                 : ", block " + std::to_string(moved.front().block) + " most");
  options.legend = {{"fixed block", kFixedGrey}, {"free block at rest", kFreePale},
                    {"moving block (outlined, displaced x" + printf_text(x, "%.3g") + ")", kMovingOutline},
                    {"displacement direction", kArrowRed}};
  options.colour_bar = ColourBar{"displacement in the trial (m)", 0.0, largest};
  return {std::move(blocks), std::move(options), moving_from, typical};
}

void write_mechanism_picture(const std::filesystem::path& path, const World& consolidated,
                             const TrialResult& trial, const std::string& what) {
  const SlopePicture p = mechanism_picture(consolidated, trial, what);
  write_block_picture(path.string(), p.blocks, p.options);
  write_close_up(path, p);
}

SlopePicture limit_analysis_picture(const World& world, const LimitAnalysisResult& la) {
  // (A mechanism has free blocks, so the median exists.)
  const double typical = std::sqrt(median_free_block_area(world));
  const double shown = 0.25 * typical;
  std::vector<PictureBlock> blocks = slope_blocks(world);
  const std::size_t moving_from = blocks.size();
  for (auto it = la.mechanism.rbegin(); it != la.mechanism.rend(); ++it) {  // fastest on top
    const Block& b = world.blocks[static_cast<std::size_t>(it->block)];
    blocks.push_back({moved_rigidly(b, shown * it->velocity, shown * it->angular_velocity),
                      sequential_colour(it->velocity.norm()), kMovingOutline, 3.0});
  }
  PictureOptions options = slope_options();
  add_bolt_lines(world, options);
  options.title = "limit-analysis mechanism at F = " + printf_text(la.upper, "%.4f") +
                  " (rigid motion exaggerated: the fastest block moved " + printf_text(shown, "%.3g") +
                  " m)";
  options.legend = {{"fixed block", kFixedGrey}, {"free block at rest", kFreePale},
                    {"block of the mechanism (outlined)", kMovingOutline}};
  options.colour_bar = ColourBar{"speed, share of the fastest block's", 0.0, 1.0};
  return {std::move(blocks), std::move(options), moving_from, typical};
}

void write_limit_analysis_picture(const std::filesystem::path& path, const World& world,
                                  const LimitAnalysisResult& la) {
  if (la.mechanism.empty()) return;
  const SlopePicture p = limit_analysis_picture(world, la);
  write_block_picture(path.string(), p.blocks, p.options);
  write_close_up(path, p);
}

ChartOptions trials_chart(const FosResult& result, double failure_displacement, const LimitAnalysisResult* la) {
  ChartSeries stable, failing, limit;
  stable.label = "stable trial";
  stable.colour = Rgb{31, 119, 180};
  failing.label = "failing trial";
  failing.colour = kArrowRed;
  for (ChartSeries* s : {&stable, &failing}) {
    s->line_width = 0.0;
    s->markers = true;
  }
  double lo = 0.0, hi = 0.0;
  for (const TrialResult& t : result.trials) {
    ChartSeries& s = t.stable ? stable : failing;
    s.x.push_back(t.factor);
    // A trial that did not move at all sits at a thousandth of the failure displacement,
    // the bottom of what the log axis shows.
    s.y.push_back(std::max(t.largest_displacement, 1e-3 * failure_displacement));
    lo = lo == 0.0 ? t.factor : std::min(lo, t.factor);
    hi = std::max(hi, t.factor);
  }
  ChartOptions o;
  o.width_px = 1000;
  o.height_px = 600;
  o.log_y = true;
  o.title = "strength-reduction trials";
  o.x_label = "strength reduction factor F";
  o.y_label = "largest displacement in the trial (m)";
  limit.label = "failure displacement " + printf_text(failure_displacement, "%.3g") + " m";
  limit.colour = Rgb{120, 120, 120};
  limit.x = {lo, hi};
  limit.y = {failure_displacement, failure_displacement};
  o.series = {limit, stable, failing};
  if (result.found || result.has_bracket) {
    ChartBand band;
    band.from = result.last_stable;
    band.to = result.first_failing;
    band.colour = Rgb{255, 221, 150};
    band.label = "bracket " + printf_text(result.last_stable, "%.4f") + " to " + printf_text(result.first_failing, "%.4f");
    o.bands.push_back(band);
  }
  if (result.found) {
    ChartVerticalLine f;
    f.x = result.factor_of_safety;
    f.label = "factor of safety " + printf_text(result.factor_of_safety, "%.4f");
    o.vertical_lines.push_back(f);
  }
  if (la != nullptr && la->found) {
    ChartVerticalLine u;
    u.x = la->upper;
    u.colour = Rgb{148, 103, 189};
    u.label = "limit analysis " + printf_text(la->upper, "%.4f");
    o.vertical_lines.push_back(u);
  }
  return o;
}

void write_trials_chart(const std::filesystem::path& path, const FosResult& result,
                        double failure_displacement, const LimitAnalysisResult* la) {
  if (result.trials.empty()) return;
  write_chart(path.string(), trials_chart(result, failure_displacement, la));
}

}  // namespace dda
