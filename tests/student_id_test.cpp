// What every output shows of text from outside: student ids read where they are
// written and refused when no student can have them, file names shown escaped but still graded,
// and ids that are one student up to case, spaces and Unicode form flagged as one. Exports that
// keep every question whatever its id: tests/export_names_test.cpp.
#include "grader/student_id.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "batch/batch.hpp"
#include "batch/variant_files.hpp"
#include "export/export_gradebook.hpp"
#include "grader/visible_text.hpp"
#include "solver/util/diagnostic.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

const char* const kSet = test::kOneDepthProblemSet;

// A file of a Japanese Windows zip: 日本.yaml in CP932.
const std::string kCp932 = "\x93\xFA\x96\x7B";

TEST(VisibleText, ControlCharactersAndForeignBytesAreShownEscaped) {
  EXPECT_EQ(visible_text("\x1b[1A\x1b[2Kalice,31,31"), "\\u001B[1A\\u001B[2Kalice,31,31");
  EXPECT_EQ(visible_text(std::string("x\0y", 3)), "x\\u0000y");
  EXPECT_EQ(visible_text("a\x07\x08\x7f"), "a\\u0007\\u0008\\u007F");
  EXPECT_EQ(visible_text("\xC2\x85\xC2\x9B"), "\\u0085\\u009B");  // C1: NEL, CSI
  EXPECT_EQ(visible_text("a\xE2\x80\xAE"
                         "b"),
            "a\\u202Eb");  // right-to-left override
  EXPECT_EQ(visible_text("\xE2\x81\xA6\xE2\x80\xA8\xE2\x80\xA9"), "\\u2066\\u2028\\u2029");
  EXPECT_EQ(visible_text(kCp932 + ".yaml"), "\\x93\\xFA\\x96{.yaml");
  // Overlong forms, surrogates, a cut sequence and bytes past U+10FFFF are not UTF-8.
  EXPECT_EQ(visible_text("\xC0\xAF|\xED\xA0\x80|\xE6\x97|\xF4\x90\x80\x80"),
            "\\xC0\\xAF|\\xED\\xA0\\x80|\\xE6\\x97|\\xF4\\x90\\x80\\x80");
  // Line breaks and tabs: escaped on one line, kept in a page's text.
  EXPECT_EQ(visible_text("a\tb\nc\r"), "a\\u0009b\\u000Ac\\u000D");
  EXPECT_EQ(visible_text("a\tb\nc\r", Breaks::Kept), "a\tb\nc\\u000D");
  // Everything else is kept: letters of every script, a zero-width joiner, U+FFFD, spaces.
  for (const char* kept : {"田中 太郎", "Ёжик", "e\xCC\x81",
                           "\xF0\x9F\x91\xA9\xE2\x80\x8D\xF0\x9F\x94\xAC", "\xEF\xBF\xBD",
                           "a\xC2\xA0"
                           "b",
                           "=HYPERLINK(1)"})
    EXPECT_EQ(visible_text(kept), kept);
  // Property: whatever the bytes, the result is text visible_text leaves alone.
  std::mt19937 rng(40);
  for (int i = 0; i < 3000; ++i) {
    std::string s(rng() % 12, ' ');
    for (char& c : s) c = static_cast<char>(rng() % 256);
    const std::string v = visible_text(s);
    EXPECT_FALSE(first_hidden(v).has_value()) << v;
    EXPECT_EQ(visible_text(v), v);
  }
}

