// Every phrase an instructor reads on the served pages (/instructor/…), by key, in English,
// Japanese and Russian (InstructorPhrases in tests/server_instructor_test.cpp fails on a key
// without all three). Phrases shared with the students' pages are phrases.hpp's.
#pragma once

#include <cstddef>

#include "solver/derivation/i18n.hpp"

namespace frustum::server {

enum class Tell : std::size_t {
  YourCourse,
  ClassTitle,
  Gradebook,
  DownloadAs,
  Student,
  Percent,
  Status,
  StatusGraded,
  StatusPending,
  StatusNone,
  ProblemsAndAnswers,
  Answer,
  Submitted,
  Right,
  PartlyRight,
  Wrong,
  Unreadable,
  MedianAttempts,
  Mistakes,
  Mistake,
  TheStudents,
  NoMistakes,
  History,
  SetVersion,
  When,
  By,
  Regrade,
  RegradeHelp,
  WholeSet,
  DryRun,
  Apply,
  Before,
  After,
  Why,
  NoChanges,
  Applied,
  SetChanged,
  SetBroken,
  CopySignals,
  CopyHelp,
  NoCopies,
  FitsVariantOf,
  OwnVerdict,
  OtherVerdict,
  AsWritten,
  Page,
  Live,
  CheckedOnly,
  AsSeen,
  Failed,
  SameVerdicts,
  Edit,
  WhatStudentsSee,
  PartVerdicts,
  PartCredit,
  PartMistakes,
  PartKey,
  PartDerivation,
  AtOnce,
  FromAttempt,
  AfterTheirDeadline,
  FromDate,
  Never,
  Attempts,
  Unlimited,
  PenaltyPerAttempt,
  Deadline,
  Extensions,
  Count
};

const char* tell(Tell key, Lang lang);

}  // namespace frustum::server
