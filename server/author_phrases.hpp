// The phrases of the authoring page, by key, in English, Japanese and Russian
// (AuthorPage.PhrasesInEveryLanguage in tests/server_author_test.cpp fails on a missing one).
#pragma once

#include <cstddef>

#include "solver/derivation/i18n.hpp"

namespace frustum::server {

enum class AuthorSay : std::size_t {
  Authoring,
  Save,
  SaveWithErrors,
  PreviewVariant,
  Errors,
  NoErrors,
  Warnings,
  Samples,
  Statement,
  AnswerKey,
  Saved,
  ChangedOnDisk,
  CheckFailed,
  PreviewFailed,
  Checking,
  Line,
  Expected,
  Graded,
  Count
};

const char* say(AuthorSay key, Lang lang);

}  // namespace frustum::server