TEST(StudentIds, AreTrimmedOrRefusedNeverRewritten) {
  EXPECT_EQ(read_student_id("  alice ").id, "alice");
  // Unicode spaces too: an ideographic space (U+3000) and a no-break space (U+00A0).
  EXPECT_EQ(read_student_id("\xE3\x80\x80田中\xC2\xA0").id, "田中");
  EXPECT_EQ(read_student_id("s 01").id, "s 01");
  EXPECT_EQ(read_student_id("").problem, "the student id is empty");
  EXPECT_EQ(read_student_id("  \xE3\x80\x80").problem, "the student id is blank (only spaces)");
  EXPECT_EQ(read_student_id("\x1b[2Kalice").problem,
            "the student id '\\u001B[2Kalice' holds U+001B (a control character) at byte 1: "
            "write the id as plain text");
  EXPECT_EQ(read_student_id(std::string("x\0y", 3)).problem,
            "the student id 'x\\u0000y' holds U+0000 (a control character) at byte 2: write the "
            "id as plain text");
  EXPECT_EQ(read_student_id("ab\x7f").problem,
            "the student id 'ab\\u007F' holds U+007F (a control character) at byte 3: write the "
            "id as plain text");
  EXPECT_EQ(read_student_id("a\xE2\x80\xAE"
                            "b")
                .problem,
            "the student id 'a\\u202Eb' holds U+202E (a character that breaks or reorders the "
            "text around it) at byte 2: write the id as plain text");
  EXPECT_EQ(read_student_id(kCp932).problem,
            "the student id '\\x93\\xFA\\x96{' holds the byte 0x93 (not UTF-8 text) at byte 1: "
            "write the id as plain text");
  EXPECT_NE(read_student_id("a\xEF\xBF\xBD").problem->find("U+FFFD (the replacement character"),
            std::string::npos);
  EXPECT_EQ(read_student_id(std::string(257, 'a')).problem,
            "the student id is 257 bytes long (the limit is 256 bytes)");
  EXPECT_FALSE(read_student_id(std::string(256, 'a')).problem);
}

TEST(StudentIds, OneStudentUpToCaseSpacesAndUnicodeForm) {
  const std::string alice = student_id_key("alice");
  for (const char* same : {"Alice", " alice ", "ALICE", "ａｌｉｃｅ",
                           "ali\xE2\x80\x8B"
                           "ce"})
    EXPECT_EQ(student_id_key(same), alice) << same;
  EXPECT_EQ(student_id_key("\xC3\xA9"), student_id_key("e\xCC\x81"));  // NFC é, NFD e + ◌́
  EXPECT_EQ(student_id_key("１２３４"), student_id_key("1234"));       // full-width digits
  EXPECT_EQ(student_id_key("straße"), student_id_key("STRASSE"));
  for (const char* other : {"alicia", "al ice", "alice2", "\xC3\xA8"})
    EXPECT_NE(student_id_key(other), alice) << other;
}

fs::path write_class(const fs::path& dir) {
  const fs::path in = dir / "class";
  fs::create_directories(in);
  const std::string answers = "answers:\n  zbuf: {z: 8}\n";
  test::write_file(in / "a.yaml", "student: \"\\e[1A\\e[2Kalice,31,31\"\n" + answers);
  test::write_file(in / "b\x1b\x07\x7f.yaml", answers);               // the id would be the name
  test::write_file(in / "c\x1b[2J.yaml", "student: cy\n" + answers);  // a name, a good id
  test::write_file(in / (kCp932 + ".yaml"), answers);                 // the id would be the name
  test::write_file(in / (kCp932 + "2.yaml"), "student: 日本\n" + answers);  // a name, a good id
  test::write_file(in / "d.yaml", "student: Alice\n" + answers);
  test::write_file(in / "e.yaml", "student: \" alice \"\n" + answers);
  test::write_file(in / "f.yaml", "student: \"\\u00e9\"\n" + answers);
  test::write_file(in / "g.yaml", "student: \"e\\u0301\"\n" + answers);
  test::write_file(in / "h.yaml", "student: \"\"\n" + answers);
  test::write_file(in / "i.yaml", "student: \"x\\0y\"\n" + answers);
  test::write_file(in / "j.yaml", "student: \"   \"\n" + answers);
  return in;
}

