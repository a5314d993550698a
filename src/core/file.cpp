#include "core/file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <utility>

namespace skipnc {
namespace {

namespace fs = std::filesystem;

// Symbolic links followed by hand before giving up (Linux's own limit).
constexpr int kMaxLinkHops = 40;
// Names tried for the temporary file before giving up (each is random).
constexpr int kTemporaryAttempts = 64;
constexpr std::string_view kTemporaryInfix = ".tmp-";
constexpr std::size_t kTemporaryRandomChars = 6;

std::string reason(int err) {
  return std::strerror(err);
}

std::unexpected<Error> io_error(std::string_view what, const std::string& name, int err) {
  return fail(AlarmId::kFileAccess, std::string(what) + " '" + name + "': " + reason(err));
}

// "-", /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: a descriptor.
int descriptor_of(std::string_view name) noexcept {
  if (name == "-" || name == "/dev/stdout") return STDOUT_FILENO;
  if (name == "/dev/stderr") return STDERR_FILENO;
  for (std::string_view prefix :
       {std::string_view("/dev/fd/"), std::string_view("/proc/self/fd/")}) {
    if (name.starts_with(prefix) && name.size() > prefix.size()) {
      int fd = -1;
      const char* first = name.data() + prefix.size();
      const char* last = name.data() + name.size();
      auto [p, ec] = std::from_chars(first, last, fd);
      if (ec == std::errc{} && p == last && fd >= 0) return fd;
    }
  }
  return -1;
}

std::string random_suffix() {
  static constexpr std::string_view kChars =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 rng = [] {
    std::random_device rd;
    const auto now =
        static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    std::seed_seq seq{rd(), rd(), static_cast<unsigned>(::getpid()), static_cast<unsigned>(now),
                      static_cast<unsigned>(now >> 32)};
    return std::mt19937_64(seq);
  }();
  std::string s(kTemporaryRandomChars, 'x');
  for (char& c : s) c = kChars[rng() % kChars.size()];
  return s;
}

void fsync_folder_of(const std::string& path) noexcept {
  std::error_code ec;
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int d = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (d < 0) return;
  (void)::fsync(d);
  ::close(d);
}

}  // namespace

Result<OutputTarget> resolve_output(const std::string& name) {
  OutputTarget t;
  t.name = name;
  t.path = name;
  if (name.empty()) return fail(AlarmId::kFileAccess, "an output file name is empty");
  struct stat st {};
  if (const int fd = descriptor_of(name); fd >= 0) {
    if (::fstat(fd, &st) != 0) return io_error("cannot write", name, errno);
    t.mode = OutputMode::kDescriptor;
    t.fd = fd;
    t.exists = true;
    t.dev = st.st_dev;
    t.ino = st.st_ino;
    t.char_device = S_ISCHR(st.st_mode);
    return t;
  }
  if (::stat(name.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    t.mode = OutputMode::kInPlace;
    t.exists = true;
    t.dev = st.st_dev;
    t.ino = st.st_ino;
    t.char_device = S_ISCHR(st.st_mode);
    return t;
  }
  // A regular file or a new name: follow symbolic links by hand, so that the
  // file at the end of them is replaced (a dangling link names the file to
  // create).
  std::string p = name;
  for (int hops = 0;; ++hops) {
    struct stat ls {};
    if (::lstat(p.c_str(), &ls) != 0) {
      if (errno == ENOENT) break;
      return io_error("cannot write", name, errno);
    }
    if (!S_ISLNK(ls.st_mode)) break;
    if (hops >= kMaxLinkHops) return io_error("cannot write", name, ELOOP);
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) return io_error("cannot write", name, ec.value());
    if (link.string().starts_with("/proc/")) {
      // A link into /proc (a descriptor of this process): written in place.
      t.mode = OutputMode::kInPlace;
      return t;
    }
    p = link.is_absolute() ? link.string() : (fs::path(p).parent_path() / link).string();
  }
  t.mode = OutputMode::kReplace;
  if (::stat(p.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode)) {
      t.mode = OutputMode::kInPlace;
      t.char_device = S_ISCHR(st.st_mode);
    }
    t.exists = true;
    t.dev = st.st_dev;
    t.ino = st.st_ino;
    t.path = p;
    return t;
  }
  // Not there yet: its absolute name identifies it.
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(fs::absolute(p, ec), ec);
  t.path = ec ? p : abs.string();
  return t;
}

