#pragma once
// A file written piece by piece and published whole: the text goes to a temporary file beside
// the target, and commit() renames it into place. A writer dropped before commit() removes its
// temporary file, so a failure never leaves a half-written file over a good one, and the text
// never has to be held in memory at once.
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

namespace acst::common {

class AtomicFileWriter {
 public:
  // Creates the temporary file; throws std::runtime_error naming it when it cannot.
  explicit AtomicFileWriter(std::string path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view text);
  // Bytes written so far.
  std::uint64_t size() const { return size_; }
  // Appends bytes [from, to) of what `source` has written so far (both writers stay open).
  void copy_from(AtomicFileWriter& source, std::uint64_t from, std::uint64_t to);
  // Closes the file and renames it to the target; throws std::runtime_error naming the file if
  // any write failed or the rename does (the target is then untouched).
  void commit();
  // Removes the temporary file; the target is untouched.
  void discard();
  const std::string& path() const { return path_; }

 private:
  std::string path_, temporary_;
  std::ofstream file_;
  std::uint64_t size_ = 0;
  bool open_ = false;
};

}  // namespace acst::common
