// Files the user asked to keep are written whole or not at all.
#pragma once

#include <string>
#include <string_view>

#include "core/diag.hpp"

namespace skipnc {

// Writes `text` to `path` through `path.tmp`: written, flushed to the disk
// (fsync) and renamed over `path`. On any failure the temporary file is
// removed, `path` is left as it was, and the error (kFileAccess) names the
// file and the reason.
[[nodiscard]] Result<void> write_file_atomic(const std::string& path, std::string_view text);

}  // namespace skipnc
