#include "parse/loader.hpp"

#include <algorithm>
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

  /// Reads one file; `owner` is the imported pack its code belongs to (empty:
  /// the pack riftc compiles), `import` the import that named it, if any.
  void read(int file_id, bool included = false, const std::string& owner = {},
            const ast::Include* import = nullptr) {
    in_progress_.push_back(file_id);
    ast::File file;
    file.included = included;
    parse_file(sources_, file_id, diags_, file);
    file.owner = import && file.has_header ? file.pack.text : owner;
    if (import) {
      check_import(file, *import);
    } else {
      check_dimension(file);
    }
    const std::string base = fs::path(sources_.file(file_id).path).parent_path().string();
    std::vector<ast::Include> includes = file.includes;
    const std::string file_owner = file.owner;
    program_.files.push_back(std::move(file));
    for (const ast::Include& inc : includes)
      include(base, inc, file_owner);
    in_progress_.pop_back();
  }

  void include(const std::string& base, const ast::Include& inc, const std::string& owner) {
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
    const char* what = inc.import ? "import" : "include";
    const int known = sources_.find(path);
    if (known >= 0) {
      for (std::size_t k = 0; k < in_progress_.size(); ++k) {
        if (in_progress_[k] != known) continue;
        std::string chain;
        for (std::size_t j = k; j < in_progress_.size(); ++j)
          chain += fs::path(sources_.file(in_progress_[j]).path).filename().string() + " -> ";
        chain += fs::path(path).filename().string();
        diags_.error(inc.loc, std::string(what) + " cycle: '" + path + "' is already being read (" +
                                  chain + ")");
        return;
      }
      // Read once; an import names its pack however often it is written.
      if (inc.import && owner.empty()) {
        for (const ast::File& f : program_.files) {
          if (f.file_id == known && !f.owner.empty()) add_import(f.owner);
        }
      }
      return;
    }
    const int id = sources_.load(path);
    if (id < 0) {
      diags_.error(inc.loc, std::string("cannot read ") + (inc.import ? "imported" : "included") +
                                " file '" + path + "'");
      return;
    }
    read(id, true, owner, inc.import ? &inc : nullptr);
    if (inc.import && owner.empty() && !program_.files.empty()) {
      for (const ast::File& f : program_.files) {
        if (f.file_id == id && !f.owner.empty()) add_import(f.owner);
      }
    }
  }

 private:
  void add_import(const std::string& pack) {
    if (std::find(program_.imports.begin(), program_.imports.end(), pack) == program_.imports.end())
      program_.imports.push_back(pack);
  }

  /// An imported file must be a pack (it has its own generated code) of the
  /// importing pack's dimension; reported at the import.
  void check_import(const ast::File& file, const ast::Include& import) {
    if (!file.has_header) {
      diags_.error(import.loc,
                   "cannot import '" + import.path +
                       "': it has no 'pack NAME dimension N;' header, and only a pack can "
                       "be imported");
      return;
    }
    if (ast::declares_only_functions(file)) return;  // reads no G-map: any dimension
    if (have_dimension_ && file.dimension != program_.dimension) {
      diags_
          .error(import.loc, "cannot import pack '" + file.pack.text + "': it is " +
                                 std::to_string(file.dimension) + "-dimensional and this pack is " +
                                 std::to_string(program_.dimension) + "-dimensional")
          .notes.push_back(
              {file.dimension_loc, "'" + file.pack.text + "' declares its dimension here"});
      return;
    }
    check_dimension(file);
  }

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
