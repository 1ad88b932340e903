#include "server/instructor_phrases.hpp"

#include <array>

#include "server/phrases.hpp"

namespace frustum::server {

namespace {

constexpr std::array<Phrase, static_cast<std::size_t>(Tell::Count)> kPhrases = {{
    {"Your course", "担当コース", "Ваш курс"},
    {"The class at a glance", "クラスの概要", "Класс в целом"},
    {"Gradebook", "成績表", "Ведомость"},
    {"Download as", "ダウンロード形式", "Скачать как"},
    {"Student", "学生", "Студент"},
    {"Percent", "百分率", "Процент"},
    {"Status", "状態", "Статус"},
    {"graded", "採点済み", "проверено"},
    {"being graded", "採点中", "проверяется"},
    {"no submission", "未提出", "не сдано"},
    {"Problems and answers", "問題と解答", "Задачи и ответы"},
    {"Answer", "解答", "Ответ"},
    {"Submitted", "提出", "Сдали"},
    {"Right", "正解", "Верно"},
    {"Partly right", "部分正解", "Частично верно"},
    {"Wrong", "不正解", "Неверно"},
    {"Could not be read", "読み取り不能", "Не прочитано"},
    {"Median attempts", "試行回数の中央値", "Медиана попыток"},
    {"Most frequent mistakes", "よくある誤り", "Частые ошибки"},
    {"Mistake", "誤り", "Ошибка"},
    {"Students who made it", "該当する学生", "Кто её допустил"},
    {"No named mistake yet.", "名前のついた誤りはまだありません。", "Названных ошибок пока нет."},
    {"Grade history", "採点履歴", "История оценок"},
    {"Version of the set", "問題集の版", "Версия набора"},
    {"When", "日時", "Когда"},
    {"By", "採点者", "Кем"},
    {"Regrade", "再採点", "Перепроверка"},
    {"Regrade the stored answers against the set file as it is now. A dry run lists every "
     "change first; nothing is written until you apply it.",
     "保存された解答を現在の問題集ファイルで採点し直します。まず試行で変更点をすべて表示し、"
     "適用するまで何も書き込みません。",
     "Перепроверить сохранённые ответы по текущему файлу набора. Сначала пробный прогон "
     "покажет все изменения; ничего не записывается, пока вы их не примените."},
    {"Whole set", "問題集全体", "Весь набор"},
    {"Dry run", "試行", "Пробный прогон"},
    {"Apply", "適用", "Применить"},
    {"Before", "変更前", "Было"},
    {"After", "変更後", "Стало"},
    {"Why", "理由", "Почему"},
    {"No score or verdict would change.", "得点や判定が変わる提出はありません。",
     "Ни баллы, ни вердикты не изменятся."},
    {"Regrade applied. Grades written:", "再採点を適用しました。書き込んだ成績:",
     "Перепроверка применена. Записано оценок:"},
    {"The set file changed after the dry run: run it again.",
     "試行の後に問題集ファイルが変わりました。もう一度試行してください。",
     "Файл набора изменился после пробного прогона: запустите его снова."},
    {"The set file cannot be served as it is now, so nothing was regraded:",
     "現在の問題集ファイルは読み込めないため、再採点していません:",
     "Текущий файл набора не читается, поэтому ничего не перепроверено:"},
    {"Answers that fit another student's variant", "他の学生の問題に合う解答",
     "Ответы, подходящие к варианту другого студента"},
    {"Only you see this. A submission is listed when its answers are wrong for the student's own "
     "variant and right for another student's.",
     "これは講師だけに表示されます。本人の問題では誤りで、他の学生の問題では正しい解答を一覧に"
     "しています。",
     "Это видите только вы. Попытка указана, если её ответы неверны для собственного варианта "
     "студента и верны для варианта другого."},
    {"None found.", "見つかりませんでした。", "Ничего не найдено."},
    {"Fits the variant of", "一致する問題の学生", "Подходит к варианту студента"},
    {"For their own variant", "本人の問題での判定", "Для своего варианта"},
    {"For that variant", "その問題での判定", "Для того варианта"},
    {"As written", "記入どおり", "Как написано"},
    {"Page", "ページ", "Страница"},
    {"This page updates as students submit.", "学生が提出するとこのページは更新されます。",
     "Страница обновляется по мере того, как студенты сдают ответы."},
    {"Only the first submissions were checked (the limit):",
     "上限のため、最初の提出だけを確認しました:", "Проверены только первые попытки (предел):"},
    {"What the student was shown", "学生に表示された内容", "Что было показано студенту"},
    {"grading failed", "採点失敗", "ошибка проверки"},
    {"the same verdicts, other credit", "判定は同じで得点が変化", "вердикты те же, баллы другие"},
    {"Edit", "編集", "Редактировать"},
    {"What students see", "学生に表示する内容", "Что видят студенты"},
    {"verdicts", "判定", "вердикты"},
    {"credit", "得点", "баллы"},
    {"named mistakes", "誤りの指摘", "названные ошибки"},
    {"right answers", "正答", "правильные ответы"},
    {"derivation", "導出", "вывод"},
    {"once graded", "採点後すぐ", "сразу после проверки"},
    {"from attempt", "次の提出回から:", "начиная с попытки"},
    {"after the student's own deadline", "各学生の締め切り後", "после срока сдачи студента"},
    {"from", "次の日時から:", "с"},
    {"never", "表示しない", "никогда"},
    {"Attempts", "提出回数の上限", "Попыток"},
    {"unlimited", "無制限", "без ограничения"},
    {"Penalty per further attempt", "2 回目以降の提出ごとの減点",
     "Штраф за каждую следующую попытку"},
    {"Deadline", "締め切り", "Срок сдачи"},
    {"Extensions", "締め切りの延長", "Продления срока"},
}};

}  // namespace

const char* tell(Tell key, Lang lang) { return kPhrases[static_cast<std::size_t>(key)].in(lang); }

}  // namespace frustum::server
