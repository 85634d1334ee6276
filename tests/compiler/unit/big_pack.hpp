// A pack of `rules` rules and as many interactions, each a copy of a small
// 2D rule (with a parameter, a guard and an update) and a spring: the input
// of the riftc benchmark (tests/bench/riftc_bench.cpp) and of the test that
// such a pack compiles (big_pack_test.cpp).
#pragma once

#include <string>

namespace rift::test {

inline std::string big_pack(int rules) {
  std::string text = R"(pack big dimension 2;
embedding position : vec3 on <1,2> merge mean;
embedding corner_mass : real on <1> = 0.0;
embedding vertex_mass : real on <1,2> = 0.0 merge sum;
embedding f : vec3 on <> = vec3(0, 0, 0);
)";
  for (int k = 0; k < rules; ++k) {
    const std::string n = std::to_string(k);
    text += "rule tri" + n + R"((s : real) {
  left  { n0 : <0,1>; }
  right {
    n0 : <0,_>;  n1 : <_,2>;  n2 : <1,2>;
    n0 -1- n1 -0- n2;
    n2.position = s * mean position over <0,1>(n0);
  }
  when norm(n0.position) > s;
  update n2.vertex_mass = sum corner_mass over <1,2>(n2);
}
interaction spring)" +
            n + R"( on <0> {
  pattern { a : <>; b : <>; a -0- b; }
  let d = b.position - a.position;
  force a.f = d;
  force b.f = -d;
  energy dot(d, d);
}
)";
  }
  return text;
}

}  // namespace rift::test
