#include "io/fos_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/probabilistic_report.hpp"
#include "io/text_file.hpp"
#include "solver/world.hpp"

namespace dda {
namespace {

using json = nlohmann::json;

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string general(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

json broken_bonds_json(const std::vector<BrokenBond>& bonds) {
  json out = json::array();
  for (const BrokenBond& b : bonds) {
    out.push_back({{"step", b.step}, {"time", b.time}, {"vertex_block", b.vertex_block},
                   {"edge_block", b.edge_block}, {"x", b.at.x()}, {"y", b.at.y()}});
  }
  return out;
}

json bond_check_json(const BondCheck& c) {
  json unexplained = json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(c.unexplained.size(), 100); ++i) {
    const UnexplainedBond& u = c.unexplained[i];
    unexplained.push_back({{"step", u.bond.step}, {"vertex_block", u.bond.vertex_block},
                           {"edge_block", u.bond.edge_block}, {"x", u.bond.at.x()},
                           {"y", u.bond.at.y()}, {"elastic_demand", u.elastic_demand}});
  }
  return {{"computed", c.computed},
          {"reason", c.reason},
          {"broken", c.broken},
          {"explained", c.explained},
          {"unexplained_count", static_cast<long>(c.unexplained.size())},
          {"bonded_elastic", c.bonded_elastic},
          {"overstressed_elastic", c.overstressed_elastic},
          {"unexplained", unexplained},
          {"wall_time_s", c.wall_time_s}};
}

// What a trial decided: "stable", "failing", or "–" when it was interrupted (no verdict).
std::string outcome(const TrialResult& t) {
  if (t.interrupted) return "–";
  return t.stable ? "stable" : "failing";
}

// The trials as a markdown table, one row each, in the order given.
std::string trials_table(const std::vector<TrialResult>& trials) {
  std::ostringstream md;
  md << "| F | verdict | why | largest displacement (m) | end speed (m/s) | speed limit (m/s) | steps | wall time (s) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const TrialResult& t : trials) {
    md << "| " << fixed(t.factor, 4) << " | " << outcome(t) << " | "
       << t.verdict << " | " << general(t.largest_displacement) << " | " << general(t.end_speed)
       << " | " << general(t.end_speed_limit) << " | " << t.steps << " | " << fixed(t.wall_time_s, 2) << " |\n";
  }
  return md.str();
}

// A trial's predicted displacement (m): null when not computed (dynamic or short trials) or
// when its motion does not decay (`decaying` false).
json predicted_json(const TrialResult& t) {
  if (!t.predicted_displacement || !std::isfinite(*t.predicted_displacement)) return nullptr;
  return *t.predicted_displacement;
}
json decaying_json(const TrialResult& t) {
  if (!t.predicted_displacement) return nullptr;
  return static_cast<bool>(std::isfinite(*t.predicted_displacement));
}

json trial_json(const TrialResult& t) {
  return {{"F", t.factor},
          {"stable", t.stable},
          {"verdict", t.verdict},
          {"largest_displacement", t.largest_displacement},
          {"end_speed", t.end_speed},
          {"end_speed_limit", t.end_speed_limit},
          {"predicted_displacement", predicted_json(t)},
          {"decaying", decaying_json(t)},
          {"kinetic_peak", t.kinetic_peak},
          {"kinetic_end", t.kinetic_end},
          {"steps", t.steps},
          {"simulated_time", t.simulated_time},
          {"wall_time_s", t.wall_time_s},
          {"watched_point", t.watched_point},
          {"interrupted", t.interrupted},
          {"cut_steps", t.stats.cut_steps},
          {"cuts_for_open_close", t.stats.cuts_for_open_close},
          {"cuts_for_displacement", t.stats.cuts_for_displacement},
          {"solves", t.stats.iterations},
          {"open_close_iterations", t.stats.open_close_total}};
}

}  // namespace

