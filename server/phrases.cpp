#include "server/phrases.hpp"

#include <array>

namespace frustum::server {

namespace {

constexpr std::array<Phrase, static_cast<std::size_t>(Say::Count)> kPhrases = {{
    {"Your problem sets", "あなたの問題集", "Ваши наборы задач"},
    {"No problem sets yet.", "問題集はまだありません。", "Наборов задач пока нет."},
    {"Open the link your instructor gave you to sign in.",
     "講師から渡されたリンクを開いてログインしてください。",
     "Откройте ссылку, которую дал вам преподаватель, чтобы войти."},
    {"This link is not valid (it may have been replaced by a newer one). Ask your instructor "
     "for your link.",
     "このリンクは無効です(新しいリンクに置き換えられた可能性があります)。講師にリンクを確認して"
     "ください。",
     "Эта ссылка недействительна (возможно, её заменили новой). Попросите у преподавателя свою "
     "ссылку."},
    {"Not found.", "見つかりません。", "Не найдено."},
    {"This request was refused: reload the page and try again.",
     "この操作は拒否されました。ページを再読み込みしてやり直してください。",
     "Запрос отклонён: обновите страницу и попробуйте снова."},
    {"Too many requests: wait a moment and try again.",
     "リクエストが多すぎます。少し待ってからやり直してください。",
     "Слишком много запросов: подождите немного и попробуйте снова."},
    {"The answer is too long.", "解答が長すぎます。", "Ответ слишком длинный."},
    {"The server is busy: try again in a moment.",
     "サーバーが混み合っています。少し待ってから"
     "やり直してください。",
     "Сервер занят: попробуйте снова через минуту."},
    {"Problem", "問題", "Задача"},
    {"Given", "与えられた値", "Дано"},
    {"Submit", "提出", "Отправить"},
    {"Read as", "読み取り結果", "Прочитано как"},
    {"Cannot be read", "読み取れません", "Не удаётся прочитать"},
    {"Received; grading…", "受け付けました。採点中…", "Получено; идёт проверка…"},
    {"Attempt", "試行", "Попытка"},
    {"Attempts left", "残りの提出回数", "Осталось попыток"},
    {"No attempts left for this problem.", "この問題の提出回数を使い切りました。",
     "Попытки для этой задачи закончились."},
    {"The deadline has passed.", "締め切りを過ぎました。", "Срок сдачи истёк."},
    {"Deadline", "締め切り", "Срок сдачи"},
    {"Feedback will be shown later.", "講評は後で表示されます。",
     "Результаты будут показаны позже."},
    {"Score", "得点", "Баллы"},
    {"Correct", "正解", "Верно"},
    {"Incorrect", "不正解", "Неверно"},
    {"Partly correct", "部分的に正解", "Частично верно"},
    {"Could not be read", "読み取れませんでした", "Не удалось прочитать"},
    {"Not answered", "未回答", "Нет ответа"},
    {"Mistake", "誤り", "Ошибка"},
    {"Where it goes wrong", "誤りの箇所", "Где ошибка"},
    {"Credit carried from your earlier answers", "前の解答から引き継いだ得点",
     "Баллы с учётом ваших предыдущих ответов"},
    {"Derivation", "導出", "Вывод"},
    {"Your answer", "あなたの解答", "Ваш ответ"},
    {"This submission could not be graded; your instructor will see it.",
     "この提出は採点できませんでした。講師が確認します。",
     "Эту попытку не удалось проверить; преподаватель её увидит."},
    {"Draft saved", "下書きを保存しました", "Черновик сохранён"},
    {"All sets", "問題集の一覧", "Все наборы"},
    {"Fill in at least one answer.", "少なくとも一つの解答を入力してください。",
     "Заполните хотя бы один ответ."},
    {"Figure", "図", "Рисунок"},
    {"Submissions", "提出履歴", "Попытки"},
    {"Grading…", "採点中…", "Проверяется…"},
    {"Feedback", "講評", "Результаты"},
    {"Not accepted", "受け付けられません", "Не принято"},
    {"Right answer", "正答", "Правильный ответ"},
    {"Credited after the penalty", "減点後の得点", "Зачтено с учётом штрафа"},
    {"Each attempt after the first loses", "2 回目以降の提出ごとの減点",
     "Штраф за каждую попытку после первой"},
}};

}  // namespace

const char* say(Say key, Lang lang) { return kPhrases[static_cast<std::size_t>(key)].in(lang); }

}  // namespace frustum::server
