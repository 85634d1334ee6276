// The helper code every generated pack source starts with (in an anonymous
// namespace): reusable buffers, the row builder of the instantiation orbit,
// the embedding slot maintenance after a rewrite, orbit collections, and the
// generic matrix built-ins. It is plain C++ over runtime/ headers only.
#pragma once

#include <string_view>

namespace rift::emit {

std::string_view prelude();

}  // namespace rift::emit