// The report lists the fastest blocks of the limit analysis's mechanism and the smallest
// single-block bounds, not all of them (a 2000-block slope has as many bounds).
constexpr std::size_t kReportedMechanismBlocks = 200;
constexpr std::size_t kReportedBounds = 20;

std::string trial_line(const TrialResult& t) {
  return "trial F = " + fixed(t.factor, 4) + ": " + outcome(t) + " (" + t.verdict +
         "), largest displacement " + general(t.largest_displacement) + " m, " +
         std::to_string(t.steps) + " steps, " + fixed(t.wall_time_s, 1) + " s";
}

namespace {

// The report's "limit_analysis" object (docs/factor-of-safety.md, section 4).
json limit_analysis_json(const LimitAnalysisInfo& l) {
  const LimitAnalysisResult& a = l.analysis;
  json mechanism = json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(a.mechanism.size(), kReportedMechanismBlocks); ++i) {
    const MechanismMotion& m = a.mechanism[i];
    mechanism.push_back({{"block", m.block},
                         {"velocity", {m.velocity.x(), m.velocity.y()}},
                         {"angular_velocity", m.angular_velocity}});
  }
  json bounds = json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(l.single_block_bounds.size(), kReportedBounds); ++i) {
    bounds.push_back({{"block", l.single_block_bounds[i].block}, {"factor", l.single_block_bounds[i].factor}});
  }
  return {{"computed", a.computed},
          {"reason", a.reason},
          {"found", a.found},
          {"factor", a.found ? json(a.factor) : json(nullptr)},
          {"bracket", a.found ? json::array({a.factor, a.upper}) : json(nullptr)},
          {"admissible_at_max_factor", a.admissible_at_max},
          {"free_blocks", a.free_blocks},
          {"contacts", a.contacts},
          {"programs", a.programs},
          {"wall_time_s", a.wall_time_s},
          {"mechanism_blocks", a.mechanism.size()},
          {"mechanism", mechanism},
          {"single_block_bounds", bounds}};
}

std::vector<std::string> joint_names(const Scene& scene) {
  std::vector<std::string> out;
  for (const JointMaterial& j : scene.joint_materials) out.push_back(j.name);
  return out;
}

// The report's "failing_mechanism" object.
json failing_mechanism_json(const LimitAnalysisInfo& l, const std::vector<std::string>& joint_names) {
  const TrialMechanism& m = l.failing;
  json blocks = json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(m.blocks.size(), kReportedMechanismBlocks); ++i) {
    const BlockMotion& b = m.blocks[i];
    blocks.push_back({{"block", b.block},
                      {"displacement", {b.displacement.x(), b.displacement.y()}},
                      {"rotation", b.rotation},
                      {"mode", b.mode}});
  }
  const LimitAnalysisResult& g = m.group_bound;
  json joints = json::array();
  for (const JointActivity& a : m.joints) {
    const auto j = static_cast<std::size_t>(a.joint);
    joints.push_back({{"joint", j < joint_names.size() ? json(joint_names[j]) : json(a.joint)},
                      {"sliding", a.sliding},
                      {"opened", a.opened}});
  }
  return {{"F", l.failing_factor},
          {"mode", m.mode},
          {"joints", joints},
          {"slip", {{"along", m.slip.along}, {"across", m.slip.across}, {"between", m.slip.between}}},
          {"block_count", m.blocks.size()},
          {"blocks", blocks},
          {"group_bound", {{"computed", g.computed},
                           {"reason", g.reason},
                           {"factor", g.found ? json(g.factor) : json(nullptr)},
                           {"admissible_at_max_factor", g.admissible_at_max}}}};
}

}  // namespace

