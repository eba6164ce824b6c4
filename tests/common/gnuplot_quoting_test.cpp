// Text that reaches a gnuplot script goes through common::gp_quoted (issue 14: command execution
// through generated scripts): gnuplot reads the literal back as exactly the text, and nothing in
// the text (quotes, backslashes, line breaks, backquotes, macros) runs a command.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "scratch.hpp"

namespace {

namespace fs = std::filesystem;

// Each hostile text tries to create `marker` by a different way out of a string literal.
std::vector<std::string> hostile_texts(const fs::path& marker) {
  const std::string touch = "system('touch " + marker.string() + "')";
  // First the text that ran a command through the former single-quoted literals (gnuplot takes
  // a string left open at the end of a line as ended and runs the next line): gnuplot stops at
  // the first error, so a later text could not show it.
  return {"line\n!touch " + marker.string() + "\n",
          "it's a 'quote'",
          "end' ; " + touch + " ; x='",
          "end\" ; " + touch + " ; x=\"",
          "line\n" + touch,
          "line\nsystem(\"touch " + marker.string() + "\")",
          "line\r\n" + touch,
          "back\\slash\\",
          "`touch " + marker.string() + "`",
          "macro @m and $0 and %s",
          "tab\tand\001control"};
}

TEST(GnuplotQuoting, TheLiteralHasNoLineBreakAndNoBackquote) {
  for (const std::string& text : hostile_texts("/nonexistent/marker")) {
    const std::string q = acst::common::gp_quoted(text);
    EXPECT_EQ(q.find('\n'), std::string::npos) << q;
    EXPECT_EQ(q.find('\r'), std::string::npos) << q;
    EXPECT_EQ(q.find('`'), std::string::npos) << q;
    EXPECT_EQ(q.front(), '"');
    EXPECT_EQ(q.back(), '"');
  }
}

TEST(GnuplotQuoting, GnuplotReadsEachTextBackExactlyAndRunsNothing) {
  if (!acst::common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = acst::test::scratch_folder("gnuplot_quoting");
  const fs::path marker = dir / "marker";
  const std::vector<std::string> texts = hostile_texts(marker);
  // One script prints every literal into a file: the file must hold exactly the texts, each
  // followed by the line break print adds.
  std::ostringstream gp;
  std::string expected;
  gp << "m = \"print 'macro ran'\"\nset print " << acst::common::gp_quoted((dir / "printed.txt").string()) << "\n";
  for (const std::string& text : texts) {
    gp << "print " << acst::common::gp_quoted(text) << "\n";
    expected += text + "\n";
  }
  gp << "unset print\n";
  acst::common::write_file_atomically((dir / "t.gp").string(), gp.str());
  ASSERT_EQ(acst::common::run_gnuplot_command(dir.string(), "t.gp"), "");
  EXPECT_EQ(acst::common::read_input_file((dir / "printed.txt").string()), expected);
  EXPECT_FALSE(fs::exists(marker)) << "a text ran a command";
  fs::remove_all(dir);
}

}  // namespace
