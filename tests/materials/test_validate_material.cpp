// Bad material input: each rule names the key at fault.
#include <catch2/catch.hpp>

#include "support/material_builders.hpp"

#include "materials/validate_material.hpp"

using namespace dda;

namespace {

MaterialParameters good_mc() { return test::soil(MaterialModel::MohrCoulomb, 10.0); }
MaterialParameters good_dp() { return test::soil(MaterialModel::DruckerPrager, 10.0); }

std::string key_of(const MaterialParameters& p) {
  const auto e = validate_material(p);
  return e ? e->key : std::string();
}

}  // namespace

TEST_CASE("material validation accepts good parameters", "[materials]") {
  CHECK_FALSE(validate_material(good_mc()));
  MaterialParameters p = good_dp();
  CHECK_FALSE(validate_material(p));
  test::strength_of(p).hardening = {{0.0, 20e3}, {0.01, 10e3}};
  CHECK_FALSE(validate_material(p));
  MaterialParameters t = good_mc();
  test::mohr_coulomb_of(t).tensile_strength = 0.0;  // no tension at all: allowed
  CHECK_FALSE(validate_material(t));
  MaterialParameters e = good_mc();
  test::set_model(e, MaterialModel::Elastic);
  e.plane = PlaneMode::Stress;  // elastic may be plane stress
  CHECK_FALSE(validate_material(e));
}

TEST_CASE("material validation rejects bad parameters, naming the key", "[materials]") {
  MaterialParameters p = good_mc();
  test::strength_of(p).friction_angle = 90.0;
  CHECK(key_of(p) == "friction_angle");
  test::strength_of(p).friction_angle = -1.0;
  CHECK(key_of(p) == "friction_angle");

  p = good_mc();
  test::strength_of(p).dilation_angle = 31.0;  // greater than friction
  CHECK(key_of(p) == "dilation_angle");
  CHECK(validate_material(p)->message.find("friction") != std::string::npos);

  p = good_mc();
  test::strength_of(p).cohesion = -1.0;
  CHECK(key_of(p) == "cohesion");

  p = good_mc();
  test::strength_of(p).hardening = {
      {0.0, 20e3}, {0.02, 10e3}, {0.01, 5e3}};  // not increasing in eps_p
  CHECK(key_of(p) == "hardening[2]");
  test::strength_of(p).hardening = {{0.0, 20e3}, {0.0, 10e3}};  // repeated eps_p
  CHECK(key_of(p) == "hardening[1]");
  test::strength_of(p).hardening = {{0.0, 20e3}, {0.01, -1.0}};
  CHECK(key_of(p) == "hardening[1]");
  test::strength_of(p).hardening = {{0.0, 25e3}, {0.01, 10e3}};  // disagrees with cohesion = 20e3
  CHECK(key_of(p) == "cohesion");

  p = good_mc();
  p.plane = PlaneMode::Stress;
  CHECK(key_of(p) == "model");

  p = good_mc();
  test::mohr_coulomb_of(p).tensile_strength = -1.0;
  CHECK(key_of(p) == "tensile_strength");
  // (A Drucker-Prager material cannot carry a cut-off: its parameter struct has none, and the
  // reader refuses the key: test_scene_input.cpp.)

  p = good_mc();
  test::strength_of(p).cohesion = 0.0;
  test::strength_of(p).friction_angle = 0.0;
  test::strength_of(p).dilation_angle = 0.0;
  CHECK(key_of(p) == "cohesion");  // no strength at all

  p = good_dp();
  test::drucker_prager_of(p).match = static_cast<DruckerPragerMatch>(7);
  CHECK(key_of(p) == "match");

  CHECK(parse_match("outer") == DruckerPragerMatch::Outer);
  CHECK(parse_match("inner") == DruckerPragerMatch::Inner);
  CHECK(parse_match("plane_strain") == DruckerPragerMatch::PlaneStrain);
  CHECK_FALSE(parse_match("middle"));
  CHECK(unknown_match("middle").key == "match");
  CHECK(unknown_match("middle").message.find("\"middle\"") != std::string::npos);
  CHECK(parse_model("mohr_coulomb") == MaterialModel::MohrCoulomb);
  CHECK(parse_model("drucker_prager") == MaterialModel::DruckerPrager);
  CHECK(parse_model("elastic") == MaterialModel::Elastic);
  CHECK_FALSE(parse_model("cam_clay"));
}
