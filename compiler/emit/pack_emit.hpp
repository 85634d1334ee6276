// A whole pack as one header (the API a simulator includes) and one source.
#pragma once

#include <string>

#include "emit/emit_context.hpp"

namespace rift::emit {

struct GeneratedPack {
  std::string header_name;  // <pack>.hpp
  std::string source_name;  // <pack>.cpp
  std::string header;
  std::string source;
};

GeneratedPack generate_pack(const PackModel& model, const diag::SourceManager& sources);

}  // namespace rift::emit
