#include "parse/loader.hpp"

#include <filesystem>

#include "parse/parse_file.hpp"
#include "parse/state_embeddings.hpp"

namespace rift::parse {

namespace {

namespace fs = std::filesystem;

class Loader {
 public:
  Loader(diag::SourceManager& sources, diag::Diagnostics& diags, ast::Program& program,
         std::vector<std::string> include_dirs = {})
      : sources_(sources),
        diags_(diags),
        program_(program),
        include_dirs_(std::move(include_dirs)) {}

  void read(int file_id, bool included = false) {
    in_progress_.push_back(file_id);
    ast::File file;
    file.included = included;
    parse_file(sources_, file_id, diags_, file);
    check_dimension(file);
    const std::string base = fs::path(sources_.file(file_id).path).parent_path().string();
    std::vector<ast::Include> includes = file.includes;
    program_.files.push_back(std::move(file));
    for (const ast::Include& inc : includes)
      include(base, inc);
    in_progress_.pop_back();
  }

  void include(const std::string& base, const ast::Include& inc) {
    std::string path =
        (base.empty() ? fs::path(inc.path) : fs::path(base) / inc.path).lexically_normal().string();
    std::error_code ec;
    if (!fs::exists(path, ec) && fs::path(inc.path).is_relative()) {
      for (const std::string& dir : include_dirs_) {
        const std::string candidate = (fs::path(dir) / inc.path).lexically_normal().string();
        if (fs::exists(candidate, ec)) {
          path = candidate;
          break;
        }
      }
    }
    const int known = sources_.find(path);
    if (known >= 0) {
      for (int open : in_progress_) {
        if (open == known) {
          diags_.error(inc.loc, "include cycle: '" + path + "' is already being read");
          return;
        }
      }
      return;  // read once
    }
    const int id = sources_.load(path);
    if (id < 0) {
      diags_.error(inc.loc, "cannot read included file '" + path + "'");
      return;
    }
    read(id, true);
  }

 private:
  void check_dimension(const ast::File& file) {
    if (!file.has_header) return;
    // A pack of functions only reads no G-map: a pack of any dimension may
    // include it (rules/laws.rules serves 2D and 3D), and it fixes none.
    if (ast::declares_only_functions(file)) return;
    if (!have_dimension_) {
      have_dimension_ = true;
      program_.dimension = file.dimension;
      first_ = file.dimension_loc;
      return;
    }
    if (file.dimension != program_.dimension) {
      diags_
          .error(file.dimension_loc, "pack '" + file.pack.text + "' has dimension " +
                                         std::to_string(file.dimension) + " but the pack is " +
                                         std::to_string(program_.dimension) + "-dimensional")
          .notes.push_back({first_, "dimension first given here"});
    }
  }

  diag::SourceManager& sources_;
  diag::Diagnostics& diags_;
  ast::Program& program_;
  std::vector<std::string> include_dirs_;
  std::vector<int> in_progress_;
  bool have_dimension_ = false;
  diag::Location first_;
};

}  // namespace

ast::Program load_program(const std::vector<std::string>& paths, diag::SourceManager& sources,
                          diag::Diagnostics& diags, const std::vector<std::string>& include_dirs) {
  ast::Program program;
  Loader loader(sources, diags, program, include_dirs);
  for (const std::string& path : paths) {
    if (sources.find(path) >= 0) continue;
    const int id = sources.load(path);
    if (id < 0) {
      diags.error({}, "cannot read '" + path + "'");
      continue;
    }
    loader.read(id);
  }
  add_state_embeddings(program, sources, diags);
  return program;
}

ast::Program load_text(const std::string& path, const std::string& text,
                       diag::SourceManager& sources, diag::Diagnostics& diags) {
  ast::Program program;
  Loader loader(sources, diags, program);
  loader.read(sources.add(path, text));
  add_state_embeddings(program, sources, diags);
  return program;
}

}  // namespace rift::parse
