#include "fapcast/core/file_io.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace fapcast {
namespace fs = std::filesystem;

namespace {
// When this process started (static initialisation), to tell a killed run's files from ours.
const std::time_t kRunStart = std::time(nullptr);

[[noreturn]] void fail(const fs::path& path, const std::string& what, int err = 0) {
  std::string msg = path.string() + ": " + what;
  if (err != 0) msg += ": " + std::string(std::strerror(err));
  throw std::runtime_error(msg);
}

// ".NAME.fapcast-tmpNNN": a leading dot, a name, ".fapcast-tmp", one or more decimal digits. The
// suffix is fapcast's own, so the sweep never takes another program's temporary files.
constexpr std::string_view kTemporarySuffix = ".fapcast-tmp";

bool has_temporary_name(const std::string& name) {
  const auto at = name.rfind(kTemporarySuffix);
  if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at < 2) return false;
  const std::string digits = name.substr(at + kTemporarySuffix.size());
  return !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
}

void sweep_once(const fs::path& dir) {
  static std::mutex mutex;
  static std::set<fs::path> swept;
  const std::lock_guard lock(mutex);
  std::error_code ec;
  const fs::path key = fs::weakly_canonical(dir, ec);
  if (!swept.insert(ec ? dir : key).second) return;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (is_stale_temporary(it->path())) ::unlink(it->path().c_str());
}
}  // namespace

bool is_stale_temporary(const fs::path& file) {
  if (!has_temporary_name(file.filename().string())) return false;
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return false;
  struct stat st {};
  bool stale = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_mtime < kRunStart &&
               ::flock(fd, LOCK_EX | LOCK_NB) == 0;
  ::close(fd);  // releases the lock taken for the test
  return stale;
}

std::string read_file(const fs::path& path, std::uint64_t max_bytes) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(path, "cannot open: no such file");
  if (!fs::is_regular_file(status)) fail(path, "not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec) fail(path, "cannot read its size");
  if (size > max_bytes)
    fail(path, "file is " + std::to_string(size) + " bytes, more than the limit of " +
                   std::to_string(max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open", errno);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  bytes.resize(static_cast<std::size_t>(in.gcount()));  // a file that shrank meanwhile
  return bytes;
}

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)) {
  const fs::path dir = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
  if (path_.filename().empty()) fail(path_, "not a file name");
  std::error_code is_dir_error;
  if (fs::is_directory(path_, is_dir_error)) fail(path_, "is a directory, not a file");
  sweep_once(dir);
  std::random_device rd;
  for (int attempt = 0; fd_ < 0; ++attempt) {
    tmp_ = dir / ("." + path_.filename().string() + std::string(kTemporarySuffix) + std::to_string(rd()));
    fd_ = ::open(tmp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd_ < 0 && (errno != EEXIST || attempt >= 8))
      fail(path_, "cannot create temporary file " + tmp_.string(), errno);
  }
  ::flock(fd_, LOCK_EX | LOCK_NB);  // marks it as in use for another run's sweep
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::abandon(const std::string& step, int err) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(tmp_.c_str());
  tmp_.clear();
  fail(path_, step, err);
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0) fail(path_, "write after commit");
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("write failed", errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::append_contents_of(const AtomicFile& source) {
  if (fd_ < 0) fail(path_, "write after commit");
  if (source.fd_ < 0) fail(path_, "cannot read " + source.tmp_.string() + ": already committed");
  loff_t from = 0;
  for (;;) {
    const ssize_t n = ::copy_file_range(source.fd_, &from, fd_, nullptr, std::size_t{1} << 30, 0);
    if (n == 0) return;  // the source's end
    if (n > 0) continue;
    if (errno == EINTR) continue;
    if (errno != EXDEV && errno != ENOSYS && errno != EOPNOTSUPP && errno != EINVAL) abandon("copy from " + source.tmp_.string() + " failed", errno);
    break;  // a file system or kernel without it: through a buffer
  }
  std::string block(std::size_t{1} << 16, '\0');
  for (;;) {
    const ssize_t n = ::pread(source.fd_, block.data(), block.size(), from);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) abandon("read of " + source.tmp_.string() + " failed", errno);
    if (n == 0) return;
    write({block.data(), static_cast<std::size_t>(n)});
    from += n;
  }
}

void AtomicFile::write_at(std::uint64_t offset, std::string_view bytes) {
  if (fd_ < 0) fail(path_, "write after commit");
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::pwrite(fd_, p, left, static_cast<off_t>(offset));
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("write failed", errno);
    }
    p += n;
    offset += static_cast<std::uint64_t>(n);
    left -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) fail(path_, "commit after commit");
  if (::fsync(fd_) != 0) abandon("fsync failed", errno);
  // Renamed while still open and locked: another run's sweep cannot take it in between.
  if (::rename(tmp_.c_str(), path_.c_str()) != 0) abandon("rename of the temporary file failed", errno);
  committed_ = true;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(path_, "close failed (the file was written and synced)", errno);
}

void commit_together(std::initializer_list<AtomicFile*> files) {
  std::vector<AtomicFile*> done;
  try {
    for (AtomicFile* f : files) {
      f->commit();
      done.push_back(f);
    }
  } catch (...) {
    for (AtomicFile* f : done) ::unlink(f->path().c_str());
    throw;
  }
}

void write_file_atomically(const fs::path& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

}  // namespace fapcast
