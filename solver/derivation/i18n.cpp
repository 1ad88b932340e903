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
        {"Normal (seed 003: n = e₀ × e₁, counter-clockwise = front)", "法線 (n = e₀ × e₁, 反時計回り = 表)"},
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

}  // namespace frustum
