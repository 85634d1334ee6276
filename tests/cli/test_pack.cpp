// A hand-written pack for testing the command line before (and independently
// of) the packs compiled from rules/: a stretch spring on every half-edge and
// a criterion separating the faces of over-stretched edges, in 2D and 3D.
#include "../sim/test_spring_model.hpp"
#include "cli/register_packs.hpp"
#include "rift/core/interrupt.hpp"
#include "rift/pack/pack.hpp"

namespace rift::test {
namespace {

class LongEdge final : public Criterion {
 public:
  explicit LongEdge(Real limit) : limit_(limit) {}
  const std::string& name() const override { return name_; }
  void initialise(GMap& map) override {
    position_ = map.embedding<Vec3>("position");
    n_ = map.dimension();
  }
  void collect(const GMap& map, std::vector<TearCandidate>& out) const override {
    map.for_each_cell(Orbit::cell(1, n_), [&](Dart d) {
      if (map.is_free(d, n_)) return;
      const Real len = (position_[map.alpha(d, 0)] - position_[d]).norm();
      if (len > limit_) out.push_back({0, d, len, {}, 0});
    });
  }
  bool apply(GMap& map, const TearCandidate& c, std::vector<Dart>& touched) override {
    if (map.is_free(c.at, n_)) return false;
    map.for_each_in_orbit(c.at, Orbit::sewing(n_, n_), [&](Dart x) {
      touched.push_back(x);
      touched.push_back(map.alpha(x, n_));
    });
    map.unsew(c.at, n_);
    return true;
  }

 private:
  std::string name_ = "test_long_edge";
  Real limit_;
  int n_ = 2;
  Embedding<Vec3> position_;
};

// A criterion whose every cell, a vertex, walks the whole face around it:
// on one face of n corners a collection costs n walks of 2n darts, which
// makes a step as long as a test of interrupts needs (a 300,000-gon: minutes).
// It polls for an interrupt once per cell, as generated criteria do, and
// never gives a candidate.
class FaceWalk final : public Criterion {
 public:
  const std::string& name() const override { return name_; }
  void initialise(GMap& map) override { position_ = map.embedding<Vec3>("position"); }
  void collect(const GMap& map, std::vector<TearCandidate>& out) const override {
    map.for_each_cell(Orbit{1, 2}, [&](Dart v) {
      throw_if_interrupted();
      Real spread = 0;
      map.for_each_in_orbit(v, Orbit{0, 1},
                            [&](Dart x) { spread += (position_[x] - position_[v]).norm(); });
      if (spread < 0) out.push_back({0, v, spread, {}, 0});  // never: keeps the walk
    });
  }
  bool apply(GMap&, const TearCandidate&, std::vector<Dart>&) override { return false; }

 private:
  std::string name_ = "test_face_walk";
  Embedding<Vec3> position_;
};

class TestPack final : public Pack {
 public:
  explicit TestPack(int dimension)
      : dimension_(dimension), name_("test" + std::to_string(dimension) + "d") {
    catalog_.interactions.push_back(
        {"test_springs",
         "a damped spring on every half-edge",
         {{"stiffness", ValueType::kReal, std::nullopt, "N/m", true, false},
          {"damping", ValueType::kReal, Value(0.0), "N s/m", false, true}}});
    catalog_.criteria.push_back({"test_long_edge",
                                 "separates the elements of an edge longer than the limit",
                                 {{"limit", ValueType::kReal, std::nullopt, "m", true, false}}});
    catalog_.criteria.push_back(
        {"test_face_walk", "walks the whole face from each of its vertices (never tears)", {}});
  }
  const std::string& name() const override { return name_; }
  int dimension() const override { return dimension_; }
  const std::string& description() const override { return description_; }
  const std::vector<EmbeddingDecl>& embeddings() const override { return embeddings_; }
  const Catalog& catalog() const override { return catalog_; }
  std::vector<std::string> rule_names() const override { return {}; }
  void initialise(GMap&) const override {}
  std::unique_ptr<ForceModel> make_interaction(const ComponentUse& use) const override {
    return std::make_unique<HalfEdgeSprings>(use.real("stiffness"), use.real("damping"));
  }
  std::unique_ptr<Criterion> make_criterion(const ComponentUse& use) const override {
    if (use.name == "test_face_walk") return std::make_unique<FaceWalk>();
    return std::make_unique<LongEdge>(use.real("limit"));
  }
  std::unique_ptr<Rule> make_rule(const std::string&) const override { return nullptr; }

 private:
  int dimension_;
  std::string name_;
  std::string description_ = "hand-written test pack";
  std::vector<EmbeddingDecl> embeddings_;
  Catalog catalog_;
};

}  // namespace
}  // namespace rift::test

void rift_register_packs(rift::PackRegistry& packs) {
  packs.add(std::make_unique<rift::test::TestPack>(2));
  packs.add(std::make_unique<rift::test::TestPack>(3));
}
