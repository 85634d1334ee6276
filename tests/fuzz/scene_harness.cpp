// Scene reader: TOML text checked against a catalog that offers one
// interaction and one criterion with a parameter of every type, as a
// simulator's packs would.
#include <string>

#include "fuzz_harness.hpp"
#include "rift/core/input_error.hpp"
#include "rift/scene/scene_reader.hpp"

namespace rift::fuzz {

namespace {

const std::string kScenePath = "fuzz-scenes/scene.toml";

Catalog make_catalog() {
  auto param = [](const char* name, ValueType type, std::optional<Value> def) {
    ParamSpec p;
    p.name = name;
    p.type = type;
    p.default_value = std::move(def);
    return p;
  };
  ComponentSpec stretch;
  stretch.name = "stretch";
  stretch.params.push_back(param("stiffness", ValueType::kReal, std::nullopt));
  stretch.params.back().positive = true;
  stretch.params.push_back(param("damping", ValueType::kReal, Value(Real(0))));
  stretch.params.back().non_negative = true;
  stretch.params.push_back(param("rest", ValueType::kVec3, Value(Vec3::Zero().eval())));
  stretch.params.push_back(param("count", ValueType::kInt, Value(std::int64_t{1})));
  stretch.params.push_back(param("enabled", ValueType::kBool, Value(Bool{true})));
  ComponentSpec global_edge;
  global_edge.name = "global_edge";
  global_edge.dimension = 2;
  global_edge.params.push_back(param("threshold", ValueType::kReal, std::nullopt));
  global_edge.params.back().positive = true;
  Catalog catalog;
  catalog.interactions.push_back(stretch);
  catalog.criteria.push_back(global_edge);
  return catalog;
}

}  // namespace

void run_scene(std::string_view input) {
  static const Catalog catalog = make_catalog();
  try {
    const Scene scene = read_scene_text(kScenePath, input, catalog);
    if (scene.mesh.source.empty()) throw FuzzFinding("a scene accepted without a mesh source");
    if (scene.interactions.empty()) throw FuzzFinding("a scene accepted without interactions");
    if (!(scene.dt > 0)) throw FuzzFinding("a scene accepted with dt <= 0");
  } catch (const InputError& e) {
    if (e.file() != kScenePath) {
      throw FuzzFinding("message names '" + e.file() + "', not the scene: " + e.what());
    }
    if (e.problem().empty()) throw FuzzFinding("an error without a message");
  }
}

}  // namespace rift::fuzz