std::string settling_phrase(const Settling& s) {
  if (s.steps == 0) return "";
  std::string out = "; then " + std::to_string(s.steps) + " static steps";
  if (s.at_rest) {
    out += " to rest";
  } else {
    out += ", stopped (" + s.stopped + ") with the largest unbalanced force at " +
           general(s.unbalanced_end) + " of a block's weight";
  }
  if (s.relaxation_steps > 0.0) {
    out += " (the relaxation lost 1/e of its force in " + general(s.relaxation_steps) + " steps)";
  }
  if (!s.kept) {
    out += "; the trials start where the consolidation ended, before those steps (a slope that "
           "does not settle at the consolidation's strength is not made to creep on)";
  }
  return out;
}

std::string bond_check_line(const BondCheck& c) {
  if (!c.computed) return "the broken bonds were not checked against an elastic solution: " + c.reason;
  return "of the " + std::to_string(c.broken) + " bonds the consolidation broke, " +
         std::to_string(c.explained) +
         " are loaded beyond their strength in an elastic solution of the slope (the same "
         "consolidation with its bonds unbreakable, which overstresses " +
         std::to_string(c.overstressed_elastic) + " of its " + std::to_string(c.bonded_elastic) +
         " bonded contacts); " + std::to_string(c.unexplained.size()) +
         " are not: the consolidation's own motion or the failure of their neighbours broke them";
}

std::string limit_analysis_line(const LimitAnalysisInfo& l) {
  const LimitAnalysisResult& a = l.analysis;
  std::string line = "limit analysis (rigid blocks, associative friction): ";
  if (!a.computed) return line + "not computed: " + a.reason;
  if (a.found) {
    line += "F = " + fixed(a.factor, 4) + ", " + std::to_string(a.mechanism.size()) +
            " blocks in its mechanism";
  } else {
    line += a.admissible_at_max ? "admissible up to the largest F" : "not admissible at the smallest F";
  }
  line += " (" + std::to_string(a.programs) + " linear programs, " + fixed(a.wall_time_s, 1) + " s)";
  if (!l.single_block_bounds.empty()) {
    line += "; smallest single-block bound F = " + fixed(l.single_block_bounds.front().factor, 4) +
            " (block " + std::to_string(l.single_block_bounds.front().block) + ")";
  }
  return line;
}

std::string failing_mechanism_line(const LimitAnalysisInfo& l, const Scene& scene) {
  const std::vector<std::string> names = joint_names(scene);
  const TrialMechanism& m = l.failing;
  std::string line = "the first failing trial (F = " + fixed(l.failing_factor, 4) + ") moved " +
                     std::to_string(m.blocks.size()) + " blocks: " + m.mode;
  if (!m.joints.empty()) {
    line += ", slipping on";
    for (std::size_t i = 0; i < m.joints.size(); ++i) {
      const JointActivity& a = m.joints[i];
      const auto j = static_cast<std::size_t>(a.joint);
      line += (i == 0 ? " " : ", ") + (j < names.size() ? names[j] : "joint " + std::to_string(a.joint)) +
              " (" + std::to_string(a.sliding) + " contacts sliding, " + std::to_string(a.opened) +
              " opened)";
    }
  }
  if (m.slip.along + m.slip.across + m.slip.between > 0) {
    line += "; of its sliding contacts " + std::to_string(m.slip.along) + " slip along the motion, " +
            std::to_string(m.slip.across) + " across it";
  }
  const LimitAnalysisResult& g = m.group_bound;
  if (g.found) {
    line += "; that group alone, every other block held, has the limit-analysis factor " +
            fixed(g.factor, 4);
  } else if (g.computed) {
    line += g.admissible_at_max ? "; that group alone is admissible up to the largest F"
                                : "; that group alone is not admissible even at the smallest F";
  }
  return line;
}

