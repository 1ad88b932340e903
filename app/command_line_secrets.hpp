// A database password given on the command line (`--db postgresql://user:secret@host/db`, or
// libpq's `password=secret`) is readable by every user of the machine in /proc/PID/cmdline.
// After the options are parsed, the password's characters in argv are overwritten, so `ps`
// shows `postgresql://user:xxxxxx@host/db` from then on, and a warning says where to give it.
#pragma once

#include <ostream>
#include <string_view>

namespace frustum::app {

// Where in `arg` a password is written: {offset, length}; {0, 0} when none is.
struct SecretSpan {
  std::size_t offset = 0, length = 0;
};
SecretSpan password_in(std::string_view arg);

// Overwrites every password in argv[1..argc) with 'x'; warns on `err` once if one was found.
void hide_passwords(int argc, char** argv, std::ostream& err);

}  // namespace frustum::app
