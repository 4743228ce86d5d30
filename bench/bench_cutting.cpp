// Block cutting: a 200 m x 100 m slope (its face cutting an 80 m x 80 m corner
// off the rectangle) cut by two persistent joint sets, at 30 degrees 4 m apart and at 120
// degrees 3 m apart, into about 1500 blocks: trace generation and the exact arrangement.
// And the full model path of `dda cut` on models/slope.json (about 2000 blocks).
// The aim: about 2000 blocks in well under a second. Run:
//   build/release/dda_bench --benchmark_filter=CutSlope
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cutting/cut_domain.hpp"
#include "cutting/joint_sets.hpp"
#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "io/model_reader.hpp"
#include "io/scene_reader.hpp"

namespace {

void BM_CutSlope(benchmark::State& state) {
  const dda::Polygon domain{{0, 0}, {200, 0}, {200, 100}, {80, 100}, {0, 20}};
  dda::JointSetSpec a, b;
  a.dip = 30.0;
  a.spacing = 4.0;
  b.dip = 120.0;
  b.spacing = 3.0;
  std::size_t blocks = 0;
  for (auto _ : state) {
    std::vector<dda::JointSegment> joints = dda::joint_set_traces(a, {0, 0}, {200, 100}, 1);
    const std::vector<dda::JointSegment> more = dda::joint_set_traces(b, {0, 0}, {200, 100}, 2);
    joints.insert(joints.end(), more.begin(), more.end());
    const dda::CutResult cut = dda::cut_domain(domain, joints);
    blocks = cut.blocks.size();
    benchmark::DoNotOptimize(blocks);
  }
  state.counters["blocks"] = static_cast<double>(blocks);
}
BENCHMARK(BM_CutSlope)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

std::string slope_model_text() {
  std::ifstream in(std::string(DDA_SOURCE_DIR) + "/models/slope.json");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The whole of `dda cut` but the file writes, on models/slope.json (a 200 m x 100 m slope,
// bedding and cross joints with rock bridges and scatter, min_block_area 0.5 m^2, regions
// and fixed edges): the model read and checked, traces drawn, the domain cut, blocks
// labelled, the scene's JSON and its text. The aim is ~2000 blocks well under a
// second.
void BM_CutSlopeModel(benchmark::State& state) {
  const std::string text = slope_model_text();
  std::size_t blocks = 0, bytes = 0;
  for (auto _ : state) {
    const dda::Model model = dda::parse_model_text(text, "slope.json");
    const dda::CutModel cut = dda::cut_model(model.spec);
    const std::string scene = dda::scene_text(dda::cut_scene(model, cut).scene);
    blocks = cut.cut.blocks.size();
    bytes = scene.size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["blocks"] = static_cast<double>(blocks);
  state.counters["scene_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_CutSlopeModel)->Unit(benchmark::kMillisecond);

// The check `dda cut` ends with: the scene read back as `dda run` reads it (the blocks'
// overlap test dominates).
void BM_ReadCutSlopeScene(benchmark::State& state) {
  const dda::Model model = dda::parse_model_text(slope_model_text(), "slope.json");
  const std::string scene =
      dda::scene_text(dda::cut_scene(model, dda::cut_model(model.spec)).scene);
  for (auto _ : state) {
    const dda::Scene read = dda::parse_scene_text(scene, "slope-scene.json");
    benchmark::DoNotOptimize(read.blocks.size());
  }
}
BENCHMARK(BM_ReadCutSlopeScene)->Unit(benchmark::kMillisecond);

}  // namespace
