// Sources of program text. Both kinds share one scanner over a byte buffer:
// the memory source's buffer is the whole text, the file source's buffer is a
// fixed window that slides over the file (pread), so memory use does not grow
// with the file.
#include "gcode/source.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace skipnc::gcode {
namespace {

// What the scanner must look at: end-of-block characters and parentheses.
enum : unsigned char { kPlain = 0, kNewline = 1, kSemicolon = 2, kOpen = 3, kClose = 4 };

constexpr std::array<unsigned char, 256> make_classes() {
  std::array<unsigned char, 256> t{};
  t['\n'] = kNewline;
  t[';'] = kSemicolon;
  t['('] = kOpen;
  t[')'] = kClose;
  return t;
}
constexpr std::array<unsigned char, 256> kClasses = make_classes();

// Index of the first end of block in data[i, stop): a '\n', or a ';' outside
// parentheses; `stop` when there is none. `in_paren` tells whether data[i]
// is inside parentheses; it is kept up to date when `stop` is returned.
// Without `semicolon` (RS274NGC, grbl: ';' begins a comment) only '\n' ends a block.
std::size_t scan(const char* data, std::size_t i, std::size_t stop, bool& in_paren,
                 bool semicolon) noexcept {
  // The usual case, found by memchr: a line end with no ';' before it, where
  // parentheses do not matter.
  if (const void* nl = std::memchr(data + i, '\n', stop - i)) {
    const auto end = static_cast<std::size_t>(static_cast<const char*>(nl) - data);
    if (!semicolon || std::memchr(data + i, ';', end - i) == nullptr) return end;
  }
  if (!semicolon) return stop;
  for (; i < stop; ++i) {
    const unsigned char k = kClasses[static_cast<unsigned char>(data[i])];
    if (k != kPlain) {
      if (k == kNewline || (k == kSemicolon && !in_paren)) break;
      if (k == kOpen) {
        in_paren = true;
      } else if (k == kClose) {
        in_paren = false;
      }
    }
  }
  return i;
}

// Index of the first '\n' in data[begin, stop), or of the first ';' when
// `semicolon` and it comes first; `stop` when there is neither. Only the
// `held` bytes of data are read (held >= stop). Sixteen bytes at a compare
// where the instruction set has it: one pass where two memchr calls were.
std::size_t first_end(const char* data, std::size_t begin, std::size_t stop, std::size_t held,
                      bool semicolon) noexcept {
  std::size_t i = begin;
#if defined(__SSE2__)
  const __m128i nl = _mm_set1_epi8('\n');
  const __m128i sc = _mm_set1_epi8(semicolon ? ';' : '\n');
  for (; i < stop && held - i >= 16; i += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + i));
    const auto m = static_cast<unsigned>(
        _mm_movemask_epi8(_mm_or_si128(_mm_cmpeq_epi8(v, nl), _mm_cmpeq_epi8(v, sc))));
    if (m != 0) return std::min(stop, i + static_cast<std::size_t>(std::countr_zero(m)));
  }
#endif
  for (; i < stop; ++i) {
    if (data[i] == '\n' || (semicolon && data[i] == ';')) return i;
  }
  return stop;
}

constexpr std::string_view kBom = "\xEF\xBB\xBF";

class TextSource final : public Source {
 public:
  // Memory source: the buffer is the whole text.
  TextSource(std::string name, std::string text, SourceLimits limits)
      : name_(std::move(name)), limits_(limits), buf_(std::move(text)) {
    len_ = buf_.size();
    size_ = len_;
    eof_ = true;
    if (std::string_view(buf_).starts_with(kBom)) start_ = kBom.size();
    pos_.offset = start_;
  }
  // File source: the buffer is a window of fixed size over the file.
  TextSource(std::string name, int fd, std::uint64_t size, SourceLimits limits)
      : name_(std::move(name)), limits_(limits), fd_(fd), size_(size) {
    // A whole block, its end of block and the look-ahead must fit in the window.
    const std::size_t window = std::max(limits_.window_bytes, limits_.max_block_bytes + 8);
    // Not cleared: only the first len_ bytes, written by pread, are read (a
    // sweep opens the program once per scenario, and clearing 1 MiB cost more
    // than a short program's reading).
    buf_.resize_and_overwrite(std::max<std::size_t>(window, 64),
                              [](char*, std::size_t n) noexcept { return n; });
  }
  ~TextSource() override {
    if (fd_ >= 0) ::close(fd_);
  }
  TextSource(const TextSource&) = delete;
  TextSource& operator=(const TextSource&) = delete;

