// The runtime's support for generated code (rift/generated/, core/
// symmetric_eigen.hpp), tested on its own: a match's rows, injectivity, slot
// upkeep after a rewrite (merge, split, new orbit), aggregates over orbits,
// the symmetric eigen-solver, and set-up helpers.
#include "rift/generated/support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "test_maps.hpp"

namespace rift {
namespace {

using generated::build_rows;
using generated::distinct_darts;
using generated::scratch;
using generated::Scratch;
using generated::update_embedding_slots;

std::set<Dart> orbit_of(const GMap& g, Dart d, Orbit o) {
  std::set<Dart> out;
  g.for_each_in_orbit(d, o, [&](Dart x) { out.insert(x); });
  return out;
}

TEST(MatchRows, OneRowPerDartOfTheHookOrbitAndTheSameWalkFromEveryHook) {
  GMap g(2);
  const Dart quad1 = test::make_polygon(g, 4);
  const Dart quad2 = test::make_polygon(g, 4);
  const Dart hooks[] = {quad1, quad2 + 2};  // any dart of the second face
  const int dims[] = {0, 1, 0, 1};          // each hook's label
  Scratch& s = scratch();
  std::size_t rows = 0;
  ASSERT_TRUE(build_rows(g, hooks, 2, dims, 2, s, rows));
  ASSERT_EQ(rows, 8u);
  const std::set<Dart> first(s.rows.begin(), s.rows.begin() + 8);
  EXPECT_EQ(first, orbit_of(g, quad1, Orbit{0, 1}));
  EXPECT_EQ(s.rows[0], quad1);
  const std::set<Dart> second(s.rows.begin() + 8, s.rows.end());
  EXPECT_EQ(second, orbit_of(g, quad2, Orbit{0, 1}));
  // Row r of each hook is reached by the same links: the two orbits are
  // isomorphic row by row.
  for (std::size_t j = 0; j < 2; ++j) {
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(g.alpha(s.rows[j * rows + r], dims[k]), s.rows[j * rows + s.nbr[r * 2 + k]]);
      }
    }
  }
}

TEST(MatchRows, HooksOnOrbitsOfDifferentShapesDoNotMatch) {
  GMap g(2);
  const Dart quad = test::make_polygon(g, 4);
  const Dart triangle = test::make_polygon(g, 3);
  const Dart hooks[] = {quad, triangle};
  const int dims[] = {0, 1, 0, 1};
  std::size_t rows = 0;
  EXPECT_FALSE(build_rows(g, hooks, 2, dims, 2, scratch(), rows));
  // No hook: a generator, one row.
  EXPECT_TRUE(build_rows(g, hooks, 0, dims, 2, scratch(), rows));
  EXPECT_EQ(rows, 1u);
}

TEST(MatchRows, AHookWithARenamedLabelWalksItsOrbitWithItsOwnLinks) {
  // Hooks labelled <0,1> and <1,0>: row r of the second face is reached from
  // its hook by the first's walk with 0 and 1 swapped.
  GMap g(2);
  const Dart quad1 = test::make_polygon(g, 4);
  const Dart quad2 = test::make_polygon(g, 4);
  const Dart hooks[] = {quad1, quad2};
  const int dims[] = {0, 1, 1, 0};
  Scratch& s = scratch();
  std::size_t rows = 0;
  ASSERT_TRUE(build_rows(g, hooks, 2, dims, 2, s, rows));
  ASSERT_EQ(rows, 8u);
  const std::set<Dart> second(s.rows.begin() + 8, s.rows.end());
  EXPECT_EQ(second, orbit_of(g, quad2, Orbit{0, 1}));
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(g.alpha(s.rows[r], dims[k]), s.rows[s.nbr[r * 2 + k]]);
      EXPECT_EQ(g.alpha(s.rows[rows + r], dims[2 + k]), s.rows[rows + s.nbr[r * 2 + k]]);
    }
  }
  // The row the first hook reaches by alpha_0 is the one the second reaches by alpha_1.
  EXPECT_EQ(s.rows[rows + s.nbr[0]], g.alpha(quad2, 1));
}

