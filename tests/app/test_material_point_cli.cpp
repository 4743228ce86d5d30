// `dda material-point SPEC.json --out FILE.csv` through the real executable: the CSV against
// closed forms (docs/closed-forms.md, "Mohr-Coulomb"), its header, a path that fails
// (exit 3, rows kept), and every kind of bad spec (one message naming the place, exit 2,
// no CSV written).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using dda::test::CommandResult;
using dda::test::read_file;
using dda::test::run_command;
using dda::test::shell_quote;
using dda::test::write_file;

namespace {

struct TempDir : dda::test::TempDir {
  TempDir() : dda::test::TempDir("dda_material_point_cli_") {}
};

constexpr const char* kHeader = "step,exx,eyy,gxy,sxx,syy,szz,sxy,eps_p,branch";

CommandResult run_point(const fs::path& spec, const fs::path& csv) {
  return run_command(shell_quote(DDA_EXE) + " material-point " + shell_quote(spec.string()) +
                     " --out " + shell_quote(csv.string()));
}

// One CSV row, by column name.
struct Row {
  int step = 0;
  std::map<std::string, double> value;
  std::string branch;
  double operator[](const std::string& column) const { return value.at(column); }
};

// The header (returned through `header`) and the rows of a material-point CSV.
std::vector<Row> read_csv(const fs::path& path, std::string& header) {
  std::istringstream in(read_file(path));
  std::getline(in, header);
  std::vector<std::string> names;
  {
    std::istringstream h(header);
    for (std::string name; std::getline(h, name, ',');) names.push_back(name);
  }
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    Row row;
    std::size_t i = 0;
    for (std::string field; std::getline(fields, field, ','); ++i) {
      if (i >= names.size()) throw std::runtime_error("too many fields: " + line);
      if (names[i] == "step") {
        row.step = std::stoi(field);
      } else if (names[i] == "branch") {
        row.branch = field;
      } else {
        row.value[names[i]] = std::stod(field);  // the shortest round-trip text reads back as the same double
      }
    }
    if (i != names.size()) throw std::runtime_error("too few fields: " + line);
    rows.push_back(row);
  }
  return rows;
}

// Plane-strain biaxial compression of a Mohr-Coulomb point: sxx held at the confining
// -s3 by stress, eyy pushed by strain, gxy held at 0. The initial stress is the plane-strain
// state reached by loading in plane from zero (szz = nu (sxx + syy)), so szz stays the
// intermediate principal stress throughout.
constexpr double kPoisson = 0.3, kCohesion = 20e3, kFriction = 30.0, kDilation = 10.0,
                 kConfining = 1e5;

const std::string kBiaxialSpec = R"json({
  "description": "plane-strain biaxial compression to failure",
  "material": {"model": "mohr_coulomb", "density": 2000, "young": 50e6, "poisson": 0.3,
               "cohesion": 20e3, "friction_angle": 30, "dilation_angle": 10},
  "initial_stress": [-1e5, -1e5, -0.6e5, 0],
  "path": [{"steps": 60, "strain": {"eyy": -0.015}, "stress": {"sxx": -1e5}}]
})json";

double deg(double d) { return d * M_PI / 180.0; }

}  // namespace

