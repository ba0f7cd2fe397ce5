#include "hinf/io/files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

std::string error_text(int error) { return std::generic_category().message(error); }

}  // namespace

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("an output file name is empty");
  const std::string cannot = str_cat("cannot write '", path, "': ");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(cannot + "it is a directory");
  // The nearest existing folder above: missing folders below it are created when writing.
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  while (!fs::exists(folder, ec)) {
    const fs::path up = folder.has_relative_path() ? folder.parent_path() : folder;
    const fs::path next = up.empty() ? fs::path(".") : up;
    if (next == folder) break;  // "/" or "." (a working directory that was removed)
    folder = next;
  }
  if (!fs::is_directory(folder, ec)) throw InputError(str_cat(cannot, "'", folder.string(), "' is not a directory"));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(str_cat(cannot, "'", folder.string(), "': ", error_text(errno)));
}

namespace {

// Writes all of text to the open file descriptor; false (errno set) on failure.
bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_text_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  check_output_path(path);
  const std::string cannot = str_cat("cannot write '", path, "': ");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or a pipe (/dev/stdout, /dev/null): written in place, it cannot be replaced.
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) throw InputError(cannot + error_text(errno));
    const bool written = write_all(fd, text);
    const int error = errno;
    if (::close(fd) != 0 && written) throw InputError(cannot + error_text(errno));
    if (!written) throw InputError(cannot + error_text(error));
    return;
  }
  // A temporary file next to the target, renamed over it once complete: a failed write (a
  // full disk) leaves the previous file, or none, never a truncated one.
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::create_directories(folder, ec);
  if (ec) throw InputError(str_cat(cannot, "cannot create the folder '", folder.string(), "': ", ec.message()));
  static std::atomic<unsigned> counter{0};
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    temporary = (folder / str_cat(".", target.filename().string(), ".", ::getpid(), ".", counter++, ".tmp")).string();
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);  // mode less the umask
    if (fd < 0 && (errno != EEXIST || attempt > 100)) throw InputError(cannot + error_text(errno));
  }
  bool ok = write_all(fd, text) && ::fsync(fd) == 0;
  int error = errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (ok && std::rename(temporary.c_str(), path.c_str()) != 0) {
    ok = false;
    error = errno;
  }
  if (!ok) {
    ::unlink(temporary.c_str());
    throw InputError(cannot + error_text(error));
  }
}

std::string read_text_file(const std::string& path, const std::string& what) {
  const std::string cannot = str_cat("cannot read ", what, " '", path, "': ");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(cannot + "it is a directory");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(cannot + error_text(errno));
  std::string text;
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) text.append(chunk, got);
  const int error = std::ferror(file) != 0 ? errno : 0;
  std::fclose(file);
  if (error != 0) throw InputError(cannot + error_text(error));
  return text;
}

}  // namespace hinf