// A hook orbit of hundreds of darts (a 200-gon, 400 darts: the row index
// grows past its first size several times) among thousands of other darts:
// every dart of the orbit gets one row, each link lands on its row, and the
// index the walk used holds the orbit, not the map (the first rule applied
// to a map of millions of darts must not fill an array per dart).
TEST(MatchRows, ALargeOrbitInALargeMapGetsItsRowsFromAnIndexOfItsOwnSize) {
  GMap g(2);
  for (int i = 0; i < 2000; ++i)
    test::make_polygon(g, 4);
  const Dart big = test::make_polygon(g, 200);
  const Dart hooks[] = {big};
  const int dims[] = {0, 1};
  Scratch& s = scratch();
  std::size_t rows = 0;
  ASSERT_TRUE(build_rows(g, hooks, 1, dims, 2, s, rows));
  ASSERT_EQ(rows, 400u);
  const std::set<Dart> found(s.rows.begin(), s.rows.end());
  EXPECT_EQ(found, orbit_of(g, big, Orbit{0, 1}));
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t k = 0; k < 2; ++k)
      ASSERT_EQ(g.alpha(s.rows[r], dims[k]), s.rows[s.nbr[r * 2 + k]]) << "row " << r;
  }
  EXPECT_LT(s.row_index.size(), 4 * rows);
  EXPECT_LT(s.row_index.size(), g.capacity() / 4);
  // The next walk starts afresh: a small face after the big one.
  ASSERT_TRUE(build_rows(g, hooks, 0, dims, 2, s, rows));
  const Dart small[] = {0};
  ASSERT_TRUE(build_rows(g, small, 1, dims, 2, s, rows));
  EXPECT_EQ(rows, 8u);
  EXPECT_EQ(std::set<Dart>(s.rows.begin(), s.rows.end()), orbit_of(g, 0, Orbit{0, 1}));
}

TEST(MatchRows, DistinctDartsAndNoMarkLeftBehind) {
  GMap g(2);
  test::make_polygon(g, 3);
  const Dart distinct[] = {0, 1, 2, 5};
  const Dart repeated[] = {0, 1, 2, 1, 4};
  EXPECT_TRUE(distinct_darts(g, distinct, 4));
  EXPECT_FALSE(distinct_darts(g, repeated, 5));
  EXPECT_EQ(g.reserved_marks(), 0);
  const Mark m = g.reserve_mark();
  EXPECT_EQ(g.marked_count(m), 0u);
  g.free_mark(m);
}

// Two triangles with a vertex weight summed when vertices merge.
struct TwoTriangles {
  GMap g{2};
  Dart a = test::make_polygon(g, 3);
  Dart b = test::make_polygon(g, 3);
  Embedding<Real> w = g.add_embedding<Real>("w", Orbit{1, 2}, MergePolicy::kSum, 0.0);
  Embedding<Real> edge = g.add_embedding<Real>("edge", Orbit{0, 2}, MergePolicy::kKeepFirst, 0.0);

  // Links (or unlinks) edge 0 of a to edge 0 of b along alpha 2, as a rule's
  // rewrite does: the links first, the slots after.
  std::vector<Dart> set_link(bool linked) {
    const Dart pairs[][2] = {{a, b}, {g.alpha(a, 0), g.alpha(b, 0)}};
    for (const auto& p : pairs) {
      if (linked) {
        g.link(p[0], p[1], 2);
      } else {
        g.unlink(p[0], 2);
      }
    }
    std::vector<Dart> darts = {a, b, g.alpha(a, 0), g.alpha(b, 0)};
    std::vector<Dart> touched;
    update_embedding_slots(g, darts.data(), darts.size(), scratch(), &touched);
    return touched;
  }
};

TEST(SlotUpkeep, MergedOrbitsCombineWithThePolicyAndSplitOnesKeepACopy) {
  TwoTriangles t;
  t.w[t.a] = 1.0;
  t.w[t.b] = 2.0;
  t.edge[t.a] = 5.0;
  t.edge[t.b] = 7.0;
  const std::vector<Dart> touched = t.set_link(true);
  EXPECT_TRUE(t.g.is_valid());
  EXPECT_EQ(t.w.slot(t.a), t.w.slot(t.b));
  EXPECT_EQ(t.w[t.a], 3.0);     // kSum
  EXPECT_EQ(t.edge[t.b], 5.0);  // kKeepFirst: the first dart's orbit's value
  EXPECT_FALSE(touched.empty());
  for (Dart x : touched)
    EXPECT_TRUE(t.g.is_alive(x));

  t.set_link(false);
  EXPECT_TRUE(t.g.is_valid());
  EXPECT_NE(t.w.slot(t.a), t.w.slot(t.b));
  EXPECT_EQ(t.w[t.a], 3.0);  // a split keeps a copy for each part (§4.1)
  EXPECT_EQ(t.w[t.b], 3.0);
  EXPECT_EQ(t.edge[t.a], 5.0);
  EXPECT_EQ(t.edge[t.b], 5.0);
}

