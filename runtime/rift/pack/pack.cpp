#include "rift/pack/pack.hpp"

#include <stdexcept>

namespace rift {

namespace {

template <class T>
void declare_one(GMap& map, const EmbeddingDecl& d) {
  map.declare_embedding<T>(d.name, d.orbit, d.policy, std::get<T>(d.default_value));
}

}  // namespace

void declare_embeddings(GMap& map, const std::vector<EmbeddingDecl>& decls) {
  for (const EmbeddingDecl& d : decls) {
    if (const ColumnBase* existing = map.find_column(d.name)) {
      const OrbitAttachment* att = map.attachment_of(d.name);
      if (existing->type() != d.type || att->orbit() != d.orbit) {
        throw std::invalid_argument(
            "embedding '" + d.name + "' is declared as " + std::string(to_string(d.type)) + " on " +
            d.orbit.str() + " but the map has it as " + std::string(to_string(existing->type())) +
            " on " + att->orbit().str());
      }
      continue;
    }
    switch (d.type) {
      case ValueType::kReal:
        declare_one<Real>(map, d);
        break;
      case ValueType::kInt:
        declare_one<std::int64_t>(map, d);
        break;
      case ValueType::kBool:
        declare_one<Bool>(map, d);
        break;
      case ValueType::kVec3:
        declare_one<Vec3>(map, d);
        break;
      case ValueType::kMat3:
        declare_one<Mat3>(map, d);
        break;
    }
  }
}

Catalog PackRegistry::catalog(int dimension) const {
  Catalog all;
  for (const auto& p : packs_) {
    if (dimension != 0 && p->dimension() != dimension) continue;
    const Catalog& c = p->catalog();
    for (ComponentSpec s : c.interactions) {
      s.dimension = p->dimension();
      if (!Catalog::find(all.interactions, s.name)) all.interactions.push_back(std::move(s));
    }
    for (ComponentSpec s : c.criteria) {
      s.dimension = p->dimension();
      if (!Catalog::find(all.criteria, s.name)) all.criteria.push_back(std::move(s));
    }
  }
  return all;
}

const Pack* PackRegistry::find(const std::string& name) const {
  for (const auto& p : packs_) {
    if (p->name() == name) return p.get();
  }
  return nullptr;
}

const Pack* PackRegistry::pack_of_interaction(const std::string& name, int dimension) const {
  for (const auto& p : packs_) {
    if (p->dimension() == dimension && Catalog::find(p->catalog().interactions, name)) {
      return p.get();
    }
  }
  return nullptr;
}

const Pack* PackRegistry::pack_of_criterion(const std::string& name, int dimension) const {
  for (const auto& p : packs_) {
    if (p->dimension() == dimension && Catalog::find(p->catalog().criteria, name)) return p.get();
  }
  return nullptr;
}

}  // namespace rift
