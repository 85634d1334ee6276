// Reading a scene from TOML text already in memory (tests, fuzzing); files
// are read by read_scene (scene.hpp), which this shares every check with.
#pragma once

#include <string>
#include <string_view>

#include "rift/scene/scene.hpp"

namespace rift {

/// read_scene on `text`: `path` names it in messages, and relative mesh
/// files are looked up next to it.
Scene read_scene_text(const std::string& path, std::string_view text, const Catalog& catalog);

}  // namespace rift