TEST(SlotUpkeep, ANewOrbitGetsTheDefault) {
  GMap g(2);
  auto w = g.add_embedding<Real>("w", Orbit{1, 2}, MergePolicy::kSum, 0.25);
  const Dart d = test::make_polygon(g, 4);
  std::vector<Dart> darts;
  g.for_each_in_orbit(d, Orbit{0, 1}, [&](Dart x) { darts.push_back(x); });
  update_embedding_slots(g, darts.data(), darts.size(), scratch(), nullptr);
  EXPECT_TRUE(g.is_valid());
  std::set<Slot> slots;
  for (Dart x : darts) {
    ASSERT_NE(w.slot(x), kNoSlot);
    EXPECT_EQ(w[x], 0.25);
    slots.insert(w.slot(x));
  }
  EXPECT_EQ(slots.size(), 4u);  // one per vertex of the quad
}

// Per-dart attachments (<>) are by dart (attachment.hpp): a dart's slot is
// the dart itself, never shared. A dart given another's slot takes a copy of
// its values at once; in the upkeep (no orbit walk) a dart without its value
// gets the default, every other dart keeps its own, and a dart listed twice
// is upkept once.
TEST(SlotUpkeep, PerDartSlotsStayOnePerDart) {
  GMap g(2);
  auto f = g.add_embedding<Real>("f", Orbit{}, MergePolicy::kKeepFirst, -1.0);
  const Dart d = test::make_polygon(g, 4);
  std::vector<Dart> darts;
  g.for_each_in_orbit(d, Orbit{0, 1}, [&](Dart x) { darts.push_back(x); });
  update_embedding_slots(g, darts.data(), darts.size(), scratch(), nullptr);
  for (std::size_t i = 0; i < darts.size(); ++i)
    f[darts[i]] = static_cast<Real>(i);
  // Darts 1 and 2 given dart 0's slot, as a rewrite copying a dart would
  // do: they take copies of its value in their own slots. Dart 3 loses its slot.
  OrbitAttachment* att = nullptr;
  for (const auto& a : g.attachments())
    if (a->orbit().empty()) att = a.get();
  ASSERT_NE(att, nullptr);
  const Slot shared = f.slot(darts[0]);
  const Slot kept = f.slot(darts[4]);
  ASSERT_TRUE(att->by_dart());
  EXPECT_EQ(att->slot_data(), nullptr);
  att->assign(darts[1], shared);
  att->assign(darts[2], shared);
  EXPECT_EQ(f.slot(darts[1]), darts[1]);
  att->release(darts[3]);
  EXPECT_EQ(f.slot(darts[3]), kNoSlot);
  const std::vector<Dart> listed = {darts[0], darts[1], darts[0], darts[2],
                                    darts[3], darts[4], darts[4]};
  std::vector<Dart> touched;
  update_embedding_slots(g, listed.data(), listed.size(), scratch(), &touched);
  EXPECT_TRUE(g.is_valid());
  EXPECT_EQ(f.slot(darts[0]), shared);
  EXPECT_EQ(f.slot(darts[4]), kept);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(f.slot(darts[i]), darts[i]) << "dart " << i << ": its own slot";
  std::set<Slot> slots;
  for (std::size_t i = 0; i < 5; ++i) {
    ASSERT_NE(f.slot(darts[i]), kNoSlot) << "dart " << i;
    slots.insert(f.slot(darts[i]));
  }
  EXPECT_EQ(slots.size(), 5u) << "one slot per dart";
  EXPECT_EQ(f[darts[0]], 0.0);
  EXPECT_EQ(f[darts[1]], 0.0);  // copies of the slot they shared
  EXPECT_EQ(f[darts[2]], 0.0);
  EXPECT_EQ(f[darts[3]], -1.0);  // a new slot: the default
  EXPECT_EQ(f[darts[4]], 4.0);
  const std::set<Dart> moved(touched.begin(), touched.end());
  EXPECT_EQ(moved, (std::set<Dart>{darts[3]}));  // the only one given a slot
  EXPECT_EQ(touched.size(), moved.size()) << "a dart touched twice";
}