  // Reads the first bytes to skip a UTF-8 byte order mark.
  Result<void> init() {
    SKIPNC_TRY(fill());
    if (std::string_view(buf_.data(), len_).starts_with(kBom)) start_ = kBom.size();
    pos_.offset = start_;
    return {};
  }

  Result<bool> next(RawBlock& out) override;
  // next() in all cases.
  Result<bool> next_general(RawBlock& out);
  SourcePos tell() const noexcept override { return pos_; }
  Result<void> seek(SourcePos pos) override;
  std::string_view name() const noexcept override { return name_; }

 private:
  // Drops buffered bytes before index `keep` and reads more after the data
  // held. Sets eof_ when the file has no more bytes. (File source only.)
  Result<void> fill(std::size_t keep = 0);
  Error read_error(const char* what) const {
    const int e = errno;
    return Error{AlarmId::kFileAccess, std::string(what) + " '" + name_ + "': " + std::strerror(e),
                 SourceLoc{name_, pos_.line, pos_.column}, -1};
  }

  std::string name_;
  SourceLimits limits_;
  int fd_ = -1;             // -1: memory source
  std::uint64_t size_ = 0;  // bytes in the text or file
  std::string buf_;
  std::uint64_t buf_off_ = 0;  // offset of buf_[0] in the text
  std::size_t len_ = 0;        // valid bytes in buf_
  bool eof_ = false;           // the text has no bytes after buf_off_ + len_
  std::size_t start_ = 0;      // offset of the first block (after a BOM)
  SourcePos pos_;
};

Result<void> TextSource::fill(std::size_t keep) {
  if (keep > 0) {
    std::memmove(buf_.data(), buf_.data() + keep, len_ - keep);
    buf_off_ += keep;
    len_ -= keep;
  }
  // One read is enough to make progress; the scanner asks again if needed.
  ssize_t n = 0;
  do {
    n = ::pread(fd_, buf_.data() + len_, buf_.size() - len_, static_cast<off_t>(buf_off_ + len_));
  } while (n < 0 && errno == EINTR);
  if (n < 0) return std::unexpected(read_error("cannot read"));
  if (n == 0) {
    eof_ = true;
  } else {
    len_ += static_cast<std::size_t>(n);
  }
  return {};
}

Result<bool> TextSource::next(RawBlock& out) {
  // The usual case: the window holds the position and, after it, a line end
  // with no ';' before it, in reach of the block size limit.
  if (pos_.offset >= buf_off_ && pos_.offset - buf_off_ <= len_) {
    const auto begin = static_cast<std::size_t>(pos_.offset - buf_off_);
    const std::size_t stop = std::min(len_, begin + limits_.max_block_bytes + 2);
    const char* data = buf_.data();
    const std::size_t i = first_end(data, begin, stop, len_, limits_.semicolon_ends_block);
    if (i < stop && data[i] == '\n') {
      std::size_t text_end = i;
      if (text_end > begin && data[text_end - 1] == '\r') --text_end;
      if (text_end - begin <= limits_.max_block_bytes) {
        out.text = std::string_view(data + begin, text_end - begin);
        out.offset = pos_.offset;
        out.line = pos_.line;
        out.column = pos_.column;
        pos_.offset += i - begin + 1;
        ++pos_.line;
        pos_.column = 1;
        return true;
      }
    }
  }
  return next_general(out);
}

