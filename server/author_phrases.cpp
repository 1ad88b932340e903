#include "server/author_phrases.hpp"

#include <array>

#include "server/phrases.hpp"

namespace frustum::server {

namespace {

constexpr std::array<Phrase, static_cast<std::size_t>(AuthorSay::Count)> kPhrases = {{
    {"Authoring", "問題集の編集", "Редактирование набора"},
    {"Save", "保存", "Сохранить"},
    {"Save with errors", "エラーがあっても保存", "Сохранить с ошибками"},
    {"Preview the variant of (roster id)", "受講者の問題を表示(名簿の ID)",
     "Показать вариант студента (id из списка)"},
    {"Errors", "エラー", "Ошибки"},
    {"No errors.", "エラーはありません。", "Ошибок нет."},
    {"Warnings", "警告", "Предупреждения"},
    {"Sample answers", "解答例", "Примеры ответов"},
    {"Statement", "問題文", "Условие"},
    {"Answer key", "正答", "Ответы"},
    {"Saved.", "保存しました。", "Сохранено."},
    {"The file changed on disk since you opened it: reload it, then make your changes again.",
     "開いた後にファイルが変更されました。再読み込みしてから変更をやり直してください。",
     "Файл изменился на диске после открытия: загрузите его заново и повторите изменения."},
    {"Not saved: the set has errors. Fix them, or save with errors.",
     "保存していません。エラーがあります。修正するか、「エラーがあっても保存」を選んでください。",
     "Не сохранено: в наборе есть ошибки. Исправьте их или сохраните с ошибками."},
    {"The preview did not finish in time.", "プレビューが時間内に終わりませんでした。",
     "Предпросмотр не завершился вовремя."},
    {"Checking…", "確認中…", "Проверка…"},
    {"line", "行", "строка"},
    {"expected", "期待した判定", "ожидалось"},
    {"graded", "採点結果", "оценено"},
}};

}  // namespace

const char* say(AuthorSay key, Lang lang) {
  return kPhrases[static_cast<std::size_t>(key)].in(lang);
}

}  // namespace frustum::server
