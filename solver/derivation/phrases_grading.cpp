// The grader's words in Japanese and Russian: its interface, verdicts, comparisons, the
// misconceptions it names and the trivial answers it recognises, and reading errors.
#include "solver/derivation/phrases.hpp"

namespace frustum {

namespace {

constexpr Phrase kPhrases[] = {
    // Interface.
    {"Student", "学生", "Студент"},
    {"(unnamed)", "(名前なし)", "(без имени)"},
    {"Source", "出典", "Источник"},
    {"Score", "得点", "Баллы"},
    // Exam sheets and answer keys on paper.
    {"exam", "試験", "контрольная работа"},
    {"answer key", "解答", "ответы"},
    {"Name", "氏名", "Имя"},
    {"Problem", "問題", "Задача"},
    {"Answer", "解答", "Ответ"},
    {"Answers", "解答", "Ответы"},
    {"Verdict", "判定", "Оценка"},
    {"You wrote", "あなたの解答", "Ваш ответ"},
    {"Expected", "正解", "Верный ответ"},
    {"How to get it", "求め方", "Как получить"},
    {"Feedback", "フィードバック", "Отзыв"},
    {"Derivation", "導出", "Вывод"},
    {"Common mistake", "よくある誤り", "Типичная ошибка"},
    {"Where it goes wrong", "誤りの生じるステップ", "Где возникает ошибка"},
    {"See step", "参照ステップ", "См. шаг"},
    {"credit carried forward from your earlier answer", "前の解答からの継続点 (誤りの持ち越し)",
     "баллы перенесены с вашего предыдущего ответа"},
    {"error", "エラー", "ошибка"},
    {"Error", "エラー", "Ошибка"},
    {"answer", "解答", "ответ"},
    {"value", "値", "значение"},
    {"warning", "警告", "предупреждение"},
    {"correct", "正解", "верно"},
    {"incorrect", "不正解", "неверно"},
    {"partial", "部分点", "частично"},
    {"unparseable", "解釈できない", "не распознано"},
    {"missing", "未解答", "нет ответа"},
    // Comparisons.
    {"no answer given", "解答がありません", "ответа нет"},
    {"equal", "一致", "равно"},
    {"exactly equal", "完全に一致", "точно равно"},
    {"within tolerance", "許容誤差内", "в пределах допуска"},
    {"there is no such value here", "ここには値がありません", "здесь такого значения нет"},
    {"there is no such value", "その値は存在しません", "такого значения нет"},
    {"there is a value here", "ここには値があります", "здесь значение есть"},
    {"there are none", "ありません", "их нет"},
    {"the same homogeneous point (a positive multiple)", "同じ同次座標の点 (正の定数倍)",
     "та же точка в однородных координатах (положительное кратное)"},
    {"the same direction (a normal is right up to a positive factor)",
     "同じ向き (法線は正の定数倍を除いて正しい)",
     "то же направление (нормаль верна с точностью до положительного множителя)"},
    {"it points the opposite way", "向きが逆です", "направлена в противоположную сторону"},
    {"the direction is right but the length is {0} — a unit vector has length 1 (divide by the "
     "length)",
     "向きは正しいが長さが {0} です — 単位ベクトルの長さは 1 (長さで割る)",
     "направление верное, но длина {0} — у единичного вектора длина 1 (разделите на длину)"},
    {"a plane has 4 coefficients [a, b, c, d] of ax + by + cz = d",
     "平面の係数は a·x + b·y + c·z = d の 4 つ [a, b, c, d] です",
     "у плоскости 4 коэффициента [a, b, c, d] уравнения a·x + b·y + c·z = d"},
    {"a plane has 4 coefficients", "平面の係数は 4 つです", "у плоскости 4 коэффициента"},
    {"read as one point", "1 つの点として読みました", "прочитано как одна точка"},
    {"read as one point in homogeneous coordinates (w = 1)",
     "同次座標 (w = 1) の 1 つの点として読みました",
     "прочитано как одна точка в однородных координатах (w = 1)"},
    {"read as points in homogeneous coordinates (w = 1)", "同次座標 (w = 1) の点として読みました",
     "прочитано как точки в однородных координатах (w = 1)"},
    {"read as homogeneous coordinates: (x, y, z, w) is the point (x/w, y/w, z/w)",
     "同次座標として読みました: (x, y, z, w) は点 (x/w, y/w, z/w) です",
     "прочитано как однородные координаты: (x, y, z, w) — это точка (x/w, y/w, z/w)"},
    {"the same plane (equations agree up to a non-zero factor)",
     "同じ平面 (方程式が 0 でない定数倍を除いて一致)",
     "та же плоскость (уравнения совпадают с точностью до ненулевого множителя)"},
    {"the same set (order does not matter)", "同じ集合 (順序は問いません)",
     "то же множество (порядок не важен)"},
    {"the same items (order does not matter)", "同じ要素 (順序は問いません)",
     "те же элементы (порядок не важен)"},
    {"the right items in the wrong order", "要素は正しいが順序が違います",
     "верные элементы в неверном порядке"},
    {"the order differs", "順序が違います", "порядок другой"},
    {"the same segment, its endpoints in the other order", "同じ線分 (端点の順序が逆)",
     "тот же отрезок, концы в другом порядке"},
    {"the same polygon, starting at another vertex", "同じ多角形 (別の頂点から始まる)",
     "тот же многоугольник, начиная с другой вершины"},
    {"the right vertices in the opposite order: the orientation decides which side is the front",
     "頂点は正しいが順序が逆です. 向きがどちらの側が表かを決めます",
     "верные вершины в обратном порядке: ориентация решает, какая сторона лицевая"},
    {"the linear part of a transform without translation", "平行移動を含まない変換の線形部分",
     "линейная часть преобразования без переноса"},
    {"read as {0} (the leading zeros restored)", "{0} と読みました (先頭の 0 を補いました)",
     "прочитано как {0} (ведущие нули восстановлены)"},
    {"{0} bits, one per window edge", "ウィンドウの辺ごとに 1 ビット、計 {0} ビットです",
     "{0} бит, по одному на каждую сторону окна"},
    {"this problem asks for the {0}×{1} homogeneous matrix",
     "この問題は {0}×{1} の同次変換行列を求めています",
     "в этой задаче нужна однородная матрица {0}×{1}"},
    {"this transform moves the origin (a translation or a projection): it needs the {0}×{1} "
     "homogeneous matrix",
     "この変換は原点を動かします (平行移動または投影). {0}×{1} の同次変換行列が必要です",
     "это преобразование сдвигает начало координат (перенос или проекция): нужна однородная "
     "матрица {0}×{1}"},
    {"expected {0} components, got {1} components", "成分は {0} 個のはずですが, {1} 個です",
     "ожидалось компонент: {0}, получено: {1}"},
    {"expected {0} components, got {1}", "成分は {0} 個のはずですが, {1} です",
     "ожидалось компонент: {0}, получено: {1}"},
    {"expected a {0} matrix, got a {1} matrix", "{0} 行列のはずですが, {1} 行列です",
     "ожидалась матрица {0}, получена матрица {1}"},
    {"expected a {0} matrix, got {1} components", "{0} 行列のはずですが, 成分 {1} 個です",
     "ожидалась матрица {0}, получено компонент: {1}"},
    {"expected {0} components, got a {1} matrix", "成分は {0} 個のはずですが, {1} 行列です",
     "ожидалось компонент: {0}, получена матрица {1}"},
    {"expected {0} items, got {1}", "要素は {0} 個のはずですが, {1} 個です",
     "ожидалось элементов: {0}, получено: {1}"},
    {"expected {0} vertices, got {1}", "頂点は {0} 個のはずですが, {1} 個です",
     "ожидалось вершин: {0}, получено: {1}"},
    {"{0} of the {1} components that take work are right",
     "計算を要する {1} 個の成分のうち {0} 個が正しい",
     "верно {0} из {1} компонент, требующих вычисления"},
    {"{0} of the {1} entries that take work are right",
     "計算を要する {1} 個の要素のうち {0} 個が正しい",
     "верно {0} из {1} элементов, требующих вычисления"},
    {"{0} of the {1} components that take work are right (entries a trivial answer also has do not "
     "count)",
     "計算を要する {1} 個の成分のうち {0} 個が正しい (自明な解答でも得られる成分は数えない)",
     "верно {0} из {1} компонент, требующих вычисления (элементы, которые есть и у тривиального "
     "ответа, не считаются)"},
    {"{0} of the {1} entries that take work are right (entries a trivial answer also has do not "
     "count)",
     "計算を要する {1} 個の要素のうち {0} 個が正しい (自明な解答でも得られる要素は数えない)",
     "верно {0} из {1} элементов, требующих вычисления (элементы, которые есть и у тривиального "
     "ответа, не считаются)"},
    {"{0} of the {1} entries that take work are right, and {2} of those that take no work are "
     "wrong: {3} of {4} counted",
     "計算を要する {1} 個の要素のうち {0} 個が正しく, 計算を要しない要素のうち {2} 個が誤り. "
     "数えた {4} 個のうち {3} 個",
     "верно {0} из {1} элементов, требующих вычисления, и {2} из не требующих вычисления неверны: "
     "засчитано {3} из {4}"},
    {"{0} of the {1} components that take work are right, and {2} of those that take no work "
     "are wrong: {3} of {4} counted",
     "計算を要する {1} 個の成分のうち {0} 個が正しく, 計算を要しない成分のうち {2} 個が誤り. "
     "数えた {4} 個のうち {3} 個",
     "верно {0} из {1} компонент, требующих вычисления, и {2} из не требующих вычисления неверны: "
     "засчитано {3} из {4}"},
    {"{0} of the {1} expected items, and {2} that should not be there, {3} of them a second copy "
     "of an item (an item written twice is right once; the copy counts as one that should not be "
     "there)",
     "期待される {1} 個のうち {0} 個, および余分なもの {2} 個 (うち {3} 個は同じ項目の二度目: "
     "二度書いた項目は一度だけ正解とし, 二度目は余分なものと数える)",
     "{0} из {1} ожидаемых элементов и {2} лишних, из них {3} — повтор элемента (элемент, "
     "записанный дважды, верен один раз; повтор считается лишним)"},
    {"{0} of the {1} expected items, and {2} that should not be there",
     "期待される {1} 個のうち {0} 個, および余分なもの {2} 個",
     "{0} из {1} ожидаемых элементов и {2} лишних"},
    {"{0} of {1} entries right, no more than one word written everywhere would get.",
     "{1} 個中 {0} 個が正しいが, どこにも同じ一語を書いた場合を超えていない.",
     "верно {0} из {1}, не больше, чем дало бы одно слово, написанное везде."},
    {"{0} of {1} entries right; answering \"{2}\" everywhere would get {3}, so the credit counts "
     "the entries beyond that.",
     "{1} 個中 {0} 個が正しい. どこにも「{2}」と答えると {3} 個になるので, "
     "得点はそれを超えた分だけ数える.",
     "верно {0} из {1}; ответ «{2}» везде дал бы {3}, поэтому засчитываются только элементы сверх "
     "этого."},
    {"{0} of {1} entries right, no more than one word written everywhere would get. {2}",
     "{1} 個中 {0} 個が正しいが, どこにも同じ一語を書いた場合を超えていない. {2}",
     "верно {0} из {1}, не больше, чем дало бы одно слово, написанное везде. {2}"},
    {"{0} of {1} entries right; answering \"{2}\" everywhere would get {3}, so the credit counts "
     "the entries beyond that. {4}",
     "{1} 個中 {0} 個が正しい. どこにも「{2}」と答えると {3} 個になるので, "
     "得点はそれを超えた分だけ数える. {4}",
     "верно {0} из {1}; ответ «{2}» везде дал бы {3}, поэтому засчитываются только элементы сверх "
     "этого. {4}"},
    {"cannot divide the vector by {0}, which is 0", "ベクトルを {0} で割れません. それは 0 です",
     "нельзя разделить вектор на {0}: это 0"},
    {"{0} entry is written twice with different words: neither word counts as right.",
     "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
     "{0} элемент записан дважды разными словами: ни одно из слов не засчитывается."},
    {"{0} entries are written twice with different words: neither word counts as right.",
     "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
     "Записано дважды разными словами элементов: {0}; ни одно из этих слов не засчитывается."},
    {"{0} entry names a face the problem does not have; it counts as a wrong entry.",
     "{0} 個の項目は問題にない面を指しています. 誤った項目として数えます.",
     "{0} элемент называет грань, которой нет в задаче; он считается неверным."},
    {"{0} entries name faces the problem does not have; each counts as a wrong entry.",
     "{0} 個の項目は問題にない面を指しています. それぞれ誤った項目として数えます.",
     "Элементов с гранями, которых нет в задаче: {0}; каждый считается неверным."},
    {"{0} entry names an edge the problem does not have; it counts as a wrong entry.",
     "{0} 個の項目は問題にない稜線を指しています. 誤った項目として数えます.",
     "{0} элемент называет ребро, которого нет в задаче; он считается неверным."},
    {"{0} entries name edges the problem does not have; each counts as a wrong entry.",
     "{0} 個の項目は問題にない稜線を指しています. それぞれ誤った項目として数えます.",
     "Элементов с рёбрами, которых нет в задаче: {0}; каждый считается неверным."},
    {"the view vector from {0}: any vertex of the face gives the same D_f",
     "{0} からの視線ベクトル: 面のどの頂点から取っても D_f は同じです",
     "вектор взгляда от {0}: любая вершина грани даёт то же D_f"},
    {"an entry written twice with the same word counts once",
     "同じ語で二度書いた項目は一度と数える",
     "элемент, записанный дважды одним словом, считается один раз"},
    {"wrong, but it follows correctly from your own earlier {0} (error carried forward: {1} of the "
     "points)",
     "誤りですが, あなた自身の前の解答から正しく導かれています (`{0}`; 誤りの持ち越し: 配点の {1})",
     "неверно, но правильно следует из вашего предыдущего ответа `{0}` (перенос ошибки: {1} "
     "баллов)"},
    {"It follows from your own {0}, which is copied from the given: nothing is carried forward "
     "from it.",
     "あなた自身の `{0}` から導かれていますが, それは与えられた値の写しなので, "
     "誤りの持ち越しはありません.",
     "Это следует из вашего `{0}`, но он скопирован из данных задачи: баллы с него не "
     "переносятся."},
    {"It follows from your own {0}, which is the {1} and takes no work: nothing is carried forward "
     "from it.",
     "あなた自身の `{0}` から導かれていますが, それは{1}で計算を要しないので, "
     "誤りの持ち越しはありません.",
     "Это следует из вашего `{0}`, но это {1} — ответ без вычислений: баллы с него не "
     "переносятся."},
    {"It follows from your own {0}, which is computed from an answer that takes no work: nothing "
     "is carried forward from it.",
     "あなた自身の `{0}` から導かれていますが, それは計算を要しない解答から求めたものなので, "
     "誤りの持ち越しはありません.",
     "Это следует из вашего `{0}`, но он получен из ответа, не требующего вычислений: баллы с него "
     "не переносятся."},
    {"cannot read {0} as a pair such as 0-1: write the items separated by commas, spaces or arrows",
     "`{0}` を 0-1 のような組として読めません. 項目はコンマ, "
     "空白または矢印で区切って書いてください",
     "не удаётся прочитать `{0}` как пару вида 0-1: разделяйте элементы запятыми, пробелами или "
     "стрелками"},
    {"cannot read {0} as an item of this list: write the items separated by commas, spaces or "
     "arrows",
     "`{0}` をこのリストの項目として読めません. 項目はコンマ, "
     "空白または矢印で区切って書いてください",
     "не удаётся прочитать `{0}` как элемент этого списка: разделяйте элементы запятыми, пробелами "
     "или стрелками"},
    {"right for your own {0}, which is also right (the key used another, equally right, choice)",
     "あなた自身の `{0}` に対して正しく, それも正しい (正解例は別の, 同じく正しい選び方をしている)",
     "верно для вашего `{0}`, который тоже верен (в ключе выбран другой, столь же верный вариант)"},
    {"right for your own {0}, which are also right (the key used another, equally right, choice)",
     "あなた自身の `{0}` に対して正しく, それらも正しい (正解例は別の, "
     "同じく正しい選び方をしている)",
     "верно для ваших `{0}`, которые тоже верны (в ключе выбран другой, столь же верный вариант)"},
    {"This is what a {0} or {1} gives; your other answers do not show which.",
     "これは「{0}」または「{1}」で生じる値です. 他の解答からはどちらかは分かりません.",
     "Так получается при ошибке «{0}» или «{1}»; по остальным ответам не видно, при какой."},
    {"This is what a {0} gives; your other answers do not show which.",
     "これは「{0}」で生じる値です. 他の解答からはどれかは分かりません.",
     "Так получается при одной из ошибок: {0}; по остальным ответам не видно, при какой."},
    {"({0})", "({0})", "({0})"},
    {"answers of this kind cannot be graded yet", "この種類の解答はまだ採点できません",
     "ответы этого вида пока не оцениваются"},
    // Reading an answer.
    {"cannot read '{0}': {1}", "`{0}` を読めません: {1}", "не удаётся прочитать `{0}`: {1}"},
    {"cannot read the plane '{0}': {1}", "平面 `{0}` を読めません: {1}",
     "не удаётся прочитать плоскость `{0}`: {1}"},
    {"unknown name '{0}'", "未知の名前 `{0}`", "неизвестное имя `{0}`"},
    {"'{0}' is not a finite number", "`{0}` は有限の数ではありません", "`{0}` — не конечное число"},
    {"'{0}' is not a real number", "`{0}` は実数ではありません", "`{0}` — не действительное число"},
    {"'{0}' cannot be evaluated as a number", "`{0}` は数として評価できません",
     "`{0}` нельзя вычислить как число"},
    {"'{0}' is not one of {1}", "`{0}` は次のいずれでもありません: `{1}`",
     "`{0}` — не одно из: `{1}`"},
    {"'{0}' is not true or false (or {1} or {2})",
     "`{0}` は true でも false でも ({1} でも {2} でも) ありません",
     "`{0}` — не true и не false (и не {1}, не {2})"},
    {"'{0}' is not true or false", "`{0}` は true でも false でもありません",
     "`{0}` — не true и не false"},
    {"'{0}' is not a bit string of 0 and 1", "`{0}` は 0 と 1 のビット列ではありません",
     "`{0}` — не строка битов из 0 и 1"},
    {"item {0} is not a number", "要素 {0} は数ではありません", "элемент {0} — не число"},
    {"item {0} is not a word", "要素 {0} は語ではありません", "элемент {0} — не слово"},
    {"expected a list of numbers", "数のリストが必要です", "ожидался список чисел"},
    {"expected a list of vertexs, like {0} or {1}", "頂点のリストが必要です (例: {0} または {1})",
     "ожидался список вершин, например {0} или {1}"},
    {"expected a list of rows, like {0} or {1}", "行のリストが必要です (例: {0} または {1})",
     "ожидался список строк, например {0} или {1}"},
    {"vertex {0}: wrong number of coordinates", "頂点 {0}: 座標の個数が違います",
     "вершина {0}: неверное число координат"},
    {"vertex {0}: {1}", "頂点 {0}: {1}", "вершина {0}: {1}"},
    {"row {0}: {1}", "行 {0}: {1}", "строка {0}: {1}"},
    {"expected a list", "リストが必要です", "ожидался список"},
    {"expected a mapping like {0}", "{0} のような対応付けが必要です",
     "ожидалось сопоставление вида {0}"},
    {"expected one number", "数が一つ必要です", "ожидалось одно число"},
    {"expected one word", "語が一つ必要です", "ожидалось одно слово"},
    {"expected true or false", "true か false が必要です", "ожидалось true или false"},
    {"expected a bit string like 0101", "0101 のようなビット列が必要です",
     "ожидалась строка битов, например 0101"},
    {"empty answer", "空の解答", "пустой ответ"},
    {"the rows have different lengths", "行の長さがそろっていません", "строки разной длины"},
    {"the plane is not linear in {0}", "平面が {0} について線形ではありません",
     "плоскость не линейна по {0}"},
    {"the plane's coefficients must be numbers", "平面の係数は数でなければなりません",
     "коэффициенты плоскости должны быть числами"},
    {"a plane is an equation like 'x + y - z = -6' or a list [a, b, c, d]",
     "平面は 'x + y - z = -6' のような方程式か, リスト [a, b, c, d] で書きます",
     "плоскость — уравнение вида 'x + y - z = -6' или список [a, b, c, d]"},
    // Misconceptions: their names and what they tell the student.
    {"reversed cross product", "外積の順序が逆", "обратный порядок векторного произведения"},
    {"unnormalised normal", "法線を正規化していない", "ненормированная нормаль"},
    {"not normalised", "正規化していない", "не нормирован"},
    {"plane through the origin", "原点を通る平面", "плоскость через начало координат"},
    {"constant on the wrong side", "定数項の符号が逆", "свободный член не с той стороны"},
    {"missing perspective divide", "透視除算 (w による除算) の忘れ",
     "пропущено перспективное деление"},
    {"degrees taken as radians", "度をラジアンとして計算", "градусы взяты как радианы"},
    {"fovx for fovy", "fovy の代わりに fovx", "fovx вместо fovy"},
    {"near/far sign", "near/far の符号", "знак near/far"},
    {"z_min, z_max read as coordinates", "z_min, z_max を座標として読んだ",
     "z_min, z_max прочитаны как координаты"},
    {"near, far read as distances", "near, far を距離として読んだ",
     "near, far прочитаны как расстояния"},
    {"Your z row is +2/(f − n), −(f + n)/(f − n): it maps z = n to −1 and z = f to +1, reading "
     "near and far as z coordinates. Here they are distances in front of an eye looking down −z "
     "(glOrtho), so the z row is −2/(f − n), −(f + n)/(f − n).",
     "あなたの z の行は +2/(f − n), −(f + n)/(f − n) で, z = n を −1 に, z = f を +1 "
     "に写します. これは near と far を z 座標として読んだ形です. ここでは両者は −z "
     "方向を向く視点の前方への距離 (glOrtho) なので, z の行は −2/(f − n), −(f + n)/(f − n) です.",
     "Ваша строка z — +2/(f − n), −(f + n)/(f − n): она переводит z = n в −1 и z = f в +1, то есть "
     "читает near и far как координаты z. Здесь это расстояния перед глазом, смотрящим вдоль −z "
     "(glOrtho), поэтому строка z — −2/(f − n), −(f + n)/(f − n)."},
    {"Your z row is glOrtho's −2/(f − n), −(f + n)/(f − n), which reads near and far as "
     "distances in front of an eye looking down −z. Here z_min = n and z_max = f are z "
     "coordinates mapped to −1 and +1, so the z row is +2/(f − n), −(f + n)/(f − n).",
     "あなたの z の行は glOrtho の −2/(f − n), −(f + n)/(f − n) で, near と far を −z "
     "方向を向く視点の前方への距離として読んでいます. ここでは z_min = n, z_max = f は −1 と +1 "
     "に写る z 座標なので, z の行は +2/(f − n), −(f + n)/(f − n) です.",
     "Ваша строка z — это −2/(f − n), −(f + n)/(f − n) из glOrtho: она читает near и far как "
     "расстояния перед глазом, смотрящим вдоль −z. Здесь z_min = n и z_max = f — координаты z, "
     "переходящие в −1 и +1, поэтому строка z — +2/(f − n), −(f + n)/(f − n)."},
    {"fovy for fovx", "fovx の代わりに fovy", "fovy вместо fovx"},
    {"aspect ratio on the top", "アスペクト比を上端に掛けた",
     "соотношение сторон умножено на верх"},
    {"You used −l = r = n·tan(θ/2) and −b = t = n·(w/h)·tan(θ/2): the aspect ratio multiplies the "
     "top. With r = n·tan(θ/2) the angle is horizontal and t = r·h/w; with θ vertical, "
     "t = n·tan(θ/2) and r = t·w/h.",
     "−l = r = n·tan(θ/2), −b = t = n·(w/h)·tan(θ/2) を使っています: アスペクト比が上端に"
     "掛かっています. r = n·tan(θ/2) なら画角は水平方向で t = r·h/w, θ が垂直方向なら "
     "t = n·tan(θ/2), r = t·w/h です.",
     "Вы взяли −l = r = n·tan(θ/2) и −b = t = n·(w/h)·tan(θ/2): соотношение сторон умножает верх. "
     "При r = n·tan(θ/2) угол горизонтальный и t = r·h/w; при вертикальном θ t = n·tan(θ/2) и "
     "r = t·w/h."},
    {"You used the angle as the vertical field of view; here it is the horizontal one (fovx).",
     "画角を縦方向として使っています. ここでは横方向の画角 (fovx) です.",
     "Вы взяли угол как вертикальный угол обзора; здесь он горизонтальный (fovx)."},
    {"composition in the wrong order", "変換の合成順序が逆", "композиция в неверном порядке"},
    {"view vector reversed", "視線ベクトルの向きが逆", "вектор взгляда развёрнут"},
    {"triangle instead of parallelogram", "平行四辺形ではなく三角形",
     "треугольник вместо параллелограмма"},
    {"radians instead of degrees", "度ではなくラジアン", "радианы вместо градусов"},
    {"degrees instead of radians", "ラジアンの代わりに度", "градусы вместо радиан"},
    {"cos for sin", "sin の代わりに cos", "cos вместо sin"},
    {"reversed look-at basis", "カメラ基底の向きの反転", "развёрнутый базис камеры"},
    {"You took {0}.", "{0} を計算しています.", "Вы взяли {0}."},
    {"The projection coordinates are left-handed, so the front normal here is {0}.",
     "投影座標系は左手系なので, ここでの表向きの法線は {0} です.",
     "Координаты проекции — левая система, поэтому лицевая нормаль здесь {0}."},
    {"That is n itself: a unit normal is n divided by its length ‖n‖.",
     "それは n そのものです. 単位法線は n をその長さ ‖n‖ で割ったものです.",
     "Это сама n: единичная нормаль — это n, делённая на свою длину ‖n‖."},
    {"Your plane passes through the origin: n·(p − A) = 0 gives d = n·A, not 0.",
     "あなたの平面は原点を通っています. n·(p − A) = 0 から d = n·A であり, 0 ではありません.",
     "Ваша плоскость проходит через начало координат: из n·(p − A) = 0 следует d = n·A, а не 0."},
    {"Your constant d has the wrong sign.", "定数 d の符号が逆です.",
     "У свободного члена d не тот знак."},
    {"Here the plane is written a·x + b·y + c·z = d with d = n·{0}; a list [a, b, c, d] means the "
     "same "
     "form, not a·x + b·y + c·z + d = 0.",
     "ここでは平面を a·x + b·y + c·z = d (d = n·{0}) と書きます. リスト [a, b, c, d] "
     "も同じ形を表し, "
     "a·x + b·y + c·z + d = 0 ではありません.",
     "Здесь плоскость записывается как a·x + b·y + c·z = d, где d = n·{0}; список [a, b, c, d] "
     "означает "
     "ту же форму, а не a·x + b·y + c·z + d = 0."},
    {"Your plane's constant has the wrong sign: the plane through {0} is n·p = n·{1} (from "
     "n·(p − {2}) = 0), and yours is n·p = −n·{3}.",
     "平面の定数項の符号が逆です. {0} を通る平面は n·p = n·{1} (n·(p − {2}) = 0 から) ですが, "
     "あなたの平面は n·p = −n·{3} です.",
     "У свободного члена плоскости не тот знак: плоскость через {0} — это n·p = n·{1} (из "
     "n·(p − {2}) = 0), а у вас n·p = −n·{3}."},
    {"You skipped the divide by w: NDC = (x_c, y_c, z_c) / w_c.",
     "w による除算が抜けています. NDC = (x_c, y_c, z_c) / w_c です.",
     "Вы пропустили деление на w: NDC = (x_c, y_c, z_c) / w_c."},
    {"Your numbers come from using the angle in degrees as if it were radians.",
     "度で与えられた角度をラジアンとして使った値になっています.",
     "Ваши числа получены, если угол в градусах взять как радианы."},
    {"Your rotation uses the angle's number of degrees as radians (cos {0} instead of cos {1}).",
     "回転で角度の度数をラジアンとして使っています (cos {1} ではなく cos {0}).",
     "В повороте число градусов взято как радианы (cos {0} вместо cos {1})."},
    {"You used the angle as the horizontal field of view; perspective() takes the vertical one "
     "(fovy).",
     "角度を水平方向の画角として使っています. perspective() が受け取るのは垂直方向の画角 (fovy) "
     "です.",
     "Вы взяли угол как горизонтальный угол обзора; perspective() принимает вертикальный (fovy)."},
    {"near and far are distances in front of the eye (positive); you used the planes' z "
     "coordinates −n and −f.",
     "near と far は視点の前方への距離 (正の値) です. あなたは平面の z 座標 −n と −f "
     "を使っています.",
     "near и far — расстояния перед глазом (положительные); вы взяли z-координаты плоскостей −n и "
     "−f."},
    {"You multiplied the steps in the order they are applied (A₁·A₂·…): with column vectors the "
     "step applied first "
     "stands rightmost, M = …·A₂·A₁ (as in P′ = A₃A₂A₁P).",
     "適用する順に行列を掛けています (A₁·A₂·…). 列ベクトルでは最初に適用する変換が一番右に来ます: "
     "M = …·A₂·A₁ (P′ = A₃A₂A₁P のように).",
     "Вы перемножили шаги в порядке применения (A₁·A₂·…): для столбцов-векторов первый шаг стоит "
     "справа, "
     "M = …·A₂·A₁ (как в P′ = A₃A₂A₁P)."},
    {"You multiplied the steps in reverse order (…·A₂·A₁): with DirectX's row vectors, P′ = P·M, "
     "the step applied first stands leftmost, M = A₁·A₂·…",
     "逆の順に行列を掛けています (…·A₂·A₁). DirectX の行ベクトルでは P′ = P·M なので, "
     "最初に適用する変換が一番左に来ます: M = A₁·A₂·…",
     "Вы перемножили шаги в обратном порядке (…·A₂·A₁): для строк-векторов DirectX, P′ = P·M, "
     "первый шаг стоит слева, M = A₁·A₂·…"},
    {"You took e₁ × e₀: with the vertices counter-clockwise seen from the front, the front normal "
     "is n = e₀ × e₁.",
     "e₁ × e₀ を計算しています. 表から見て頂点が反時計回りなので, 表向きの法線は n = e₀ × e₁ です.",
     "Вы взяли e₁ × e₀: вершины обходятся против часовой стрелки, если смотреть с лицевой стороны, "
     "поэтому лицевая "
     "нормаль n = e₀ × e₁."},
    {"Your view vector points from the eye to the polygon: v = p_eye − pᵢ points from the polygon "
     "to the eye, and that "
     "flips the sign of D_f.",
     "あなたの視線ベクトルは視点から多角形へ向いています. v = p_eye − pᵢ "
     "は多角形から視点へ向くベクトルで, 向きが逆だと D_f の符号が反転します.",
     "Ваш вектор взгляда направлен от глаза к многоугольнику: v = p_eye − pᵢ направлен от "
     "многоугольника к глазу, и "
     "это меняет знак D_f."},
    {"You computed b × a = −(a × b): the cross product is anti-commutative.",
     "b × a = −(a × b) を計算しています. 外積は反可換です.",
     "Вы вычислили b × a = −(a × b): векторное произведение антикоммутативно."},
    {"That is half the area: ‖a × b‖ is the parallelogram's area, the triangle's is half of it.",
     "それは面積の半分です. ‖a × b‖ は平行四辺形の面積で, 三角形の面積はその半分です.",
     "Это половина площади: ‖a × b‖ — площадь параллелограмма, а треугольника — её половина."},
    {"Your angle is in radians; the problem asks for degrees.",
     "角度がラジアンになっています. 問題は度で求めています.",
     "Ваш угол в радианах; в задаче нужны градусы."},
    {"Your angle is in degrees; the problem asks for radians.",
     "角度が度になっています. 問題はラジアンで求めています.",
     "Ваш угол в градусах; в задаче нужны радианы."},
    {"That is cos θ = a·b/(‖a‖‖b‖); sin θ uses ‖a × b‖.",
     "それは cos θ = a·b/(‖a‖‖b‖) です. sin θ には ‖a × b‖ を使います.",
     "Это cos θ = a·b/(‖a‖‖b‖); для sin θ нужно ‖a × b‖."},
    {"Your camera's z axis points at the scene: the camera looks down −z, so z = (eye − "
     "center)/‖eye − center‖ and "
     "x = up × z.",
     "あなたのカメラの z 軸はシーンの方を向いています. カメラは −z 方向を見るので, z = (eye − "
     "center)/‖eye − center‖, x = up × z です.",
     "Ось z вашей камеры направлена на сцену: камера смотрит вдоль −z, поэтому z = (eye − "
     "center)/‖eye − center‖ и "
     "x = up × z."},
    {"Your camera's z axis points away from the scene: DirectX's camera looks down +z, so z = "
     "(center − eye)/‖center − "
     "eye‖ and x = up × z.",
     "あなたのカメラの z 軸はシーンと反対を向いています. DirectX のカメラは +z 方向を見るので, z = "
     "(center − eye)/‖center − eye‖, x = up × z です.",
     "Ось z вашей камеры направлена от сцены: камера DirectX смотрит вдоль +z, поэтому z = (center "
     "− eye)/‖center − "
     "eye‖ и x = up × z."},
    // Trivial answers.
    {"identity matrix", "単位行列", "единичная матрица"},
    {"zero vector", "零ベクトル", "нулевой вектор"},
    {"zero matrix", "零行列", "нулевая матрица"},
    {"copied from the given", "問題の値の写し", "скопировано из условия"},
    {"transposed matrix (row- vs column-vector convention)",
     "転置行列 (行ベクトルと列ベクトルの規約の取り違え)",
     "транспонированная матрица (путаница строк- и столбцов-векторов)"},
    {"transposed matrix", "転置行列", "транспонированная матрица"},
    {"That is the identity matrix: it leaves every point where it is.",
     "それは単位行列です. どの点も動かしません.",
     "Это единичная матрица: она оставляет каждую точку на месте."},
    {"Every entry is 0: that takes no computation.", "すべて 0 です. 計算を必要としません.",
     "Все элементы равны 0: это не требует вычислений."},
    {"The zero vector has no direction: it is no normal.",
     "零ベクトルには向きがなく, 法線になりません.",
     "У нулевого вектора нет направления: это не нормаль."},
    {"That is the transpose of the expected matrix: rows and columns swapped.",
     "それは正解の行列の転置です. 行と列が入れ替わっています.",
     "Это транспонированная верная матрица: строки и столбцы переставлены."},
    {"That is the transpose: the column-vector form p′ = M·p (as OpenGL writes it).",
     "それは転置です. 列ベクトルの形 p′ = M·p (OpenGL の書き方) になっています.",
     "Это транспонированная матрица: форма для столбцов p′ = M·p (как пишет OpenGL)."},
    {"With DirectX's row vectors p′ = p·M the translation stands in the bottom row.",
     "DirectX の行ベクトル p′ = p·M では平行移動は最下行に来ます.",
     "Для строк-векторов DirectX p′ = p·M перенос стоит в нижней строке."},
    {"That is the transpose: the row-vector form p′ = p·M (as DirectX writes it).",
     "それは転置です. 行ベクトルの形 p′ = p·M (DirectX の書き方) になっています.",
     "Это транспонированная матрица: форма для строк p′ = p·M (как пишет DirectX)."},
    {"With column vectors p′ = M·p the translation stands in the last column.",
     "列ベクトル p′ = M·p では平行移動は最後の列に来ます.",
     "Для столбцов-векторов p′ = M·p перенос стоит в последнем столбце."},
    {"That is `{0}` from the problem, copied unchanged: the answer is what the computation makes "
     "of it.",
     "それは問題の `{0}` をそのまま写したものです. 解答はそれを計算した結果です.",
     "Это `{0}` из условия без изменений: ответ — то, что из него получается при вычислении."},
    {"That is the given, copied unchanged: the answer is what the computation makes of it.",
     "それは問題の値をそのまま写したものです. 解答はそれを計算した結果です.",
     "Это данные из условия без изменений: ответ — то, что из них получается при вычислении."},
    // statements: reading and judging which statements a student marks true.
    {"Statement {0} is true, not false (see step {1}).",
     "記述 {0} は正しい (○). 誤り (×) ではない (ステップ {1} 参照).",
     "Утверждение {0} верно, а не неверно (см. шаг {1})."},
    {"Statement {0} is false, not true (see step {1}).",
     "記述 {0} は誤り (×). 正しい (○) ではない (ステップ {1} 参照).",
     "Утверждение {0} неверно, а не верно (см. шаг {1})."},
    {"You chose {0} of the {1} true statements and {2} of the {3} false ones.",
     "{1} 個の正しい記述のうち {0} 個と, {3} 個の誤った記述のうち {2} 個を選んだ.",
     "Выбрано верных утверждений: {0} из {1}, неверных: {2} из {3}."},
    {"Each true statement chosen earns 1/{0} of the points; each false one chosen takes 1/{1} "
     "away.",
     "正しい記述を 1 つ選ぶごとに配点の 1/{0} を得て, 誤った記述を 1 つ選ぶごとに 1/{1} を失う.",
     "Каждое выбранное верное утверждение даёт 1/{0} баллов, каждое выбранное неверное отнимает "
     "1/{1}."},
    {"there is no statement {0}: the statements are numbered 1 to {1}",
     "記述 {0} はない. 記述の番号は 1 から {1} まで",
     "утверждения {0} нет: утверждения пронумерованы от 1 до {1}"},
    {"there is no statement 0: the statements are numbered from 1",
     "記述 0 はない. 記述の番号は 1 から始まる", "утверждения 0 нет: утверждения нумеруются с 1"},
    {"statement {0} is given twice", "記述 {0} が 2 回書かれている",
     "утверждение {0} указано дважды"},
    {"{0} statements, but {1} true/false values: give one per statement, or the numbers of the "
     "true ones",
     "記述は {0} 個だが, 真偽の値は {1} 個. 記述ごとに 1 つ書くか, 正しい記述の番号を書くこと",
     "утверждений {0}, а значений верно/неверно {1}: укажите по одному на утверждение или номера "
     "верных"},
    {"'{0}' is neither the number of a statement nor true or false",
     "`{0}` は記述の番号でも真偽の値でもない", "`{0}` — не номер утверждения и не верно/неверно"},
    {"the answer mixes statement numbers and true/false: write the numbers of the true statements, "
     "like [1, 3], or one true/false per statement, like [true, false, true]",
     "記述の番号と真偽の値が混ざっている. 正しい記述の番号 (例: [1, 3]) か, 記述ごとの真偽 (例: "
     "[○, ×, ○]) "
     "のどちらかで書くこと",
     "в ответе смешаны номера утверждений и верно/неверно: укажите номера верных утверждений, "
     "например "
     "[1, 3], или по одному верно/неверно на утверждение, например [да, нет, да]"},
    {"item {0} is not a statement number or true/false",
     "{0} 番目の項目は記述の番号でも真偽の値でもない",
     "элемент {0} — не номер утверждения и не верно/неверно"},
    {"item {0} is empty", "{0} 番目の項目が空", "элемент {0} пуст"},
    {"a mapping's keys are statement numbers 1, 2, …, like {1: true, 2: false}",
     "対応表のキーは記述の番号 1, 2, … (例: {1: ○, 2: ×})",
     "ключи соответствия — номера утверждений 1, 2, …, например {1: да, 2: нет}"},
    {"statement {0}: expected true or false", "記述 {0}: 真偽 (○ か ×) を書くこと",
     "утверждение {0}: ожидается верно или неверно"},
    {"expected the numbers of the true statements", "正しい記述の番号を書くこと",
     "ожидаются номера верных утверждений"},
    {"empty answer: write the numbers of the true statements, or none",
     "解答が空. 正しい記述の番号を書くか, なければ「なし」と書くこと",
     "пустой ответ: укажите номера верных утверждений или «ни одного»"},
    // Handedness as a course convention (issue 16).
    {"right-handed matrix", "右手系の行列", "матрица правой системы"},
    {"You used the right-handed matrix (the eye looking down −z); in this course's left-handed "
     "coordinates the eye looks down +z, so the third column has the opposite sign (w′ = z).",
     "右手系の行列 (視点は −z 方向を見る) を使っています. このコースの左手系の座標では視点は +z "
     "方向を"
     "見るので, 第 3 列の符号が逆になります (w′ = z).",
     "Вы использовали матрицу правой системы (глаз смотрит вдоль −z); в левой системе координат "
     "этого "
     "курса глаз смотрит вдоль +z, поэтому третий столбец имеет обратный знак (w′ = z)."},
    {"You took e₀ × e₁, the right-handed formula: in these left-handed coordinates, with the "
     "vertices "
     "counter-clockwise seen from the front, the front normal is n = e₁ × e₀.",
     "右手系の式 e₀ × e₁ を計算しています. この左手系の座標では, 表から見て頂点が反時計回りなので, "
     "表向きの法線は n = e₁ × e₀ です.",
     "Вы взяли e₀ × e₁, формулу правой системы: в этих левых координатах, когда вершины обходятся "
     "против часовой стрелки при взгляде с лицевой стороны, лицевая нормаль n = e₁ × e₀."},
    {"Your camera's z axis points away from the scene: in left-handed coordinates the camera looks "
     "down +z, so z = (center − eye)/‖center − eye‖ and x = up × z.",
     "あなたのカメラの z 軸はシーンと反対を向いています. 左手系の座標ではカメラは +z "
     "方向を見るので, "
     "z = (center − eye)/‖center − eye‖, x = up × z です.",
     "Ось z вашей камеры направлена от сцены: в левой системе координат камера смотрит вдоль +z, "
     "поэтому z = (center − eye)/‖center − eye‖ и x = up × z."},
    // PrairieLearn questions (issue 47): inputs, their hints, and the grader's messages.
    {"see the feedback below", "下のフィードバックを参照", "см. отзыв ниже"},
    {"Some answers could not be read; fix them and submit again (this attempt is not counted).",
     "読み取れない解答があります. 直して再提出してください (この提出は回数に数えません).",
     "Некоторые ответы не удалось прочитать; исправьте их и отправьте снова (эта попытка не "
     "засчитывается)."},
    {"None of the statements above is true", "上の記述はどれも正しくない",
     "Ни одно из утверждений выше не верно"},
    {"a number such as 15/2, sqrt(3)/2 or 0.25", "15/2, sqrt(3)/2, 0.25 のような数",
     "число, например 15/2, sqrt(3)/2 или 0.25"},
    {"a vector such as [1, -2, sqrt(3)/2]", "[1, -2, sqrt(3)/2] のようなベクトル",
     "вектор, например [1, -2, sqrt(3)/2]"},
    {"a matrix row by row, such as [[1, 0], [0, 1]]", "[[1, 0], [0, 1]] のように行ごとに書いた行列",
     "матрица по строкам, например [[1, 0], [0, 1]]"},
    {"rows such as [[1, 0, 2], [0, 1, 3]]: a matrix row by row, or one point per row",
     "[[1, 0, 2], [0, 1, 3]] のような行の並び: 行ごとの行列, または 1 行に 1 点",
     "строки, например [[1, 0, 2], [0, 1, 3]]: матрица по строкам или по точке в строке"},
    {"a list in order, such as [2, 0, 1]", "[2, 0, 1] のように順に並べたリスト",
     "список по порядку, например [2, 0, 1]"},
    {"points in order, such as [[0, 0], [4, 0], [0, 3]], or none",
     "[[0, 0], [4, 0], [0, 3]] のように順に並べた点, または none",
     "точки по порядку, например [[0, 0], [4, 0], [0, 3]], или none"},
    {"an equation such as x + y - z = -6", "x + y - z = -6 のような方程式",
     "уравнение, например x + y - z = -6"},
    {"a bit string such as 0101", "0101 のようなビット列", "битовая строка, например 0101"},
    {"a mapping such as {0-1: visible, 1-2: hidden}", "{0-1: visible, 1-2: hidden} のような対応",
     "соответствие, например {0-1: visible, 1-2: hidden}"},
    {"a list such as [1-3, 2-7]", "[1-3, 2-7] のようなリスト", "список, например [1-3, 2-7]"},
    {"Exact forms such as 15/2 or sqrt(3)/2 are accepted; a decimal is right within {0} of the "
     "exact value.",
     "15/2 や sqrt(3)/2 のような厳密な形で答えてよい. 小数は厳密な値との差が {0} 以内なら正解.",
     "Можно писать точные значения, например 15/2 или sqrt(3)/2; десятичная дробь верна, если "
     "отличается от точного значения не более чем на {0}."},
    {"Exact forms such as 15/2 or sqrt(3)/2 are accepted; decimals are right within {0} of the "
     "exact values, in order.",
     "15/2 や sqrt(3)/2 のような厳密な形で答えてよい. 小数は厳密な値との差が順に {0} "
     "以内なら正解.",
     "Можно писать точные значения, например 15/2 или sqrt(3)/2; десятичные дроби верны, если "
     "отличаются от точных значений не более чем на {0} (по порядку)."},
    // Canvas and Moodle quiz questions: what a field asks, and the credit rules they state.
    {"the true statements", "正しい記述", "верные утверждения"},
    {"scaled to length 1", "長さ 1 に正規化して", "нормированный к длине 1"},
    {"scaled so that w = {0}", "w = {0} となるように定数倍して",
     "умноженный на число так, чтобы w = {0}"},
    // Slots {0}, {1}, {2} hold the same number T (a slot is filled once per use).
    {"Canvas scores this question by its own rule: each right choice ticked earns 1/{0} of the "
     "points and each wrong one ticked loses 1/{1} ({2} right choices), never below 0.",
     "この問題は Canvas の規則で採点される: 正しい選択肢 1 つごとに配点の 1/{0} を得て, "
     "誤った選択肢 1 つごとに 1/{1} を失う (正しい選択肢は {2} 個, 0 点未満にはならない).",
     "Этот вопрос Canvas оценивает по своему правилу: каждый отмеченный верный вариант даёт 1/{0} "
     "баллов, каждый отмеченный неверный отнимает 1/{1} (верных вариантов: {2}), но не меньше 0."},
    {"Each number is scored on its own here.", "ここでは数ごとに採点される.",
     "Здесь каждое число оценивается отдельно."},
    {"Not asked here:", "ここでは問わない:", "Здесь не спрашивается:"},
    {"1e30 stands for +∞, the depth of a pixel no polygon covers",
     "1e30 は +∞ (どの多角形にも覆われない画素の奥行き) を表す",
     "1e30 обозначает +∞ — глубину пикселя, не покрытого ни одним многоугольником"},
    {"Figure", "図", "Рисунок"},
    {"+∞, the depth of a pixel no polygon covers, is written inf (or 1e30)",
     "+∞ (どの多角形にも覆われない画素の奥行き) は inf (または 1e30) と書く",
     "+∞ — глубину пикселя, не покрытого ни одним многоугольником, — пишут inf (или 1e30)"},
    {"it has no value here", "ここでは値がない", "здесь у него нет значения"},
    {"a zero vector has no direction", "零ベクトルには向きがない",
     "у нулевого вектора нет направления"},
    {"a plane's equation is right up to any non-zero factor",
     "平面の方程式は 0 でない定数倍しても正しい",
     "уравнение плоскости верно с точностью до ненулевого множителя"},
    {"a polygon is right from any starting vertex", "多角形はどの頂点から始めても正しい",
     "многоугольник верен при любой начальной вершине"},
    {"a segment is right in either direction", "線分はどちらの向きでも正しい",
     "отрезок верен в обоих направлениях"},
    {"a set of points is right in any order", "点の集合はどの順でも正しい",
     "множество точек верно в любом порядке"},
    {"a set of labels is right in any order", "ラベルの集合はどの順でも正しい",
     "множество меток верно в любом порядке"},
    {"an order of labels has no quiz field", "ラベルの順序を問う欄はない",
     "для порядка меток нет поля теста"},
    {"no quiz field fits it", "合う欄がない", "для него нет подходящего поля"},
    // The answer lines of a paper exam, labelled in the sheet's language (an answer with no
    // symbol of its own).
    {"answer line: accept", "採択", "принятие"},
    {"answer line: reject", "棄却", "отбрасывание"},
    {"answer line: backface_sufficient", "背面除去だけで十分か",
     "достаточно ли отсечения нелицевых граней"},
    {"answer line: centroids", "重心", "центроиды"},
    {"answer line: clip", "クリップ座標", "координаты отсечения"},
    {"answer line: clipped", "クリッピングの結果", "результат отсечения"},
    {"answer line: color", "色", "цвет"},
    {"answer line: convex", "凸か", "выпуклый ли"},
    {"answer line: depth", "奥行き", "глубина"},
    {"answer line: depths", "奥行き", "глубины"},
    {"answer line: faces", "面", "грани"},
    {"answer line: facing", "表裏", "ориентация"},
    {"answer line: frame", "フレーム", "кадр"},
    {"answer line: inside", "内側か", "внутри ли"},
    {"answer line: ndc", "正規化デバイス座標", "нормализованные координаты"},
    {"answer line: object", "物体", "объект"},
    {"answer line: order", "描画順", "порядок рисования"},
    {"answer line: outcode_p", "p の領域コード", "код области p"},
    {"answer line: outcode_q", "q の領域コード", "код области q"},
    {"answer line: perspective_matrix", "透視変換行列", "матрица перспективы"},
    {"answer line: pixels", "画素", "пиксели"},
    {"answer line: plane", "平面", "плоскость"},
    {"answer line: point", "点", "точка"},
    {"answer line: points", "点", "точки"},
    {"answer line: scale_matrix", "拡大縮小行列", "матрица масштабирования"},
    {"answer line: steps", "手順", "шаги"},
    {"answer line: total", "合計", "сумма"},
    {"answer line: true_statements", "正しい記述", "верные утверждения"},
    {"answer line: window", "ウィンドウ座標", "оконные координаты"},
    {"answer line: conflicts", "競合", "конфликты"},
    {"answer line: edges", "稜線", "рёбра"},
    {"answer line: hidden", "不可視の稜線", "невидимые рёбра"},
    {"answer line: silhouette", "輪郭線", "контурные рёбра"},
    // Problems in the students' languages (issue 16): quiz and paper questions of a variant.
    {"(Use the values given below.)", "(下に示す値を使うこと.)",
     "(Используйте значения, данные ниже.)"},
    // A problem without a text is asked by its kind's summary (quiz and paper questions).
    {"is a polygon front- or back-facing from the eye", "多角形は視点から見て表か裏か",
     "какой стороной, лицевой или нелицевой, многоугольник обращён к глазу"},
    {"Cohen–Sutherland outcodes and clipping of a segment (2D or 3D)",
     "Cohen–Sutherland のアルゴリズムによる線分の領域コードとクリッピング (2次元または3次元)",
     "коды областей Коэна — Сазерленда (Cohen–Sutherland) и отсечение отрезка (2D или 3D)"},
    {"Sutherland–Hodgman clipping of a polygon (2D window or 3D volume)",
     "Sutherland–Hodgman のアルゴリズムによる多角形のクリッピング "
     "(2次元のウィンドウまたは3次元の視体積)",
     "отсечение многоугольника алгоритмом Сазерленда — Ходжмана (Sutherland–Hodgman): окном 2D или "
     "объёмом 3D"},
    {"barycentric coordinates of a pixel in a projected triangle, and its interpolated z",
     "投影された三角形での画素の重心座標と, 補間した z 値",
     "барицентрические координаты пикселя в спроецированном треугольнике и интерполированное "
     "значение z"},
    {"z of a pixel inside a projected triangle by the plane method",
     "平面の方程式による, 投影された三角形の内部の画素の z 値",
     "значение z пикселя внутри спроецированного треугольника методом уравнения плоскости"},
    {"painter's algorithm: centroid order back to front, and its conflicts",
     "奥行きソート法: 奥から手前への重心の順序と, その矛盾",
     "алгоритм художника: порядок центров тяжести от дальних к ближним и его конфликты"},
    {"the view matrix of a camera at eye looking at center",
     "eye から center を見るカメラのビュー変換行列",
     "матрица вида камеры в точке eye, смотрящей на center"},
    {"the normal and unit normal of a polygon", "多角形の法線ベクトルと単位法線ベクトル",
     "нормаль и единичная нормаль многоугольника"},
    {"the plane through points, or through a point with a normal",
     "点を通る平面, または 1 点と法線ベクトルで決まる平面",
     "плоскость через точки или через точку с заданной нормалью"},
    {"a point's clip, NDC and window coordinates", "点のクリップ座標, NDC とウィンドウ座標",
     "координаты точки в пространстве отсечения, в NDC и в окне"},
    {"the matrix of perspective(), frustum() or ortho()",
     "perspective(), frustum() または ortho() の行列",
     "матрица perspective(), frustum() или ortho()"},
    {"where the projection plane lies and where a point lands on it",
     "投影面の位置と, その上に点が写る位置",
     "где лежит плоскость проекции и куда на неё попадает точка"},
    {"colour and depth of queried pixels of a rendered scene (z-buffer trace)",
     "レンダリングしたシーンの指定した画素の色と奥行き (Zバッファ法の追跡)",
     "цвет и глубина заданных пикселей визуализированной сцены (трассировка z-буфера)"},
    {"pixels covered by a triangle (top-left fill rule)", "三角形が覆う画素 (左上規則)",
     "пиксели, покрытые треугольником (правило верхнего левого края)"},
    {"which of the given statements are true", "与えられた記述のうちどれが正しいか",
     "какие из данных утверждений верны"},
    {"the composite of translations, scalings, rotations and shears",
     "平行移動, 拡大縮小, 回転, せん断の合成",
     "композиция переносов, масштабирований, поворотов и сдвигов"},
    {"the normalized perspective view volume of Foley et al.",
     "フォーリーらの正規化視体積 (透視投影)",
     "нормированный видимый объём перспективной проекции по Фоли и др."},
    {"NDC to window coordinates", "NDC からウィンドウ座標へ", "из NDC в оконные координаты"},
    {"dot and cross products of two vectors, the parallelogram's area, sin, cos and the angle",
     "2 つのベクトルの内積と外積, 平行四辺形の面積, sin, cos となす角",
     "скалярное и векторное произведения двух векторов, площадь параллелограмма, sin, cos и угол"},
    {"front/back faces and visible, silhouette and hidden edges of a polyhedron",
     "多面体の表/裏の面と, 見える稜線, 輪郭線, 隠れる稜線",
     "лицевые и нелицевые грани многогранника, его видимые, контурные и невидимые рёбра"},
    {"frame and depth buffers of the Z-buffer algorithm on a small grid",
     "小さな格子上の Zバッファ法のフレームバッファと奥行きバッファ",
     "буфер кадра и буфер глубины алгоритма z-буфера на малой сетке"},
};

}  // namespace

std::span<const Phrase> grading_phrases() { return kPhrases; }

}  // namespace frustum
