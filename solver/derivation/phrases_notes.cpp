// The notes under steps (conventions, how a value is read, warnings) in Japanese and Russian,
// sentence by sentence: a note is translated whole when the catalogue holds it, otherwise one
// sentence at a time (i18n.cpp).
#include "solver/derivation/phrases.hpp"

namespace frustum {

namespace {

constexpr Phrase kPhrases[] = {
    {"Each polygon's edges that the line crosses give the two ends of its section; along the "
     "section the depth changes linearly, as the polygon is planar.",
     "走査線が横切るポリゴンの辺から断面の両端が求まる. ポリゴンは平面なので, 断面に沿って奥行きは"
     "線形に変わる.",
     "Рёбра многоугольника, которые пересекает строка, дают два конца его сечения; вдоль сечения "
     "глубина меняется линейно, так как многоугольник плоский."},
    {"On each piece between two breakpoints one section is nearest all along (depths are linear "
     "and cross only at breakpoints): the smallest z is seen. The method keeps one line's "
     "sections at a time, not a depth for every pixel.",
     "2 つの区切り点の間の各区間では, 1 つの断面が全体にわたって最も手前にある (奥行きは線形で, "
     "区切り点でしか交わらない): z が最も小さい断面が見える. この方法は 1 本の走査線の断面だけを"
     "保持し, 画素ごとの奥行きは持たない.",
     "На каждом отрезке между двумя точками разбиения одно сечение ближе всех на всём отрезке "
     "(глубины линейны и пересекаются только в точках разбиения): видно сечение с наименьшим z. "
     "Метод хранит сечения одной строки, а не глубину каждого пикселя."},
    {"Each column of M lies in one piece: m0–m2 is the image of the x axis, m4–m6 that of the y "
     "axis, m8–m10 that of the z axis, and m12–m14 the translation (where the origin goes).",
     "M の各列が連続して並ぶ: m0–m2 は x 軸の像, m4–m6 は y 軸の像, m8–m10 は z 軸の像, "
     "m12–m14 は平行移動 (原点の移る先) である.",
     "Каждый столбец M лежит подряд: m0–m2 — образ оси X, m4–m6 — оси Y, m8–m10 — оси Z, "
     "m12–m14 — перенос (куда переходит начало координат)."},
    {"Each column of M lies in one piece: m0–m1 is the image of the x axis, m3–m4 that of the y "
     "axis, and m6–m7 the translation (where the origin goes).",
     "M の各列が連続して並ぶ: m0–m1 は x 軸の像, m3–m4 は y 軸の像, m6–m7 は平行移動 "
     "(原点の移る先) である.",
     "Каждый столбец M лежит подряд: m0–m1 — образ оси X, m3–m4 — оси Y, m6–m7 — перенос "
     "(куда переходит начало координат)."},
    {"With W = {0} the point {1} is written {2}.", "W = {0} とすると, 点 {1} は {2} と表される.",
     "При W = {0} точка {1} записывается как {2}."},
    // Conventions.
    {"OpenGL: right-handed eye space looking down −z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
     "with near → −1, "
     "window origin bottom-left; angles in {0}",
     "OpenGL: 視点座標系は右手系で −z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
     "1]³ (near → −1), "
     "ウィンドウの原点は左下; 角度の単位は{0}",
     "OpenGL: правая система координат вида, взгляд вдоль −z, столбцы-векторы (p′ = M·p), куб NDC "
     "[−1, 1]³ (near → −1), "
     "начало окна внизу слева; углы в {0}"},
    {"DirectX: left-handed eye space looking down +z, row vectors (p′ = p·M), NDC z in [0, 1], "
     "window origin top-left "
     "with y pointing down; angles in {0}",
     "DirectX: 視点座標系は左手系で +z 方向を見る, 行ベクトル (p′ = p·M), 正規化座標の z は [0, "
     "1], "
     "ウィンドウの原点は左上で y は下向き; 角度の単位は{0}",
     "DirectX: левая система координат вида, взгляд вдоль +z, строки-векторы (p′ = p·M), z в NDC "
     "из [0, 1], "
     "начало окна вверху слева, y направлена вниз; углы в {0}"},
    {"Processing: OpenGL's matrices and NDC cube [−1, 1]³, column vectors, window origin top-left "
     "with y pointing "
     "down; angles in {0}",
     "Processing: OpenGL の行列と正規化視体積 [−1, 1]³, 列ベクトル, ウィンドウの原点は左上で y "
     "は下向き; 角度の単位は{0}",
     "Processing: матрицы и куб NDC [−1, 1]³ как в OpenGL, столбцы-векторы, начало окна вверху "
     "слева, y направлена "
     "вниз; углы в {0}"},
    {"OpenGL: right-handed eye space looking down −z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
     "with near → −1, "
     "window origin bottom-left",
     "OpenGL: 視点座標系は右手系で −z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
     "1]³ (near → −1), "
     "ウィンドウの原点は左下",
     "OpenGL: правая система координат вида, взгляд вдоль −z, столбцы-векторы (p′ = M·p), куб NDC "
     "[−1, 1]³ (near → −1), "
     "начало окна внизу слева"},
    {"DirectX: left-handed eye space looking down +z, row vectors (p′ = p·M), NDC z in [0, 1], "
     "window origin top-left "
     "with y pointing down",
     "DirectX: 視点座標系は左手系で +z 方向を見る, 行ベクトル (p′ = p·M), 正規化座標の z は [0, "
     "1], "
     "ウィンドウの原点は左上で y は下向き",
     "DirectX: левая система координат вида, взгляд вдоль +z, строки-векторы (p′ = p·M), z в NDC "
     "из [0, 1], "
     "начало окна вверху слева, y направлена вниз"},
    {"Processing: OpenGL's matrices and NDC cube [−1, 1]³, column vectors, window origin top-left "
     "with y pointing "
     "down",
     "Processing: OpenGL の行列と正規化視体積 [−1, 1]³, 列ベクトル, ウィンドウの原点は左上で y "
     "は下向き",
     "Processing: матрицы и куб NDC [−1, 1]³ как в OpenGL, столбцы-векторы, начало окна вверху "
     "слева, y направлена "
     "вниз"},
    {"{0}; ortho's near and far are the z coordinates z_min, z_max; angles in {1}",
     "{0}; ortho の near, far は z 座標 z_min, z_max; 角度の単位は{1}",
     "{0}; near и far в ortho — z-координаты z_min, z_max; углы в {1}"},
    {"{0}; the field of view is horizontal (fovx); angles in {1}",
     "{0}; 画角は水平方向 (fovx); 角度の単位は{1}",
     "{0}; угол обзора горизонтальный (fovx); углы в {1}"},
    {"Here the field of view spans the width (fovx): it sets the right edge r, and the top is r "
     "divided by the aspect ratio. perspective() takes the vertical angle fovy; both give the same "
     "frustum and the same matrix.",
     "ここでは画角は横方向 (fovx) に広がる: 右端 r を決め, 上端は r をアスペクト比で割ったもの. "
     "perspective() は縦方向の画角 fovy を取る. どちらも同じ視体積, 同じ行列を与える.",
     "Здесь угол обзора охватывает ширину (fovx): он задаёт правый край r, а верх равен r, "
     "делённому на соотношение сторон. perspective() принимает вертикальный угол fovy; оба дают "
     "один и тот же объём и одну и ту же матрицу."},
    {"{0}; ortho's near and far are the z coordinates z_min, z_max",
     "{0}; ortho の near, far は z 座標 z_min, z_max",
     "{0}; near и far в ortho — z-координаты z_min, z_max"},
    // Course conventions (issue 16): each clause a pattern of its own, with and without the
    // angle unit after it, so that any combination of them reads in every language.
    {"{0}; the field of view is horizontal (fovx)", "{0}; 画角は水平方向 (fovx)",
     "{0}; угол обзора горизонтальный (fovx)"},
    {"Here near and far are the z coordinates z_min = n and z_max = f, mapped to −1 and +1: the z "
     "row is +2/(z_max − "
     "z_min).",
     "ここでは near と far は z 座標 z_min = n, z_max = f で, それぞれ −1 と +1 に写る: z の行は "
     "+2/(z_max − z_min).",
     "Здесь near и far — z-координаты z_min = n и z_max = f, переходящие в −1 и +1: строка z равна "
     "+2/(z_max − z_min)."},
    {"OpenGL's glOrtho reads them as distances in front of an eye looking down −z (the planes z = "
     "−n and z = −f), which "
     "gives −2/(f − n) there; the two matrices differ only in the direction of the z axis.",
     "OpenGL の glOrtho はこれらを −z 方向を見る視点の前方への距離 (平面 z = −n と z = −f) "
     "として読むので, そこは −2/(f − n) "
     "になる. 二つの行列の違いは z 軸の向きだけである.",
     "glOrtho в OpenGL читает их как расстояния перед глазом, смотрящим вдоль −z (плоскости z = −n "
     "и z = −f), и даёт "
     "там −2/(f − n); две матрицы различаются только направлением оси z."},
    {"Angles in {0}", "角度の単位は{0}", "Углы в {0}"},
    {"Column vectors, p′ = M·p.", "列ベクトル: p′ = M·p.", "Столбцы-векторы: p′ = M·p."},
    {"Column vectors, p′ = M·p. z = −n maps to z_ndc = −1 and z = −f to +1.",
     "列ベクトル: p′ = M·p. z = −n は z_ndc = −1 に, z = −f は +1 に移る.",
     "Столбцы-векторы: p′ = M·p. z = −n переходит в z_ndc = −1, а z = −f — в +1."},
    {"(A sentence stating z = −n ↦ +1 contradicts this matrix; the matrix decides.)",
     "(z = −n ↦ +1 とする記述はこの行列と矛盾します. 行列の方が正しい.)",
     "(Утверждение z = −n ↦ +1 противоречит этой матрице; верна матрица.)"},
    {"The product of the matrices is computed once and applies to every vertex of the object; it "
     "gives the same clip coordinates as the steps one by one.",
     "行列の積は一度だけ計算すれば物体のすべての頂点に使える. "
     "一段ずつ変換した場合と同じクリップ座標になる.",
     "Произведение матриц вычисляется один раз и применяется ко всем вершинам объекта; оно даёт те "
     "же координаты отсечения, что и пошаговое преобразование."},
    {"Column vectors: P′ = M·P, so the step applied first stands rightmost (P′ = A₃A₂A₁P).",
     "列ベクトル: P′ = M·P なので, 最初に適用する変換が一番右に来る (P′ = A₃A₂A₁P).",
     "Столбцы-векторы: P′ = M·P, поэтому первое применяемое преобразование стоит справа (P′ = "
     "A₃A₂A₁P)."},
    {"Processing negates the y row because its window's y axis points down.",
     "Processing ではウィンドウの y 軸が下向きなので, y の行の符号を反転する.",
     "Processing меняет знак строки y, потому что ось y его окна направлена вниз."},
    {"DirectX multiplies row vectors, p′ = p·M: the matrix is printed in that form (the transpose "
     "of the column-vector "
     "matrix).",
     "DirectX は行ベクトルを掛ける (p′ = p·M). 行列はその形 (列ベクトルの行列の転置) で示す.",
     "DirectX умножает строки-векторы, p′ = p·M: матрица записана в этой форме (транспонированная "
     "матрица для "
     "столбцов)."},
    {"DirectX multiplies row vectors: P′ = P·M, so the step applied first stands leftmost and "
     "every matrix is the "
     "transpose of its column-vector form (a translation in the bottom row, as XMMatrixTranslation "
     "builds it).",
     "DirectX は行ベクトルを掛ける: P′ = P·M なので, 最初に適用する変換が一番左に来て, "
     "どの行列も列ベクトルの形の転置になる "
     "(平行移動は最下行, XMMatrixTranslation と同じ).",
     "DirectX умножает строки-векторы: P′ = P·M, поэтому первое применяемое преобразование стоит "
     "слева, а каждая "
     "матрица — транспонированная форма для столбцов (перенос в нижней строке, как строит "
     "XMMatrixTranslation)."},
    {"Looking down +z, z_ndc runs from 0 at near to 1 at far.",
     "+z 方向を見るので, z_ndc は near で 0, far で 1 になる.",
     "При взгляде вдоль +z z_ndc меняется от 0 на near до 1 на far."},
    {"DirectX's eye space looks down +z.", "DirectX の視点座標系は +z 方向を見る.",
     "В DirectX пространство вида смотрит вдоль +z."},
    {"The course's left-handed eye space looks down +z, so the plane is at positive z.",
     "この講義の左手系の視点座標系は +z 方向を見るので, この平面は正の z にある.",
     "В левой системе координат курса пространство вида смотрит вдоль +z, поэтому плоскость "
     "лежит при положительном z."},
    {"Read right-handed (looking down −z), the same picture has the plane at z = −s and every "
     "point's z negated: x′ and y′ are the same in both readings.",
     "右手系 (−z 方向を見る) で読むと, 同じ像で平面は z = −s にあり, 各点の z の符号が反転する: "
     "x′ と y′ はどちらで読んでも同じである.",
     "В правой системе (взгляд вдоль −z) та же картина даёт плоскость z = −s и противоположный "
     "знак z у каждой точки: x′ и y′ в обоих прочтениях одинаковы."},
    {"Eye space looks down −z, so the plane is at negative z.",
     "視点座標系は −z 方向を見るので, この平面は負の z にある.",
     "Пространство вида смотрит вдоль −z, поэтому плоскость лежит при отрицательном z."},
    {"DirectX's window origin is top-left, y down; NDC z is already in [0, 1].",
     "DirectX のウィンドウの原点は左上で y は下向き. 正規化座標の z はすでに [0, 1] にある.",
     "В DirectX начало окна вверху слева, y вниз; z в NDC уже в [0, 1]."},
    {"OpenGL's window origin is bottom-left, y up.",
     "OpenGL のウィンドウの原点は左下で y は上向き.", "В OpenGL начало окна внизу слева, y вверх."},
    {"Processing's window origin is top-left with y down (its screenY); its projection negated y "
     "for its y-down world, "
     "so world y and window y both point down.",
     "Processing のウィンドウの原点は左上で y は下向き (screenY). その投影は y "
     "が下向きのワールドに合わせて y を反転するので, "
     "ワールドの y もウィンドウの y も下を向く.",
     "В Processing начало окна вверху слева, y вниз (его screenY); его проекция меняет знак y для "
     "мира с осью y "
     "вниз, так что y мира и y окна направлены вниз."},
    {"The back clipping plane moves to z = 1, where x and y span [−1, 1].",
     "後方クリッピング面は z = 1 に移り, そこで x と y は [−1, 1] に広がる.",
     "Дальняя плоскость отсечения переходит в z = 1, где x и y пробегают [−1, 1]."},
    {"The eye looks down +z: the view volume runs from z = z_min to z = z_max, with half-widths a "
     "(in x) and b (in "
     "y) at distance d. S and P map it to 0 ≤ z ≤ 1 with near → 0 and far → 1, and x, y to [−1, 1] "
     "(OpenGL's NDC "
     "cube instead sends near to −1).",
     "視点は +z 方向を見る: 視体積は z = z_min から z = z_max まで, 距離 d での半幅は a (x 方向) "
     "と b (y 方向). S と P は"
     "これを 0 ≤ z ≤ 1 (前方クリッピング面 → 0, 後方クリッピング面 → 1), x, y を [−1, 1] に写す "
     "(OpenGL の正規化視体積の立方体では前方は −1 に行く).",
     "Глаз смотрит вдоль +z: видимый объём простирается от z = z_min до z = z_max, с полуширинами "
     "a (по x) и b (по "
     "y) на расстоянии d. S и P переводят его в 0 ≤ z ≤ 1 (ближняя плоскость → 0, дальняя → 1), а "
     "x, y — в [−1, 1] "
     "(куб NDC в OpenGL переводит ближнюю плоскость в −1)."},
    {"A point (x, y, z) in front of the eye (z > 0) meets the near plane z = n at (x_n, y_n): the "
     "projection divides by "
     "the depth z.",
     "視点の前方 (z > 0) の点 (x, y, z) は前方クリッピング面 z = n と (x_n, y_n) で交わる: "
     "投影は奥行き z で割る.",
     "Точка (x, y, z) перед глазом (z > 0) попадает на ближнюю плоскость z = n в (x_n, y_n): "
     "проекция делит на "
     "глубину z."},
    {"A point (x, y, z) in front of the eye (z < 0, so −z is its depth) meets the near plane z = "
     "−n at (x_n, y_n): the "
     "projection divides by −z.",
     "視点の前方 (z < 0 なので −z が奥行き) の点 (x, y, z) は前方クリッピング面 z = −n と (x_n, "
     "y_n) で交わる (三角形の相似より). "
     "投影は −z で割る.",
     "Точка (x, y, z) перед глазом (z < 0, так что −z — её глубина) попадает на ближнюю плоскость "
     "z = −n в "
     "(x_n, y_n): проекция делит на −z."},
    {"No 4 × 4 matrix divides by a coordinate, but the perspective divide by w′ does: the matrix "
     "only has to put the "
     "depth into w′ and scale x_n, y_n from the window [l, r] × [b, t] to [−1, 1].",
     "4 × 4 行列は座標で割ることはできないが, w′ による透視除算ならできる: 行列は奥行きを w′ "
     "に入れ, x_n, y_n を"
     "窓 [l, r] × [b, t] から [−1, 1] に拡大縮小すればよい.",
     "Никакая матрица 4 × 4 не делит на координату, а перспективное деление на w′ делит: матрице "
     "остаётся "
     "поместить глубину в w′ и перевести x_n, y_n из окна [l, r] × [b, t] в [−1, 1]."},
    {"X′ and Y′ are unchanged and W′ = z: the matrix is projective, not affine.",
     "X′ と Y′ は変わらず W′ = z: この行列はアフィンではなく射影変換である.",
     "X′ и Y′ не меняются, а W′ = z: матрица проективная, не аффинная."},
    {"eye = the camera's position (e), center = the point it looks at (c), up = the up vector.",
     "eye = カメラの位置 (e), center = 注視点 (c), up = 上方向ベクトル.",
     "eye — положение камеры (e), center — точка, на которую она смотрит (c), up — вектор "
     "«вверх»."},
    {"Each row of V dots a point with one camera axis after moving the eye to the origin: s·(p − "
     "eye) = s·p − s·eye.",
     "V の各行は, 視点を原点に移した後の点とカメラの軸 1 本との内積: s·(p − eye) = s·p − s·eye.",
     "Каждая строка V — скалярное произведение точки на одну ось камеры после переноса глаза в "
     "начало координат: "
     "s·(p − eye) = s·p − s·eye."},
    {"Each step is undone on its own (a translation by its negative, a scaling by its reciprocal, "
     "a rotation by its "
     "transpose), in reverse order.",
     "各ステップを個別に元に戻す (平行移動は符号を反転, 拡大縮小は逆数, 回転は転置) — 逆の順序で.",
     "Каждый шаг обращается отдельно (перенос — противоположным, масштабирование — обратными "
     "величинами, поворот — "
     "транспонированием), в обратном порядке."},
    {"Rodrigues' formula R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ, written entry by entry, for the unit "
     "axis u = (x, y, z).",
     "Rodrigues の公式 R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ を, 単位軸 u = (x, y, z) "
     "について成分ごとに書いたもの.",
     "Формула Родрига R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ, записанная поэлементно для единичной оси "
     "u = (x, y, z)."},
    {"The axis is normalised first: (x, y, z) = {0}.", "軸をまず正規化する: (x, y, z) = {0}.",
     "Сначала ось нормируется: (x, y, z) = {0}."},
    {"fovy is the vertical field of view: it sets the top t, and the aspect ratio width/height "
     "widens the right edge r.",
     "fovy は垂直方向の画角: これが上端 t を決め, アスペクト比 width/height が右端 r を広げる.",
     "fovy — вертикальный угол обзора: он задаёт верх t, а соотношение сторон width/height "
     "расширяет правый край r."},
    {"Read as a horizontal angle, θ would give −l = r = n·tan(θ/2) and t = r·h/w = "
     "n·(h/w)·tan(θ/2).",
     "θ を水平方向の画角と読むと −l = r = n·tan(θ/2), t = r·h/w = n·(h/w)·tan(θ/2) となる.",
     "Если читать θ как горизонтальный угол, то −l = r = n·tan(θ/2) и t = r·h/w = "
     "n·(h/w)·tan(θ/2)."},
    {"Some notes write −b = t = n·(w/h)·tan(θ/2) beside r = n·tan(θ/2): for w ≠ h that matches "
     "neither reading of θ.",
     "r = n·tan(θ/2) と並べて −b = t = n·(w/h)·tan(θ/2) と書く資料もあるが, w ≠ h "
     "のときこれはどちらの読み方にも合わない.",
     "В некоторых материалах рядом с r = n·tan(θ/2) пишут −b = t = n·(w/h)·tan(θ/2): при w ≠ h "
     "это не соответствует ни одному прочтению θ."},
    {"Processing's defaults: without arguments perspective() uses a 60° vertical field of view "
     "and puts the eye where the window's height exactly fills it.",
     "Processing の既定値: 引数なしの perspective() は垂直方向の画角 60° を使い, "
     "ウィンドウの高さがちょうどその画角を満たす位置に視点を置く.",
     "Значения Processing по умолчанию: без аргументов perspective() берёт вертикальный угол "
     "обзора 60° и ставит глаз туда, где высота окна ровно заполняет этот угол."},
    {"The plane on which the window's height exactly fills the vertical field of view; Processing "
     "puts its default "
     "camera at this distance.",
     "ウィンドウの高さがちょうど垂直方向の画角を満たす平面. Processing "
     "は既定のカメラをこの距離に置く.",
     "Плоскость, на которой высота окна в точности заполняет вертикальный угол обзора; Processing "
     "ставит камеру по "
     "умолчанию на этом расстоянии."},
    {"v is the direction the viewer looks (into the scene), so larger depth = farther (with v = "
     "(0, 0, −1), OpenGL's "
     "default view, depth = −z).",
     "v は見る人が見る方向 (シーンの奥へ) なので, 奥行きが大きいほど遠い (OpenGL の既定の v = (0, "
     "0, −1) では奥行き = −z).",
     "v — направление взгляда наблюдателя (в сцену), поэтому большая глубина = дальше (при v = (0, "
     "0, −1), "
     "взгляде OpenGL по умолчанию, глубина = −z)."},
    {"Larger depth = farther from the eye.", "奥行きが大きいほど視点から遠い.",
     "Большая глубина = дальше от глаза."},
    {"Equal depths keep the listed order.", "奥行きが等しいものは列挙した順のまま.",
     "Равные глубины сохраняют исходный порядок."},
    // Clipping.
    {"{0}-bit codes, most significant first: 1000 top (y > ymax), 0100 bottom (y < ymin), 0010 "
     "right (x > xmax), "
     "0001 left (x < xmin).",
     "{0} ビットのコード (上位ビットから): 1000 上 (y > ymax), 0100 下 (y < ymin), 0010 右 (x > "
     "xmax), 0001 左 (x < xmin).",
     "{0}-битные коды, старший бит первым: 1000 сверху (y > ymax), 0100 снизу (y < ymin), 0010 "
     "справа (x > xmax), "
     "0001 слева (x < xmin)."},
    {"{0}-bit codes (the 2D codes with two bits for z added), most significant first: 100000 z > "
     "zmax, 010000 z < zmin, "
     "001000 top (y > ymax), 000100 bottom (y < ymin), 000010 right (x > xmax), 000001 left (x < "
     "xmin).",
     "{0} ビットのコード (2 次元のコードに z の 2 ビットを加えたもの, 上位ビットから): 100000 z > "
     "zmax, 010000 z < zmin, "
     "001000 上 (y > ymax), 000100 下 (y < ymin), 000010 右 (x > xmax), 000001 左 (x < xmin).",
     "{0}-битные коды (двумерные коды плюс два бита для z), старший бит первым: 100000 z > zmax, "
     "010000 z < zmin, "
     "001000 сверху (y > ymax), 000100 снизу (y < ymin), 000010 справа (x > xmax), 000001 слева (x "
     "< xmin)."},
    {"A point on a boundary is inside (bit 0).", "境界上の点は内側とする (ビット 0).",
     "Точка на границе считается внутренней (бит 0)."},
    {"Both codes are now 0000: accept.", "両方のコードが 0000 になった: 採用.",
     "Оба кода теперь 0000: принимаем."},
    {"Both codes are now {0}: accept.", "両方のコードが {0} になった: 採用.",
     "Оба кода теперь {0}: принимаем."},
    {"Trivially accepted: the segment is unchanged.", "自明な採用: 線分はそのまま残る.",
     "Тривиально принят: отрезок не меняется."},
    {"yes: the whole segment is inside", "はい: 線分全体が内側", "да: весь отрезок внутри"},
    {"After clipping, both endpoints share an outside bit: the segment misses the region.",
     "クリッピング後, 両端点が共通の外側ビットを持つ: 線分は領域を通らない.",
     "После отсечения оба конца имеют общий внешний бит: отрезок не проходит через область."},
    {"depths are equal (coplanar)", "奥行きが等しい (同一平面上)", "глубины равны (компланарны)"},
    {"Trivially rejected: the segment lies outside one boundary.",
     "自明な棄却: 線分は一つの境界の外側にある.",
     "Тривиально отброшен: отрезок лежит вне одной из границ."},
    {"t is the fraction of the way from {0} to {1} at which the segment crosses {2}.",
     "t は, 線分が {2} と交わる点が {0} から {1} へ向かう道のりのどれだけの割合にあるかを表す.",
     "t — доля пути от {0} к {1}, на которой отрезок пересекает {2}."},
    {"top (y > ymax)", "上 (y > ymax)", "сверху (y > ymax)"},
    {"bottom (y < ymin)", "下 (y < ymin)", "снизу (y < ymin)"},
    {"right (x > xmax)", "右 (x > xmax)", "справа (x > xmax)"},
    {"left (x < xmin)", "左 (x < xmin)", "слева (x < xmin)"},
    {"Sutherland–Hodgman: clip against one boundary at a time; for each edge S → E keep E when it "
     "is inside (on the "
     "boundary counts as inside) and add the intersection where the edge crosses.",
     "Sutherland–Hodgman: 境界を一つずつ使ってクリップする. 各辺 S → E について, E が内側なら E "
     "を残し (境界上は内側), "
     "辺が境界を横切るところでは交点を加える.",
     "Sutherland–Hodgman: отсекаем по одной границе за раз; для каждого ребра S → E оставляем E, "
     "если она внутри "
     "(на границе — тоже внутри), и добавляем точку пересечения, где ребро пересекает границу."},
    {"w_c < 0: dividing by w would send the point to infinity or mirror it in front of the eye, so "
     "it has no NDC or "
     "window position; clipping removes it before the divide.",
     "w_c < 0: w で割ると点は無限遠に飛ぶか視点の前に鏡映されるので, "
     "正規化座標もウィンドウ上の位置もない. 除算の前にクリッピングで除かれる.",
     "w_c < 0: деление на w отправило бы точку в бесконечность или отразило бы её перед глазом, "
     "поэтому у неё нет "
     "положения в NDC и в окне; отсечение удаляет её до деления."},
    {"w_c = 0: dividing by w would send the point to infinity or mirror it in front of the eye, so "
     "it has no NDC or "
     "window position; clipping removes it before the divide.",
     "w_c = 0: w で割ると点は無限遠に飛ぶか視点の前に鏡映されるので, "
     "正規化座標もウィンドウ上の位置もない. 除算の前にクリッピングで除かれる.",
     "w_c = 0: деление на w отправило бы точку в бесконечность или отразило бы её перед глазом, "
     "поэтому у неё нет "
     "положения в NDC и в окне; отсечение удаляет её до деления."},
    // Back faces, solids, edges.
    {"D_f > 0: v and n make an acute angle, so the eye sees the front.",
     "D_f > 0: v と n のなす角は鋭角なので, 視点からは表が見える.",
     "D_f > 0: v и n образуют острый угол, поэтому глаз видит лицевую сторону."},
    {"D_f < 0: v and n make an obtuse angle, so the eye sees the back.",
     "D_f < 0: v と n のなす角は鈍角なので, 視点からは裏が見える.",
     "D_f < 0: v и n образуют тупой угол, поэтому глаз видит обратную сторону."},
    {"D_f = 0 exactly: the eye lies in the polygon's plane, which it sees edge-on.",
     "D_f = 0 (厳密): 視点は多角形の平面上にあり, 多角形を真横から見る.",
     "D_f = 0 точно: глаз лежит в плоскости многоугольника и видит его с ребра."},
    {"Face(s) {0} have D_f = 0 exactly: the eye lies in their plane, so they cover no area on "
     "screen.",
     "面 {0} は D_f = 0 (厳密): 視点がその平面上にあるので, 画面上で面積を持たない.",
     "У граней {0} D_f = 0 точно: глаз лежит в их плоскости, поэтому на экране они не занимают "
     "площади."},
    {"They count as back for the edge classes, as back-face culling treats them.",
     "稜線の分類では, バックフェースカリングと同じく裏として扱う.",
     "При классификации рёбер они считаются обратными, как их и трактует отсечение нелицевых "
     "граней."},
    {"D_f > 0: front; D_f < 0: back (p_i is the face's first vertex, n its normal, "
     "counter-clockwise = front).",
     "D_f > 0: 表, D_f < 0: 裏 (p_i は面の最初の頂点, n はその法線, 反時計回り = 表).",
     "D_f > 0: лицевая; D_f < 0: обратная (p_i — первая вершина грани, n — её нормаль, против "
     "часовой стрелки = "
     "лицевая)."},
    {"face {0}: n = {1}, D_f = {2} → {3}", "面 {0}: n = {1}, D_f = {2} → {3}",
     "грань {0}: n = {1}, D_f = {2} → {3}"},
    {"{0}: {1} vertices, {2} faces (counter-clockwise from outside).",
     "{0}: 頂点 {1} 個, 面 {2} 個 (外から見て反時計回り).",
     "{0}: {1} вершин, {2} граней (против часовой стрелки, если смотреть снаружи)."},
    {"{0}: {1} vertices, {2} faces (counter-clockwise from outside). φ = (1 + √5)/2 is kept exact.",
     "{0}: 頂点 {1} 個, 面 {2} 個 (外から見て反時計回り). φ = (1 + √5)/2 は厳密に扱う.",
     "{0}: {1} вершин, {2} граней (против часовой стрелки, если смотреть снаружи). φ = (1 + √5)/2 "
     "хранится точно."},
    {"φ = (1 + √5)/2 is kept exact.", "φ = (1 + √5)/2 は厳密に扱う.",
     "φ = (1 + √5)/2 хранится точно."},
    {"cube", "立方体", "куб"},
    {"dodecahedron", "正十二面体", "додекаэдр"},
    {"icosahedron", "正二十面体", "икосаэдр"},
    {"octahedron", "正八面体", "октаэдр"},
    {"tetrahedron", "正四面体", "тетраэдр"},
    {"prism", "角柱", "призма"},
    {"pyramid", "角錐", "пирамида"},
    {"solid", "立体", "тело"},
    {"Every edge joins exactly two faces, which walk it in opposite directions.",
     "どの辺もちょうど 2 つの面に共有され, 2 つの面はその辺を逆向きにたどる.",
     "Каждое ребро соединяет ровно две грани, которые обходят его в противоположных направлениях."},
    {"Every vertex lies on the inner side of (or on) every face plane.",
     "どの頂点もすべての面の平面の内側 (または平面上) にある.",
     "Каждая вершина лежит с внутренней стороны каждой плоскости грани (или на ней)."},
    {"Not convex: vertex {0} lies outside the plane of face {1}.",
     "凸でない: 頂点 {0} は面 {1} の平面の外側にある.",
     "Невыпуклый: вершина {0} лежит снаружи плоскости грани {1}."},
    {"A single closed convex polyhedron: no front face can hide another, so culling the back faces "
     "removes every "
     "hidden surface.",
     "閉じた凸多面体が一つだけ: 表の面が他の面を隠すことはないので, "
     "裏面を除去すれば隠面はすべて消える.",
     "Один замкнутый выпуклый многогранник: лицевая грань не может закрыть другую, поэтому "
     "отсечение нелицевых "
     "граней удаляет все невидимые поверхности."},
    {"Not convex: from some viewpoints a front face hides part of another front face, so "
     "back-face culling alone does not always remove the hidden surfaces; a depth test is still "
     "needed.",
     "凸でない: 視点によっては表の面が別の表の面の一部を隠すので, "
     "バックフェースカリングだけでは隠面がいつも消えるとは限らない. 奥行きテストが必要.",
     "Невыпуклый: при некоторых положениях глаза лицевая грань закрывает часть другой лицевой "
     "грани, поэтому одно отсечение нелицевых граней не всегда удаляет невидимые поверхности; "
     "нужен ещё тест глубины."},
    {"An edge is classified by the two faces that share it.",
     "稜線はそれを共有する 2 つの面で分類される.",
     "Ребро классифицируется по двум граням, которые его разделяют."},
    {"Hidden-line drawing = the edges of the front faces (visible + silhouette): {0}.",
     "隠線消去した図 = 表の面の稜線 (見える稜線 + 輪郭線): {0}.",
     "Рисунок с удалёнными невидимыми линиями = рёбра лицевых граней (видимые + силуэт): {0}."},
    {"Drawing only these shows the lines that should be hidden.",
     "これらだけを描くと, 隠れるべき線が見える.",
     "Если рисовать только их, видны линии, которые должны быть скрыты."},
    {"Chained by shared vertices: {0} ({1} loop).", "共有する頂点でつなぐ: {0} (ループ {1} 個).",
     "Связаны общими вершинами: {0} ({1} контур)."},
    {"Chained by shared vertices: {0} ({1} loops).", "共有する頂点でつなぐ: {0} (ループ {1} 個).",
     "Связаны общими вершинами: {0} (контуров: {1})."},
    {"A convex polyhedron's silhouette is one closed loop, a convex polygon on screen.",
     "凸多面体の輪郭線は閉じたループ一つで, 画面上では凸多角形になる.",
     "Силуэт выпуклого многогранника — один замкнутый контур, выпуклый многоугольник на экране."},
    {"A{0}: rotate_y {1}; A{2}: translate {3}.", "A{0}: rotate_y {1}; A{2}: 平行移動 {3}.",
     "A{0}: rotate_y {1}; A{2}: перенос на {3}."},
    {"Every vertex moves by P′ = M·P; faces keep their vertex lists.",
     "各頂点は P′ = M·P で移り, 面の頂点リストは変わらない.",
     "Каждая вершина переходит по P′ = M·P; грани сохраняют свои списки вершин."},
    {"The faces are listed counter-clockwise seen from outside in this left-handed frame, where "
     "e₀ × e₁ points inward: each face's outward (front) normal is n = e₁ × e₀.",
     "この左手系では各面の頂点は外側から見て反時計回りに並べられ, e₀ × e₁ は内側を向く. "
     "各面の外向き(表側)の法線は n = e₁ × e₀ である.",
     "В этой левой системе координат вершины каждой грани перечислены против часовой стрелки "
     "при взгляде снаружи, и e₀ × e₁ направлен внутрь: внешняя (лицевая) нормаль каждой грани — "
     "n = e₁ × e₀."},
    {"In DirectX's left-handed coordinates the same formula n = e₀ × e₁ points to the side from "
     "which the vertices "
     "appear clockwise — Direct3D's default front face (FrontCounterClockwise = false).",
     "DirectX の左手系では同じ式 n = e₀ × e₁ が, 頂点が時計回りに見える側を向く — Direct3D "
     "の既定の表面 "
     "(FrontCounterClockwise = false).",
     "В левой системе DirectX та же формула n = e₀ × e₁ указывает в сторону, откуда вершины видны "
     "по часовой "
     "стрелке, — лицевая грань Direct3D по умолчанию (FrontCounterClockwise = false)."},
    {"Mind the order of the cross product: in a left-handed frame the front normal of a triangle "
     "ABC is AC × AB (the "
     "order used by default).",
     "外積の順序に注意: 左手系では三角形 ABC の表向きの法線は AC × AB (既定の順序).",
     "Следите за порядком векторного произведения: в левой системе лицевая нормаль треугольника "
     "ABC — AC × AB "
     "(порядок по умолчанию)."},
    {"In a right-handed frame AB × AC points to the side from which A, B, C run counter-clockwise; "
     "in a left-handed "
     "frame (such as projection coordinates) that side's normal is AC × AB.",
     "右手系では AB × AC は A, B, C が反時計回りに見える側を向く. 左手系 (投影座標系など) "
     "ではその側の法線は AC × AB.",
     "В правой системе AB × AC направлен в ту сторону, откуда A, B, C идут против часовой стрелки; "
     "в левой системе "
     "(например, в координатах проекции) нормаль этой стороны — AC × AB."},
    {"Mind the order of the cross product; this problem uses {0}.",
     "外積の順序に注意. この問題では {0} を使う.",
     "Следите за порядком векторного произведения; в этой задаче используется {0}."},
    {"Newell's method sums every edge pair, so it stays accurate when some edges are nearly "
     "parallel or nearly zero "
     "(where eᵢ × eᵢ₊₁ loses accuracy), and gives twice the vector area (the same direction as eᵢ "
     "× eᵢ₊₁ for a convex "
     "polygon).",
     "Newell の方法はすべての辺の組を足し合わせるので, ほぼ平行な辺やほぼ長さ 0 "
     "の辺があっても精度を保ち (eᵢ × eᵢ₊₁ "
     "では精度が落ちる), ベクトル面積の 2 倍を与える (凸多角形では eᵢ × eᵢ₊₁ と同じ向き).",
     "Метод Newell суммирует все пары рёбер, поэтому остаётся точным, когда некоторые рёбра почти "
     "параллельны или "
     "почти нулевые (где eᵢ × eᵢ₊₁ теряет точность), и даёт удвоенную векторную площадь (то же "
     "направление, что "
     "eᵢ × eᵢ₊₁, для выпуклого многоугольника)."},
    // Conditioning and exactness.
    {"D_f (its sign, front or back, is decided exactly here; a floating-point sign needs an "
     "error-bounded filter with "
     "an exact fallback) is ill-conditioned ({0}).",
     "D_f (その符号, つまり表か裏かはここでは厳密に判定する. "
     "浮動小数点での符号には誤差限界付きのフィルタと厳密計算による代替が必要) "
     "は条件が悪い ({0}).",
     "D_f (его знак — лицевая или обратная — здесь определяется точно; знаку в плавающей точке "
     "нужен фильтр с "
     "оценкой погрешности и точный запасной путь) плохо обусловлен ({0})."},
    {"The normal's direction is ill-conditioned ({0}).", "法線の向きは条件が悪い ({0}).",
     "Направление нормали плохо обусловлено ({0})."},
    {"c is small beside the terms it is computed from (κ_c ≈ {0}), so z = (d − a·xₛ − b·yₛ)/c is "
     "ill-conditioned ({1}).",
     "c はそれを計算する項に比べて小さい (κ_c ≈ {0}) ので, z = (d − a·xₛ − b·yₛ)/c は条件が悪い "
     "({1}).",
     "c мало по сравнению со слагаемыми, из которых вычисляется (κ_c ≈ {0}), поэтому z = (d − a·xₛ "
     "− b·yₛ)/c "
     "плохо обусловлено ({1})."},
    {"κ ≈ {0}: {1}; the exact value shown is unaffected",
     "κ ≈ {0}: {1}. 示した厳密値には影響しない",
     "κ ≈ {0}: {1}; показанное точное значение от этого не зависит"},
    {"float keeps no correct digit, double keeps no correct digit, long-double keeps about {0} of "
     "its {1} digits",
     "float では正しい桁は残らず, double でも残らず, long double では {1} 桁中およそ {0} 桁が残る",
     "во float не остаётся ни одной верной цифры, в double — тоже, в long double — около {0} из "
     "{1} цифр"},
    {"float keeps no correct digit, double keeps about {0} of its {1} digits, long-double keeps "
     "about {2} of its {3} digits",
     "float では正しい桁は残らず, double では {1} 桁中およそ {0} 桁, long double では {3} "
     "桁中およそ {2} 桁が残る",
     "во float не остаётся ни одной верной цифры, в double — около {0} из {1} цифр, в long double "
     "— около {2} из {3}"},
    {"float keeps about {0} of its {1} digits, double keeps about {2} of its {3} digits, "
     "long-double keeps about {4} of "
     "its {5} digits",
     "float では {1} 桁中およそ {0} 桁, double では {3} 桁中およそ {2} 桁, long double では {5} "
     "桁中およそ {4} 桁が残る",
     "во float остаётся около {0} из {1} цифр, в double — около {2} из {3}, в long double — около "
     "{4} из {5}"},
    {"Computed in floating point with fewer than half its digits left, z is better found by "
     "barycentric interpolation "
     "z = Σ λᵢ zᵢ.",
     "浮動小数点で計算すると桁が半分も残らないので, z は重心座標による補間 z = Σ λᵢ zᵢ "
     "で求める方がよい.",
     "При вычислении в плавающей точке остаётся меньше половины цифр, поэтому z лучше найти "
     "барицентрической "
     "интерполяцией z = Σ λᵢ zᵢ."},
    {"e{0} and e{1} are nearly parallel (sin θ ≈ {2}); e × e loses about {3} of double precision's "
     "16 digits here, but "
     "this normal is computed exactly.",
     "e{0} と e{1} はほぼ平行 (sin θ ≈ {2}). ここで e × e は double の 16 桁のうちおよそ {3} "
     "桁を失うが, この法線は厳密に計算している.",
     "e{0} и e{1} почти параллельны (sin θ ≈ {2}); здесь e × e теряет около {3} из 16 цифр double, "
     "но эта нормаль "
     "вычислена точно."},
    {"far/near = {0}: a float depth buffer in [0, 1] separates surfaces at this distance only when "
     "they are more than "
     "Δz ≈ {1} apart (Δz ≈ 2⁻²⁴(f − n)z²/(f·n); a reversed-Z depth buffer keeps far more).",
     "far/near = {0}: [0, 1] の float の奥行きバッファがこの距離で面を区別できるのは, 面が Δz ≈ "
     "{1} より離れているときだけ "
     "(Δz ≈ 2⁻²⁴(f − n)z²/(f·n). 逆 Z の奥行きバッファならはるかに多くの精度が残る).",
     "far/near = {0}: float-буфер глубины в [0, 1] различает поверхности на этом расстоянии, "
     "только если они "
     "отстоят больше чем на Δz ≈ {1} (Δz ≈ 2⁻²⁴(f − n)z²/(f·n); обратный Z-буфер сохраняет гораздо "
     "больше)."},
    // Scan conversion and pixels.
    {"{0} pixel(s) covered.", "{0} 個の画素を覆う.", "Покрыто пикселей: {0}."},
    {"A pixel is covered when E > 0 on all three edges, or E = 0 on an edge that is top or left.",
     "画素が覆われるのは, 3 辺すべてで E > 0 のとき, または E = 0 となる辺が上辺か左辺のとき.",
     "Пиксель покрыт, если E > 0 на всех трёх рёбрах или E = 0 на верхнем или левом ребре."},
    {"left edge: centres on it are covered", "左辺: その上の画素中心は覆われる",
     "левое ребро: центры на нём покрыты"},
    {"top edge: centres on it are covered", "上辺: その上の画素中心は覆われる",
     "верхнее ребро: центры на нём покрыты"},
    {"bottom or right edge: centres on it are not covered",
     "下辺または右辺: その上の画素中心は覆われない",
     "нижнее или правое ребро: центры на нём не покрыты"},
    {"The signs agree (0 = on an edge), so the pixel is inside the closed triangle.",
     "符号がそろっている (0 = 辺上) ので, 画素は閉じた三角形の内側にある.",
     "Знаки совпадают (0 — на ребре), поэтому пиксель внутри замкнутого треугольника."},
    {"The triangle {0} is clockwise; it is scanned as {1} (counter-clockwise) so the interior has "
     "E > 0 on every edge.",
     "三角形 {0} は時計回りなので, {1} (反時計回り) として走査し, 内部がすべての辺で E > 0 "
     "となるようにする.",
     "Треугольник {0} обходится по часовой стрелке; он сканируется как {1} (против часовой), чтобы "
     "внутри E > 0 на "
     "каждом ребре."},
    {"The signs differ, so the pixel is outside; the plane still gives its z.",
     "符号がそろっていないので画素は外側にある. それでも平面から z は求まる.",
     "Знаки различаются, поэтому пиксель снаружи; плоскость всё равно даёт его z."},
    {"The signs differ, so the pixel is outside (some λᵢ is negative); the interpolation still "
     "gives its z.",
     "符号がそろっていないので画素は外側にある (負の λᵢ がある). それでも補間から z は求まる.",
     "Знаки различаются, поэтому пиксель снаружи (некоторое λᵢ отрицательно); интерполяция всё "
     "равно даёт его z."},
    {"Scan conversion culls nothing.", "走査変換では何も除去しない.",
     "Растеризация ничего не отбрасывает."},
    {"Window y points up; pixel (i, j) has its centre at (i + ½, j + ½).",
     "ウィンドウの y は上向き. 画素 (i, j) の中心は (i + ½, j + ½).",
     "Ось y окна направлена вверх; центр пикселя (i, j) — в (i + ½, j + ½)."},
    {"Vertices are snapped to 1/256 pixel and the edge functions are evaluated exactly.",
     "頂点は 1/256 画素に丸め, エッジ関数は厳密に評価する.",
     "Вершины привязываются к 1/256 пикселя, функции рёбер вычисляются точно."},
    {"Top-left rule: a centre exactly on an edge is covered only when the edge is a top edge "
     "(horizontal, interior "
     "below) or a left edge (interior to its right); on a bottom or right edge it is not.",
     "左上規則: ちょうど辺上にある中心が覆われるのは, その辺が上辺 (水平で内部が下) か左辺 "
     "(内部が右) のときだけで, 下辺や右辺では覆われない.",
     "Правило «верх-лево»: центр ровно на ребре покрыт, только если ребро верхнее (горизонтальное, "
     "внутренность "
     "ниже) или левое (внутренность справа); на нижнем или правом ребре — нет."},
    {"Some vertex is not a multiple of 1/256 pixel; it was rounded to the nearest one, as a GPU "
     "does.",
     "1/256 画素の倍数でない頂点があるので, GPU と同じく最も近い倍数に丸めた.",
     "Некоторая вершина не кратна 1/256 пикселя; она округлена до ближайшей, как это делает GPU."},
    {"Rows top first, joined by “/”.", "行は上から順に “/” でつないで書く.",
     "Строки сверху вниз, через «/»."},
    {"Pixel (i, j) has its centre at (i + ½, j + ½), window y up; grids are written top row first.",
     "画素 (i, j) の中心は (i + ½, j + ½), ウィンドウの y は上向き. 格子は上の行から書く.",
     "Центр пикселя (i, j) — в (i + ½, j + ½), ось y окна вверх; сетки записаны с верхней строки."},
    {"Coverage uses the top-left fill rule; convex polygons are split into a fan of triangles from "
     "their first vertex; z "
     "is interpolated linearly in x and y (the plane through the vertices).",
     "被覆は左上規則による. 凸多角形は最初の頂点から扇形に三角形分割する. z は x と y "
     "について線形に補間する (頂点を通る平面).",
     "Покрытие — по правилу «верх-лево»; выпуклые многоугольники разбиваются веером треугольников "
     "от первой "
     "вершины; z интерполируется линейно по x и y (плоскость через вершины)."},
    {"A pixel is overwritten when the polygon's z is smaller than Z(i, j); equal z keeps the "
     "earlier polygon.",
     "多角形の z が Z(i, j) より小さいとき画素を上書きする. z が等しいときは先の多角形のまま.",
     "Пиксель перезаписывается, если z многоугольника меньше Z(i, j); при равных z остаётся "
     "прежний многоугольник."},
    {"Pixel (i, j) is counted in the y-down window (row 0 at the top) and has its centre at (i + "
     "½, j + ½).",
     "画素 (i, j) は y が下向きのウィンドウで数え (0 行目が上), 中心は (i + ½, j + ½).",
     "Пиксель (i, j) отсчитывается в окне с осью y вниз (строка 0 сверху), его центр — в (i + ½, j "
     "+ ½)."},
    {"Pixel (i, j) is counted in the y-up window (row 0 at the bottom) and has its centre at (i + "
     "½, j + ½).",
     "画素 (i, j) は y が上向きのウィンドウで数え (0 行目が下), 中心は (i + ½, j + ½).",
     "Пиксель (i, j) отсчитывается в окне с осью y вверх (строка 0 снизу), его центр — в (i + ½, j "
     "+ ½)."},
    {"Triangles are clipped in homogeneous clip space, divided by w, mapped by the viewport, "
     "snapped to 1/256 pixel and "
     "covered under the top-left rule; depth is window z in [0, 1], interpolated as the plane "
     "through the snapped "
     "vertices (z/w is affine in screen space) and stored as a 32-bit float.",
     "三角形は同次クリップ空間でクリップし, w で割り, ビューポート変換で写し, 1/256 画素に丸め, "
     "左上規則で被覆を決める. 奥行きは "
     "[0, 1] のウィンドウ z で, 丸めた頂点を通る平面として補間し (z/w は画面空間でアフィン), 32 "
     "ビット float で格納する.",
     "Треугольники отсекаются в однородном пространстве отсечения, делятся на w, отображаются в "
     "область просмотра, "
     "привязываются к 1/256 пикселя и покрываются по правилу «верх-лево»; глубина — z окна в [0, "
     "1], "
     "интерполируется как плоскость через привязанные вершины (z/w аффинно в экранном "
     "пространстве) и хранится как "
     "32-битный float."},
    {"The depth buffer starts at 1 (far) and a fragment is written when its depth is less than the "
     "stored one (equal "
     "keeps the earlier).",
     "奥行きバッファは 1 (遠方) で始まり, 断片は奥行きが格納値より小さいときに書き込まれる "
     "(等しければ先のまま).",
     "Буфер глубины начинается с 1 (далеко), фрагмент записывается, если его глубина меньше "
     "сохранённой (при "
     "равенстве остаётся прежний)."},
    {"Lighting as Processing's lights(): ambient {0} + directional {1} travelling along {2}, flat "
     "and two-sided.",
     "照明は Processing の lights() と同じ: 環境光 {0} + 方向 {2} に進む平行光 {1}, "
     "フラットシェーディング, 両面.",
     "Освещение как lights() в Processing: фоновое {0} + направленное {1} вдоль {2}, плоское, "
     "двустороннее."},
    {"No light: each triangle has its fill colour.", "照明なし: 各三角形は塗りつぶし色のまま.",
     "Без освещения: у каждого треугольника свой цвет заливки."},
    {"{0} objects.", "物体 {0} 個.", "Объектов: {0}."},
    {"Only the queried pixels are resolved: a triangle competes for a pixel when its screen bounds "
     "hold the pixel "
     "centre; no {0} frame is allocated.",
     "問われた画素だけを求める: 画面上の範囲が画素中心を含む三角形がその画素を争う. {0} "
     "のフレームは確保しない.",
     "Вычисляются только запрошенные пиксели: треугольник претендует на пиксель, если его экранные "
     "границы содержат "
     "центр пикселя; кадр {0} не выделяется."},
    {"Z-buffer trace, drawing order ({0} competitor(s)):",
     "Z バッファの経過, 描画順 (候補 {0} 個):",
     "Трассировка Z-буфера в порядке рисования (претендентов: {0}):"},
    {"No triangle covers this pixel centre.", "この画素中心を覆う三角形はない.",
     "Ни один треугольник не покрывает центр этого пикселя."},
    {"Every decision (clipping, facing, snapping, the depth test) is exact: taken on the computed "
     "values when their error bound proves it, else by exact arithmetic on the given numbers.",
     "判定 (クリッピング, 表裏, スナップ, 奥行き比較) はすべて厳密: "
     "計算値の誤差限界が判定を保証するときは"
     "計算値で, そうでなければ与えられた数での厳密な計算で決める.",
     "Каждое решение (отсечение, ориентация, привязка к сетке, тест глубины) точное: принимается "
     "по "
     "вычисленным значениям, когда их оценка погрешности его гарантирует, иначе точной арифметикой "
     "над "
     "заданными числами."},
    {"Exact arithmetic on the given numbers decided the clipping, facing or snapping of {0} "
     "triangle(s) that rounding could not settle.",
     "丸め誤差で決まらなかった三角形 {0} 個のクリッピング, 表裏またはスナップは, 与えられた数での"
     "厳密な計算で決めた.",
     "Отсечение, ориентацию или привязку к сетке для треугольников ({0}), которые округление не "
     "позволяло определить, решила точная арифметика над заданными числами."},
    {"The depth test was decided by exact arithmetic on the given numbers (the computed depths "
     "were "
     "within rounding of each other).",
     "奥行き比較は与えられた数での厳密な計算で決めた (計算した奥行きの差が丸め誤差の範囲内だった).",
     "Тест глубины решён точной арифметикой над заданными числами (вычисленные глубины совпадали в "
     "пределах округления)."},
    {"{0}. triangle {1} ({2} face {3}, {4}): z = {5} → written, colour {6}",
     "{0}. 三角形 {1} (`{2}` の面 {3}, {4}): z = {5} → 書き込む, 色 {6}",
     "{0}. треугольник {1} (`{2}`, грань {3}, {4}): z = {5} → записан, цвет {6}"},
    {"{0}. triangle {1} ({2} face {3}, {4}): z = {5} → hidden",
     "{0}. 三角形 {1} (`{2}` の面 {3}, {4}): z = {5} → 隠れる",
     "{0}. треугольник {1} (`{2}`, грань {3}, {4}): z = {5} → скрыт"},
    // Depth sort.
    {"Overlap is decided exactly by the orthographic projection along the view direction (each "
     "polygon cut into "
     "triangles on screen).",
     "重なりは視線方向への平行投影で厳密に判定する (各多角形を画面上で三角形に分割).",
     "Перекрытие определяется точно ортографической проекцией вдоль направления взгляда (каждый "
     "многоугольник "
     "разрезан на треугольники на экране)."},
    {"Overlap is decided exactly by the perspective projection from the eye onto the plane "
     "perpendicular to the "
     "direction from the eye to the mean centroid (each polygon cut into triangles on screen).",
     "重なりは, 視点から平均重心への方向に垂直な平面への, 視点からの透視投影で厳密に判定する "
     "(各多角形を画面上で三角形に分割).",
     "Перекрытие определяется точно перспективной проекцией из глаза на плоскость, "
     "перпендикулярную направлению от "
     "глаза к среднему центру тяжести (каждый многоугольник разрезан на треугольники на экране)."},
    {"Over each overlapping piece the depths of the two planes are compared at the piece's corners "
     "(depth is affine "
     "there), which gives the true order; Newell's plane tests are shown beside it.",
     "重なる各部分で, 2 つの平面の奥行きをその部分の角で比べる (そこでは奥行きはアフィン). "
     "これが本当の前後関係を与える. "
     "Newell の平面テストも並べて示す.",
     "На каждом перекрывающемся куске глубины двух плоскостей сравниваются в углах куска (там "
     "глубина аффинна), "
     "что даёт истинный порядок; рядом показаны плоскостные тесты Newell."},
    {"A pair conflicts when the centroid order is wrong, they interpenetrate, one wraps around the "
     "other, or they lie on "
     "a cycle (polygons have size, so one centroid cannot order them).",
     "重心の順序が誤っているとき, 貫通しているとき, 一方が他方を包むとき, または三すくみのとき, "
     "その組は矛盾する "
     "(ポリゴンには「大きさ」があるので, 重心だけでは前後関係が定まらない).",
     "Пара конфликтует, если порядок центров тяжести неверен, они взаимно проникают, одна "
     "охватывает другую или они "
     "лежат на цикле (у многоугольников есть размер, поэтому один центр тяжести не упорядочивает "
     "их)."},
    // The two plane tests of a pair, each translated on its own (the shorter pattern below would
    // take both as one test).
    {"{0}-{1}: overlap on screen; over the overlap {2}; plane tests: {3}, {5} — {4}",
     "{0}-{1}: 画面上で重なる. 重なりでは {2}. 平面テスト: {3}, {5} — {4}",
     "{0}-{1}: перекрываются на экране; на перекрытии {2}; плоскостные тесты: {3}, {5} — {4}"},
    {"{0}-{1}: overlap on screen; over the overlap {2}; plane tests: {3} — {4}",
     "{0}-{1}: 画面上で重なる. 重なりでは {2}. 平面テスト: {3} — {4}",
     "{0}-{1}: перекрываются на экране; на перекрытии {2}; плоскостные тесты: {3} — {4}"},
    {"{0} is behind {1}", "{0} が {1} の奥", "{0} за {1}"},
    {"nearer one changes: they interpenetrate", "手前のものが入れ替わる: 貫通している",
     "ближний меняется: они взаимно проникают"},
    {"nearer one differs between parts: one wraps around the other",
     "部分によって手前のものが異なる: 一方が他方を包んでいる",
     "ближний различается по частям: один охватывает другой"},
    {"{0} entirely behind the plane of {1}", "{0} は {1} の平面の完全に奥",
     "{0} целиком за плоскостью {1}"},
    {"{0} entirely in front of the plane of {1}", "{0} は {1} の平面の完全に手前",
     "{0} целиком перед плоскостью {1}"},
    {"{0} on both sides of the plane of {1}", "{0} は {1} の平面の両側にある",
     "{0} по обе стороны плоскости {1}"},
    {"the centroid order is right", "重心の順序で正しい", "порядок центров тяжести верен"},
    {"CONFLICT: they lie on a cycle of overlaps (三すくみ): each polygon must be drawn before the "
     "next, around the cycle, "
     "so no order of whole polygons is right",
     "矛盾: 三すくみ. 各多角形を次のものより先に描かねばならず, それが一巡するので, "
     "多角形単位のどの順序も正しくない",
     "КОНФЛИКТ: они лежат на цикле перекрытий: каждый многоугольник нужно рисовать раньше "
     "следующего по циклу, "
     "поэтому никакой порядок целых многоугольников не верен"},
    {"CONFLICT: they interpenetrate (貫通): over their overlap the nearer polygon changes inside "
     "one piece, so no order of "
     "whole polygons is right",
     "矛盾: 貫通している. 重なりの一つの部分の中で手前の多角形が入れ替わるので, "
     "多角形単位のどの順序も正しくない",
     "КОНФЛИКТ: они взаимно проникают: на их перекрытии ближний многоугольник меняется внутри "
     "одного куска, поэтому "
     "никакой порядок целых многоугольников не верен"},
    {"CONFLICT: over their overlap {0} is nearer everywhere, but its centroid is farther than "
     "{1}'s, "
     "so the centroid order draws {2} first and {3} paints over it",
     "矛盾: 重なりではどこでも {0} が手前だが, その重心は {1} の重心より奥にあるので, "
     "重心の順では {2} を先に描き, {3} がその上に描かれてしまう",
     "КОНФЛИКТ: на перекрытии {0} везде ближе, но его центр тяжести дальше, чем у {1}, поэтому "
     "порядок по центрам тяжести рисует {2} первым, и {3} закрашивает его"},
    {"CONFLICT: over their overlap {0} is nearer everywhere, but its centroid is as far as {1}'s, "
     "so the centroid order draws {2} first and {3} paints over it",
     "矛盾: 重なりではどこでも {0} が手前だが, その重心は {1} の重心と同じ奥行きなので, "
     "重心の順では {2} を先に描き, {3} がその上に描かれてしまう",
     "КОНФЛИКТ: на перекрытии {0} везде ближе, но его центр тяжести так же далеко, как у {1}, "
     "поэтому порядок по центрам тяжести рисует {2} первым, и {3} закрашивает его"},
    {"CONFLICT: one wraps around the other (a concave polygon): part of the overlap has one in "
     "front, part the other, so no order of whole polygons is right",
     "矛盾: 一方が他方を包んでいる (凹ポリゴン). 重なりの一部では一方が, 残りでは他方が手前なので, "
     "多角形単位のどの順序も正しくない",
     "КОНФЛИКТ: один охватывает другой (невыпуклый многоугольник): на части перекрытия впереди "
     "один, на части — другой, поэтому никакой порядок целых многоугольников не верен"},
    // vectors: parallel a and b.
    {"a and b are parallel (a × b = 0): the points 0, a, b are collinear and span no plane, so "
     "there is no unit normal.",
     "a と b は平行 (a × b = 0): 点 0, a, b は一直線上にあって平面を張らないので, 単位法線はない.",
     "a и b параллельны (a × b = 0): точки 0, a, b лежат на одной прямой и не задают плоскость, "
     "поэтому единичной нормали нет."},
    // Numeric backends (--precision): the Backend note, one sentence per line, and the warnings.
    {"Answers computed in {0} ({1}, {2}-bit significand, unit roundoff {3}, about {4} decimal "
     "digits); "
     "values only, no derivation steps (--precision exact gives them).",
     "{0} で計算した解答 (`{1}`, 仮数 {2} ビット, 単位丸め誤差 {3}, 10 進で約 {4} 桁). 値だけで, "
     "導出の手順はない "
     "(`--precision exact` で手順が出る).",
     "Ответы вычислены в {0} (`{1}`, мантисса {2} бит, единица округления {3}, около {4} "
     "десятичных "
     "знаков); только значения, без шагов вывода (их даёт `--precision exact`)."},
    {"Answers computed in exact (GiNaC: rationals and radicals, no rounding anywhere).",
     "厳密計算 (`GiNaC`: 有理数と根号, 丸めは一切ない) で計算した解答.",
     "Ответы вычислены точно (`GiNaC`: рациональные числа и радикалы, без округлений)."},
    {"exact (GiNaC: rationals and radicals, no rounding anywhere)",
     "厳密計算 (`GiNaC`: 有理数と根号, 丸めは一切ない)",
     "точно (`GiNaC`: рациональные числа и радикалы, без округлений)"},
    {"The kind {0} has no numeric path; it was solved exactly ({1}).",
     "種類 `{0}` には数値計算の経路がないので, 厳密に解いた ({1}).",
     "У вида `{0}` нет численного пути; он решён точно ({1})."},
    {"{0}: decided by exact arithmetic on the given numbers (the {1} computation could not settle "
     "it).",
     "{0}: 与えられた数の厳密計算で決めた ({1} の計算では決められなかった).",
     "{0}: решено точной арифметикой на данных числах (вычисление в {1} не смогло это решить)."},
    {"facing", "表裏", "ориентация"},
    {"w_c > 0 and inside", "w_c > 0 と内側かどうか", "w_c > 0 и «внутри»"},
    {"whether the normal is zero", "法線がゼロかどうか", "равна ли нормаль нулю"},
    {"whether a and b are parallel", "a と b が平行かどうか", "параллельны ли a и b"},
    {"{0}: computed exactly on the given numbers (the floating-point computation could not tell "
     "it from zero); only its final rounding is in it.",
     "{0}: 与えられた数の厳密計算で求めた (浮動小数点の計算では 0 と区別できなかった). "
     "誤差は最後の丸め"
     "だけ.",
     "{0}: вычислено точно на данных числах (вычисление с плавающей точкой не отличило это от "
     "нуля); "
     "в нём только последнее округление."},
    {"the normal", "法線", "нормаль"},
    {"angle = atan2(‖a × b‖, a·b).", "角度 = atan2(‖a × b‖, a·b).", "угол = atan2(‖a × b‖, a·b)."},
    {"facing: the sign of D_f, proven by its rounding-error bound or else computed exactly.",
     "表裏: D_f の符号. 丸め誤差の上界で確かめ, 確かめられなければ厳密に計算する.",
     "ориентация: знак D_f, доказанный оценкой ошибки округления или иначе вычисленный точно."},
    {"inverse by LU with partial pivoting.", "逆行列は部分ピボット選択付き LU 分解で求めた.",
     "обратная матрица — LU-разложением с частичным выбором ведущего элемента."},
    {"inverse = A₁⁻¹·…·Aₙ⁻¹.", "逆行列 = A₁⁻¹·…·Aₙ⁻¹.", "обратная матрица = A₁⁻¹·…·Aₙ⁻¹."},
    {"plane = (n, n·p₀), not rescaled; distance = |n̂·p₀|.",
     "平面 = (n, n·p₀) (係数は約さない), 距離 = |n̂·p₀|.",
     "плоскость = (n, n·p₀) без масштабирования; расстояние = |n̂·p₀|."},
    {"z = (d − a·xₛ − b·yₛ)/c (the plane method).",
     "z = (d − a·xₛ − b·yₛ)/c (平面の方程式による方法).",
     "z = (d − a·xₛ − b·yₛ)/c (метод плоскости)."},
    {"z by barycentric interpolation (stable fallback).",
     "z は重心座標による補間で求めた (安定な代替法).",
     "z найдено барицентрической интерполяцией (устойчивая замена)."},
    {"{0} is ill-conditioned ({1}): {2}; solve with --precision exact for the exact value.",
     "{0} は条件が悪い ({1}): {2}. 厳密な値は `--precision exact` で解くこと.",
     "{0} плохо обусловлено ({1}): {2}; точное значение даёт решение с `--precision exact`."},
    {"w_c ≤ 0: no NDC or window position.", "w_c ≤ 0: NDC もウィンドウ上の位置もない.",
     "w_c ≤ 0: нет ни NDC, ни положения в окне."},
    {"the normal's direction", "法線の向き", "направление нормали"},
    {"a × b (and with it the area, sin θ and the angle)", "a × b (と, それに従う面積, sin θ, 角度)",
     "a × b (а с ним площадь, sin θ и угол)"},
    {"a · b (and with it cos θ)", "a · b (と, それに従う cos θ)", "a · b (а с ним cos θ)"},
    {"the plane's normal", "平面の法線", "нормаль плоскости"},
    {"z at this pixel", "この画素の z", "z в этом пикселе"},
    {"the total (twice the projected area), and λ and z with it",
     "合計 (投影した面積の 2 倍) と, それに従う λ と z",
     "сумма (удвоенная площадь проекции), а с ней λ и z"},
    {"w_c (and the NDC divided by it)", "w_c (と, それで割った NDC)",
     "w_c (и NDC, делённые на него)"},
    {"the inverse (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)", "逆行列 (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)",
     "обратная матрица (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)"},
    {"{0} keeps no correct digit", "{0} では正しい桁が残らない",
     "в {0} не остаётся ни одной верной цифры"},
    {"{0} keeps about {1} of its {2} digits", "{0} では {2} 桁のうち約 {1} 桁が残る",
     "в {0} остаётся около {1} из {2} цифр"},
    {"c ≈ 0 (κ_c ≈ {0}); the plane method would keep {1} digits of z, so z = Σ λᵢ zᵢ with λᵢ from "
     "the "
     "edge functions at the pixel is used: for a pixel inside the triangle it stays within the "
     "vertices' "
     "depths.",
     "c ≈ 0 (κ_c ≈ {0}). 平面の方程式では z が {1} 桁しか残らないので, 画素での辺関数から求めた λᵢ "
     "による "
     "z = Σ λᵢ zᵢ を使う. 三角形の内側の画素ではこの値は頂点の奥行きの範囲内にある.",
     "c ≈ 0 (κ_c ≈ {0}); метод плоскости сохранил бы {1} цифр z, поэтому используется z = Σ λᵢ zᵢ "
     "с λᵢ "
     "из рёберных функций в пикселе: для пикселя внутри треугольника оно остаётся в пределах "
     "глубин "
     "вершин."},
    {"some inputs exceed the range of {0} and became infinite; the values computed from them are "
     "meaningless, and every discrete answer was decided on the exact inputs.",
     "一部の入力は {0} の範囲を超えて無限大になった. それから計算した値は意味をもたないが, "
     "離散的な答えはすべて"
     "厳密な入力で決めた.",
     "некоторые входные данные выходят за диапазон {0} и стали бесконечными; вычисленные из них "
     "значения "
     "бессмысленны, а каждый дискретный ответ решён по точным входным данным."},
    {"some inputs are below the normal range of {0} and were rounded to subnormal numbers or to 0: "
     "the "
     "values computed from them keep few or none of their digits, and every discrete answer was "
     "decided "
     "on the exact inputs.",
     "一部の入力は {0} の正規化数の範囲より小さく, 非正規化数か 0 に丸められた. "
     "それから計算した値には正しい桁が"
     "ほとんど残らないが, 離散的な答えはすべて厳密な入力で決めた.",
     "некоторые входные данные меньше нормального диапазона {0} и округлены до субнормальных чисел "
     "или до 0: "
     "вычисленные из них значения сохраняют мало верных цифр или ни одной, а каждый дискретный "
     "ответ решён "
     "по точным входным данным."},
    {"some values exceed the range of {0} and are infinite; exact answers are computed up to "
     "about 1.8·10³⁰⁸ (the range of a double).",
     "一部の値は {0} の範囲を超えて無限大になった. 厳密計算の答えは約 1.8·10³⁰⁸ (double の範囲) "
     "まで求められる.",
     "некоторые значения выходят за диапазон {0} и равны бесконечности; точные ответы "
     "вычисляются до примерно 1,8·10³⁰⁸ (диапазон double)."},
    {"some values are not a number: an operation without a value in {0} (0/0 or ∞ − ∞, after a "
     "cancellation or an overflow); solve with --precision exact for the exact values.",
     "一部の値は非数になった: {0} で値をもたない演算 (桁落ちやオーバーフローの後の 0/0 や ∞ − ∞) "
     "による. 厳密な値は `--precision exact` で求められる.",
     "некоторые значения не являются числом: операция без значения в {0} (0/0 или ∞ − ∞ после "
     "потери точности или переполнения); точные значения даёт `--precision exact`."},
    {"some values are below the normal range of {0} (subnormal, or flushed to 0): they keep few or "
     "none of "
     "their digits.",
     "一部の値は {0} の正規化数の範囲より小さい (非正規化数か 0): 正しい桁はほとんど残らない.",
     "некоторые значения меньше нормального диапазона {0} (субнормальные или обращены в 0): в них "
     "мало "
     "верных цифр или нет ни одной."},
    // Text not split into sentences above.
    {"depth:", "奥行き:", "глубина:"},
    {"frame:", "フレーム:", "кадр:"},
    // Handedness as a course convention (issue 16).
    {"OpenGL, left-handed: eye space looking down +z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
     "with near → −1, window origin bottom-left",
     "OpenGL, 左手系: 視点座標系は +z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
     "1]³ "
     "(near → −1), ウィンドウの原点は左下",
     "OpenGL, левая система: система координат вида с взглядом вдоль +z, столбцы-векторы (p′ = "
     "M·p), "
     "куб NDC [−1, 1]³ (near → −1), начало окна внизу слева"},
    {"OpenGL, left-handed: eye space looking down +z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
     "with near → −1, window origin bottom-left; angles in {0}",
     "OpenGL, 左手系: 視点座標系は +z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
     "1]³ "
     "(near → −1), ウィンドウの原点は左下; 角度の単位は{0}",
     "OpenGL, левая система: система координат вида с взглядом вдоль +z, столбцы-векторы (p′ = "
     "M·p), "
     "куб NDC [−1, 1]³ (near → −1), начало окна внизу слева; углы в {0}"},
    {"Processing, left-handed: eye space looking down +z, OpenGL's NDC cube [−1, 1]³, column "
     "vectors, "
     "window origin top-left with y pointing down",
     "Processing, 左手系: 視点座標系は +z 方向を見る, OpenGL の正規化視体積 [−1, 1]³, 列ベクトル, "
     "ウィンドウの原点は左上で y は下向き",
     "Processing, левая система: система координат вида с взглядом вдоль +z, куб NDC [−1, 1]³ как "
     "в "
     "OpenGL, столбцы-векторы, начало окна вверху слева, y направлена вниз"},
    {"Processing, left-handed: eye space looking down +z, OpenGL's NDC cube [−1, 1]³, column "
     "vectors, "
     "window origin top-left with y pointing down; angles in {0}",
     "Processing, 左手系: 視点座標系は +z 方向を見る, OpenGL の正規化視体積 [−1, 1]³, 列ベクトル, "
     "ウィンドウの原点は左上で y は下向き; 角度の単位は{0}",
     "Processing, левая система: система координат вида с взглядом вдоль +z, куб NDC [−1, 1]³ как "
     "в "
     "OpenGL, столбцы-векторы, начало окна вверху слева, y направлена вниз; углы в {0}"},
    {"Left-handed coordinates", "左手系の座標", "Левая система координат"},
    {"Left-handed coordinates; angles in {0}", "左手系の座標; 角度の単位は{0}",
     "Левая система координат; углы в {0}"},
    {"In left-handed coordinates the side from which p₀, p₁, p₂ run counter-clockwise is the side "
     "of "
     "e₁ × e₀ = −(e₀ × e₁): the right-handed formula e₀ × e₁ gives the opposite normal, that of "
     "the "
     "mirror image.",
     "左手系では p₀, p₁, p₂ が反時計回りに見える側は e₁ × e₀ = −(e₀ × e₁) の側である: 右手系の式 "
     "e₀ × e₁ は逆向きの法線, すなわち鏡像の法線を与える.",
     "В левой системе координат сторона, откуда p₀, p₁, p₂ идут против часовой стрелки, — это "
     "сторона e₁ × e₀ = −(e₀ × e₁): формула правой системы e₀ × e₁ даёт противоположную нормаль, "
     "нормаль зеркального образа."},
    {"In left-handed coordinates the counter-clockwise side's normal is the right-handed sum with "
     "its "
     "sign changed (e₁ × e₀ for a triangle).",
     "左手系では反時計回りに見える側の法線は右手系の和の符号を変えたもの (三角形では e₁ × e₀).",
     "В левой системе координат нормаль стороны, откуда обход идёт против часовой стрелки, — это "
     "сумма правой системы с обратным знаком (для треугольника e₁ × e₀)."},
    {"These coordinates are left-handed: AC × AB points to the side from which A, B, C run "
     "counter-clockwise (the front).",
     "この座標は左手系である: AC × AB は A, B, C が反時計回りに見える側 (表) を向く.",
     "Эти координаты — левая система: AC × AB направлен в ту сторону, откуда A, B, C идут против "
     "часовой стрелки (лицевая сторона)."},
    {"Read in a right-handed frame, the same numbers describe the mirror image, whose front normal "
     "is "
     "AB × AC = −(AC × AB).",
     "右手系で読むと同じ数値は鏡像を表し, その表の法線は AB × AC = −(AC × AB) である.",
     "Прочитанные в правой системе, те же числа описывают зеркальный образ, лицевая нормаль "
     "которого AB × AC = −(AC × AB)."},
    {"Read in right-handed coordinates the same numbers describe the mirror image: its normal e₀ × "
     "e₁ "
     "is −n, D_f changes sign, and the eye would see the other side.",
     "右手系で読むと同じ数値は鏡像を表す: その法線 e₀ × e₁ は −n で, D_f の符号が変わり, "
     "視点からは反対側が見える.",
     "Прочитанные в правой системе, те же числа описывают зеркальный образ: его нормаль e₀ × e₁ "
     "равна −n, D_f меняет знак, и глаз увидел бы другую сторону."},
    {"The handedness decides the answer.", "答えは座標系の右手・左手で決まる.",
     "Ответ зависит от ориентации системы координат."},
    {"Left-handed, the camera looks down +z.", "左手系では, カメラは +z 方向を見る.",
     "В левой системе камера смотрит вдоль +z."},
    {"A right-handed camera at the same place (gluLookAt, looking down −z) has the x and z rows "
     "negated: V_right = diag(−1, 1, −1, 1)·V.",
     "同じ位置の右手系のカメラ (gluLookAt, −z 方向を見る) では x と z の行の符号が逆になる: "
     "V_right = diag(−1, 1, −1, 1)·V.",
     "У камеры правой системы в том же месте (gluLookAt, взгляд вдоль −z) строки x и z меняют "
     "знак: "
     "V_right = diag(−1, 1, −1, 1)·V."},
    {"Left-handed, looking down +z: z = n maps to z_ndc = −1 and z = f to +1, so near and far are "
     "also "
     "the z coordinates of their planes.",
     "左手系で +z 方向を見る: z = n は z_ndc = −1 に, z = f は +1 に写るので, near と far "
     "はそれぞれの"
     "平面の z 座標でもある.",
     "Левая система, взгляд вдоль +z: z = n переходит в z_ndc = −1, а z = f — в +1, так что near и "
     "far "
     "— это и z-координаты их плоскостей."},
    {"The right-handed matrix (looking down −z) is this one with its third column negated: the "
     "same "
     "view volume with the z axis reversed.",
     "右手系の行列 (−z 方向を見る) はこの行列の第 3 列の符号を変えたもの: 同じ視体積で z "
     "軸の向きだけが"
     "逆である.",
     "Матрица правой системы (взгляд вдоль −z) — эта же матрица с третьим столбцом с обратным "
     "знаком: "
     "тот же видимый объём с обращённой осью z."},
    {"Read in right-handed coordinates (gluLookAt and the right-handed projection on the same "
     "numbers), "
     "the chain is P_right·diag(−1, 1, 1, 1)·V_right instead: the view coordinates' x changes sign "
     "between V and P, so for a view volume symmetric in x (l = −r) the picture is mirrored left "
     "to "
     "right.",
     "右手系で読むと (同じ数値に gluLookAt と右手系の投影を使うと), 連鎖は代わりに "
     "P_right·diag(−1, 1, 1, 1)·V_right になる: V と P の間で視点座標の x の符号が変わるので, x "
     "について"
     "対称な視体積 (l = −r) では画像が左右反転する.",
     "В правой системе координат (gluLookAt и проекция правой системы на тех же числах) цепочка "
     "вместо этого равна P_right·diag(−1, 1, 1, 1)·V_right: координата x вида меняет знак между V "
     "и P, "
     "поэтому для видимого объёма, симметричного по x (l = −r), изображение зеркально отражается "
     "слева направо."},
    {"Mind the order of the cross product: projection coordinates (x, y on the screen, z the depth "
     "away "
     "from the eye) are left-handed, as this course's eye space is, so the front normal of a "
     "triangle "
     "ABC is AC × AB (the order used by default).",
     "外積の順序に注意: 投影座標系 (画面上の x, y と視点から奥へ向かう奥行き z) "
     "はこのコースの視点座標系と"
     "同じく左手系なので, 三角形 ABC の表の法線は AC × AB (既定の順序) である.",
     "Следите за порядком векторного произведения: координаты проекции (x, y на экране, z — "
     "глубина "
     "от глаза) образуют левую систему, как и система координат вида в этом курсе, поэтому лицевая "
     "нормаль треугольника ABC — AC × AB (порядок по умолчанию)."},
};

}  // namespace

std::span<const Phrase> note_phrases() { return kPhrases; }

}  // namespace frustum