namespace {

// --spread: the search's factor at each of kSpreadSettings.
json settings_spread_json(const SettingsSpread& spread) {
  json factors = json::array();
  for (const SpreadFactor& f : spread.factors) {
    factors.push_back({{"setting", f.setting},
                       {"time_step_scale", f.time_step_scale},
                       {"penalty_scale", f.penalty_scale},
                       {"time_step", f.time_step},
                       {"penalty", f.penalty},
                       {"found", f.found},
                       {"factor", f.found ? json(f.factor) : json(nullptr)},
                       {"bracket", f.found ? json::array({f.last_stable, f.first_failing}) : json(nullptr)},
                       {"message", f.message},
                       {"trials", f.trials},
                       {"wall_time_s", f.wall_time_s},
                       {"interrupted", f.interrupted}});
  }
  return {{"computed", spread.computed},
          {"within", spread.within},
          {"spread", spread.spread},
          {"resolution", spread.resolution},
          {"agreement", kSpreadAgreement},
          {"text", spread.text},
          {"factors", factors}};
}

std::string settings_spread_markdown(const Scene& scene, const FosResult& result,
                                     const SettingsSpread& spread) {
  std::string text = spread.text;
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  std::ostringstream md;
  md << "\n## The factor over the time step and the penalty (--spread)\n\n" << text
     << ". Each row consolidates the scene again with every time step or the penalty scaled "
        "and searches as above; the spread is (max - min) / mean of the factors found "
        "(docs/factor-of-safety.md, section 6).\n\n"
     << "| setting | time step (s) | penalty (N/m) | F | bracket | trials | wall time (s) |\n"
        "|---|---|---|---|---|---|---|\n"
     << "| scene | " << general(trial_time_step(scene)) << " | "
     << general(resolve_penalty(scene)) << " | " << fixed(result.factor_of_safety, 4) << " | " << fixed(result.last_stable, 4)
     << " to " << fixed(result.first_failing, 4) << " | " << result.trials.size() << " | |\n";
  for (const SpreadFactor& f : spread.factors) {
    md << "| " << f.setting << " | " << general(f.time_step) << " | " << general(f.penalty) << " | "
       << (f.found ? fixed(f.factor, 4) : std::string("none")) << " | "
       << (f.found ? fixed(f.last_stable, 4) + " to " + fixed(f.first_failing, 4) : f.message) << " | "
       << f.trials << " | " << fixed(f.wall_time_s, 1) << " |\n";
  }
  return md.str();
}

}  // namespace