TEST(OrbitValues, OneValuePerCornerOfAFace) {
  // `OP x over <0,1>(quad)` with x on vertices <1,2>: the fold over the
  // sub-orbits <1> of the face, its corners.
  GMap g(2);
  const Dart quad = test::make_polygon(g, 4);
  auto x = g.add_embedding<Vec3>("x", Orbit{1, 2}, MergePolicy::kKeepFirst, Vec3::Zero());
  auto k = g.add_embedding<std::int64_t>("k", Orbit{1, 2}, MergePolicy::kKeepFirst, 0);
  for (int i = 0; i < 4; ++i) {
    const Dart corner = quad + 2 * static_cast<Dart>(i);
    x[corner] = Vec3(i, 2 * i, 1);
    k[corner] = 10 + i;
  }
  const Orbit face{0, 1}, corner{1};
  EXPECT_EQ(generated::count_sub_orbits(g, quad, face, corner), 4);  // 8 darts, 4 corners
  EXPECT_EQ(generated::fold_sum(g, x, quad, face, corner), Vec3(6, 12, 4));
  EXPECT_EQ(generated::fold_mean(g, x, quad, face, corner), Vec3(1.5, 3, 1));
  EXPECT_EQ(generated::fold_mean(g, k, quad, face, corner), 11.5);  // of integers: a real
  EXPECT_EQ(generated::fold_min(g, k, quad, face, corner), 10);
  EXPECT_EQ(generated::fold_max(g, k, quad, face, corner), 13);
  // Over a single vertex's orbit: its own value.
  EXPECT_EQ(generated::fold_sum(g, k, quad + 2, Orbit{1, 2}, Orbit{1, 2}), 11);
}

/// Two quads' faces through an OrbitMemo, keyed by darts (`slotted` false)
/// or by the slots of an embedding on the faces: one entry per face, found
/// from any of its darts; each value computed once per collection.
void expect_one_entry_per_face_and_collection(bool slotted) {
  GMap g(2);
  const Dart q1 = test::make_polygon(g, 4);
  const Dart q2 = test::make_polygon(g, 4);
  const Orbit face{0, 1};
  if (slotted) g.add_embedding<Real>("w", face, MergePolicy::kKeepFirst, 0.0);
  generated::OrbitMemo memo;
  generated::OrbitMemoValues<Real> values;
  int computed = 0;
  for (int collection = 0; collection < 3; ++collection) {
    memo.begin(g, face);
    // The second quad first: entries are numbered in visiting order.
    const std::uint32_t e2 = memo.entry(g, q2 + 5, face);
    const std::uint32_t e1 = memo.entry(g, q1, face);
    EXPECT_EQ(e2, 0u);
    EXPECT_EQ(e1, 1u);
    for (Dart k = 0; k < 8; ++k) {
      EXPECT_EQ(memo.entry(g, q1 + k, face), e1);
      EXPECT_EQ(memo.entry(g, q2 + k, face), e2);
    }
    EXPECT_EQ(memo.entries(), 2u);
    // Computed on the first request of each collection, then read back.
    const Real v = 10.0 * collection;
    for (int ask = 0; ask < 3; ++ask) {
      EXPECT_EQ(values.get(memo, e1, 0,
                           [&] {
                             ++computed;
                             return v + 1;
                           }),
                v + 1);
      EXPECT_EQ(values.get(memo, e2, 0,
                           [&] {
                             ++computed;
                             return v + 2;
                           }),
                v + 2);
    }
  }
  EXPECT_EQ(computed, 6);
}

TEST(OrbitMemo, OneEntryPerOrbitAndValuesForgottenByTheNextCollection) {
  expect_one_entry_per_face_and_collection(false);
  expect_one_entry_per_face_and_collection(true);
}

/// The darts GMap::for_each_sub_orbit gives, in its order.
std::vector<Dart> sub_orbits_by_marks(const GMap& g, Dart d, Orbit o, Orbit sub) {
  std::vector<Dart> out;
  g.for_each_sub_orbit(d, o, sub, [&](Dart x) { out.push_back(x); });
  return out;
}

