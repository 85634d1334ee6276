// Reads a scene from TOML and validates every value before any simulation
// starts. Every error names the file, the line and what is expected.
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <string_view>

#include "rift/core/input_error.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/scene/scene.hpp"
#include "rift/scene/scene_reader.hpp"
#include "rift/scene/suggest.hpp"

namespace rift {

namespace {

int line_of(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

class SceneReader {
 public:
  /// `text`: the scene's TOML; none: read the file `path`.
  SceneReader(std::string path, std::optional<std::string_view> text, const Catalog& catalog)
      : path_(std::move(path)), text_(text), catalog_(catalog) {}

  Scene read() {
    toml::table root;
    try {
      root = text_ ? toml::parse(*text_, path_) : toml::parse_file(path_);
    } catch (const toml::parse_error& e) {
      throw InputError(path_, static_cast<int>(e.source().begin.line),
                       "not valid TOML: " + std::string(e.description()));
    }
    Scene scene;
    scene.path = path_;
    scene.name = std::filesystem::path(path_).stem().string();
    check_keys(
        root,
        {"mesh", "simulation", "implicit", "mass", "pin", "handle", "load", "initial_velocity",
         "obstacle", "notch", "drag", "interaction", "criterion", "tearing", "output"},
        "the scene");
    read_mesh(require_table(root, "mesh", "the scene"), scene.mesh);
    if (auto* t = optional_table(root, "simulation")) read_simulation(*t, scene);
    if (auto* t = optional_table(root, "implicit")) read_implicit(*t, scene);
    if (auto* t = optional_table(root, "mass")) read_mass(*t, scene);
    if (auto* t = optional_table(root, "pin")) read_pins(*t, scene.pins);
    for_each_table(root, "handle", [&](const toml::table& t) { read_handle(t, scene); });
    for_each_table(root, "load", [&](const toml::table& t) { read_load(t, scene); });
    for_each_table(root, "initial_velocity", [&](const toml::table& t) {
      check_keys(t, {"select", "velocity"}, "[[initial_velocity]]");
      SceneInitialVelocity iv;
      iv.line = line_of(t);
      iv.select = require_selection(t, "[[initial_velocity]]");
      iv.velocity =
          vec3(require(t, "velocity", "[[initial_velocity]]", "[vx, vy, vz] in m/s"), "velocity");
      scene.initial_velocities.push_back(iv);
    });
    for_each_table(root, "obstacle", [&](const toml::table& t) { read_obstacle(t, scene); });
    for_each_table(root, "notch", [&](const toml::table& t) {
      check_keys(t, {"from", "to", "depth"}, "[[notch]]");
      SceneNotch n;
      n.line = line_of(t);
      n.from = vec3(require(t, "from", "[[notch]]", "one end of the cut, [x, y, z]"), "from");
      n.to = vec3(require(t, "to", "[[notch]]", "the other end of the cut, [x, y, z]"), "to");
      if (auto* d = t.get("depth")) n.depth = vec3(*d, "depth");
      if ((n.to - n.from).norm() == 0) fail(t, "a notch needs 'from' and 'to' apart");
      scene.notches.push_back(n);
    });
    if (auto* t = optional_table(root, "drag")) {
      check_keys(*t, {"coefficient", "wind"}, "[drag]");
      scene.drag.line = line_of(*t);
      scene.drag.coefficient =
          positive_real(require(*t, "coefficient", "[drag]", "N s/m^3"), "coefficient");
      if (auto* w = t->get("wind")) scene.drag.wind = vec3(*w, "wind");
    }
    read_components(root, "interaction", catalog_.interactions, scene.interactions);
    read_components(root, "criterion", catalog_.criteria, scene.criteria);
    if (auto* t = optional_table(root, "tearing")) {
      check_keys(*t, {"max_per_step"}, "[tearing]");
      if (auto* n = t->get("max_per_step")) {
        scene.tearing.max_per_step = static_cast<int>(integer(*n, "max_per_step", 0, 1 << 30));
      }
    }
    scene.output.dir = "out/" + scene.name;
    if (auto* t = optional_table(root, "output")) read_output(*t, scene.output);
    if (scene.implicit_line > 0 && !is_implicit(scene.integrator)) {
      fail(scene.implicit_line,
           "[implicit] sets the solver of integrator = \"implicit_euler\" or \"bdf2\", but the "
           "scene's "
           "integrator is '" +
               std::string(to_string(scene.integrator)) + "'");
    }
    if (scene.interactions.empty()) {
      throw InputError(path_, 0,
                       "the scene has no [[interaction]]: nothing would move but gravity");
    }
    return scene;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw InputError(path_, line, problem);
  }
  [[noreturn]] void fail(const toml::node& node, const std::string& problem) const {
    fail(line_of(node), problem);
  }

  void check_keys(const toml::table& table, const std::vector<std::string>& allowed,
                  const std::string& where) const {
    for (auto&& [key, node] : table) {
      const std::string k(key.str());
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
        fail(static_cast<int>(key.source().begin.line),
             "unknown key '" + k + "' in " + where + did_you_mean(k, allowed));
      }
    }
  }

  const toml::table& require_table(const toml::table& parent, const std::string& key,
                                   const std::string& where) const {
    const toml::node* node = parent.get(key);
    if (!node) fail(0, where + " needs a [" + key + "] table");
    if (!node->is_table()) fail(*node, "'" + key + "' must be a table");
    return *node->as_table();
  }

  const toml::table* optional_table(const toml::table& parent, const std::string& key) const {
    const toml::node* node = parent.get(key);
    if (!node) return nullptr;
    if (!node->is_table()) fail(*node, "'" + key + "' must be a table ([" + key + "])");
    return node->as_table();
  }

  Real real(const toml::node& node, const std::string& key) const {
    if (auto v = node.value_exact<double>()) {
      if (!std::isfinite(*v)) fail(node, "'" + key + "' must be a finite number");
      return *v;
    }
    if (auto i = node.value_exact<std::int64_t>()) return static_cast<Real>(*i);
    fail(node, "'" + key + "' must be a number, not " + type_name(node));
  }

  Real positive_real(const toml::node& node, const std::string& key) const {
    const Real v = real(node, key);
    if (!(v > 0)) fail(node, "'" + key + "' must be positive, not " + toml_text(node));
    return v;
  }

  std::int64_t integer(const toml::node& node, const std::string& key, std::int64_t lo,
                       std::int64_t hi) const {
    auto i = node.value_exact<std::int64_t>();
    if (!i) fail(node, "'" + key + "' must be an integer, not " + type_name(node));
    if (*i < lo || *i > hi) {
      fail(node, "'" + key + "' must be between " + std::to_string(lo) + " and " +
                     std::to_string(hi) + ", not " + std::to_string(*i));
    }
    return *i;
  }

  bool boolean(const toml::node& node, const std::string& key) const {
    auto b = node.value_exact<bool>();
    if (!b) fail(node, "'" + key + "' must be true or false, not " + type_name(node));
    return *b;
  }

  std::string string(const toml::node& node, const std::string& key) const {
    auto s = node.value_exact<std::string>();
    if (!s) fail(node, "'" + key + "' must be a string, not " + type_name(node));
    return *s;
  }

  Vec3 vec3(const toml::node& node, const std::string& key) const {
    const toml::array* a = node.as_array();
    if (!a || a->size() != 3)
      fail(node, "'" + key + "' must be an array of 3 numbers, like [0, 0, -9.81]");
    return Vec3(real(*a->get(0), key), real(*a->get(1), key), real(*a->get(2), key));
  }

  static std::string type_name(const toml::node& node) {
    switch (node.type()) {
      case toml::node_type::string:
        return "a string";
      case toml::node_type::integer:
        return "an integer";
      case toml::node_type::floating_point:
        return "a number";
      case toml::node_type::boolean:
        return "a boolean";
      case toml::node_type::array:
        return "an array";
      case toml::node_type::table:
        return "a table";
      default:
        return "a date or time";
    }
  }

  static std::string toml_text(const toml::node& node) {
    if (auto v = node.value<double>()) {
      std::ostringstream out;
      out << *v;
      return out.str();
    }
    return type_name(node);
  }

  void read_mesh(const toml::table& t, SceneMesh& mesh) const {
    check_keys(t, {"source", "scale", "rotate", "translate"}, "[mesh]");
    const toml::node* source = t.get("source");
    if (!source)
      fail(line_of(t),
           "[mesh] needs 'source': a generator such as \"grid:quad:10x10\" or a mesh file");
    mesh.source = string(*source, "source");
    if (is_generator_spec(mesh.source)) {
      try {
        check_generator_spec(mesh.source);  // the spelling only: the mesh is built at set-up
      } catch (const std::invalid_argument& e) {
        fail(*source, e.what());
      }
    } else {
      namespace fs = std::filesystem;
      fs::path p(mesh.source);
      if (p.is_relative()) p = fs::path(path_).parent_path() / p;
      std::error_code ec;
      if (!fs::is_regular_file(p, ec))
        fail(*source, "mesh file '" + p.string() + "' does not exist");
      mesh.source = p.lexically_normal().string();
    }
    if (auto* n = t.get("scale")) {
      if (n->is_array()) {
        mesh.scale = vec3(*n, "scale");
      } else {
        mesh.scale = Vec3::Constant(real(*n, "scale"));
      }
      if (!(mesh.scale.array() > 0).all()) fail(*n, "'scale' must be positive");
    }
    if (auto* n = t.get("rotate")) mesh.rotate_degrees = vec3(*n, "rotate");
    if (auto* n = t.get("translate")) mesh.translate = vec3(*n, "translate");
  }

  void read_simulation(const toml::table& t, Scene& scene) const {
    check_keys(t, {"integrator", "dt", "steps", "gravity", "divergence_factor"}, "[simulation]");
    if (auto* n = t.get("integrator")) {
      const std::string name = string(*n, "integrator");
      auto kind = parse_integrator(name);
      if (!kind) {
        fail(*n, "unknown integrator '" + name +
                     "': expected euler, symplectic_euler, rk4, implicit_euler or bdf2" +
                     did_you_mean(name,
                                  {"euler", "symplectic_euler", "rk4", "implicit_euler", "bdf2"}));
      }
      scene.integrator = *kind;
    }
    if (auto* n = t.get("dt")) scene.dt = positive_real(*n, "dt");
    if (auto* n = t.get("steps")) scene.steps = integer(*n, "steps", 1, std::int64_t(1) << 40);
    if (auto* n = t.get("gravity")) scene.gravity = vec3(*n, "gravity");
    if (auto* n = t.get("divergence_factor")) {
      scene.divergence_factor = real(*n, "divergence_factor");
      if (!(scene.divergence_factor >= 0))
        fail(*n, "'divergence_factor' must be 0 (off) or positive");
    }
  }

  void read_implicit(const toml::table& t, Scene& scene) const {
    check_keys(t,
               {"cg_tolerance", "cg_max_iterations", "preconditioner", "newton_iterations",
                "newton_tolerance", "jacobian", "project_definite", "line_search"},
               "[implicit]");
    ImplicitSettings& s = scene.implicit;
    scene.implicit_line = line_of(t);
    if (auto* n = t.get("cg_tolerance")) {
      s.cg_tolerance = positive_real(*n, "cg_tolerance");
      if (s.cg_tolerance >= 1) fail(*n, "'cg_tolerance' is a relative residual: below 1");
    }
    if (auto* n = t.get("cg_max_iterations")) {
      s.cg_max_iterations = static_cast<int>(integer(*n, "cg_max_iterations", 1, 1 << 30));
    }
    if (auto* n = t.get("preconditioner")) {
      const std::string name = string(*n, "preconditioner");
      auto kind = parse_preconditioner(name);
      if (!kind) {
        fail(*n, "unknown preconditioner '" + name +
                     "': expected none, jacobi or incomplete_cholesky" +
                     did_you_mean(name, {"none", "jacobi", "incomplete_cholesky"}));
      }
      s.preconditioner = *kind;
    }
    if (auto* n = t.get("newton_iterations")) {
      s.newton_iterations = static_cast<int>(integer(*n, "newton_iterations", 1, 1000));
    }
    if (auto* n = t.get("newton_tolerance"))
      s.newton_tolerance = positive_real(*n, "newton_tolerance");
    if (auto* n = t.get("jacobian")) {
      const std::string name = string(*n, "jacobian");
      auto mode = parse_jacobian_mode(name);
      if (!mode) {
        fail(*n, "unknown jacobian '" + name + "': expected assembled or matrix_free" +
                     did_you_mean(name, {"assembled", "matrix_free"}));
      }
      s.jacobian = *mode;
    }
    if (auto* n = t.get("line_search")) {
      const std::string name = string(*n, "line_search");
      auto search = parse_line_search(name);
      if (!search) {
        fail(*n, "unknown line_search '" + name + "': expected energy or residual" +
                     did_you_mean(name, {"energy", "residual"}));
      }
      s.line_search = *search;
    }
    if (auto* n = t.get("project_definite")) {
      s.project_definite = boolean(*n, "project_definite");
      if (s.project_definite && s.jacobian == JacobianMode::kMatrixFree) {
        fail(*n, "'project_definite' needs the element matrices: jacobian = \"assembled\"");
      }
    }
  }

  void read_mass(const toml::table& t, Scene& scene) const {
    check_keys(t, {"total", "density"}, "[mass]");
    const toml::node* total = t.get("total");
    const toml::node* density = t.get("density");
    if (total && density) fail(*density, "[mass] takes 'total' or 'density', not both");
    if (total) scene.total_mass = positive_real(*total, "total");
    if (density) scene.density = positive_real(*density, "density");
  }

  void read_pins(const toml::table& t, ScenePins& pins) const {
    check_keys(t, {"corners", "vertices", "box"}, "[pin]");
    pins.line = line_of(t);
    static const std::vector<std::string> kCorners = {"top-left", "top-right", "bottom-left",
                                                      "bottom-right"};
    if (auto* n = t.get("corners")) {
      const toml::array* a = n->as_array();
      if (!a) fail(*n, "'corners' must be an array of names like [\"top-left\", \"top-right\"]");
      for (const toml::node& c : *a) {
        const std::string name = string(c, "corners");
        if (std::find(kCorners.begin(), kCorners.end(), name) == kCorners.end()) {
          fail(c, "unknown corner '" + name +
                      "': expected top-left, top-right, bottom-left or bottom-right" +
                      did_you_mean(name, kCorners));
        }
        pins.corners.push_back(name);
      }
    }
    if (auto* n = t.get("vertices")) {
      const toml::array* a = n->as_array();
      if (!a) fail(*n, "'vertices' must be an array of point indices");
      for (const toml::node& v : *a)
        pins.vertices.push_back(integer(v, "vertices", 0, std::int64_t(1) << 32));
    }
    if (auto* n = t.get("box")) {
      auto read_box = [&](const toml::node& b) {
        const toml::table* bt = b.as_table();
        if (!bt) fail(b, "'box' must be a table { min = [x, y, z], max = [x, y, z] }");
        check_keys(*bt, {"min", "max"}, "a pin box");
        const toml::node* lo = bt->get("min");
        const toml::node* hi = bt->get("max");
        if (!lo || !hi) fail(b, "a pin box needs 'min' and 'max'");
        pins.boxes.emplace_back(vec3(*lo, "min"), vec3(*hi, "max"));
      };
      if (const toml::array* a = n->as_array()) {
        for (const toml::node& b : *a)
          read_box(b);
      } else {
        read_box(*n);
      }
    }
  }

  template <class F>
  void for_each_table(const toml::table& root, const std::string& key, F&& f) const {
    const toml::node* node = root.get(key);
    if (!node) return;
    const toml::array* list = node->as_array();
    if (!list || !list->is_array_of_tables()) {
      fail(*node, "'" + key + "' must be written as [[" + key + "]] tables");
    }
    for (const toml::node& entry : *list)
      f(*entry.as_table());
  }

  const toml::node& require(const toml::table& t, const std::string& key, const std::string& where,
                            const std::string& what) const {
    const toml::node* n = t.get(key);
    if (!n) fail(t, where + " needs '" + key + "' (" + what + ")");
    return *n;
  }

  Real non_negative_real(const toml::node& node, const std::string& key) const {
    const Real v = real(node, key);
    if (v < 0) fail(node, "'" + key + "' must not be negative, not " + toml_text(node));
    return v;
  }

  Selection require_selection(const toml::table& t, const std::string& where) const {
    const toml::node* n = t.get("select");
    if (!n) {
      fail(t, where + " needs 'select': a side (\"top\", \"left\"...), a corner " +
                  "(\"top-left\"...), \"all\", or a table such as { box = { min = [..], max = " +
                  "[..] } }, { sphere = { center = [..], radius = r } }, { vertices = [..] }, " +
                  "{ group = tag }");
    }
    return selection(*n);
  }

  Selection selection(const toml::node& node) const {
    Selection sel;
    sel.line = line_of(node);
    std::vector<std::string> names = side_names();
    names.insert(names.end(), corner_names().begin(), corner_names().end());
    names.push_back("all");
    auto by_name = [&](const toml::node& n) {
      const std::string name = string(n, "select");
      if (name == "all") {
        sel.kind = Selection::Kind::kAll;
      } else if (std::find(side_names().begin(), side_names().end(), name) != side_names().end()) {
        sel.kind = Selection::Kind::kSide;
      } else if (std::find(corner_names().begin(), corner_names().end(), name) !=
                 corner_names().end()) {
        sel.kind = Selection::Kind::kCorner;
      } else {
        fail(n, "unknown selection '" + name +
                    "': expected a side (top, bottom, left, right, front, back), a corner "
                    "(top-left, top-right, bottom-left, bottom-right) or all" +
                    did_you_mean(name, names));
      }
      sel.name = name;
    };
    if (node.is_string()) {
      by_name(node);
      return sel;
    }
    const toml::table* t = node.as_table();
    if (!t) {
      fail(node,
           "'select' must be a name such as \"top\" or a table such as { box = { min = [..], "
           "max = [..] } }, not " +
               type_name(node));
    }
    check_keys(*t, {"side", "corner", "within", "vertices", "box", "sphere", "group"},
               "a selection");
    int kinds = 0;
    for (const char* k : {"side", "corner", "vertices", "box", "sphere", "group"})
      kinds += t->get(k) ? 1 : 0;
    if (kinds != 1) {
      fail(node, "a selection takes exactly one of side, corner, vertices, box, sphere or group");
    }
    if (auto* n = t->get("side")) by_name(*n);
    if (auto* n = t->get("corner")) by_name(*n);
    if (auto* n = t->get("within")) {
      if (sel.kind != Selection::Kind::kSide && sel.kind != Selection::Kind::kCorner)
        fail(*n, "'within' goes with a side or a corner");
      sel.within = non_negative_real(*n, "within");
    }
    if (auto* n = t->get("vertices")) {
      sel.kind = Selection::Kind::kVertices;
      const toml::array* a = n->as_array();
      if (!a || a->empty()) fail(*n, "'vertices' must be a non-empty array of point indices");
      for (const toml::node& v : *a)
        sel.vertices.push_back(integer(v, "vertices", 0, std::int64_t(1) << 32));
    }
    if (auto* n = t->get("box")) {
      sel.kind = Selection::Kind::kBox;
      const toml::table* bt = n->as_table();
      if (!bt) fail(*n, "'box' must be a table { min = [x, y, z], max = [x, y, z] }");
      check_keys(*bt, {"min", "max"}, "a box");
      sel.lo = vec3(require(*bt, "min", "a box", "[x, y, z]"), "min");
      sel.hi = vec3(require(*bt, "max", "a box", "[x, y, z]"), "max");
      if (!(sel.lo.array() <= sel.hi.array()).all())
        fail(*n, "a box needs min <= max on each axis");
    }
    if (auto* n = t->get("sphere")) {
      sel.kind = Selection::Kind::kSphere;
      const toml::table* st = n->as_table();
      if (!st) fail(*n, "'sphere' must be a table { center = [x, y, z], radius = r }");
      check_keys(*st, {"center", "radius"}, "a sphere");
      sel.centre = vec3(require(*st, "center", "a sphere", "[x, y, z]"), "center");
      sel.radius = positive_real(require(*st, "radius", "a sphere", "a length"), "radius");
    }
    if (auto* n = t->get("group")) {
      sel.kind = Selection::Kind::kGroup;
      sel.group = integer(*n, "group", INT64_MIN, INT64_MAX);
    }
    return sel;
  }

  void read_handle(const toml::table& t, Scene& scene) const {
    check_keys(t, {"name", "select", "velocity", "keyframes", "pivot", "release"}, "[[handle]]");
    SceneHandle h;
    h.line = line_of(t);
    h.motion.name = "handle" + std::to_string(scene.handles.size() + 1);
    if (auto* n = t.get("name")) h.motion.name = string(*n, "name");
    for (const SceneHandle& other : scene.handles) {
      if (other.motion.name == h.motion.name)
        fail(t, "two handles are named '" + h.motion.name + "'");
    }
    h.select = require_selection(t, "[[handle]]");
    if (auto* n = t.get("velocity")) h.motion.velocity = vec3(*n, "velocity");
    if (auto* n = t.get("pivot")) {
      h.motion.pivot = vec3(*n, "pivot");
      h.pivot_given = true;
    }
    if (auto* n = t.get("release")) h.motion.release = non_negative_real(*n, "release");
    if (auto* n = t.get("keyframes")) {
      const toml::array* a = n->as_array();
      if (!a || !a->is_array_of_tables() || a->empty()) {
        fail(*n,
             "'keyframes' must be an array of tables like { time = 1.0, translate = [0, 0, "
             "0.1], rotate = [0, 0, 30] }");
      }
      Real last = -INFINITY;
      for (const toml::node& k : *a) {
        const toml::table& kt = *k.as_table();
        check_keys(kt, {"time", "translate", "rotate"}, "a keyframe");
        HandleMotion::Keyframe key;
        key.time = non_negative_real(require(kt, "time", "a keyframe", "seconds"), "time");
        if (!(key.time > last)) fail(k, "keyframe times must increase");
        last = key.time;
        if (auto* tr = kt.get("translate")) key.translate = vec3(*tr, "translate");
        if (auto* rot = kt.get("rotate")) key.rotate_degrees = vec3(*rot, "rotate");
        h.motion.keyframes.push_back(key);
      }
    }
    scene.handles.push_back(h);
  }

  void read_load(const toml::table& t, Scene& scene) const {
    check_keys(t, {"name", "select", "force", "per_vertex", "acceleration", "start", "ramp"},
               "[[load]]");
    SceneLoad l;
    l.line = line_of(t);
    l.spec.name = "load" + std::to_string(scene.loads.size() + 1);
    if (auto* n = t.get("name")) l.spec.name = string(*n, "name");
    if (t.get("select")) l.select = require_selection(t, "[[load]]");
    if (auto* n = t.get("force")) l.spec.force = vec3(*n, "force");
    if (auto* n = t.get("per_vertex")) l.spec.per_vertex = boolean(*n, "per_vertex");
    if (auto* n = t.get("acceleration")) l.spec.acceleration = vec3(*n, "acceleration");
    if (auto* n = t.get("start")) l.spec.start = non_negative_real(*n, "start");
    if (auto* n = t.get("ramp")) l.spec.ramp = non_negative_real(*n, "ramp");
    if (!t.get("force") && !t.get("acceleration"))
      fail(t,
           "[[load]] needs 'force' ([fx, fy, fz] in N) or 'acceleration' ([ax, ay, az] in m/s^2)");
    scene.loads.push_back(l);
  }

  void read_obstacle(const toml::table& t, Scene& scene) const {
    SceneObstacle so;
    so.line = line_of(t);
    Obstacle& o = so.obstacle;
    const std::vector<std::string> shapes = {"plane", "sphere", "box", "capsule"};
    const std::string shape =
        string(require(t, "shape", "[[obstacle]]", "plane, sphere, box or capsule"), "shape");
    std::vector<std::string> keys = {"shape", "velocity", "friction", "start"};
    if (shape == "plane") {
      o.shape = Obstacle::Shape::kPlane;
      keys.insert(keys.end(), {"point", "normal"});
    } else if (shape == "sphere") {
      o.shape = Obstacle::Shape::kSphere;
      keys.insert(keys.end(), {"center", "radius"});
    } else if (shape == "box") {
      o.shape = Obstacle::Shape::kBox;
      keys.insert(keys.end(), {"min", "max"});
    } else if (shape == "capsule") {
      o.shape = Obstacle::Shape::kCapsule;
      keys.insert(keys.end(), {"from", "to", "radius"});
    } else {
      fail(*t.get("shape"), "unknown obstacle shape '" + shape +
                                "': expected plane, sphere, box or capsule" +
                                did_you_mean(shape, shapes));
    }
    check_keys(t, keys, "[[obstacle]] '" + shape + "'");
    const std::string where = "a " + shape + " obstacle";
    switch (o.shape) {
      case Obstacle::Shape::kPlane:
        if (auto* n = t.get("point")) o.a = vec3(*n, "point");
        if (auto* n = t.get("normal")) o.b = vec3(*n, "normal");
        if (o.b.norm() == 0) fail(t, "the normal of a plane must not be zero");
        break;
      case Obstacle::Shape::kSphere:
        o.a = vec3(require(t, "center", where, "[x, y, z]"), "center");
        o.radius = positive_real(require(t, "radius", where, "a length"), "radius");
        break;
      case Obstacle::Shape::kBox:
        o.a = vec3(require(t, "min", where, "[x, y, z]"), "min");
        o.b = vec3(require(t, "max", where, "[x, y, z]"), "max");
        if (!(o.a.array() < o.b.array()).all()) fail(t, "a box needs min < max on each axis");
        break;
      case Obstacle::Shape::kCapsule:
        o.a = vec3(require(t, "from", where, "one end of its axis"), "from");
        o.b = vec3(require(t, "to", where, "the other end of its axis"), "to");
        o.radius = positive_real(require(t, "radius", where, "a length"), "radius");
        break;
    }
    if (auto* n = t.get("velocity")) o.velocity = vec3(*n, "velocity");
    if (auto* n = t.get("friction")) o.friction = non_negative_real(*n, "friction");
    if (auto* n = t.get("start")) o.start = non_negative_real(*n, "start");
    scene.obstacles.push_back(so);
  }

  void read_components(const toml::table& root, const std::string& key,
                       const std::vector<ComponentSpec>& known,
                       std::vector<ComponentUse>& out) const {
    const toml::node* node = root.get(key);
    if (!node) return;
    const toml::array* list = node->as_array();
    if (!list || !list->is_array_of_tables()) {
      fail(*node, "'" + key + "' must be written as [[" + key + "]] tables");
    }
    std::vector<std::string> names;
    names.reserve(known.size());
    for (const ComponentSpec& c : known)
      names.push_back(c.name);
    for (const toml::node& entry : *list) {
      const toml::table& t = *entry.as_table();
      const toml::node* name_node = t.get("name");
      if (!name_node) fail(entry, "[[" + key + "]] needs a 'name'");
      ComponentUse use;
      use.name = string(*name_node, "name");
      use.line = line_of(*name_node);
      const ComponentSpec* spec = Catalog::find(known, use.name);
      if (!spec) {
        std::string list_text;
        for (const std::string& n : names)
          list_text += (list_text.empty() ? "" : ", ") + n;
        fail(*name_node, "unknown " + key + " '" + use.name + "'" + did_you_mean(use.name, names) +
                             "; this simulator has: " + (list_text.empty() ? "none" : list_text));
      }
      std::vector<std::string> allowed{"name"};
      for (const ParamSpec& p : spec->params)
        allowed.push_back(p.name);
      check_keys(t, allowed, "[[" + key + "]] '" + use.name + "'");
      for (const ParamSpec& p : spec->params) {
        const toml::node* v = t.get(p.name);
        if (!v) {
          if (!p.default_value)
            fail(line_of(t), key + " '" + use.name + "' needs parameter '" + p.name + "'" +
                                 (p.description.empty() ? "" : " (" + p.description + ")"));
          use.params[p.name] = {*p.default_value, use.line};
          continue;
        }
        use.params[p.name] = {param_value(*v, p, use.name), line_of(*v)};
      }
      out.push_back(std::move(use));
    }
  }

  Value param_value(const toml::node& node, const ParamSpec& p, const std::string& owner) const {
    const std::string key = owner + "." + p.name;
    switch (p.type) {
      case ValueType::kReal: {
        const Real v = real(node, p.name);
        if (p.positive && !(v > 0))
          fail(node,
               "'" + p.name + "' of '" + owner + "' must be positive, not " + toml_text(node));
        if (p.non_negative && v < 0)
          fail(node,
               "'" + p.name + "' of '" + owner + "' must not be negative, not " + toml_text(node));
        return v;
      }
      case ValueType::kInt: {
        const std::int64_t v =
            integer(node, p.name, p.positive ? 1 : (p.non_negative ? 0 : INT64_MIN), INT64_MAX);
        return v;
      }
      case ValueType::kBool:
        return Bool(boolean(node, p.name));
      case ValueType::kVec3:
        return vec3(node, p.name);
      case ValueType::kMat3: {
        const toml::array* a = node.as_array();
        if (!a || a->size() != 9)
          fail(node, "'" + p.name + "' must be an array of 9 numbers (row by row)");
        Mat3 m;
        for (int i = 0; i < 9; ++i)
          m(i / 3, i % 3) = real(*a->get(static_cast<std::size_t>(i)), p.name);
        return m;
      }
    }
    (void)key;
    fail(node, "unsupported parameter type");
  }

  void read_output(const toml::table& t, SceneOutput& out) const {
    check_keys(
        t,
        {"dir", "every", "formats", "png_every", "png_size", "camera", "gif_delay", "vtu_encoding"},
        "[output]");
    if (auto* n = t.get("camera")) {
      const std::string mode = string(*n, "camera");
      if (mode == "fixed") {
        out.camera = CameraMode::kFixed;
      } else if (mode == "follow") {
        out.camera = CameraMode::kFollow;
      } else if (mode == "follow_union") {
        out.camera = CameraMode::kFollowUnion;
      } else {
        fail(*n, "unknown camera '" + mode + "': expected fixed, follow or follow_union" +
                     did_you_mean(mode, {"fixed", "follow", "follow_union"}));
      }
    }
    if (auto* n = t.get("gif_delay"))
      out.gif_delay_ms = static_cast<int>(integer(*n, "gif_delay", 10, 10000));
    if (auto* n = t.get("vtu_encoding")) {
      const std::string encoding = string(*n, "vtu_encoding");
      if (encoding != "binary" && encoding != "ascii") {
        fail(*n, "unknown vtu_encoding '" + encoding + "': expected \"binary\" or \"ascii\"");
      }
      out.vtu_ascii = encoding == "ascii";
    }
    if (auto* n = t.get("dir")) out.dir = string(*n, "dir");
    if (auto* n = t.get("every")) out.every = static_cast<int>(integer(*n, "every", 1, 1 << 30));
    if (auto* n = t.get("png_every"))
      out.png_every = static_cast<int>(integer(*n, "png_every", 0, 1 << 30));
    if (auto* n = t.get("formats")) {
      static const std::vector<std::string> kFormats = {"vtu", "obj", "png", "gif", "csv"};
      const toml::array* a = n->as_array();
      if (!a) fail(*n, "'formats' must be an array such as [\"vtu\", \"png\", \"csv\"]");
      out.formats.clear();
      for (const toml::node& f : *a) {
        const std::string name = string(f, "formats");
        if (std::find(kFormats.begin(), kFormats.end(), name) == kFormats.end()) {
          fail(f, "unknown output format '" + name + "': expected vtu, obj, png, gif or csv" +
                      did_you_mean(name, kFormats));
        }
        out.formats.push_back(name);
      }
    }
    if (auto* n = t.get("png_size")) {
      const toml::array* a = n->as_array();
      if (!a || a->size() != 2) fail(*n, "'png_size' must be [width, height]");
      out.width = static_cast<int>(integer(*a->get(0), "png_size", 16, 8192));
      out.height = static_cast<int>(integer(*a->get(1), "png_size", 16, 8192));
    }
  }

  std::string path_;
  std::optional<std::string_view> text_;
  const Catalog& catalog_;
};

}  // namespace

Scene read_scene(const std::string& path, const Catalog& catalog) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, 0, "no such scene file");
  return SceneReader(path, std::nullopt, catalog).read();
}

Scene read_scene_text(const std::string& path, std::string_view text, const Catalog& catalog) {
  return SceneReader(path, text, catalog).read();
}

}  // namespace rift
