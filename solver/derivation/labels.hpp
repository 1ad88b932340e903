// The words around a derivation or a report that are not mathematics: headings and labels
// ("Answers", "Source", "Warning"), in the reader's language.
#pragma once

#include <string>

#include "solver/util/said.hpp"

namespace frustum::labels {

inline constexpr Phrase kAnswers{"Answers", "解答", "Ответы"};
inline constexpr Phrase kAnswer{"answer", "解答", "ответ"};
inline constexpr Phrase kValue{"value", "値", "значение"};
inline constexpr Phrase kSource{"Source", "出典", "Источник"};
inline constexpr Phrase kWarning{"Warning", "警告", "Предупреждение"};
inline constexpr Phrase kWarningLower{"warning", "警告", "предупреждение"};
inline constexpr Phrase kError{"Error", "エラー", "Ошибка"};
inline constexpr Phrase kErrorLower{"error", "エラー", "ошибка"};
inline constexpr Phrase kFigure{"Figure", "図", "Рисунок"};
inline constexpr Phrase kYourAnswerDashedWithKey{
    "Dashed red: your answer; green: the right answer.", "赤い破線: あなたの解答, 緑: 正しい解答.",
    "Красный пунктир — ваш ответ, зелёный — правильный."};
inline constexpr Phrase kYourAnswerDashed{"Dashed red: your answer.", "赤い破線: あなたの解答.",
                                          "Красный пунктир — ваш ответ."};

// A label in `lang`, as a string to build text with.
inline std::string in(const Phrase& label, Lang lang) { return std::string(label.in(lang)); }

}  // namespace frustum::labels
