#include "parse/state_embeddings.hpp"

#include <sstream>
#include <vector>

#include "ast/orbit_text.hpp"

#include "parse/parse_file.hpp"
#include "rift/core/state_embeddings.hpp"

namespace rift::parse {

namespace {

const char* type_text(state::Kind kind) {
  switch (kind) {
    case state::Kind::kReal:
      return "real";
    case state::Kind::kVec3:
      return "vec3";
    case state::Kind::kBool:
      return "bool";
    case state::Kind::kInt:
      return "int";
  }
  return "real";
}

/// The table's orbit as dimensions, written as riftc writes every orbit.
std::string orbit_text(state::Where where, int dimension) {
  const int first = where == state::Where::kElement ? 0 : 1;
  const int last = where == state::Where::kVertex ? dimension : dimension - 1;
  std::vector<int> dims;
  for (int i = first; i <= last; ++i)
    dims.push_back(i);
  return ast::orbit_text(dims);
}

std::string default_text(const state::Declaration& d) {
  std::ostringstream number;
  number << d.fill;
  std::string n = number.str();
  switch (d.kind) {
    case state::Kind::kReal:
      return n.find('.') == std::string::npos ? n + ".0" : n;
    case state::Kind::kVec3: {
      const std::string c = n.find('.') == std::string::npos ? n + ".0" : n;
      return "vec3(" + c + ", " + c + ", " + c + ")";
    }
    case state::Kind::kBool:
      return d.fill != 0 ? "true" : "false";
    case state::Kind::kInt:
      return n;
  }
  return n;
}

const char* merge_text(state::Merge merge) {
  switch (merge) {
    case state::Merge::kKeep:
      return "keep";
    case state::Merge::kSum:
      return "sum";
    case state::Merge::kMean:
      return "mean";
  }
  return "keep";
}

}  // namespace

std::string state_embeddings_text(int dimension) {
  std::string text = "pack rift_state dimension " + std::to_string(dimension) + ";\n";
  for (const state::Declaration& d : state::kDeclarations) {
    text += "// " + std::string(d.role) + "\n";
    text += "embedding " + std::string(d.name) + " : " + type_text(d.kind) + " on " +
            orbit_text(d.where, dimension) + " = " + default_text(d) + " merge " +
            merge_text(d.merge) + ";\n";
  }
  return text;
}

void add_state_embeddings(ast::Program& program, diag::SourceManager& sources,
                          diag::Diagnostics& diags) {
  if (program.dimension < 0 || program.dimension > 3) return;  // reported by the checks
  ast::File file;
  parse_file(sources, sources.add(kStateSource, state_embeddings_text(program.dimension)), diags,
             file);
  file.builtin = true;
  program.files.push_back(std::move(file));
}

}  // namespace rift::parse