Result<bool> TextSource::next_general(RawBlock& out) {
  // The window may not hold the position (after a seek, or at its end).
  if (pos_.offset < buf_off_ || pos_.offset > buf_off_ + len_) {
    buf_off_ = pos_.offset;
    len_ = 0;
    eof_ = false;
  }
  std::size_t begin = static_cast<std::size_t>(pos_.offset - buf_off_);
  std::size_t i = begin;
  bool in_paren = false;
  bool too_long = false;
  std::size_t skipped = 0;  // bytes of a too long block already dropped from the window
  const std::size_t max = limits_.max_block_bytes;
  for (;;) {
    const char* data = buf_.data();
    // Scan for the end of the block; past max + 1 bytes the block is too long
    // whatever its end, and only its end is still needed.
    const std::size_t stop = too_long ? len_ : std::min(len_, begin + max + 2);
    i = scan(data, i, stop, in_paren, limits_.semicolon_ends_block);
    if (i == stop && stop < len_) {
      too_long = true;
      continue;
    }
    const bool found = i < len_;
    // A ';' directly followed by a line end is one end of block, so that
    // listings written "G0 X1 ;" give no empty blocks: look two bytes ahead.
    const bool need_more =
        found ? (data[i] == ';' && limits_.semicolon_ends_block && i + 2 >= len_ && !eof_) : !eof_;
    if (need_more) {
      const std::size_t keep = too_long ? i : begin;
      if (too_long) skipped += i - begin;
      SKIPNC_TRY(fill(keep));
      i -= keep;
      begin = 0;
      continue;
    }
    if (!found && i == begin && skipped == 0) return false;  // end of text
    // The block is [begin, text_end); i is at its end of block or the end of text.
    std::size_t text_end = i;
    std::size_t eob = 0;  // bytes of the end of block
    bool newline = false;
    if (found) {
      if (data[i] == '\n') {
        eob = 1;
        newline = true;
        if (text_end > begin && data[text_end - 1] == '\r') --text_end;
      } else if (i + 1 < len_ && data[i + 1] == '\n') {
        eob = 2;
        newline = true;
      } else if (i + 2 < len_ && data[i + 1] == '\r' && data[i + 2] == '\n') {
        eob = 3;
        newline = true;
      } else {
        eob = 1;
      }
    }
    const SourcePos at = pos_;
    const std::size_t length = skipped + (text_end - begin);
    const std::size_t consumed = skipped + (i - begin) + eob;
    pos_.offset += consumed;
    if (newline) {
      ++pos_.line;
      pos_.column = 1;
    } else {
      pos_.column += static_cast<std::uint32_t>(consumed);
    }
    if (length > max) {
      return std::unexpected(
          Error{AlarmId::kBlockTooLong,
                "block of " + std::to_string(length) + " bytes, longer than " + std::to_string(max),
                SourceLoc{name_, at.line, at.column}, -1});
    }
    out.text = std::string_view(data + begin, text_end - begin);
    out.offset = at.offset;
    out.line = at.line;
    out.column = at.column;
    return true;
  }
}

Result<void> TextSource::seek(SourcePos pos) {
  if (pos.offset > size_) {
    return std::unexpected(Error{AlarmId::kFileAccess,
                                 "cannot seek to byte " + std::to_string(pos.offset) + " of '" +
                                     name_ + "' (" + std::to_string(size_) + " bytes)",
                                 SourceLoc{name_, pos.line, pos.column}, -1});
  }
  if (pos.offset < start_) pos.offset = start_;  // never re-read a BOM
  pos_ = pos;
  return {};
}

}  // namespace

std::unique_ptr<Source> make_string_source(std::string name, std::string text,
                                           SourceLimits limits) {
  return std::make_unique<TextSource>(std::move(name), std::move(text), limits);
}

Result<std::unique_ptr<Source>> open_file_source(const std::string& path, std::string display_name,
                                                 SourceLimits limits) {
  // A program is read by position (pread), so only a regular file can be
  // one. O_NONBLOCK: opening a FIFO that no one writes must not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int e = errno;
    return std::unexpected(Error{
        AlarmId::kFileAccess, "cannot open '" + path + "': " + std::strerror(e), SourceLoc{}, -1});
  }
  struct stat st {};
  const bool stat_ok = ::fstat(fd, &st) == 0;
  if (!stat_ok || !S_ISREG(st.st_mode)) {
    const std::string why = !stat_ok              ? std::strerror(errno)
                            : S_ISDIR(st.st_mode) ? std::strerror(EISDIR)
                                                  : "not a regular file (a pipe or a device)";
    ::close(fd);
    return std::unexpected(
        Error{AlarmId::kFileAccess, "cannot open '" + path + "': " + why, SourceLoc{}, -1});
  }
  auto src = std::make_unique<TextSource>(std::move(display_name), fd,
                                          static_cast<std::uint64_t>(st.st_size), limits);
  SKIPNC_TRY(src->init());
  return std::unique_ptr<Source>(std::move(src));
}

}  // namespace skipnc::gcode