TEST(SubOrbits, TheDartsAndOrderOfTheMarkingWalkWithOrWithoutSlots) {
  // A strip of quads sewn along edges: each vertex is met by several faces.
  GMap g(2);
  std::vector<Dart> quads;
  for (int i = 0; i < 4; ++i)
    quads.push_back(test::make_polygon(g, 4));
  for (int i = 0; i + 1 < 4; ++i)
    ASSERT_TRUE(g.sew(quads[static_cast<std::size_t>(i)] + 2,
                      quads[static_cast<std::size_t>(i) + 1] + 7, 2));
  const Orbit vertex{1, 2}, face{0, 1}, corner{1}, all{0, 1, 2};
  for (int slotted = 0; slotted < 2; ++slotted) {
    if (slotted) {
      g.add_embedding<Real>("f", face, MergePolicy::kKeepFirst, 0.0);
      g.add_embedding<Real>("c", corner, MergePolicy::kKeepFirst, 0.0);
    }
    for (Dart d = 0; d < g.capacity(); ++d) {
      for (const auto& [o, sub] : {std::pair{vertex, face}, std::pair{all, face},
                                   std::pair{face, corner}, std::pair{all, corner}}) {
        std::vector<Dart> got;
        // A nested walk in f (a fold inside a fold) must not disturb the outer one.
        generated::for_each_sub_orbit(g, d, o, sub, [&](Dart x) {
          got.push_back(x);
          std::size_t inner = 0;
          generated::for_each_sub_orbit(g, x, face, corner, [&](Dart) { ++inner; });
          EXPECT_EQ(inner, 4u);
        });
        EXPECT_EQ(got, sub_orbits_by_marks(g, d, o, sub))
            << "dart " << d << ", slotted " << slotted;
      }
    }
  }
  EXPECT_EQ(generated::sub_orbit_buffers().depth, 0u);
}

// Nested lists (a script's for-each applying a script that lists darts of
// its own) each keep their darts; a list opened after one closed reuses its
// buffer empty, and a warm list allocates nothing new from the pool.
TEST(DartLists, NestedListsKeepTheirDartsAndReuseTheirBuffers) {
  const std::size_t pooled = scratch().dart_lists.size();
  const Dart* inner_buffer = nullptr;
  {
    generated::DartList outer;
    for (Dart d = 0; d < 5; ++d)
      outer.push_back(d);
    for (Dart d : outer) {
      generated::DartList inner;
      for (Dart k = 0; k < 100; ++k)
        inner.push_back(1000 + d * 100 + k);
      ASSERT_EQ(inner.size(), 100u);
      EXPECT_EQ(*inner.begin(), 1000 + d * 100);
      if (inner_buffer == nullptr) inner_buffer = inner.begin();
      EXPECT_EQ(inner.begin(), inner_buffer) << "the closed list's buffer is reused";
    }
    ASSERT_EQ(outer.size(), 5u);
    for (Dart d = 0; d < 5; ++d)
      EXPECT_EQ(outer.begin()[d], d);
  }
  EXPECT_EQ(scratch().dart_lists_open, 0u);
  EXPECT_EQ(scratch().dart_lists.size(), std::max<std::size_t>(pooled, 2));
  generated::DartList again;
  EXPECT_EQ(again.size(), 0u);
}

TEST(SymmetricEigen, EigenvaluesAndTheLargestEigenvectorOfRandomSpectra) {
  std::mt19937 rng(3);
  std::normal_distribution<Real> n(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    Eigen::Quaternion<Real> q(n(rng), n(rng), n(rng), n(rng));
    q.normalize();
    const Mat3 r = q.toRotationMatrix();
    Vec3 lambda(n(rng), n(rng), n(rng));
    if (trial % 5 == 0) lambda(1) = lambda(0);  // repeated eigenvalues
    std::sort(lambda.data(), lambda.data() + 3);
    const Mat3 m = r * lambda.asDiagonal() * r.transpose();
    const Vec3 found = symmetric_eigenvalues(m);
    EXPECT_LT((found - lambda).norm(), 1e-12 * (1 + lambda.norm())) << "trial " << trial;
    EXPECT_NEAR(symmetric_max_eigenvalue(m), lambda(2), 1e-12 * (1 + lambda.norm()));
    const Vec3 v = symmetric_max_eigenvector(m);
    EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    // M v = λ3 v (the eigenvector of a repeated λ3 is any of its space).
    EXPECT_LT((m * v - lambda(2) * v).norm(), 1e-10 * (1 + lambda.norm())) << "trial " << trial;
  }
}

