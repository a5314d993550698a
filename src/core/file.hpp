// Files the user asked to keep are written whole or not at all.
//
// A regular file (or a name that does not exist yet) is replaced atomically:
// the text goes to a temporary file with a unique name in the same folder
// ("<name>.tmp-XXXXXX", created with O_EXCL | O_NOFOLLOW, so a file or link
// planted there is never written through), is flushed to the disk and renamed
// over the target. An existing target keeps its permission bits (and, where
// the process may, its owner and group); a symbolic link is followed, so the
// file it names is replaced and the link stays a link. A target that is not a
// regular file (a device such as /dev/null or /dev/full, a FIFO, a terminal;
// "-", /dev/stdout, /dev/stderr, /dev/fd/N) is written in place, as the text
// comes: it is never replaced by a file. A write error (ENOSPC, EPIPE, ...)
// is an error value (kFileAccess) that names the file and the reason.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "core/diag.hpp"

namespace skipnc {

// How an output name is written.
enum class OutputMode : std::uint8_t {
  kReplace,     // a regular file or a new name: through a temporary, then rename
  kDescriptor,  // "-", /dev/stdout, /dev/stderr, /dev/fd/N: the open descriptor
  kInPlace,     // a device, a FIFO, a socket: opened and written where it is
};

struct OutputTarget {
  std::string name;  // as given
  OutputMode mode = OutputMode::kReplace;
  std::string path;  // kReplace: the file to replace (links followed); else the name
  int fd = -1;       // kDescriptor: the descriptor
  bool exists = false;
  // The file's identity when it exists (dev, inode); for a new name, `path`
  // made absolute identifies it.
  dev_t dev = 0;
  ino_t ino = 0;
  bool char_device = false;  // /dev/null, a terminal: sharing one is harmless
};

// Decides how `name` is written, without writing anything.
[[nodiscard]] Result<OutputTarget> resolve_output(const std::string& name);

// True when two outputs, or an output and an input, are the same file: the
// same (device, inode), or the same absolute path for names not yet created.
// Character devices are never "the same" (two outputs to /dev/null are fine).
bool same_file(const OutputTarget& a, const OutputTarget& b) noexcept;

// An output written as it comes (the trace) or at once (the report). The
// first write error is kept; later writes do nothing and commit() returns it.
class OutputFile {
 public:
  OutputFile() = default;
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  OutputFile(OutputFile&& o) noexcept;
  OutputFile& operator=(OutputFile&& o) noexcept;

  // `fixed_temporary`: a replaced file is written to "<name><fixed_temporary>"
  // (e.g. ".partial"), a name the user can find when the process is killed
  // before commit(); one left by an earlier run is replaced. Empty: a unique
  // random name.
  [[nodiscard]] static Result<OutputFile> open(const std::string& name,
                                               std::string_view fixed_temporary = {});
  // Writes all of `text` (retrying short writes and EINTR).
  [[nodiscard]] Result<void> write(std::string_view text);
  // Ends the output: a replaced file is flushed and renamed into place; an
  // in-place output is closed. Returns the first error of the output.
  [[nodiscard]] Result<void> commit();
  // Abandons the output: the temporary file is removed, the target is left
  // as it was (an in-place output keeps what was written).
  void discard() noexcept;

  std::uint64_t bytes_written() const noexcept { return bytes_; }
  bool failed() const noexcept { return !error_.empty(); }
  const std::string& name() const noexcept { return target_.name; }
  const OutputTarget& target() const noexcept { return target_; }
  // The temporary file of a replaced output ("" otherwise).
  const std::string& temporary() const noexcept { return tmp_; }

 private:
  OutputTarget target_;
  int fd_ = -1;
  bool own_fd_ = false;
  std::string tmp_;
  std::string error_;
  std::uint64_t bytes_ = 0;
};

// Inputs. Every file a run reads besides the program (machine files and
// their `extends` chain, scenes, STL meshes, sweep specs, variable and
// parameter files) is read through read_input_file: only a regular file is
// read (a device such as /dev/zero, a FIFO, a socket or a folder is refused
// with its name, without waiting for a writer), and a file larger than the
// cap of its kind is refused before a byte of it is read (docs/bad-input.md).
struct InputKind {
  std::string_view what;    // "machine file", "scene file", ...
  std::uint64_t max_bytes;  // the cap
};
inline constexpr InputKind kMachineFileInput{"machine file", 1u << 20};
inline constexpr InputKind kSceneFileInput{"scene file", 16u << 20};
inline constexpr InputKind kSweepSpecInput{"sweep spec", 1u << 20};
inline constexpr InputKind kVariableFileInput{"variable file", 1u << 20};
inline constexpr InputKind kParameterFileInput{"parameter file", 16u << 20};
// 256 MiB: a binary STL of 5.3 million facets.
inline constexpr InputKind kStlFileInput{"STL mesh", 256u << 20};

// The file's size when it can be read as `kind` (kFileAccess naming it and
// why not otherwise); with `fd_out`, the open descriptor is handed over.
[[nodiscard]] Result<std::uint64_t> check_input_file(const std::string& path, InputKind kind,
                                                     int* fd_out = nullptr);
// The whole file, read once.
[[nodiscard]] Result<std::string> read_input_file(const std::string& path, InputKind kind);

// Writes `text` to `name` as above: whole or not at all for a regular file.
[[nodiscard]] Result<void> write_file_atomic(const std::string& name, std::string_view text);

}  // namespace skipnc
