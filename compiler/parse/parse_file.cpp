#include "parse/parse_file.hpp"

#include "parse/lexer.hpp"
#include "parse/parser.hpp"

namespace rift::parse {

void parse_file(const diag::SourceManager& sources, int file_id, diag::Diagnostics& diags,
                ast::File& out) {
  out.file_id = file_id;
  grammar::Lexer lexer(sources.file(file_id).text, file_id, diags);
  ParseContext ctx{lexer, out, diags, {}, {}, {}, {}, nullptr, nullptr, nullptr};
  grammar::Parser parser(ctx);
  parser.parse();
}

}  // namespace rift::parse
