#include "solver/derivation/i18n.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace frustum {

namespace {

// English → Japanese, in the vocabulary of the seeds' lecture notes (法線, 視点, 投影, 裏面…).
const std::vector<std::pair<std::string_view, std::string_view>>& catalogue() {
  static const std::vector<std::pair<std::string_view, std::string_view>> table = [] {
    std::vector<std::pair<std::string_view, std::string_view>> t = {
        // Step titles.
        {"A point through both, then the divide by W′", "両方を通る点と W′ による除算"},
        {"Angle", "角度"},
        {"Area of the parallelogram", "平行四辺形の面積"},
        {"Back-face culling alone?", "バックフェースカリングだけで十分か?"},
        {"Bounding box of the pixel centres", "画素中心のバウンディングボックス"},
        {"Camera axes (left-handed, looking down +z)", "カメラの軸 (左手系, +z 方向を見る)"},
        {"Camera axes (right-handed, looking down −z)", "カメラの軸 (右手系, −z 方向を見る)"},
        {"Centroids", "重心"},
        {"Check each overlapping pair (Newell)", "重なる組を調べる (Newell)"},
        {"Clip against", "クリップ:"},
        {"Clip coordinates", "クリップ座標"},
        {"Clipped segment", "クリップ後の線分"},
        {"Closed and consistently oriented", "閉じていて向きがそろっている"},
        {"Composite (first step applied first)", "合成変換 (最初のステップを最初に適用)"},
        {"Convex?", "凸か?"},
        {"Cosine of the angle", "角度の余弦"},
        {"Covered pixels, row by row", "覆われる画素 (行ごと)"},
        {"Cross product", "外積"},
        {"Degenerate polygon", "退化した多角形"},
        {"Degenerate triangle", "退化した三角形"},
        {"Depth along the view direction", "視線方向の奥行き"},
        {"Depth at the pixel", "画素での奥行き (z 値)"},
        {"Depth: distance from the eye", "奥行き: 視点からの距離"},
        {"Discriminant", "判別式"},
        {"Distance from the origin", "原点からの距離"},
        {"Distance of the projection plane", "投影面までの距離"},
        {"Dot product", "内積"},
        {"Draw back to front (farthest centroid first)", "奥から手前へ描く (重心が最も遠いものから)"},
        {"Edge classes", "稜線の分類"},
        {"Edge function", "エッジ関数"},
        {"Edge vectors", "辺ベクトル"},
        {"Final frame buffer", "最終のフレームバッファ"},
        {"Front or back per face", "各面の表裏"},
        {"Front or back", "表か裏か"},
        {"Geometry: model → world → clip → window", "幾何: モデル → ワールド → クリップ → ウィンドウ"},
        {"Hidden edges: the back–back edges", "隠れる稜線: 裏と裏の辺"},
        {"Initialise", "初期化"},
        {"Inside the view volume?", "視野錐台の内側か?"},
        {"Inverse", "逆行列"},
        {"Is the pixel inside the projected triangle?", "画素は投影された三角形の内側か?"},
        {"Iteration", "反復"},
        {"Nearly edge-on triangle: barycentric fallback", "ほぼ真横から見た三角形: 重心座標による代替"},
        {"Nearly edge-on triangle", "ほぼ真横から見た三角形"},
        {"Nearly parallel edges", "ほぼ平行な辺"},
        {"No inverse", "逆行列なし"},
        {"No plane", "平面なし"},
        {"Non-planar polygon", "平面でない多角形"},
        {"Normal (n = e₀ × e₁, counter-clockwise = front)", "法線 (n = e₀ × e₁, 反時計回り = 表)"},
        {"Normal", "法線"},
        {"Nothing is left", "何も残らない"},
        {"Nothing is visible", "何も見えない"},
        {"Outcode of p", "p のアウトコード"},
        {"Outcode of q", "q のアウトコード"},
        {"Perspective divide", "透視除算"},
        {"Plane through A with normal n̂", "A を通り法線 n̂ の平面"},
        {"Plane through p₀ with normal n", "p₀ を通り法線 n の平面"},
        {"Polygon", "多角形"},
        {"Repeated vertex", "重複した頂点"},
        {"Sign decided exactly", "符号は厳密に判定"},
        {"Silhouette (輪郭線): the front–back edges", "輪郭線: 表と裏の境の辺"},
        {"Similar triangles", "相似な三角形"},
        {"Sine of the angle", "角度の正弦"},
        {"The frustum of perspective(fovy, aspect, near, far)", "perspective(fovy, aspect, near, far) の視錐台"},
        {"Transform the solid (first step applied first)", "立体を変換 (最初のステップを最初に適用)"},
        {"Transform a point", "点を変換"},
        {"Trivial accept? (both codes 0)", "自明な採用? (両方のコードが 0)"},
        {"Trivial reject? (a common outside bit)", "自明な棄却? (共通の外側ビット)"},
        {"Unit normal of the plane through 0, a, b", "0, a, b を通る平面の単位法線"},
        {"Unit normal", "単位法線"},
        {"Vertices snapped to the sub-pixel grid", "頂点をサブピクセル格子に丸める"},
        {"View matrix", "視野変換行列"},
        {"View vector from p₀ to the eye", "p₀ から視点への視線ベクトル"},
        {"Viewport", "ビューポート変換"},
        {"World to view coordinates", "ワールド座標から視点座標へ"},
        {"Zero normal in this precision", "この精度では法線がゼロ"},
        {"Normalize the view volume", "視野錐台の正規化"},
        {"Perspective of the normalized volume", "正規化された錐台の透視変換"},
        {"Conventions", "規約"},
        {"Backend", "計算方式 (精度)"},
        {"Conventions and model", "規約とモデル"},
        {"Depth precision", "奥行きの精度"},
        {"Edge-on faces", "真横から見た面"},
        {"Orientation", "向き"},
        {"Pixels and the fill rule", "画素と塗りつぶし規則"},
        {"Pixels, orientation and the depth test", "画素, 向きと奥行きテスト"},
        {"Projection coordinates are left-handed", "投影座標系は左手系"},
        {"The solid", "立体"},
        {"Winding in a left-handed frame", "左手系での頂点の回り順"},
        {"Warning", "警告"},
        // Grader interface.
        {"Student", "学生"},
        {"Score", "得点"},
        {"Problem", "問題"},
        {"Answer", "解答"},
        {"Answers", "解答"},
        {"Verdict", "判定"},
        {"You wrote", "あなたの解答"},
        {"Expected", "正解"},
        {"How to get it", "求め方"},
        {"Feedback", "フィードバック"},
        {"Derivation", "導出"},
        {"Common mistake", "よくある誤り"},
        {"Where it goes wrong", "誤りの生じるステップ"},
        {"credit carried forward from your earlier answer", "前の解答からの継続点 (誤りの持ち越し)"},
        {"error", "エラー"},
        {"warning", "警告"},
        {"correct", "正解"},
        {"incorrect", "不正解"},
        {"partial", "部分点"},
        {"unparseable", "解釈できない"},
        {"missing", "未解答"},
        // Misconceptions (grader feedback): their names and what they tell the student.
        {"reversed cross product", "外積の順序が逆"},
        {"unnormalised normal", "法線を正規化していない"},
        {"plane through the origin", "原点を通る平面"},
        {"missing perspective divide", "透視除算 (w による除算) の忘れ"},
        {"degrees taken as radians", "度をラジアンとして計算"},
        {"fovx for fovy", "fovy の代わりに fovx"},
        {"near/far sign", "near/far の符号"},
        {"composition in the wrong order", "変換の合成順序が逆"},
        {"view vector reversed", "視線ベクトルの向きが逆"},
        {"triangle instead of parallelogram", "平行四辺形ではなく三角形"},
        {"radians instead of degrees", "度ではなくラジアン"},
        {"cos for sin", "sin の代わりに cos"},
        {"You took", "あなたが計算したのは"},
        {"The projection coordinates are left-handed (seed 001), so the front normal here is",
         "投影座標系は左手系 (seed 001) なので, ここでの表向きの法線は"},
        {"That is n itself: a unit normal is n divided by its length ‖n‖.",
         "それは n そのものです. 単位法線は n をその長さ ‖n‖ で割ったものです."},
        {"Your plane passes through the origin: n·(p − A) = 0 gives d = n·A, not 0.",
         "あなたの平面は原点を通っています. n·(p − A) = 0 から d = n·A であり, 0 ではありません."},
        {"You skipped the divide by w: NDC = (x_c, y_c, z_c) / w_c.",
         "w による除算が抜けています. NDC = (x_c, y_c, z_c) / w_c です."},
        {"Your numbers come from using the angle in degrees as if it were radians.",
         "度で与えられた角度をラジアンとして使った値になっています."},
        {"You used the angle as the horizontal field of view; perspective() takes the vertical one (fovy).",
         "角度を水平方向の視野角として使っています. perspective() が受け取るのは垂直方向の視野角 (fovy) です."},
        {"near and far are distances in front of the eye (positive); you used the planes' z coordinates −n and −f.",
         "near と far は視点の前方への距離 (正の値) です. あなたは平面の z 座標 −n と −f を使っています."},
        {"You multiplied the steps in the order they are applied (A₁·A₂·…): with column vectors the "
         "step applied first stands rightmost, M = …·A₂·A₁ (seed 002: P′ = A₃A₂A₁P).",
         "適用する順に行列を掛けています (A₁·A₂·…). 列ベクトルでは最初に適用する変換が一番右に来ます: "
         "M = …·A₂·A₁ (seed 002: P′ = A₃A₂A₁P)."},
        {"You took e₁ × e₀: with the vertices counter-clockwise seen from the front, the front "
         "normal is n = e₀ × e₁ (seed 003).",
         "e₁ × e₀ を計算しています. 表から見て頂点が反時計回りなので, 表向きの法線は n = e₀ × e₁ です (seed 003)."},
        {"Your view vector points from the eye to the polygon: v = p_eye − pᵢ points from the "
         "polygon to the eye, and that flips the sign of D_f.",
         "あなたの視線ベクトルは視点から多角形へ向いています. v = p_eye − pᵢ は多角形から視点へ向くベクトルで, "
         "向きが逆だと D_f の符号が反転します."},
        {"You computed b × a = −(a × b): the cross product is anti-commutative.",
         "b × a = −(a × b) を計算しています. 外積は反可換です."},
        {"That is half the area: ‖a × b‖ is the parallelogram's area, the triangle's is half of it.",
         "それは面積の半分です. ‖a × b‖ は平行四辺形の面積で, 三角形の面積はその半分です."},
        {"Your angle is in radians; the problem asks for degrees.", "角度がラジアンになっています. 問題は度で求めています."},
        {"That is cos θ = a·b/(‖a‖‖b‖); sin θ uses ‖a × b‖.", "それは cos θ = a·b/(‖a‖‖b‖) です. sin θ には ‖a × b‖ を使います."},
        // Comparison and grading feedback.
        {"no answer given", "解答がありません"},
        {"exactly equal", "完全に一致"},
        {"within tolerance", "許容誤差内"},
        {"there is no such value here", "ここには値がありません"},
        {"there is no such value", "その値は存在しません"},
        {"there is a value here", "ここには値があります"},
        {"the same homogeneous point (a positive multiple)", "同じ同次座標の点 (正の定数倍)"},
        {"it points the opposite way: check the order of the cross product", "向きが逆です. 外積の順序を確かめてください"},
        {"a plane has 4 coefficients", "平面の係数は 4 つです"},
        {"the same plane (equations agree up to a non-zero factor)", "同じ平面 (方程式が 0 でない定数倍を除いて一致)"},
        {"the same set (order does not matter)", "同じ集合 (順序は問いません)"},
        {"the order differs", "順序が違います"},
        {"wrong, but it follows correctly from your own earlier", "誤りですが, あなた自身の前の解答から正しく導かれています:"},
        {"error carried forward", "誤りの持ち越し"},
        {"of the points", "の配点"},
        // Trivial answers and the diagnoses of docs/grading.md.
        {"identity matrix", "単位行列"},
        {"zero vector", "零ベクトル"},
        {"zero matrix", "零行列"},
        {"copied from the given", "問題の値の写し"},
        {"transposed matrix (row- vs column-vector convention)", "転置行列 (行ベクトルと列ベクトルの規約の取り違え)"},
        {"transposed matrix", "転置行列"},
        {"reversed look-at basis", "カメラ基底の向きの反転"},
        {"degrees instead of radians", "ラジアンの代わりに度"},
        {"That is the identity matrix: it leaves every point where it is.", "それは単位行列です. どの点も動かしません."},
        {"Every entry is 0: that takes no computation.", "すべて 0 です. 計算を必要としません."},
        {"The zero vector has no direction: it is no normal.", "零ベクトルには向きがなく, 法線になりません."},
        {"the same segment, its endpoints in the other order", "同じ線分 (端点の順序が逆)"},
        {"the same items (order does not matter)", "同じ要素 (順序は問いません)"},
        {"front", "表"},
        {"back", "裏"},
        {"edge_on", "真横"},
    };
    return t;
  }();
  return table;
}

}  // namespace