TEST_CASE("material-point: a biaxial Mohr-Coulomb path levels off at N s3 + 2 c sqrt(N)",
          "[materials][cli]") {
  TempDir dir;
  const fs::path spec = dir.path / "biaxial.json";
  const fs::path csv = dir.path / "biaxial.csv";
  write_file(spec, kBiaxialSpec);
  const CommandResult r = run_point(spec, csv);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("60 increments") != std::string::npos);

  std::string header;
  const std::vector<Row> rows = read_csv(csv, header);
  CHECK(header == kHeader);
  REQUIRE(rows.size() == 61);  // step 0 and one row per increment
  for (std::size_t k = 0; k < rows.size(); ++k) CHECK(rows[k].step == static_cast<int>(k));

  const double n = (1.0 + std::sin(deg(kFriction))) / (1.0 - std::sin(deg(kFriction)));
  const double s1 = n * kConfining + 2.0 * kCohesion * std::sqrt(n);  // compression magnitude
  // Newton stops when the sxx residual is below 1e-10 x the stress scale (~3.7e5 Pa), so
  // sxx is off -s3 by at most ~4e-5 Pa; on the yield plane syy = -(N |sxx| + 2 c sqrt N)
  // carries that times N = 3, about 3e-10 of s1. 1e-9 relative bounds it with room; the
  // return itself is closed form on the plane (round-off, ~1e-15).
  constexpr double kStressTol = 1e-9;
  const double scale = s1;
  int plane_rows = 0;
  bool yielded = false;
  for (const Row& row : rows) {
    INFO("step " << row.step << ", branch " << row.branch);
    CHECK(std::abs(row["sxx"] + kConfining) <= kStressTol * scale);
    CHECK(row["gxy"] == 0.0);
    CHECK(row["sxy"] == 0.0);
    // While szz is the intermediate stress, plastic flow has no zz part: szz = nu (sxx + syy)
    // on every row, elastic or plastic (same Newton tolerance).
    CHECK(std::abs(row["szz"] - kPoisson * (row["sxx"] + row["syy"])) <= kStressTol * scale);
    if (row.branch == "plane") {
      yielded = true;
      ++plane_rows;
      CHECK(std::abs(-row["syy"] - s1) <= kStressTol * s1);
      CHECK(row["eps_p"] > 0.0);
    } else {
      // Elastic until the plateau, never elastic again on a monotonic path.
      CHECK(row.branch == "elastic");
      CHECK_FALSE(yielded);
      CHECK(row["eps_p"] == 0.0);
      CHECK(-row["syy"] < s1 * (1.0 + kStressTol));
    }
  }
  // The elastic part: with sxx held, plane strain gives dsyy / deyy = E / (1 - nu^2) (the
  // spec's E = 50 MPa), eyy = -0.015 / 60 per increment. Same Newton tolerance as above.
  const double slope = 50e6 / (1.0 - kPoisson * kPoisson);
  CHECK(std::abs(rows[1]["syy"] - (-kConfining - slope * 0.015 / 60.0)) <= kStressTol * scale);
  // Yield at |dsyy| = s1 - s3 = 2.69e5 Pa, reached at |eyy| ~ 4.9e-3 (plane-strain stiffness
  // 5.5e7 Pa confined laterally), so 2/3 of the 60 increments are on the plateau.
  CHECK(plane_rows >= 30);

  // On the plateau the stress stands still, so the strain increments are plastic only:
  // d exx / d eyy = -(1 + sin psi) / (1 - sin psi). The stress noise (~4e-5 Pa) over the
  // plane-strain modulus (~6e7 Pa) is ~1e-12 of strain per row against increments of 2.5e-4:
  // ~1e-8 relative at most; 1e-7 bounds it.
  const double ratio = -(1.0 + std::sin(deg(kDilation))) / (1.0 - std::sin(deg(kDilation)));
  for (std::size_t k = rows.size() - 10; k < rows.size(); ++k) {
    const double dexx = rows[k]["exx"] - rows[k - 1]["exx"];
    const double deyy = rows[k]["eyy"] - rows[k - 1]["eyy"];
    CHECK_THAT(dexx / deyy, Catch::Matchers::WithinRel(ratio, 1e-7));
  }
}

TEST_CASE("material-point: the CSV header and step 0 are exact", "[materials][cli]") {
  TempDir dir;
  const fs::path spec = dir.path / "elastic.json";
  const fs::path csv = dir.path / "sub" / "elastic.csv";  // the parent is created
  write_file(spec, R"json({
    "material": {"model": "elastic", "density": 2500, "young": 2e9, "poisson": 0.2},
    "plane": "stress",
    "initial_stress": [-1e5, 0, 0, 3e4],
    "path": [{"steps": 2, "strain": {"exx": 1e-4}}, {"steps": 1, "stress": {"sxy": 0}}]
  })json");
  const CommandResult r = run_point(spec, csv);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string text = read_file(csv);
  CHECK(text.substr(0, text.find('\n')) == kHeader);
  // Step 0 is the initial stress at zero strain, each number as the shortest text that
  // reads back as it (-1e5 is shorter in scientific notation).
  const std::string second = text.substr(text.find('\n') + 1);
  CHECK(second.substr(0, second.find('\n')) == "0,0,0,0,-1e+05,0,0,30000,0,elastic");
  std::string header;
  const std::vector<Row> rows = read_csv(csv, header);
  REQUIRE(rows.size() == 4);
  // Plane stress: szz = 0; sxy brought to 0 by stress in the last segment (Newton tolerance
  // 1e-10 of the stress scale, 1e5 Pa here).
  CHECK(rows[3]["szz"] == 0.0);
  CHECK(std::abs(rows[3]["sxy"]) <= 1e-10 * 1e5);
  CHECK(rows[3]["exx"] == 1e-4);  // kept at its last strain target
}

