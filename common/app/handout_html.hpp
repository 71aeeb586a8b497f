#pragma once
// A lesson's markdown as HTML for the handout: the same parse the overlay draws
// (base/markdown_text.hpp), so the page and the overlay cannot read a step's text differently.
// Paragraphs, lists (nested by indent), ### headings, code blocks, tables with their header row;
// inside text **bold**, *emphasis*, `code` and pictures. A link keeps its text only, as in the
// overlay: every link of a lesson's text points into the source tree, which a handout does not carry.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fx::handout {

// Text for HTML: & < > " escaped.
std::string escapeHtml(std::string_view text);

// Where a picture of the text is in the handout: its `src`, from the target written in the markdown.
using PictureSource = std::function<std::string(const std::string& target)>;

// The HTML of a markdown text (a step's section, or any section of lesson.md). Headings inside the
// text become <h`headingLevel`>.
std::string markdownToHtml(std::string_view markdown, const PictureSource& pictures, int headingLevel = 4);

// The picture targets of a text, in order, each once ("../../docs/images/x.png").
std::vector<std::string> pictureTargets(std::string_view markdown);

// The `code` spans of a text outside code blocks, in order, each once: the names a step's text points
// the reader at (a texture to inspect, a parameter, a file).
std::vector<std::string> codeSpans(std::string_view markdown);

}  // namespace fx::handout
