#pragma once
// The handout's own words (headings, captions, column names) in each language a lesson's text has.
// The lesson's prose comes from its lesson.md and lesson.ja.md; these are only the page's frame. The
// Japanese follows docs/japanese-terms.md (ステップ, 情報, パステーブル, フレームグラフ, インスペクター,
// 精度のコスト, フルスクリーンコピー).
#include <string>

namespace fx::handout {

struct Words {
    std::string language;          // "en", "ja": the page's lang attribute
    std::string languageName;      // how a link to this language reads: "English", "日本語"
    std::string handout;           // "fxlab handout"
    std::string contents;          // the list of steps and parts
    std::string step;              // "Step" (before the number)
    std::string facts;             // the overlay's list of facts
    std::string inspector;         // textures the step's text points at
    std::string frameGraph;        // the frame graph picture
    std::string passTable;         // the pass table
    std::string sameFrame;         // "The frame graph and the passes are those of step " + N
    std::string sameFrameEnd;      // after the number
    std::string sameForAllPasses;  // a column whose value is the same in every row: "for every pass"
    std::string modelledColumn;    // what the pass table's MB/taps column is
    std::string bench;             // the bench's section
    std::string benchMeasured;     // "Measured by ./fxlab bench at " + size + ...
    std::string benchMissing;      // no bench output: how to make it
    std::string knob, value;       // the bench table's first columns
    std::string costCopies;        // its cost column: the frame in full-screen copies
    std::string costMs;            // or in milliseconds, when no copy was timed
    std::string reference;         // the row a knob is compared against
    std::string current;           // the value the lesson starts with
    std::string englishOnly;       // a part of lesson.md that has no translation
    std::string picturesMade;      // how the pictures were made: "Pictures: "
    std::string frameOf;           // "frame N of a headless run at a fixed time step" (N before it)
    std::string renderedBy;        // "rendered by"
    std::string lessons;           // the contents page's title
    std::string stepsCount;        // "steps"
};

// The words for `language`; English for a language it does not know.
const Words& wordsFor(const std::string& language);

// A report key as a column name: the known ones in the page's words, any other one spelled out
// ("trafficBytes" -> "traffic bytes"), so a column the report gains shows without a change here.
std::string columnName(const std::string& key, const std::string& language);

}  // namespace fx::handout