TEST_CASE("material-point: a path beyond the strength stops with exit code 3, rows kept",
          "[materials][cli]") {
  // Shear stress pushed to 40 kPa with free normal stresses: Mohr-Coulomb's simple-shear
  // strength at zero mean stress is c cos phi = 17.3 kPa, so the fifth increment (20 kPa)
  // has no solution; the four before it are written.
  TempDir dir;
  const fs::path spec = dir.path / "beyond.json";
  const fs::path csv = dir.path / "beyond.csv";
  write_file(spec, R"json({
    "material": {"model": "mohr_coulomb", "density": 2000, "young": 50e6, "poisson": 0.3,
                 "cohesion": 20e3, "friction_angle": 30},
    "path": [{"steps": 10, "stress": {"sxx": 0, "syy": 0, "sxy": 40e3}}]
  })json");
  const CommandResult r = run_point(spec, csv);
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("dda: error: " + spec.string() +
                      ": the path stopped at segment 0, increment 5") != std::string::npos);
  std::string header;
  const std::vector<Row> rows = read_csv(csv, header);
  CHECK(header == kHeader);
  REQUIRE(rows.size() == 5);
  CHECK(rows.back()["sxy"] == Approx(16e3).epsilon(1e-10));  // Newton tolerance
}

TEST_CASE("material-point: an unwritable output is exit code 1", "[materials][cli]") {
  TempDir dir;
  const fs::path spec = dir.path / "ok.json";
  write_file(spec, kBiaxialSpec);
  write_file(dir.path / "file", "");
  const CommandResult r = run_point(spec, dir.path / "file" / "out.csv");
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("cannot create directory") != std::string::npos);
}

TEST_CASE("material-point: every example spec runs", "[materials][cli]") {
  TempDir dir;
  int count = 0;
  const fs::path specs = fs::path(DDA_SOURCE_DIR) / "verification" / "constitutive" / "specs";
  for (const auto& entry : fs::directory_iterator(specs)) {
    if (entry.path().extension() != ".json") continue;
    INFO("spec: " << entry.path());
    const fs::path csv = dir.path / (entry.path().stem().string() + ".csv");
    const CommandResult r = run_point(entry.path(), csv);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    std::string header;
    const std::vector<Row> rows = read_csv(csv, header);
    CHECK(header == kHeader);
    CHECK(rows.size() >= 2);
    if (!rows.empty()) CHECK(rows.back().branch != "elastic");  // each is driven to yield
    ++count;
  }
  CHECK(count >= 3);
}

TEST_CASE("material-point: the example specs reach their closed forms", "[materials][cli]") {
  // Both plateaus are fixed by stress-controlled components, which Newton holds to 1e-10 of
  // the stress scale; the closed form carries that with a factor of order one (N = 3 for
  // Mohr-Coulomb, eta = 0.29 for Drucker-Prager): 1e-9 relative bounds it.
  constexpr double kTol = 1e-9;
  TempDir dir;
  const fs::path specs = fs::path(DDA_SOURCE_DIR) / "verification" / "constitutive" / "specs";
  const auto last_row = [&](const char* name) {
    const fs::path csv = dir.path / (std::string(name) + ".csv");
    const CommandResult r = run_point(specs / (std::string(name) + ".json"), csv);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    std::string header;
    return read_csv(csv, header).back();
  };
  {
    // Drucker-Prager, plane-strain match, psi = 0, simple shear with free normal stresses:
    // szz -> p = 0, so sxy -> xi c = 3 c / sqrt(9 + 12 tan^2 phi).
    const Row end = last_row("dp_simple_shear");
    const double t = std::tan(deg(30.0));
    CHECK(end.branch == "cone");
    CHECK_THAT(end["sxy"],
               Catch::Matchers::WithinRel(3.0 * 20e3 / std::sqrt(9.0 + 12.0 * t * t), kTol));
    CHECK(std::abs(end["szz"]) <= kTol * 20e3);
  }
  {
    // Mohr-Coulomb softening to the residual cohesion 5 kPa: syy -> -(N s3 + 2 c_r sqrt N).
    const Row end = last_row("mc_softening_biaxial");
    CHECK(end["eps_p"] > 0.02);  // past the end of the table
    CHECK_THAT(-end["syy"],
               Catch::Matchers::WithinRel(3.0 * 1e5 + 2.0 * 5e3 * std::sqrt(3.0), kTol));
  }
}

// ---------------------------------------------------------------------------------------
// Bad specs

namespace {

// A valid spec using every key; each bad spec below is one edit of it.
const std::string kValidSpec = R"json({
  "description": "every key",
  "material": {"model": "drucker_prager", "density": 2000, "young": 50e6, "poisson": 0.3,
               "cohesion": 20e3, "friction_angle": 30, "dilation_angle": 10, "match": "outer",
               "hardening": [[0, 20e3], [0.01, 25e3]]},
  "plane": "strain",
  "initial_stress": [-1e5, -1e5, -0.6e5, 0],
  "path": [
    {"steps": 5, "strain": {"eyy": -0.005}, "stress": {"sxx": -1e5}},
    {"steps": 2, "strain": {"gxy": 0.001}}
  ]
}
)json";