// Every byte of every output but KaTeX's fonts: UTF-8 with no control character but LF (and
// TAB, which the pages may hold). A run's record of its files (.frustum/files-N, name hashes) is
// the transaction's state, read by Frustum only, not an output.
void expect_visible_outputs(const fs::path& out) {
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    if (!e.is_regular_file() || e.path().string().find("/katex/") != std::string::npos) continue;
    if (e.path().parent_path().filename() == ".frustum" &&
        e.path().filename().string().rfind("files-", 0) == 0)
      continue;
    ++files;
    const std::string text = test::read_file(e.path());
    const std::optional<Hidden> h = first_hidden(text, Breaks::Kept);
    EXPECT_FALSE(h) << e.path() << ": " << (h ? describe(*h) : "") << " at " << (h ? h->offset : 0);
    if (e.path().extension() == ".csv") {
      EXPECT_EQ(text.find('\t'), std::string::npos) << e.path();
    }
  }
  EXPECT_GT(files, 0);
}

TEST(OutputText, HostileIdsAndFileNamesGiveVisibleUtf8OutputsAndRowsThatSayWhy) {
  const fs::path dir = test::scratch_dir("output-text");
  const fs::path in = write_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.out_dir = (dir / "out").string();
  options.jobs = 1;
  const BatchResult r = grade_batch(set, collect_submissions(in.string()), options);
  const std::string c = in.string() + "/";
  const std::string also = ": each file is graded; keep the one that counts";
  const std::string plain = ": write the id as plain text";
  const std::string book_head = "student,score,max_score,percent,status,zbuf,source,message,file";
  const std::vector<std::string> rows = {
      // Ids written with YAML escapes are refused where they are read (line and column).
      ",0,1,0.0,error,," + c + "a.yaml,\"" + c +
          "a.yaml:1:10: student: the student id '\\u001B[1A\\u001B[2Kalice,31,31' holds U+001B "
          "(a control character) at byte 1" +
          plain + "\",%",
      // A file without `student:` whose name cannot be an id.
      ",0,1,0.0,error,," + c + "b\\u001B\\u0007\\u007F.yaml," + c +
          "b\\u001B\\u0007\\u007F.yaml: file name: the file has no `student:` and its name "
          "cannot be the id: the student id 'b\\u001B\\u0007\\u007F' holds U+001B (a control "
          "character) at byte 2" +
          plain + " (or add `student:` to the file),%~2",
      // A file whose name holds ESC and which states its id: graded, its name shown escaped.
      "cy,1,1,100.0,graded,1," + c + "c\\u001B[2J.yaml,,cy",
      // One student up to case and spaces, and up to Unicode form: each row names the other.
      "Alice,1,1,100.0,graded,1," + c + "d.yaml," + c +
          "e.yaml (as 'alice') also claims student 'Alice'" + also + ",Alice",
      "alice,1,1,100.0,graded,1," + c + "e.yaml," + c +
          "d.yaml (as 'Alice') also claims student 'alice'" + also + ",alice~2",
      "é,1,1,100.0,graded,1," + c + "f.yaml," + c +
          "g.yaml (as 'e\xCC\x81') also claims student 'é'" + also + ",%C3%A9",
      "e\xCC\x81,1,1,100.0,graded,1," + c + "g.yaml," + c +
          "f.yaml (as 'é') also claims student 'e\xCC\x81'" + also + ",e%CC%81",
      ",0,1,0.0,error,," + c + "h.yaml," + c + "h.yaml:1:10: student: the student id is empty,%~3",
      ",0,1,0.0,error,," + c + "i.yaml," + c +
          "i.yaml:1:10: student: the student id 'x\\u0000y' holds U+0000 (a control character) "
          "at byte 2" +
          plain + ",%~4",
      ",0,1,0.0,error,," + c + "j.yaml," + c +
          "j.yaml:1:10: student: the student id is blank (only spaces),%~5",
      // CP932 names: without `student:` an error row, with one graded; both shown escaped.
      ",0,1,0.0,error,," + c + "\\x93\\xFA\\x96{.yaml," + c +
          "\\x93\\xFA\\x96{.yaml: file name: the file has no `student:` and its name cannot be "
          "the id: the student id '\\x93\\xFA\\x96{' holds the byte 0x93 (not UTF-8 text) at "
          "byte 1" +
          plain + " (or add `student:` to the file),%~6",
      "日本,1,1,100.0,graded,1," + c + "\\x93\\xFA\\x96{2.yaml,,%E6%97%A5%E6%9C%AC"};
  std::string book = book_head + "\n";
  for (const std::string& row : rows) book += row + "\n";
  EXPECT_EQ(test::read_file(dir / "out" / "gradebook.csv"), book);
  ASSERT_EQ(r.rows.size(), 12u);
  expect_visible_outputs(dir / "out");
  // The file named in CP932 that states its id is graded under it; a refused one says why.
  const std::string page = test::read_file(dir / "out" / "feedback" / "%E6%97%A5%E6%9C%AC.md");
  EXPECT_NE(page.find("# Student 日本"), std::string::npos) << page;
  const std::string failed = test::read_file(dir / "out" / "feedback" / "%.md");
  EXPECT_NE(failed.find("U+001B (a control character)"), std::string::npos) << failed;
  fs::remove_all(dir);
}

