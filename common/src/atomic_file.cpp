#include "acst_common/atomic_file.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "acst_common/files.hpp"

namespace acst::common {

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)), temporary_(temporary_name(path_)) {
  file_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!file_) throw std::runtime_error("cannot write '" + temporary_ + "'");
  open_ = true;
}

AtomicFileWriter::~AtomicFileWriter() { discard(); }

void AtomicFileWriter::write(std::string_view text) {
  file_.write(text.data(), static_cast<std::streamsize>(text.size()));
  size_ += text.size();
}

void AtomicFileWriter::copy_from(AtomicFileWriter& source, std::uint64_t from, std::uint64_t to) {
  source.file_.flush();
  std::ifstream in(source.temporary_, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(from));
  std::vector<char> chunk(1 << 16);
  for (std::uint64_t left = to > from ? to - from : 0; left > 0 && in;) {
    const std::streamsize n = static_cast<std::streamsize>(std::min<std::uint64_t>(left, chunk.size()));
    in.read(chunk.data(), n);
    write(std::string_view(chunk.data(), static_cast<std::size_t>(in.gcount())));
    left -= static_cast<std::uint64_t>(in.gcount());
  }
  if (!source.file_ || !in) file_.setstate(std::ios::failbit);  // reported by commit()
}

void AtomicFileWriter::commit() {
  if (!open_) throw std::runtime_error("'" + path_ + "' was already written or discarded");
  file_.close();
  open_ = false;
  if (!file_) {
    std::remove(temporary_.c_str());
    throw std::runtime_error("writing '" + temporary_ + "' failed");
  }
  std::error_code ec;
  std::filesystem::rename(temporary_, path_, ec);
  if (ec) {
    std::remove(temporary_.c_str());
    throw std::runtime_error("cannot rename '" + temporary_ + "' to '" + path_ + "': " + ec.message());
  }
}

void AtomicFileWriter::discard() {
  if (!open_) return;
  file_.close();
  open_ = false;
  std::remove(temporary_.c_str());
}

}  // namespace acst::common
