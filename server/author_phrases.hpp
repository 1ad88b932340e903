// The phrases of the authoring page, each a named `Phrase` (solver/util/said.hpp) in English,
// Japanese and Russian, said as `kSave.in(lang)` (AuthorPage.PhrasesInEveryLanguage in
// tests/server_author_test.cpp checks kAllAuthorPagePhrases).
#pragma once

#include "solver/derivation/i18n.hpp"
#include "solver/util/said.hpp"

namespace frustum::server {

inline constexpr Phrase kAuthoring{"Authoring", "問題集の編集", "Редактирование набора"};
inline constexpr Phrase kSave{"Save", "保存", "Сохранить"};
inline constexpr Phrase kSaveWithErrors{"Save with errors", "エラーがあっても保存",
                                        "Сохранить с ошибками"};
inline constexpr Phrase kPreviewVariant{"Preview the variant of (roster id)",
                                        "受講者の問題を表示(名簿の ID)",
                                        "Показать вариант студента (id из списка)"};
inline constexpr Phrase kErrors{"Errors", "エラー", "Ошибки"};
inline constexpr Phrase kNoErrors{"No errors.", "エラーはありません。", "Ошибок нет."};
inline constexpr Phrase kWarnings{"Warnings", "警告", "Предупреждения"};
inline constexpr Phrase kSamples{"Sample answers", "解答例", "Примеры ответов"};
inline constexpr Phrase kStatement{"Statement", "問題文", "Условие"};
inline constexpr Phrase kAnswerKey{"Answer key", "正答", "Ответы"};
inline constexpr Phrase kSaved{"Saved.", "保存しました。", "Сохранено."};
inline constexpr Phrase kChangedOnDisk{
    "The file changed on disk since you opened it: reload it, then make your changes again.",
    "開いた後にファイルが変更されました。再読み込みしてから変更をやり直してください。",
    "Файл изменился на диске после открытия: загрузите его заново и повторите изменения."};
inline constexpr Phrase kCheckFailed{
    "Not saved: the set has errors. Fix them, or save with errors.",
    "保存していません。エラーがあります。修正するか、「エラーがあっても保存」を選んでください。",
    "Не сохранено: в наборе есть ошибки. Исправьте их или сохраните с ошибками."};
inline constexpr Phrase kPreviewFailed{"The preview did not finish in time.",
                                       "プレビューが時間内に終わりませんでした。",
                                       "Предпросмотр не завершился вовремя."};
inline constexpr Phrase kChecking{"Checking…", "確認中…", "Проверка…"};
inline constexpr Phrase kLine{"line", "行", "строка"};
inline constexpr Phrase kExpected{"expected", "期待した判定", "ожидалось"};
inline constexpr Phrase kGraded{"graded", "採点結果", "оценено"};

// Every phrase above, for AuthorPage.PhrasesInEveryLanguage in tests/server_author_test.cpp.
inline constexpr const Phrase* kAllAuthorPagePhrases[] = {
    &kAuthoring,   &kSave,          &kSaveWithErrors, &kPreviewVariant, &kErrors,   &kNoErrors,
    &kWarnings,    &kSamples,       &kStatement,      &kAnswerKey,      &kSaved,    &kChangedOnDisk,
    &kCheckFailed, &kPreviewFailed, &kChecking,       &kLine,           &kExpected, &kGraded};

}  // namespace frustum::server
