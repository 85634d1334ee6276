// Small file helpers shared by the writers: folders, atomic whole-file writes,
// zero-padded frame names and exact, locale-free number formatting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rift {

/// Creates `dir` and its missing parents. Throws OutputError when it cannot,
/// or when `dir` exists and is not a folder.
void ensure_directory(const std::filesystem::path& dir);

/// Writes `data` to `path.tmp` then renames it over `path`: a reader (or a
/// crash) sees either the old file or the complete new one, never a part.
/// Throws OutputError with the path and the OS error (e.g. disk full).
void write_file_atomically(const std::filesystem::path& path, std::string_view data);

/// "frame_000042.vtu" for (frame_, 42, "vtu"): the index zero-padded to
/// `digits` (wider indices are written in full).
std::string frame_file_name(std::string_view prefix, std::size_t index, std::string_view extension,
                            int digits = 6);

/// Appends the shortest decimal text that reads back as exactly `value`
/// (std::to_chars: no locale, no precision loss). Non-finite values are
/// written as nan, inf, -inf.
void append_real(std::string& out, double value);
void append_int(std::string& out, std::int64_t value);

/// Appends `text` with &, <, >, " escaped for an XML attribute or text.
void append_xml_escaped(std::string& out, std::string_view text);

}  // namespace rift
