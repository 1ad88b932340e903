// Every phrase a student reads on the served pages, each a named `Phrase` (solver/util/said.hpp)
// in English, Japanese and Russian, said as `kYourSets.in(lang)`. A phrase without all three does
// not compile; ServePhrases in tests/server_student_app_test.cpp checks, over
// kAllStudentPagePhrases, that no Japanese or Russian text is left in English.
#pragma once

#include "solver/derivation/i18n.hpp"
#include "solver/util/said.hpp"

namespace frustum::server {

inline constexpr Phrase kYourSets{"Your problem sets", "あなたの問題集", "Ваши наборы задач"};
inline constexpr Phrase kNoSets{"No problem sets yet.", "問題集はまだありません。",
                                "Наборов задач пока нет."};
inline constexpr Phrase kSignInFirst{
    "Open the link your instructor gave you to sign in.",
    "講師から渡されたリンクを開いてログインしてください。",
    "Откройте ссылку, которую дал вам преподаватель, чтобы войти."};
inline constexpr Phrase kLinkInvalid{
    "This link is not valid (it may have been replaced by a newer one). Ask your instructor "
    "for your link.",
    "このリンクは無効です(新しいリンクに置き換えられた可能性があります)。講師にリンクを確認して"
    "ください。",
    "Эта ссылка недействительна (возможно, её заменили новой). Попросите у преподавателя свою "
    "ссылку."};
inline constexpr Phrase kNotFound{"Not found.", "見つかりません。", "Не найдено."};
inline constexpr Phrase kRefused{
    "This request was refused: reload the page and try again.",
    "この操作は拒否されました。ページを再読み込みしてやり直してください。",
    "Запрос отклонён: обновите страницу и попробуйте снова."};
inline constexpr Phrase kTooMany{"Too many requests: wait a moment and try again.",
                                 "リクエストが多すぎます。少し待ってからやり直してください。",
                                 "Слишком много запросов: подождите немного и попробуйте снова."};
inline constexpr Phrase kTooLarge{"The answer is too long.", "解答が長すぎます。",
                                  "Ответ слишком длинный."};
inline constexpr Phrase kBusy{"The server is busy: try again in a moment.",
                              "サーバーが混み合っています。少し待ってから"
                              "やり直してください。",
                              "Сервер занят: попробуйте снова через минуту."};
inline constexpr Phrase kProblem{"Problem", "問題", "Задача"};
inline constexpr Phrase kGiven{"Given", "与えられた値", "Дано"};
inline constexpr Phrase kSubmit{"Submit", "提出", "Отправить"};
inline constexpr Phrase kReadAs{"Read as", "読み取り結果", "Прочитано как"};
inline constexpr Phrase kCannotRead{"Cannot be read", "読み取れません", "Не удаётся прочитать"};
inline constexpr Phrase kReceived{"Received; grading…", "受け付けました。採点中…",
                                  "Получено; идёт проверка…"};
inline constexpr Phrase kAttempt{"Attempt", "試行", "Попытка"};
inline constexpr Phrase kAttemptsLeft{"Attempts left", "残りの提出回数", "Осталось попыток"};
inline constexpr Phrase kNoAttemptsLeft{"No attempts left for this problem.",
                                        "この問題の提出回数を使い切りました。",
                                        "Попытки для этой задачи закончились."};
inline constexpr Phrase kDeadlinePassed{"The deadline has passed.", "締め切りを過ぎました。",
                                        "Срок сдачи истёк."};
inline constexpr Phrase kDeadline{"Deadline", "締め切り", "Срок сдачи"};
inline constexpr Phrase kFeedbackLater{"Feedback will be shown later.", "講評は後で表示されます。",
                                       "Результаты будут показаны позже."};
inline constexpr Phrase kScore{"Score", "得点", "Баллы"};
inline constexpr Phrase kCorrect{"Correct", "正解", "Верно"};
inline constexpr Phrase kIncorrect{"Incorrect", "不正解", "Неверно"};
inline constexpr Phrase kPartial{"Partly correct", "部分的に正解", "Частично верно"};
inline constexpr Phrase kUnreadable{"Could not be read", "読み取れませんでした",
                                    "Не удалось прочитать"};
inline constexpr Phrase kMissing{"Not answered", "未回答", "Нет ответа"};
inline constexpr Phrase kMistake{"Mistake", "誤り", "Ошибка"};
inline constexpr Phrase kWhereWrong{"Where it goes wrong", "誤りの箇所", "Где ошибка"};
inline constexpr Phrase kCarried{"Credit carried from your earlier answers",
                                 "前の解答から引き継いだ得点",
                                 "Баллы с учётом ваших предыдущих ответов"};
inline constexpr Phrase kDerivation{"Derivation", "導出", "Вывод"};
inline constexpr Phrase kYourAnswer{"Your answer", "あなたの解答", "Ваш ответ"};
inline constexpr Phrase kGradingFailed{
    "This submission could not be graded; your instructor will see it.",
    "この提出は採点できませんでした。講師が確認します。",
    "Эту попытку не удалось проверить; преподаватель её увидит."};
inline constexpr Phrase kDraftSaved{"Draft saved", "下書きを保存しました", "Черновик сохранён"};
inline constexpr Phrase kAllSets{"All sets", "問題集の一覧", "Все наборы"};
inline constexpr Phrase kFillOneAnswer{"Fill in at least one answer.",
                                       "少なくとも一つの解答を入力してください。",
                                       "Заполните хотя бы один ответ."};
inline constexpr Phrase kFigure{"Figure", "図", "Рисунок"};
inline constexpr Phrase kSubmissions{"Submissions", "提出履歴", "Попытки"};
inline constexpr Phrase kPending{"Grading…", "採点中…", "Проверяется…"};
inline constexpr Phrase kFeedback{"Feedback", "講評", "Результаты"};
inline constexpr Phrase kNotAccepted{"Not accepted", "受け付けられません", "Не принято"};
inline constexpr Phrase kRightAnswer{"Right answer", "正答", "Правильный ответ"};
inline constexpr Phrase kCreditedAfterPenalty{"Credited after the penalty", "減点後の得点",
                                              "Зачтено с учётом штрафа"};
inline constexpr Phrase kPenaltyPerAttempt{"Each attempt after the first loses",
                                           "2 回目以降の提出ごとの減点",
                                           "Штраф за каждую попытку после первой"};

// Every phrase above, for ServePhrases in tests/server_student_app_test.cpp.
inline constexpr const Phrase* kAllStudentPagePhrases[] = {&kYourSets,
                                                           &kNoSets,
                                                           &kSignInFirst,
                                                           &kLinkInvalid,
                                                           &kNotFound,
                                                           &kRefused,
                                                           &kTooMany,
                                                           &kTooLarge,
                                                           &kBusy,
                                                           &kProblem,
                                                           &kGiven,
                                                           &kSubmit,
                                                           &kReadAs,
                                                           &kCannotRead,
                                                           &kReceived,
                                                           &kAttempt,
                                                           &kAttemptsLeft,
                                                           &kNoAttemptsLeft,
                                                           &kDeadlinePassed,
                                                           &kDeadline,
                                                           &kFeedbackLater,
                                                           &kScore,
                                                           &kCorrect,
                                                           &kIncorrect,
                                                           &kPartial,
                                                           &kUnreadable,
                                                           &kMissing,
                                                           &kMistake,
                                                           &kWhereWrong,
                                                           &kCarried,
                                                           &kDerivation,
                                                           &kYourAnswer,
                                                           &kGradingFailed,
                                                           &kDraftSaved,
                                                           &kAllSets,
                                                           &kFillOneAnswer,
                                                           &kFigure,
                                                           &kSubmissions,
                                                           &kPending,
                                                           &kFeedback,
                                                           &kNotAccepted,
                                                           &kRightAnswer,
                                                           &kCreditedAfterPenalty,
                                                           &kPenaltyPerAttempt};

}  // namespace frustum::server