bool same_file(const OutputTarget& a, const OutputTarget& b) noexcept {
  if (a.char_device || b.char_device) return false;
  if (a.exists && b.exists) return a.dev == b.dev && a.ino == b.ino;
  if (!a.exists && !b.exists) return a.path == b.path;
  return false;
}

OutputFile::~OutputFile() {
  discard();
}

OutputFile::OutputFile(OutputFile&& o) noexcept
    : target_(std::move(o.target_)),
      fd_(std::exchange(o.fd_, -1)),
      own_fd_(std::exchange(o.own_fd_, false)),
      tmp_(std::exchange(o.tmp_, {})),
      error_(std::move(o.error_)),
      bytes_(o.bytes_) {}

OutputFile& OutputFile::operator=(OutputFile&& o) noexcept {
  if (this != &o) {
    discard();
    target_ = std::move(o.target_);
    fd_ = std::exchange(o.fd_, -1);
    own_fd_ = std::exchange(o.own_fd_, false);
    tmp_ = std::exchange(o.tmp_, {});
    error_ = std::move(o.error_);
    bytes_ = o.bytes_;
  }
  return *this;
}

Result<OutputFile> OutputFile::open(const std::string& name, std::string_view fixed_temporary) {
  auto t = resolve_output(name);
  SKIPNC_TRY(t);
  OutputFile f;
  f.target_ = std::move(*t);
  switch (f.target_.mode) {
    case OutputMode::kDescriptor:
      // What the C library holds for the same descriptor goes first.
      if (f.target_.fd == STDOUT_FILENO) std::fflush(stdout);
      if (f.target_.fd == STDERR_FILENO) std::fflush(stderr);
      f.fd_ = f.target_.fd;
      f.own_fd_ = false;
      return f;
    case OutputMode::kInPlace: {
      // No O_CREAT, no O_TRUNC: a device or a FIFO is written as it is (a
      // FIFO waits here for its reader).
      // A signal while it waits ends the wait (EINTR): the run is stopping.
      const int fd = ::open(name.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) return io_error("cannot write", name, errno);
      f.fd_ = fd;
      f.own_fd_ = true;
      return f;
    }
    case OutputMode::kReplace:
      break;
  }
  struct stat old {};
  const bool had = ::stat(f.target_.path.c_str(), &old) == 0;
  int err = EEXIST;
  for (int attempt = 0; attempt < kTemporaryAttempts && err == EEXIST; ++attempt) {
    std::string tmp = f.target_.path;
    if (fixed_temporary.empty()) {
      tmp += kTemporaryInfix;
      tmp += random_suffix();
    } else {
      tmp += fixed_temporary;
      // An earlier run's leftover (or a link planted there) goes; the file
      // is then made anew with O_EXCL.
      struct stat ls {};
      if (attempt == 0 && ::lstat(tmp.c_str(), &ls) == 0 && !S_ISDIR(ls.st_mode))
        (void)::unlink(tmp.c_str());
    }
    // O_EXCL with O_CREAT never follows a link; O_NOFOLLOW says so twice.
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
      err = errno;
      continue;
    }
    if (had) {
      // The replaced file keeps its permissions, and its owner and group
      // where this process may set them.
      (void)::fchown(fd, old.st_uid, old.st_gid);
      // Never the set-user-ID, set-group-ID or sticky bits: a replaced output
      // is data, not a program.
      (void)::fchmod(fd, old.st_mode & 0777);
    }
    f.fd_ = fd;
    f.own_fd_ = true;
    f.tmp_ = std::move(tmp);
    return f;
  }
  return io_error("cannot write", name, err);
}

Result<void> OutputFile::write(std::string_view text) {
  if (!error_.empty()) return fail(AlarmId::kFileAccess, error_);
  if (fd_ < 0) return fail(AlarmId::kFileAccess, "cannot write '" + target_.name + "': not open");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd_, text.data() + done, text.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      error_ = "cannot write '" + target_.name + "': " + reason(errno);
      return fail(AlarmId::kFileAccess, error_);
    }
    done += static_cast<std::size_t>(w);
  }
  bytes_ += done;
  return {};
}