TEST(SymmetricEigen, TheClosedFormLargestEigenvalueEqualsTheSolversNearDegenerateSpectraIncluded) {
  // Random rotations of spectra whose eigenvalues are apart, nearly equal in
  // pairs (gaps from 1e-1 down to 1e-15 of the spread, either pair), or all
  // nearly equal, around a large or a zero mean: symmetric_max_eigenvalue
  // (the closed form, or the solver where it is ill-conditioned) against the
  // solver's λ3 and the spectrum it was built from.
  std::mt19937 rng(7);
  std::normal_distribution<Real> n(0, 1);
  std::uniform_int_distribution<int> gap_exponent(1, 15);
  std::size_t closed_form = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Eigen::Quaternion<Real> rot(n(rng), n(rng), n(rng), n(rng));
    rot.normalize();
    const Mat3 r = rot.toRotationMatrix();
    Vec3 lambda(n(rng), n(rng), n(rng));
    std::sort(lambda.data(), lambda.data() + 3);
    const Real gap = std::pow(10.0, -gap_exponent(rng));
    switch (trial % 4) {
      case 0:
        break;  // apart
      case 1:
        lambda(1) = lambda(0) + gap;
        break;  // the two smallest nearly equal
      case 2:
        lambda(1) = lambda(2) - gap;
        break;  // the two largest nearly equal
      default:
        lambda = Vec3(1, 1 + gap, 1 - gap);
        break;  // all three nearly equal
    }
    const Real mean = trial % 3 == 0 ? 1e4 : 0.0;  // a large isotropic part
    lambda.array() += mean;
    std::sort(lambda.data(), lambda.data() + 3);
    const Mat3 m = r * lambda.asDiagonal() * r.transpose();
    const Real scale = 1 + lambda.cwiseAbs().maxCoeff();
    const Real fast = symmetric_max_eigenvalue(m);
    EXPECT_NEAR(fast, symmetric_eigenvalues(m)(2), 1e-12 * scale) << "trial " << trial;
    EXPECT_NEAR(fast, lambda(2), 1e-12 * scale) << "trial " << trial;
    closed_form += fast != symmetric_eigenvalues(m)(2);
  }
  // The closed form did answer most of them (not the solver every time).
  EXPECT_GT(closed_form, 1000u);
  EXPECT_EQ(symmetric_max_eigenvalue(Mat3::Zero()), 0.0);
  EXPECT_EQ(symmetric_max_eigenvalue(Mat3(3.5 * Mat3::Identity())), 3.5);
  EXPECT_TRUE(std::isnan(symmetric_max_eigenvalue(Mat3::Constant(std::nan("")))));
}

TEST(PackValues, ParameterValuesTaggedDartsAndRequiredEmbeddings) {
  EXPECT_EQ(generated::value_as<Real>(Value{std::int64_t{3}}, "k"), 3.0);
  EXPECT_EQ(generated::value_as<Vec3>(Value{Vec3(1, 2, 3)}, "v"), Vec3(1, 2, 3));
  EXPECT_TRUE(generated::value_as<bool>(Value{Bool{true}}, "b"));
  try {
    generated::value_as<Vec3>(Value{2.0}, "parameter 'gravity'");
    ADD_FAILURE() << "a real read as a vec3";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "parameter 'gravity' has a value of the wrong type");
  }

  GMap g(2);
  const Dart quad = test::make_polygon(g, 4);
  auto tag = g.add_embedding<Bool>("tag", Orbit{}, MergePolicy::kKeepFirst, Bool{false});
  EXPECT_EQ(generated::tagged_dart(g, tag, quad + 3, Orbit{0, 1}), kNoDart);
  tag[quad + 5] = Bool{true};
  EXPECT_EQ(generated::tagged_dart(g, tag, quad + 3, Orbit{0, 1}), quad + 5);

  EXPECT_TRUE(generated::require_embedding<Bool>(g, "tag", "interaction 'x'"));
  try {
    generated::require_embedding<Real>(g, "stiffness", "interaction 'stretch'");
    ADD_FAILURE() << "a missing embedding was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("interaction 'stretch' reads embedding 'stiffness'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rift