using dda::test::edit;

std::string with(const std::string& text, const std::string& pointer, const nlohmann::json& value) {
  nlohmann::json document = nlohmann::json::parse(text);
  document[nlohmann::json::json_pointer(pointer)] = value;
  return document.dump(2);
}

std::string without(const std::string& text, const std::string& pointer) {
  nlohmann::json document = nlohmann::json::parse(text);
  const nlohmann::json::json_pointer at(pointer);
  document[at.parent_pointer()].erase(at.back());
  return document.dump(2);
}

using BadSpec = dda::test::BadInput;

std::vector<BadSpec> bad_specs() {
  const std::string& s = kValidSpec;
  const auto json = [](const char* text) { return nlohmann::json::parse(text); };
  return {
      // ---- not JSON ----
      // The comma after "strain" (line 6) is missing; nlohmann notices at the end of the next
      // token, the key "initial_stress" (line 7, columns 3 to 18).
      {"invalid JSON",
       edit(s, "\"plane\": \"strain\",", "\"plane\": \"strain\""),
       "line 7, column 18",
       {"invalid JSON"}},
      {"empty file", "", "line 1, column 1", {"invalid JSON", "end of input"}},
      {"document is a list", "[]", "top level", {"expected an object"}},
      // ---- keys ----
      {"unknown top-level key",
       edit(s, "\"path\":", "\"pth\":"),
       "pth",
       {"unknown key", "did you mean \"path\"", "known keys: description, material, plane"}},
      {"unknown segment key",
       with(s, "/path/0/step", 3),
       "path[0].step",
       {"unknown key", "did you mean \"steps\""}},
      {"unknown strain component",
       with(s, "/path/1/strain/ezz", 0),
       "path[1].strain.ezz",
       {"unknown key", "known keys: exx, eyy, gxy"}},
      {"unknown stress component",
       with(s, "/path/0/stress/szz", 0),
       "path[0].stress.szz",
       {"unknown key", "known keys: sxx, syy, sxy"}},
      {"unknown material key",
       with(s, "/material/colour", "red"),
       "material.colour",
       {"unknown key"}},
      {"missing material", without(s, "/material"), "material", {"required key is missing"}},
      {"missing path", without(s, "/path"), "path", {"required key is missing"}},
      {"missing steps", without(s, "/path/1/steps"), "path[1].steps", {"required key is missing"}},
      // ---- the path ----
      {"strain and stress for one component",
       with(s, "/path/0/strain/exx", 0),
       "path[0].stress.sxx",
       {"also given in \"strain\" (exx)", "by strain or by stress, not both"}},
      {"steps zero", with(s, "/path/1/steps", 0), "path[1].steps", {"at least 1, got 0"}},
      {"steps negative", with(s, "/path/0/steps", -3), "path[0].steps", {"at least 1, got -3"}},
      {"steps not an integer",
       with(s, "/path/0/steps", 2.5),
       "path[0].steps",
       {"expected an integer", "2.5"}},
      {"empty path",
       with(s, "/path", nlohmann::json::array()),
       "path",
       {"at least one segment", "got 0"}},
      {"segment names nothing", without(s, "/path/1/strain"), "path[1]", {"names no component"}},
      {"target not a number",
       with(s, "/path/1/strain/gxy", "0.001"),
       "path[1].strain.gxy",
       {"expected a number"}},
      {"path not a list", with(s, "/path", json("{}")), "path", {"expected a list"}},
      // ---- initial stress and plane ----
      {"initial stress of 3 numbers",
       with(s, "/initial_stress", json("[-1e5, -1e5, 0]")),
       "initial_stress",
       {"expected a list of 4 numbers [sxx, syy, szz, sxy]"}},
      {"initial stress outside the yield surface",
       with(s, "/initial_stress", json("[-1e6, 0, -3e5, 0]")),
       "initial_stress",
       {"outside the yield surface", "\"cone\""}},
      {"unknown plane", with(s, "/plane", "3d"), "plane", {"unknown plane mode \"3d\""}},
      {"plastic model in plane stress",
       with(s, "/plane", "stress"),
       "material.model",
       {"need plane strain"}},
      {"szz in plane stress",
       R"json({"material": {"model": "elastic", "density": 2000, "young": 50e6, "poisson": 0.3},
               "plane": "stress", "initial_stress": [-1e5, -1e5, -6e4, 0],
               "path": [{"steps": 1, "strain": {"exx": 1e-3}}]})json",
       "initial_stress",
       {"szz must be 0 in plane stress, got -60000"}},
      // ---- bad material parameters (validate_material, at their key) ----
      {"friction angle 90",
       with(s, "/material/friction_angle", 90),
       "material.friction_angle",
       {"must be in [0, 90) degrees, got 90"}},
      {"dilation above friction",
       with(s, "/material/dilation_angle", 35),
       "material.dilation_angle",
       {"must not exceed the friction angle"}},
      {"cohesion negative",
       with(without(s, "/material/hardening"), "/material/cohesion", -1),
       "material.cohesion",
       {"must be >= 0 Pa, got -1"}},
      {"hardening not increasing",
       with(s, "/material/hardening", json("[[0, 20e3], [0, 25e3]]")),
       "material.hardening[1]",
       {"eps_p must increase along the table"}},
      {"hardening not at the cohesion",
       with(s, "/material/hardening", json("[[0, 10e3]]")),
       "material.cohesion",
       {"hardening table gives 10000 Pa at eps_p = 0"}},
      {"unknown match",
       with(s, "/material/match", "middle"),
       "material.match",
       {"unknown match \"middle\""}},
      {"tension cut-off in Drucker-Prager",
       with(s, "/material/tensile_strength", 1e3),
       "material.tensile_strength",
       {"not a key of the \"drucker_prager\" model"}},
      {"unknown model",
       with(s, "/material/model", "cam_clay"),
       "material.model",
       {"unknown model \"cam_clay\""}},
      {"young negative",
       with(s, "/material/young", -5),
       "material.young",
       {"must be positive, got -5"}},
      // ---- rigid (a scene key of materials; docs/scene-format.md, "Rigid blocks") ----
      {"rigid not a boolean",
       with(s, "/material/rigid", "yes"),
       "material.rigid",
       {"expected true or false"}},
      {"rigid plastic material",
       with(s, "/material/rigid", true),
       "material.rigid",
       {"a rigid material cannot be plastic (\"drucker_prager\")"}},
      {"rigid elastic material",
       with(without(s, "/initial_stress"), "/material",
            json(R"({"model": "elastic", "density": 2000, "young": 5e7, "poisson": 0.3,
                     "rigid": true})")),
       "material.rigid",
       {"a rigid material does not deform", "leave \"rigid\" out of a material-point spec"}},
  };
}

}  // namespace

