// Every phrase an instructor reads on the served pages (/instructor/…), each a named `Phrase`
// (solver/util/said.hpp) in English, Japanese and Russian, said as `kGradebook.in(lang)`. A phrase
// without all three does not compile; InstructorPhrases in tests/server_instructor_test.cpp
// checks, over kAllInstructorPagePhrases, that no Japanese or Russian text is left in English.
// Phrases shared with the students' pages are phrases.hpp's (kMistake, kDeadline); the two
// named kInstructor… here say for instructors what a student's page says otherwise.
#pragma once

#include "server/phrases.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/util/said.hpp"

namespace frustum::server {

inline constexpr Phrase kYourCourse{"Your course", "担当コース", "Ваш курс"};
inline constexpr Phrase kClassTitle{"The class at a glance", "クラスの概要", "Класс в целом"};
inline constexpr Phrase kGradebook{"Gradebook", "成績表", "Ведомость"};
inline constexpr Phrase kDownloadAs{"Download as", "ダウンロード形式", "Скачать как"};
inline constexpr Phrase kStudent{"Student", "学生", "Студент"};
inline constexpr Phrase kPercent{"Percent", "百分率", "Процент"};
inline constexpr Phrase kStatus{"Status", "状態", "Статус"};
inline constexpr Phrase kStatusGraded{"graded", "採点済み", "проверено"};
inline constexpr Phrase kStatusPending{"being graded", "採点中", "проверяется"};
inline constexpr Phrase kStatusNone{"no submission", "未提出", "не сдано"};
inline constexpr Phrase kProblemsAndAnswers{"Problems and answers", "問題と解答",
                                            "Задачи и ответы"};
inline constexpr Phrase kAnswer{"Answer", "解答", "Ответ"};
inline constexpr Phrase kSubmitted{"Submitted", "提出", "Сдали"};
inline constexpr Phrase kRight{"Right", "正解", "Верно"};
inline constexpr Phrase kPartlyRight{"Partly right", "部分正解", "Частично верно"};
inline constexpr Phrase kWrong{"Wrong", "不正解", "Неверно"};
inline constexpr Phrase kInstructorUnreadable{"Could not be read", "読み取り不能", "Не прочитано"};
inline constexpr Phrase kMedianAttempts{"Median attempts", "試行回数の中央値", "Медиана попыток"};
inline constexpr Phrase kMistakes{"Most frequent mistakes", "よくある誤り", "Частые ошибки"};
inline constexpr Phrase kTheStudents{"Students who made it", "該当する学生", "Кто её допустил"};
inline constexpr Phrase kNoMistakes{"No named mistake yet.", "名前のついた誤りはまだありません。",
                                    "Названных ошибок пока нет."};
inline constexpr Phrase kHistory{"Grade history", "採点履歴", "История оценок"};
inline constexpr Phrase kSetVersion{"Version of the set", "問題集の版", "Версия набора"};
inline constexpr Phrase kWhen{"When", "日時", "Когда"};
inline constexpr Phrase kBy{"By", "採点者", "Кем"};
inline constexpr Phrase kRegrade{"Regrade", "再採点", "Перепроверка"};
inline constexpr Phrase kRegradeHelp{
    "Regrade the stored answers against the set file as it is now. A dry run lists every "
    "change first; nothing is written until you apply it.",
    "保存された解答を現在の問題集ファイルで採点し直します。まず試行で変更点をすべて表示し、"
    "適用するまで何も書き込みません。",
    "Перепроверить сохранённые ответы по текущему файлу набора. Сначала пробный прогон "
    "покажет все изменения; ничего не записывается, пока вы их не примените."};
inline constexpr Phrase kWholeSet{"Whole set", "問題集全体", "Весь набор"};
inline constexpr Phrase kDryRun{"Dry run", "試行", "Пробный прогон"};
inline constexpr Phrase kApply{"Apply", "適用", "Применить"};
inline constexpr Phrase kBefore{"Before", "変更前", "Было"};
inline constexpr Phrase kAfter{"After", "変更後", "Стало"};
inline constexpr Phrase kWhy{"Why", "理由", "Почему"};
inline constexpr Phrase kNoChanges{"No score or verdict would change.",
                                   "得点や判定が変わる提出はありません。",
                                   "Ни баллы, ни вердикты не изменятся."};
inline constexpr Phrase kApplied{
    "Regrade applied. Grades written:", "再採点を適用しました。書き込んだ成績:",
    "Перепроверка применена. Записано оценок:"};
inline constexpr Phrase kSetChanged{
    "The set file changed after the dry run: run it again.",
    "試行の後に問題集ファイルが変わりました。もう一度試行してください。",
    "Файл набора изменился после пробного прогона: запустите его снова."};
inline constexpr Phrase kSetBroken{
    "The set file cannot be served as it is now, so nothing was regraded:",
    "現在の問題集ファイルは読み込めないため、再採点していません:",
    "Текущий файл набора не читается, поэтому ничего не перепроверено:"};
inline constexpr Phrase kCopySignals{"Answers that fit another student's variant",
                                     "他の学生の問題に合う解答",
                                     "Ответы, подходящие к варианту другого студента"};
inline constexpr Phrase kCopyHelp{
    "Only you see this. A submission is listed when its answers are wrong for the student's own "
    "variant and right for another student's.",
    "これは講師だけに表示されます。本人の問題では誤りで、他の学生の問題では正しい解答を一覧に"
    "しています。",
    "Это видите только вы. Попытка указана, если её ответы неверны для собственного варианта "
    "студента и верны для варианта другого."};
inline constexpr Phrase kNoCopies{"None found.", "見つかりませんでした。", "Ничего не найдено."};
inline constexpr Phrase kFitsVariantOf{"Fits the variant of", "一致する問題の学生",
                                       "Подходит к варианту студента"};
inline constexpr Phrase kOwnVerdict{"For their own variant", "本人の問題での判定",
                                    "Для своего варианта"};
inline constexpr Phrase kOtherVerdict{"For that variant", "その問題での判定", "Для того варианта"};
inline constexpr Phrase kAsWritten{"As written", "記入どおり", "Как написано"};
inline constexpr Phrase kPage{"Page", "ページ", "Страница"};
inline constexpr Phrase kLive{"This page updates as students submit.",
                              "学生が提出するとこのページは更新されます。",
                              "Страница обновляется по мере того, как студенты сдают ответы."};
inline constexpr Phrase kCheckedOnly{
    "Only the first submissions were checked (the limit):",
    "上限のため、最初の提出だけを確認しました:", "Проверены только первые попытки (предел):"};
inline constexpr Phrase kAsSeen{"What the student was shown", "学生に表示された内容",
                                "Что было показано студенту"};
inline constexpr Phrase kFailed{"grading failed", "採点失敗", "ошибка проверки"};
inline constexpr Phrase kSameVerdicts{"the same verdicts, other credit", "判定は同じで得点が変化",
                                      "вердикты те же, баллы другие"};
inline constexpr Phrase kEdit{"Edit", "編集", "Редактировать"};
inline constexpr Phrase kWhatStudentsSee{"What students see", "学生に表示する内容",
                                         "Что видят студенты"};
inline constexpr Phrase kPartVerdicts{"verdicts", "判定", "вердикты"};
inline constexpr Phrase kPartCredit{"credit", "得点", "баллы"};
inline constexpr Phrase kPartMistakes{"named mistakes", "誤りの指摘", "названные ошибки"};
inline constexpr Phrase kPartKey{"right answers", "正答", "правильные ответы"};
inline constexpr Phrase kPartDerivation{"derivation", "導出", "вывод"};
inline constexpr Phrase kAtOnce{"once graded", "採点後すぐ", "сразу после проверки"};
inline constexpr Phrase kFromAttempt{"from attempt", "次の提出回から:", "начиная с попытки"};
inline constexpr Phrase kAfterTheirDeadline{"after the student's own deadline",
                                            "各学生の締め切り後", "после срока сдачи студента"};
inline constexpr Phrase kFromDate{"from", "次の日時から:", "с"};
inline constexpr Phrase kNever{"never", "表示しない", "никогда"};
inline constexpr Phrase kAttempts{"Attempts", "提出回数の上限", "Попыток"};
inline constexpr Phrase kUnlimited{"unlimited", "無制限", "без ограничения"};
inline constexpr Phrase kInstructorPenaltyPerAttempt{"Penalty per further attempt",
                                                     "2 回目以降の提出ごとの減点",
                                                     "Штраф за каждую следующую попытку"};
inline constexpr Phrase kExtensions{"Extensions", "締め切りの延長", "Продления срока"};

// Every phrase above, for InstructorPhrases in tests/server_instructor_test.cpp.
inline constexpr const Phrase* kAllInstructorPagePhrases[] = {&kYourCourse,
                                                              &kClassTitle,
                                                              &kGradebook,
                                                              &kDownloadAs,
                                                              &kStudent,
                                                              &kPercent,
                                                              &kStatus,
                                                              &kStatusGraded,
                                                              &kStatusPending,
                                                              &kStatusNone,
                                                              &kProblemsAndAnswers,
                                                              &kAnswer,
                                                              &kSubmitted,
                                                              &kRight,
                                                              &kPartlyRight,
                                                              &kWrong,
                                                              &kInstructorUnreadable,
                                                              &kMedianAttempts,
                                                              &kMistakes,
                                                              &kTheStudents,
                                                              &kNoMistakes,
                                                              &kHistory,
                                                              &kSetVersion,
                                                              &kWhen,
                                                              &kBy,
                                                              &kRegrade,
                                                              &kRegradeHelp,
                                                              &kWholeSet,
                                                              &kDryRun,
                                                              &kApply,
                                                              &kBefore,
                                                              &kAfter,
                                                              &kWhy,
                                                              &kNoChanges,
                                                              &kApplied,
                                                              &kSetChanged,
                                                              &kSetBroken,
                                                              &kCopySignals,
                                                              &kCopyHelp,
                                                              &kNoCopies,
                                                              &kFitsVariantOf,
                                                              &kOwnVerdict,
                                                              &kOtherVerdict,
                                                              &kAsWritten,
                                                              &kPage,
                                                              &kLive,
                                                              &kCheckedOnly,
                                                              &kAsSeen,
                                                              &kFailed,
                                                              &kSameVerdicts,
                                                              &kEdit,
                                                              &kWhatStudentsSee,
                                                              &kPartVerdicts,
                                                              &kPartCredit,
                                                              &kPartMistakes,
                                                              &kPartKey,
                                                              &kPartDerivation,
                                                              &kAtOnce,
                                                              &kFromAttempt,
                                                              &kAfterTheirDeadline,
                                                              &kFromDate,
                                                              &kNever,
                                                              &kAttempts,
                                                              &kUnlimited,
                                                              &kInstructorPenaltyPerAttempt,
                                                              &kExtensions};

}  // namespace frustum::server