void write_fos_report(const std::filesystem::path& dir, const Scene& scene,
                      const FosSettings& s, const ConsolidationInfo& consolidation,
                      const FosResult& result, double wall_time_s, const LimitAnalysisInfo* limit,
                      const DynamicCheck* dynamic, const SettingsSpread* spread,
                      const ProbabilisticResult* probabilistic) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());

  json laws = json::object();
  for (const JointMaterial& j : scene.joint_materials) laws[j.name] = joint_law_name(j.law);
  json trials = json::array();
  for (const TrialResult& t : result.trials) trials.push_back(trial_json(t));
  json report = {
      {"scene", scene.source},
      {"found", result.found},
      {"factor_of_safety", result.found ? json(result.factor_of_safety) : json(nullptr)},
      {"bracket", result.found ? json::array({result.last_stable, result.first_failing})
                               : json(nullptr)},
      {"message", result.message},
      {"interrupted", result.interrupted},
      {"bracket_so_far", result.has_bracket
                             ? json::array({result.last_stable, result.first_failing})
                             : json(nullptr)},
      {"settings",
       {{"tolerance", s.tolerance},
        {"min_factor", s.min_factor},
        {"max_factor", s.max_factor},
        {"failure_displacement", s.failure_displacement},
        {"trial_time", s.trial_time},
        {"detect_acceleration", s.detect_acceleration},
        {"relaxations_per_trial", s.relaxations_per_trial},
        {"decay_horizon_steps", s.decay_horizon_steps},
        {"dynamic_coefficient", s.dynamic_coefficient},
        {"reduce_materials", s.reduce_materials},
        {"jobs", s.jobs},
        {"seismic_coefficient", s.seismic_coefficient},
        {"first_failing_guess", s.first_failing_guess > 0.0 ? json(s.first_failing_guess) : json(nullptr)},
        {"consolidation_factor", consolidation.factor},
        {"watched", scene.monitors.empty() ? "free block centroids" : "monitors"}}},
      {"joint_laws", laws},
      {"consolidation",
       {{"steps", consolidation.steps},
        {"time", consolidation.time},
        {"wall_time_s", consolidation.wall_time_s},
        {"kinetic_end", consolidation.kinetic_end},
        {"bonds_broken", consolidation.bonds_broken},
        {"broken_bonds", broken_bonds_json(consolidation.broken_bonds)},
        {"factor", consolidation.factor},
        {"bond_check", bond_check_json(consolidation.bond_check)},
        {"settling",
         {{"steps", consolidation.settling.steps},
          {"at_rest", consolidation.settling.at_rest},
          {"stopped", consolidation.settling.stopped},
          {"unbalanced_start", consolidation.settling.unbalanced_start},
          {"unbalanced_end", consolidation.settling.unbalanced_end},
          {"relaxation_steps", consolidation.settling.relaxation_steps},
          {"kept", consolidation.settling.kept},
          {"wall_time_s", consolidation.settling.stats.wall_time_s}}}}},
      {"trials", trials},
      {"discarded_trials",
       {{"count", result.discarded_trials}, {"wall_time_s", result.discarded_wall_time_s}}},
      {"wall_time_s", wall_time_s},
  };
  if (limit != nullptr) {
    report["method"] = limit->method;
    report["limit_analysis"] = limit_analysis_json(*limit);
    if (limit->has_failing) report["failing_mechanism"] = failing_mechanism_json(*limit, joint_names(scene));
  }
  if (dynamic != nullptr) {
    json dyn_trials = json::array();
    for (const TrialResult& t : dynamic->trials) dyn_trials.push_back(trial_json(t));
    report["dynamic_check"] = {{"computed", dynamic->computed},
                               {"agrees", dynamic->agrees},
                               {"text", dynamic->text},
                               {"trials", dyn_trials}};
  } else {
    report["dynamic_check"] = {{"computed", false}};
  }
  report["settings_spread"] = spread != nullptr ? settings_spread_json(*spread)
                                                : json{{"computed", false}};
  if (probabilistic != nullptr) {
    report["probabilistic"] = probabilistic_json(*probabilistic, scene.random_strengths);
  }
  write_text_file((dir / "report.json").string(), report.dump(2) + "\n");

  std::ostringstream md;
  md << "# Factor of safety: " << scene.source << "\n\n";
  if (probabilistic != nullptr) {
    md << probabilistic_markdown(*probabilistic, scene.random_strengths) << "\n## How each trial runs\n\n";
  } else if (result.found) {
    md << "**F = " << fixed(result.factor_of_safety, 3) << "**, between the last stable trial "
       << fixed(result.last_stable, 4) << " and the first failing " << fixed(result.first_failing, 4)
       << " (tolerance " << general(s.tolerance) << ").\n\n";
  } else if (result.interrupted) {
    md << "**" << result.message << "**. The trials below are those run so far; an interrupted trial has no verdict.\n\n";
  } else {
    md << "**No factor found**: " << result.message << "\n\n";
  }
  if (result.found && !result.message.empty()) md << "Note: " << result.message << "\n\n";
  md << "Strength reduction: tan(phi)/F, c/F and tensile strength/F on every joint"
     << (s.reduce_materials ? " and on plastic blocks' materials" : "") << ". Joint laws:";
  for (const JointMaterial& j : scene.joint_materials) md << " " << j.name << " (" << joint_law_name(j.law) << ")";
  md << ".";
  if (s.seismic_coefficient != 0.0) {
    md << " Seismic coefficient " << general(s.seismic_coefficient)
       << " (a horizontal body force of that share of the weight along +x, from the consolidation on).";
  }
  if (consolidation.bond_check.computed || !consolidation.bond_check.reason.empty()) {
    md << "\n\nBonds: " << bond_check_line(consolidation.bond_check)
       << " (report.json: consolidation.bond_check; docs/factor-of-safety.md, section 1).";
  }
  md << "\n\nEach trial starts at rest from the scene consolidated at F = "
     << general(consolidation.factor) << " ("
     << consolidation.steps << " steps, " << general(consolidation.time) << " s simulated, "
     << consolidation.bonds_broken << " bonds broken"
     << settling_phrase(consolidation.settling) << ") and runs "
     << general(s.trial_time) << " s with dynamic coefficient " << general(s.dynamic_coefficient)
     << ". It fails when a watched point ("
     << (scene.monitors.empty() ? "the centroid of a free block" : "a monitor")
     << ") moves more than " << general(s.failure_displacement) << " m, or is still moving at the end faster than ";
  if (s.dynamic_coefficient >= 1.0) {
    md << general(s.failure_displacement / s.trial_time) << " m/s (d / T).\n\n";
  } else {
    md << "a mechanism accelerating at " << general(s.detect_acceleration)
       << " g would move in these damped steps (the table's speed limit).\n\n";
  }
  if (probabilistic == nullptr) md << trials_table(result.trials);
  if (dynamic != nullptr && dynamic->computed) {
    md << "\n## Static and dynamic trials\n\n" << dynamic->text
       << " (dynamic coefficient 1, the same trial time and verdict; docs/factor-of-safety.md).\n\n"
       << trials_table(dynamic->trials);
  }
  if (spread != nullptr && spread->computed) md << settings_spread_markdown(scene, result, *spread);
  if (limit != nullptr) {
    md << "\n## A second factor: rigid-block limit analysis\n\n" << limit_analysis_line(*limit)
       << ".\n\nThe consolidated blocks taken as rigid, their closed contacts as the points "
          "where they press on each other, the joints' strengths divided by F, associative "
          "friction (docs/limit-analysis.md). A single-block bound is the factor of one block "
          "moving while every other block is held: the slope's factor cannot exceed the "
          "smallest.\n";
    if (!limit->analysis.mechanism.empty()) {
      md << "\n| block | velocity x | velocity y | angular velocity (1/m) |\n|---|---|---|---|\n";
      for (std::size_t i = 0; i < std::min<std::size_t>(limit->analysis.mechanism.size(), 20); ++i) {
        const MechanismMotion& m = limit->analysis.mechanism[i];
        md << "| " << m.block << " | " << fixed(m.velocity.x(), 3) << " | " << fixed(m.velocity.y(), 3)
           << " | " << general(m.angular_velocity) << " |\n";
      }
    }
  }
  if (limit != nullptr && limit->has_failing) {
    md << "\n## The first failing trial's mechanism\n\n" << failing_mechanism_line(*limit, scene)
       << ".\n\nBlocks that moved more than " << general(kMechanismShare)
       << " of the largest displacement (\"toppling\" or \"rotating\": they turned about a point "
          "of their own, below their centroid or elsewhere; docs/factor-of-safety.md):\n\n"
          "| block | displacement x (m) | displacement y (m) | "
          "rotation (rad) | mode |\n|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < std::min<std::size_t>(limit->failing.blocks.size(), 20); ++i) {
      const BlockMotion& b = limit->failing.blocks[i];
      md << "| " << b.block << " | " << general(b.displacement.x()) << " | " << general(b.displacement.y())
         << " | " << general(b.rotation) << " | " << b.mode << " |\n";
    }
  }
  md << "\nWall time " << fixed(wall_time_s, 1) << " s in all";
  if (result.discarded_trials > 0) {
    md << ", of which " << result.discarded_trials << " trials started ahead of a verdict and "
       << "dropped when it went the other way took " << fixed(result.discarded_wall_time_s, 1)
       << " s of a thread's time";
  }
  md << ".\n";
  write_text_file((dir / "report.md").string(), md.str());
}

}  // namespace dda