TEST_CASE("material-point: the valid spec of the bad-spec table runs", "[materials][cli]") {
  TempDir dir;
  write_file(dir.path / "valid.json", kValidSpec);
  const CommandResult r = run_point(dir.path / "valid.json", dir.path / "valid.csv");
  INFO(r.output);
  CHECK(r.exit_code == 0);
}

TEST_CASE("material-point: every bad spec gives one message with its place and exit code 2",
          "[materials][cli]") {
  TempDir dir;
  int index = 0;
  for (const BadSpec& bad : bad_specs()) {
    const fs::path spec = dir.path / ("bad_" + std::to_string(index) + ".json");
    const fs::path csv = dir.path / ("bad_" + std::to_string(index) + ".csv");
    ++index;
    write_file(spec, bad.text);
    const CommandResult r = run_point(spec, csv);
    INFO("case: " << bad.name);
    INFO("output: " << r.output);
    CHECK(r.exit_code == 2);
    // One line: the message and nothing else.
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    CHECK(r.output.rfind("dda: error: " + spec.string() + ": " + bad.place + ": ", 0) == 0);
    for (const std::string& word : bad.words) CHECK(r.output.find(word) != std::string::npos);
    CHECK_FALSE(fs::exists(csv));  // the spec is checked before anything is written
  }
}

TEST_CASE("material-point: a missing or absent spec file is exit code 2", "[materials][cli]") {
  TempDir dir;
  const fs::path missing = dir.path / "no_such_spec.json";
  const CommandResult r = run_point(missing, dir.path / "out.csv");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output ==
        "dda: error: " + missing.string() + ": cannot open file (No such file or directory)\n");

  const CommandResult none = run_command(shell_quote(DDA_EXE) + " material-point");
  INFO(none.output);
  CHECK(none.exit_code == 2);
  CHECK(none.output.find("no spec file given") != std::string::npos);

  const CommandResult on_dir = run_point(dir.path, dir.path / "out.csv");
  INFO(on_dir.output);
  CHECK(on_dir.exit_code == 2);
  CHECK(on_dir.output.find("it is a directory, not a material-point spec") != std::string::npos);
}