Result<void> OutputFile::commit() {
  if (!error_.empty()) {
    discard();
    return fail(AlarmId::kFileAccess, error_);
  }
  if (fd_ < 0) return fail(AlarmId::kFileAccess, "cannot write '" + target_.name + "': not open");
  if (!own_fd_) {
    fd_ = -1;
    return {};
  }
  if (tmp_.empty()) {
    const int rc = ::close(std::exchange(fd_, -1));
    if (rc != 0 && errno != EINTR) return io_error("cannot write", target_.name, errno);
    return {};
  }
  if (::fsync(fd_) != 0) {
    const int e = errno;
    error_ = "cannot flush '" + target_.name + "': " + reason(e);
    discard();
    return fail(AlarmId::kFileAccess, error_);
  }
  if (::close(std::exchange(fd_, -1)) != 0 && errno != EINTR) {
    const int e = errno;
    error_ = "cannot write '" + target_.name + "': " + reason(e);
    discard();
    return fail(AlarmId::kFileAccess, error_);
  }
  if (std::rename(tmp_.c_str(), target_.path.c_str()) != 0) {
    const int e = errno;
    error_ = "cannot replace '" + target_.name + "': " + reason(e);
    discard();
    return fail(AlarmId::kFileAccess, error_);
  }
  tmp_.clear();
  fsync_folder_of(target_.path);
  return {};
}

void OutputFile::discard() noexcept {
  if (fd_ >= 0 && own_fd_) ::close(fd_);
  fd_ = -1;
  if (!tmp_.empty()) {
    ::unlink(tmp_.c_str());
    tmp_.clear();
  }
}

Result<std::uint64_t> check_input_file(const std::string& path, InputKind kind, int* fd_out) {
  const std::string what = "cannot read the " + std::string(kind.what) + " '" + path + "': ";
  // O_NONBLOCK: opening a FIFO that no one writes must not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) return fail(AlarmId::kFileAccess, what + reason(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int e = errno;
    ::close(fd);
    return fail(AlarmId::kFileAccess, what + reason(e));
  }
  std::string why;
  if (S_ISDIR(st.st_mode)) {
    why = reason(EISDIR);
  } else if (!S_ISREG(st.st_mode)) {
    why = "not a regular file (a device, a FIFO or a socket)";
  } else if (static_cast<std::uint64_t>(st.st_size) > kind.max_bytes) {
    why = std::to_string(st.st_size) + " bytes, more than the " + std::to_string(kind.max_bytes) +
          " a " + std::string(kind.what) + " may have";
  }
  if (!why.empty() || fd_out == nullptr) {
    ::close(fd);
    if (!why.empty()) return fail(AlarmId::kFileAccess, what + why);
  } else {
    // Reads wait for the disk as usual.
    (void)::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    *fd_out = fd;
  }
  return static_cast<std::uint64_t>(st.st_size);
}

Result<std::string> read_input_file(const std::string& path, InputKind kind) {
  int fd = -1;
  auto size = check_input_file(path, kind, &fd);
  SKIPNC_TRY(size);
  std::string text;
  text.resize(static_cast<std::size_t>(*size));
  std::size_t done = 0;
  // A file that grows while it is read is read up to its size when opened.
  while (done < text.size()) {
    const ssize_t r = ::read(fd, text.data() + done, text.size() - done);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      const int e = errno;
      ::close(fd);
      return fail(AlarmId::kFileAccess,
                  "cannot read the " + std::string(kind.what) + " '" + path + "': " + reason(e));
    }
    if (r == 0) break;
    done += static_cast<std::size_t>(r);
  }
  ::close(fd);
  text.resize(done);
  return text;
}

Result<void> write_file_atomic(const std::string& name, std::string_view text) {
  auto f = OutputFile::open(name);
  SKIPNC_TRY(f);
  auto w = f->write(text);
  if (!w) {
    f->discard();
    return w;
  }
  return f->commit();
}

}  // namespace skipnc