std::optional<Lang> parse_lang(std::string_view code) {
  if (code == "en") return Lang::En;
  if (code == "ja") return Lang::Ja;
  return std::nullopt;
}

std::string_view to_string(Lang lang) { return lang == Lang::Ja ? "ja" : "en"; }

std::string tr(std::string_view english, Lang lang) {
  if (lang == Lang::En || english.empty()) return std::string(english);
  const auto& table = catalogue();
  for (const auto& [en, ja] : table)
    if (en == english) return std::string(ja);
  // Phrases inside a longer title ("Clip against x ≤ 1", "Iteration 2: …"), longest first,
  // only at word boundaries so that "Normal" does not eat "Normalize".
  static const std::vector<std::pair<std::string_view, std::string_view>> by_length = [&] {
    auto sorted = table;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    return sorted;
  }();
  const auto is_word = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  std::string out(english);
  for (const auto& [en, ja] : by_length) {
    if (en.size() < 4) continue;  // short words only as whole texts
    std::size_t at = 0;
    while ((at = out.find(en, at)) != std::string::npos) {
      const bool left = at == 0 || !is_word(out[at - 1]);
      const bool right = at + en.size() >= out.size() || !is_word(out[at + en.size()]);
      if (left && right) {
        out.replace(at, en.size(), ja);
        at += ja.size();
      } else {
        at += en.size();
      }
    }
  }
  return out;
}

MathText tr(const MathText& m, Lang lang) {
  if (lang == Lang::En || m.words.empty()) return m;
  MathText out = m;
  const auto is_word = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  for (const std::string& w : m.words) {
    const std::string t = tr(w, lang);
    if (t == w) continue;
    for (std::size_t at = 0; (at = out.unicode.find(w, at)) != std::string::npos;) {
      const bool whole = (at == 0 || !is_word(out.unicode[at - 1])) &&
                         (at + w.size() >= out.unicode.size() || !is_word(out.unicode[at + w.size()]));
      if (whole) {
        out.unicode.replace(at, w.size(), t);
        at += t.size();
      } else {
        at += w.size();
      }
    }
    const std::string from = "\\text{" + latex_text(w) + "}", to = "\\text{" + latex_text(t) + "}";
    for (std::size_t at = 0; (at = out.latex.find(from, at)) != std::string::npos; at += to.size())
      out.latex.replace(at, from.size(), to);
  }
  return out;
}

}  // namespace frustum