TEST(OutputText, CsvRosterIdsAreReadLikeFileIds) {
  const fs::path dir = test::scratch_dir("output-text-csv");
  test::write_file(dir / "roster.csv", "student,zbuf.z\n s1 ,8\n,8\n\"a\x1b\",8\nS1,9\n");
  const std::vector<BatchEntry> e = collect_submissions((dir / "roster.csv").string());
  ASSERT_EQ(e.size(), 4u);
  const std::string f = (dir / "roster.csv").string();
  EXPECT_EQ(e[0].student, "s1");
  EXPECT_FALSE(e[0].error);
  EXPECT_EQ(e[1].error, f + ":3:1: student: the student id is empty");
  EXPECT_EQ(e[2].error, f + ":4:1: student: the student id 'a\\u001B' holds U+001B (a control "
                            "character) at byte 2: write the id as plain text");
  EXPECT_EQ(e[3].note, f + " row 2 (as 's1') also claims student 'S1': each file is graded; keep "
                           "the one that counts");
  // A roster of ids: the same reading, and one student up to case is listed twice.
  test::write_file(dir / "ids.txt",
                   "ann\nb\x1b"
                   "b\n");
  try {
    read_roster((dir / "ids.txt").string());
    ADD_FAILURE() << "a roster id with ESC was read";
  } catch (const InputError& x) {
    EXPECT_EQ(x.diagnostic().format(), (dir / "ids.txt").string() +
                                           ":2:1: student: the student id 'b\\u001Bb' holds "
                                           "U+001B (a control character) at byte 2: write the id "
                                           "as plain text");
  }
  test::write_file(dir / "ids.csv", "student\nAnn\n ann\n");
  try {
    read_roster((dir / "ids.csv").string());
    ADD_FAILURE() << "Ann and ann were two students";
  } catch (const InputError& x) {
    EXPECT_EQ(x.diagnostic().format(),
              (dir / "ids.csv").string() +
                  ":3:1: student: 'ann' is listed twice (first on line 2 as 'Ann')");
  }
  fs::remove_all(dir);
}

TEST(OutputText, GradebookImportsRefuseIdsNoStudentHasAndOneStudentTwice) {
  const std::string head = "student,score,max_score,status\n";
  const std::string canvas = export_gradebook(head + "日本,1,1,graded\n,0,1,error\n", "g.csv",
                                              GradebookFormat::Canvas, "A\x1b[2J");
  EXPECT_EQ(canvas,
            "Student,ID,SIS User ID,SIS Login ID,Section,A\\u001B[2J\n"
            "Points Possible,,,,,1\n"
            ",,日本,,,1\n");
  const auto error = [&](const std::string& rows) {
    try {
      export_gradebook(head + rows, "g.csv", GradebookFormat::Moodle, "A");
    } catch (const InputError& x) {
      return x.diagnostic().format();
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("\"a\x1b[1A\",1,1,graded\n"),
            "g.csv:2:1: student: the student id 'a\\u001B[1A' holds U+001B (a control "
            "character) at byte 2: write the id as plain text");
  EXPECT_EQ(error("Ann,1,1,graded\nann ,0,1,graded\n"),
            "g.csv:3:1: student: student 'ann' is also on line 2 (as 'Ann'); keep one row per "
            "student before importing");
}

}  // namespace
}  // namespace frustum
