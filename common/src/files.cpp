#include "acst_common/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "acst_common/atomic_file.hpp"
#include "acst_common/input_error.hpp"

namespace acst::common {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "another kind of file";
}

std::string mib(std::uintmax_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string resolve(const std::string& base_dir, const std::string& name) {
  const std::filesystem::path p(name);
  return p.is_absolute() || base_dir.empty() ? name : (std::filesystem::path(base_dir) / p).string();
}

std::string read_input_file(const std::string& path, std::uintmax_t max_bytes) {
  const auto refuse = [&](const std::string& reason) { return InputError("'" + path + "': " + reason); };
  const std::string too_large = "larger than the " + mib(max_bytes) + " an input file may have";
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  const Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (d.fd < 0) throw refuse(std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) throw refuse(std::string("cannot read: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw refuse(std::string(kind_of(st.st_mode)) + ", not a regular file");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) throw refuse(too_large);
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  for (;;) {
    if (got == text.size()) {
      // The file may have grown since fstat: read on, within the cap.
      if (text.size() >= max_bytes + 1) break;
      text.resize(std::min<std::uintmax_t>(max_bytes + 1, text.size() + 65536));
    }
    const ssize_t n = ::read(d.fd, &text[got], text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw refuse(std::string("cannot read: ") + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got > max_bytes) throw refuse(too_large);
  text.resize(got);
  return text;
}

std::string temporary_name(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

bool is_temporary_name(const std::string& name) {
  const auto at = name.rfind(".tmp");  // ".NAME.tmpPID", as temporary_name makes it
  if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at == 0 || at + 4 == name.size()) return false;
  return name.find_first_not_of("0123456789", at + 4) == std::string::npos;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFileWriter file(path);
  file.write(text);
  file.commit();
}

}  // namespace acst::common
