#include "app/handout_words.hpp"

#include <cctype>
#include <map>

namespace fx::handout {
namespace {

const Words kEnglish{
    .language = "en",
    .languageName = "English",
    .handout = "fxlab handout",
    .contents = "Contents",
    .step = "Step",
    .facts = "Facts",
    .inspector = "In the inspector",
    .frameGraph = "Frame graph",
    .passTable = "Pass table",
    .sameFrame = "The frame graph and the passes are those of step ",
    .sameFrameEnd = ".",
    .sameForAllPasses = "for every pass",
    .modelledColumn =
        "MB/taps: the cost model's memory traffic at 1920x1080 in MB / texture lookups per pixel written (docs/frame-graph.md)",
    .bench = "What accuracy costs, measured by the bench",
    .benchMeasured = "Measured by ./fxlab bench at ",
    .benchMissing =
        "No bench results were found for this lesson: run ./fxlab bench first, or make the handout with --with-bench. The lesson's own text below may show earlier measurements.",
    .knob = "knob",
    .value = "value",
    .costCopies = "frame (full-screen copies)",
    .costMs = "frame (ms)",
    .reference = "reference",
    .current = "default",
    .englishOnly = "This part is in English only (lesson.md).",
    .picturesMade = "Pictures: ",
    .frameOf = " of a headless run at a fixed time step",
    .renderedBy = "rendered by ",
    .lessons = "Lessons",
    .stepsCount = "steps",
};

const Words kJapanese{
    .language = "ja",
    .languageName = "日本語",
    .handout = "fxlab ハンドアウト",
    .contents = "目次",
    .step = "ステップ",
    .facts = "情報",
    .inspector = "インスペクターで見るテクスチャ",
    .frameGraph = "フレームグラフ",
    .passTable = "パステーブル",
    .sameFrame = "フレームグラフとパスはステップ ",
    .sameFrameEnd = " と同じです。",
    .sameForAllPasses = "すべてのパスで同じ",
    .modelledColumn =
        "MB/タップ：コストモデルによる 1920x1080 でのメモリ転送量（MB）／書き込む 1 ピクセルあたりのテクスチャ参照数（docs/frame-graph.md）",
    .bench = "精度のコスト（ベンチの計測）",
    .benchMeasured = "./fxlab bench による計測：",
    .benchMissing =
        "このレッスンのベンチ結果が見つかりません。先に ./fxlab bench を実行するか、--with-bench を付けてハンドアウトを作ってください。下のレッスン本文には以前の計測が載っていることがあります。",
    .knob = "ノブ",
    .value = "値",
    .costCopies = "フレーム（フルスクリーンコピー）",
    .costMs = "フレーム（ms）",
    .reference = "リファレンス",
    .current = "既定値",
    .englishOnly = "この部分は英語のみです（lesson.md）。",
    .picturesMade = "図：",
    .frameOf = "（固定タイムステップのヘッドレス実行）",
    .renderedBy = "描画：",
    .lessons = "レッスン",
    .stepsCount = "ステップ",
};

}  // namespace

const Words& wordsFor(const std::string& language) {
    return language == "ja" ? kJapanese : kEnglish;
}

std::string columnName(const std::string& key, const std::string& language) {
    static const std::map<std::string, std::pair<std::string, std::string>> known{
        {"name", {"pass", "パス"}},
        {"status", {"status", "状況"}},
        {"reason", {"why it did not run", "実行しなかった理由"}},
        {"timeMs", {"ms", "ms"}},
        {"timingMethod", {"timed by", "計測方法"}},
        {"reads", {"reads", "読むテクスチャ"}},
        {"writes", {"writes", "書くテクスチャ"}},
        {"stateLeft", {"state left for the next pass", "次のパスに残したステート"}},
        {"stateInherited", {"state inherited", "引き継いだステート"}},
        {"modelledMbTaps", {"MB/taps", "MB/タップ"}},
    };
    if (auto it = known.find(key); it != known.end())
        return language == "ja" ? it->second.second : it->second.first;
    std::string words;
    for (char c : key) {
        if (std::isupper(static_cast<unsigned char>(c))) {
            words += ' ';
            words += char(std::tolower(static_cast<unsigned char>(c)));
        } else {
            words += c == '_' ? ' ' : c;
        }
    }
    return words;
}

}  // namespace fx::handout
