// The YAML Frustum writes (generated sets, answer keys) reads the same in every YAML reader:
// yaml-cpp, YAML 1.1 readers such as PyYAML, and YAML 1.2 readers.
#include "solver/input/yaml_emit.hpp"

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

TEST(YamlEmit, QuotesWhatYaml11And12ReadDifferently) {
  // Octal in YAML 1.1 (0010 is 8), decimal in 1.2; 0b/0o/underscores exist in one only.
  for (const char* s :
       {"0010", "0101", "0000", "00", "0089", "+07", "0b11", "0o17", "1_000", "1e3"})
    EXPECT_EQ(emit_scalar(s), std::string("\"") + s + "\"") << s;
  // YAML 1.1 booleans that 1.2 reads as strings.
  for (const char* s : {"y", "Y", "n", "yes", "No", "on", "OFF"})
    EXPECT_EQ(emit_scalar(s), std::string("\"") + s + "\"") << s;
  // Read alike everywhere: stays plain.
  for (const char* s : {"3", "-12", "0", "2.5", "-0.125", "true", "false", "1000", "-1/2",
                        "sqrt(3)/3", "front", "pi/3", "1.0e-3", "0.5", "-2.5e+10", "0x1F"})
    EXPECT_EQ(emit_scalar(s), s) << s;
}

// Integers and exact values are written plain without trying the readers' patterns; the
// numbers that need quotes still get them.
TEST(YamlEmit, NumbersAndExactValuesArePlainUnlessAReaderDisagrees) {
  for (int i = -1000; i <= 1000; ++i) EXPECT_EQ(emit_scalar(std::to_string(i)), std::to_string(i));
  for (const char* s : {"+7", "1/2", "-sqrt(3)/3", "2*sqrt(6)/3", "pi/4", "(1)", "AC", "kind",
                        "seed001-plane", "yesterday", "Nothing", "x1.5", "nullable", "e3"})
    EXPECT_EQ(emit_scalar(s), s);
  for (const char* s : {"007", "-010", "+0_1", "1e3", "0o17", "yes", "-", "1:30", "Off", "N"})
    EXPECT_EQ(emit_scalar(s), std::string("\"") + s + "\"") << s;
}

TEST(YamlEmit, StringNodesStayStrings) {
  // A bit string or a word is a string whatever it looks like.
  EXPECT_EQ(emit_flow(string_node("1000")), "\"1000\"");
  EXPECT_EQ(emit_flow(string_node("0101")), "\"0101\"");
  EXPECT_EQ(emit_flow(string_node("true")), "\"true\"");
  EXPECT_EQ(emit_flow(string_node("null")), "\"null\"");
  EXPECT_EQ(emit_flow(string_node("front")), "front");
  EXPECT_EQ(emit_flow(string_node("0-1")), "0-1");
  EXPECT_TRUE(plain_reads_as_string("edge_on"));
  EXPECT_FALSE(plain_reads_as_string("1.5"));
  EXPECT_FALSE(plain_reads_as_string("~"));
}

// Answer keys of many generated clip_line variants: yaml-cpp and PyYAML (YAML 1.1) read every
// outcode as the same string of 0s and 1s.
TEST(YamlEmit, OutcodesInAnswerKeysReadTheSameInPyYaml) {
  const fs::path dir =
      fs::temp_directory_path() / ("frustum-yaml-emit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream(dir / "clip.yaml")
        << "title: outcodes\nproblems:\n  - id: c\n    kind: clip_line\n"
           "    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}\n";
  }
  ASSERT_EQ(test::frustum_run({"generate", (dir / "clip.yaml").string(), "--seed", "5", "--count",
                               "60", "-o", (dir / "gen").string()})
                .status,
            0);
  // PyYAML's reading of every key, one "file outcode_p outcode_q" line each.
  RunOptions to_file;
  to_file.out = OutputTo::File;
  to_file.err = OutputTo::Inherit;
  to_file.log_file = (dir / "pyyaml.txt").string();
  ASSERT_EQ(run_program({"python3", "-c",
                         "import sys, yaml, glob, os\n"
                         "for f in sorted(glob.glob(sys.argv[1] + \"/*.yaml\")):\n"
                         "    a = yaml.safe_load(open(f))[\"answers\"][\"c\"]\n"
                         "    print(os.path.basename(f), repr(a[\"outcode_p\"]), "
                         "repr(a[\"outcode_q\"]))",
                         (dir / "gen" / "answers").string()},
                        to_file)
                .status,
            0)
      << "python3-yaml is in tools/packages/test.txt";
  std::ifstream in(dir / "pyyaml.txt");
  std::string file, p, q;
  int keys = 0, leading_zero = 0;
  while (in >> file >> p >> q) {
    const YAML::Node key =
        YAML::LoadFile((dir / "gen" / "answers" / file).string())["answers"]["c"];
    for (const auto& [py, name] : {std::pair{p, "outcode_p"}, std::pair{q, "outcode_q"}}) {
      const std::string cpp = key[name].Scalar();
      EXPECT_EQ(py, "'" + cpp + "'") << file << " " << name;  // a Python str, the same bits
      EXPECT_TRUE(cpp.size() == 4 || cpp.size() == 6) << file << ": " << cpp;  // 2D TBRL or 3D
      EXPECT_EQ(cpp.find_first_not_of("01"), std::string::npos) << file << ": " << cpp;
      leading_zero += cpp[0] == '0';
    }
    ++keys;
  }
  EXPECT_EQ(keys, 60);
  EXPECT_GT(leading_zero, 0);  // the case that used to read as an octal integer
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
