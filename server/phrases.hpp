// Every phrase a student reads on the served pages, by key, in English, Japanese and Russian
// (ServePhrases in tests/server_student_app_test.cpp fails on a key without all three).
#pragma once

#include <cstddef>

#include "solver/derivation/i18n.hpp"

namespace frustum::server {

enum class Say : std::size_t {
  YourSets,
  NoSets,
  SignInFirst,
  LinkInvalid,
  NotFound,
  Refused,
  TooMany,
  TooLarge,
  Busy,
  Problem,
  Given,
  Submit,
  ReadAs,
  CannotRead,
  Received,
  Attempt,
  AttemptsLeft,
  NoAttemptsLeft,
  DeadlinePassed,
  Deadline,
  FeedbackLater,
  Score,
  Correct,
  Incorrect,
  Partial,
  Unreadable,
  Missing,
  Mistake,
  WhereWrong,
  Carried,
  Derivation,
  YourAnswer,
  GradingFailed,
  DraftSaved,
  AllSets,
  FillOneAnswer,
  Figure,
  Submissions,
  Pending,
  Feedback,
  NotAccepted,
  RightAnswer,
  CreditedAfterPenalty,
  PenaltyPerAttempt,
  Count
};

const char* say(Say key, Lang lang);

// One phrase in the three languages of the pages, and the one a reader of `lang` reads
// (instructor_phrases.hpp keeps the instructors' own phrases in this form).
struct Phrase {
  const char* en;
  const char* ja;
  const char* ru;
  const char* in(Lang lang) const { return lang == Lang::Ja ? ja : lang == Lang::Ru ? ru : en; }
};

}  // namespace frustum::server
