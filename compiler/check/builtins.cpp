#include "check/builtins.hpp"

#include <map>

namespace rift::check {

namespace {

using ast::Type;
constexpr Type kR = Type::Real;
constexpr Type kI = Type::Int;
constexpr Type kV = Type::Vec3;
constexpr Type kM = Type::Mat3;

const std::map<std::string, std::vector<Signature>, std::less<>>& table() {
  static const std::map<std::string, std::vector<Signature>, std::less<>> kTable = [] {
    std::map<std::string, std::vector<Signature>, std::less<>> m;
    for (const char* f : {"sqrt", "exp", "log", "sin", "cos", "tan", "acos", "asin", "atan"}) {
      m[f] = {{{kR}, kR}};
    }
    m["abs"] = {{{kI}, kI}, {{kR}, kR}};
    m["atan2"] = {{{kR, kR}, kR}};
    m["pow"] = {{{kR, kR}, kR}};
    m["min"] = {{{kI, kI}, kI}, {{kR, kR}, kR}};
    m["max"] = {{{kI, kI}, kI}, {{kR, kR}, kR}};
    m["clamp"] = {{{kI, kI, kI}, kI}, {{kR, kR, kR}, kR}};
    m["real"] = {{{kR}, kR}};
    m["int"] = {{{kI}, kI}, {{kR}, kI}};
    m["vec3"] = {{{kR, kR, kR}, kV}};
    m["mat3"] = {{{kV, kV, kV}, kM}, {{kR, kR, kR, kR, kR, kR, kR, kR, kR}, kM}};
    m["identity"] = {{{}, kM}};
    m["dot"] = {{{kV, kV}, kR}};
    m["cross"] = {{{kV, kV}, kV}};
    m["norm"] = {{{kV}, kR}};
    m["normalize"] = {{{kV}, kV}};
    m["outer"] = {{{kV, kV}, kM}};
    m["transpose"] = {{{kM}, kM}};
    m["inverse"] = {{{kM}, kM}};
    m["det"] = {{{kM}, kR}};
    m["trace"] = {{{kM}, kR}};
    m["rotation"] = {{{kM}, kM}};
    m["max_eigenvalue"] = {{{kM}, kR}};
    m["max_eigenvector"] = {{{kM}, kV}};
    m["eigenvalues"] = {{{kM}, kV}};
    // Its argument's value, held constant when riftc differentiates forces.
    m["stop_gradient"] = {{{kR}, kR}, {{kV}, kV}, {{kM}, kM}};
    return m;
  }();
  return kTable;
}

bool fits(const Signature& s, const std::vector<Type>& args, bool promote) {
  if (s.params.size() != args.size()) return false;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k] == s.params[k]) continue;
    if (promote && args[k] == kI && s.params[k] == kR) continue;
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
