#include "check/builtins.hpp"

#include <map>

namespace rift::check {

namespace {

using ast::Type;
constexpr Type R = Type::Real;
constexpr Type I = Type::Int;
constexpr Type V = Type::Vec3;
constexpr Type M = Type::Mat3;

const std::map<std::string, std::vector<Signature>, std::less<>>& table() {
  static const std::map<std::string, std::vector<Signature>, std::less<>> t = [] {
    std::map<std::string, std::vector<Signature>, std::less<>> m;
    for (const char* f : {"sqrt", "exp", "log", "sin", "cos", "tan", "acos", "asin", "atan"}) {
      m[f] = {{{R}, R}};
    }
    m["abs"] = {{{I}, I}, {{R}, R}};
    m["atan2"] = {{{R, R}, R}};
    m["pow"] = {{{R, R}, R}};
    m["min"] = {{{I, I}, I}, {{R, R}, R}};
    m["max"] = {{{I, I}, I}, {{R, R}, R}};
    m["clamp"] = {{{I, I, I}, I}, {{R, R, R}, R}};
    m["real"] = {{{R}, R}};
    m["int"] = {{{I}, I}, {{R}, I}};
    m["vec3"] = {{{R, R, R}, V}};
    m["mat3"] = {{{V, V, V}, M}, {{R, R, R, R, R, R, R, R, R}, M}};
    m["identity"] = {{{}, M}};
    m["dot"] = {{{V, V}, R}};
    m["cross"] = {{{V, V}, V}};
    m["norm"] = {{{V}, R}};
    m["normalize"] = {{{V}, V}};
    m["outer"] = {{{V, V}, M}};
    m["transpose"] = {{{M}, M}};
    m["inverse"] = {{{M}, M}};
    m["det"] = {{{M}, R}};
    m["trace"] = {{{M}, R}};
    m["rotation"] = {{{M}, M}};
    m["max_eigenvalue"] = {{{M}, R}};
    m["max_eigenvector"] = {{{M}, V}};
    m["eigenvalues"] = {{{M}, V}};
    // Its argument's value, held constant when riftc differentiates forces.
    m["stop_gradient"] = {{{R}, R}, {{V}, V}, {{M}, M}};
    return m;
  }();
  return t;
}

bool fits(const Signature& s, const std::vector<Type>& args, bool promote) {
  if (s.params.size() != args.size()) return false;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k] == s.params[k]) continue;
    if (promote && args[k] == I && s.params[k] == R) continue;
    return false;
  }
  return true;
}

}  // namespace

const std::vector<Signature>* builtin(std::string_view name) {
  auto it = table().find(name);
  return it == table().end() ? nullptr : &it->second;
}

const Signature* select_overload(const std::vector<Signature>& overloads,
                                 const std::vector<Type>& args) {
  for (const Signature& s : overloads) {
    if (fits(s, args, false)) return &s;
  }
  for (const Signature& s : overloads) {
    if (fits(s, args, true)) return &s;
  }
  return nullptr;
}

std::string describe(const std::vector<Type>& types) {
  std::string out = "(";
  for (std::size_t k = 0; k < types.size(); ++k) {
    if (k) out += ", ";
    out += ast::to_string(types[k]);
  }
  return out + ")";
}

}  // namespace rift::check
