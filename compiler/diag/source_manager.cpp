#include "diag/source_manager.hpp"

#include <fstream>
#include <sstream>

namespace rift::diag {

int SourceManager::add(std::string path, std::string text) {
  auto f = std::make_unique<SourceFile>();
  f->path = std::move(path);
  f->text = std::move(text);
  f->line_starts.push_back(0);
  for (std::size_t i = 0; i < f->text.size(); ++i) {
    if (f->text[i] == '\n') f->line_starts.push_back(i + 1);
  }
  files_.push_back(std::move(f));
  return static_cast<int>(files_.size() - 1);
}

int SourceManager::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return -1;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return -1;
  return add(path, buffer.str());
}

int SourceManager::find(std::string_view path) const {
  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (files_[i]->path == path) return static_cast<int>(i);
  }
  return -1;
}

std::string_view SourceManager::line_text(int id, int line) const {
  if (id < 0 || static_cast<std::size_t>(id) >= files_.size() || line < 1) return {};
  const SourceFile& f = *files_[static_cast<std::size_t>(id)];
  const auto index = static_cast<std::size_t>(line - 1);
  if (index >= f.line_starts.size()) return {};
  const std::size_t begin = f.line_starts[index];
  std::size_t end = index + 1 < f.line_starts.size() ? f.line_starts[index + 1] - 1 : f.text.size();
  if (end > begin && f.text[end - 1] == '\r') --end;
  return std::string_view(f.text).substr(begin, end - begin);
}

}  // namespace rift::diag
