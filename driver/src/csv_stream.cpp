// An element test's CSV written while the run goes (see output.hpp).
#include "acst_driver/output.hpp"

namespace acst::driver {

CsvStream::CsvStream(const ElementScene& scene, const std::string& csv_path) : file_(csv_path) {
  file_.write(csv_comments(scene));
  comments_end_ = file_.size();
  file_.write(csv_column_names());
}

void CsvStream::add(const Record& r) {
  row_.clear();
  append_csv_row(row_, r);
  file_.write(row_);
}

void CsvStream::publish() { file_.commit(); }

// The failure is known only at the end, and its line belongs above the column names: the rows
// written so far are copied behind a new header (failures are rare; a good run is written once).
void CsvStream::publish_failed(const std::string& failed_path, const std::string& message) {
  common::AtomicFileWriter failed(failed_path);
  failed.copy_from(file_, 0, comments_end_);
  failed.write(csv_failure_line(message));
  failed.copy_from(file_, comments_end_, file_.size());
  failed.commit();
  file_.discard();
}

}  // namespace acst::driver
