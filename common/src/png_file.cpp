#include "acst_common/png_file.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace acst::common {

namespace {

constexpr std::array<unsigned char, 8> png_signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// The last chunk of every PNG: length 0, type IEND and its CRC, always these 12 bytes.
constexpr std::array<unsigned char, 12> iend_chunk{0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};

bool bytes_at(std::ifstream& in, std::streamoff offset, std::ios::seekdir from, const unsigned char* expected,
              std::size_t n) {
  char got[16] = {};
  in.clear();
  in.seekg(offset, from);
  in.read(got, static_cast<std::streamsize>(n));
  return in.gcount() == static_cast<std::streamsize>(n) && std::memcmp(got, expected, n) == 0;
}

}  // namespace

std::string png_problem(const std::string& path) {
  const std::string name = "'" + path + "'";
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return name + " was not written (" + ec.message() + ")";
  if (size == 0) return name + " is empty";
  std::ifstream in(path, std::ios::binary);
  if (size < png_signature.size() + iend_chunk.size() ||
      !bytes_at(in, 0, std::ios::beg, png_signature.data(), png_signature.size()))
    return name + " is not a PNG file";
  if (!bytes_at(in, -static_cast<std::streamoff>(iend_chunk.size()), std::ios::end, iend_chunk.data(), iend_chunk.size()))
    return name + " ends before its IEND chunk (cut short)";
  return "";
}

std::string keep_complete_png(const std::string& written, const std::string& target) {
  if (const std::string problem = png_problem(written); !problem.empty()) {
    std::remove(written.c_str());
    return "the figure " + problem + " (a full disk?): removed" +
           (written == target ? std::string() : "; an earlier '" + target + "' is kept as it was");
  }
  if (written == target) return "";
  std::error_code ec;
  std::filesystem::rename(written, target, ec);
  if (!ec) return "";
  std::remove(written.c_str());
  return "cannot rename the figure to '" + target + "': " + ec.message();
}

}  // namespace acst::common
