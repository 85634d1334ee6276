#include "rift/pack/component_use.hpp"

#include <variant>

namespace rift {

Real ComponentUse::real(const std::string& param) const {
  const Value& v = params.at(param).value;
  if (auto* i = std::get_if<std::int64_t>(&v)) return static_cast<Real>(*i);
  return std::get<Real>(v);
}
Vec3 ComponentUse::vec3(const std::string& param) const {
  return std::get<Vec3>(params.at(param).value);
}
std::int64_t ComponentUse::integer(const std::string& param) const {
  return std::get<std::int64_t>(params.at(param).value);
}
bool ComponentUse::boolean(const std::string& param) const {
  return std::get<Bool>(params.at(param).value);
}

}  // namespace rift
