// The instructors' side of `frustum serve`, one handler that StudentApp's route() dispatches
// /instructor/… to once the session is an instructor's (a student's gets 403 before this):
//
//   GET  /instructor/                        the course's sets
//   GET  /instructor/set/S[?sort=K&desc=1&page=N]  the class at a glance: the gradebook, per
//                                            problem and answer counts, the frequent mistakes
//   GET  /instructor/set/S/gradebook.csv     the gradebook as `grade -o` writes it
//   GET  /instructor/set/S/canvas.csv        … as Canvas and Moodle import it
//   GET  /instructor/set/S/moodle.csv
//   GET  /instructor/set/S/student/ID        one student's submissions, answers as written,
//                                            what they were shown, each grade's history
//   GET  /instructor/set/S/copies            answers that fit another student's variant
//   POST /instructor/set/S/regrade           a dry run; with apply=1, the regrade applied
//   GET  /instructor/events?set=S&mark=M     server-sent events: `change` when the class moves
//
// /instructor/author/… is the authoring page's, not this handler's.
#pragma once

#include "server/session.hpp"
#include "server/student_app.hpp"

namespace frustum::server {

Response handle_instructor(StudentApp& app, const Visitor& v, const Request& r, Millis now);

}  // namespace frustum::server
