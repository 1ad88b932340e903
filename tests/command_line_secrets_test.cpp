// A database password on the command line is hidden from `ps` once the options are parsed.
#include "app/command_line_secrets.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace frustum::app {
namespace {

std::string hidden(std::string arg) {
  const SecretSpan s = password_in(arg);
  return arg.replace(s.offset, s.length, std::string(s.length, 'x'));
}

TEST(CommandLineSecrets, FindsTheURLsPasswordAndLibpqsKeyword) {
  EXPECT_EQ(hidden("postgresql://frustum:s3cr%40t@db.example.edu:5432/course"),
            "postgresql://frustum:xxxxxxxx@db.example.edu:5432/course");
  EXPECT_EQ(hidden("--db=postgres://u:p@h/db?sslmode=require"),
            "--db=postgres://u:x@h/db?sslmode=require");
  // An '@' in the password itself: the host starts after the last one.
  EXPECT_EQ(hidden("postgresql://u:a@b@h/db"), "postgresql://u:xxx@h/db");
  EXPECT_EQ(hidden("host=db user=u password=hunter2 dbname=c"),
            "host=db user=u password=xxxxxxx dbname=c");
  EXPECT_EQ(hidden("postgresql://u@h/db?password=pw&sslmode=require"),
            "postgresql://u@h/db?password=xx&sslmode=require");
  // Nothing secret: a user without a password, a path, a file name with "password" in it.
  for (const std::string arg : {"postgresql://u@h/db", "postgresql://h/db", "sqlite:/tmp/p.db",
                                "my_password=notes.yaml", "postgresql://u:@h/db", "course"})
    EXPECT_EQ(password_in(arg).length, 0u) << arg;
}

TEST(CommandLineSecrets, OverwritesArgvInPlaceAndWarnsOnce) {
  std::vector<std::string> args{
      "frustum",  "serve",      "course", "--db", "postgresql://u:topsecret@h/db",
      "--listen", "127.0.0.1:0"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::ostringstream err;
  hide_passwords(static_cast<int>(argv.size()), argv.data(), err);
  EXPECT_STREQ(argv[4], "postgresql://u:xxxxxxxxx@h/db");
  EXPECT_STREQ(argv[2], "course");
  EXPECT_NE(err.str().find("PGPASSWORD"), std::string::npos);
  EXPECT_EQ(err.str().find("topsecret"), std::string::npos);
  std::ostringstream quiet;
  hide_passwords(3, argv.data(), quiet);
  EXPECT_TRUE(quiet.str().empty());
}

}  // namespace
}  // namespace frustum::app
