// A lesson's markdown as the handout's HTML (app/handout_html.hpp): the overlay's parse, written out.
#include <gtest/gtest.h>

#include "app/handout_html.hpp"

namespace {

using namespace fx::handout;

std::string html(const std::string& markdown) {
    return markdownToHtml(markdown, [](const std::string& target) { return "figures/" + target; });
}

TEST(HandoutHtml, EscapesEverythingItWrites) {
    EXPECT_EQ(escapeHtml("a < b && \"c\" > d"), "a &lt; b &amp;&amp; &quot;c&quot; &gt; d");
    EXPECT_EQ(html("x < 1 **and <b>** `<i>`"),
              "<p>x &lt; 1 <strong>and &lt;b&gt;</strong> <code>&lt;i&gt;</code></p>\n");
    EXPECT_EQ(html("```\nif (a < b) {}\n```"), "<pre><code>if (a &lt; b) {}</code></pre>\n");
}

TEST(HandoutHtml, InlineStylesAndLinksAsTheOverlayShowsThem) {
    EXPECT_EQ(html("*soft* and [the chapter](../../docs/chapters.md)."),
              "<p><em>soft</em> and the chapter.</p>\n");
}

TEST(HandoutHtml, APictureAloneIsAFigureWithItsCaption) {
    EXPECT_EQ(html("![Step 1: \"x\"](a.png)"),
              "<figure class=\"text-figure\"><img src=\"figures/a.png\" alt=\"Step 1: &quot;x&quot;\">"
              "<figcaption>Step 1: &quot;x&quot;</figcaption></figure>\n");
    EXPECT_EQ(html("see ![](a.png) here"), "<p>see <img src=\"figures/a.png\" alt=\"\"> here</p>\n");
}

TEST(HandoutHtml, ListsNestByIndentAndNumberedOnesKeepTheirStart) {
    EXPECT_EQ(html("- a\n  - b\n  - c\n- d\n\n3. three\n4. four"),
              "<ul>\n<li>a<ul>\n<li>b</li>\n<li>c</li>\n</ul>\n</li>\n<li>d</li>\n</ul>\n"
              "<ol start=\"3\">\n<li>three</li>\n<li>four</li>\n</ol>\n");
    // A bullet list after a numbered one at the same depth is a list of its own.
    EXPECT_EQ(html("1. one\n- dot"), "<ol>\n<li>one</li>\n</ol>\n<ul>\n<li>dot</li>\n</ul>\n");
}

TEST(HandoutHtml, TablesHaveTheirHeaderAndEveryColumn) {
    EXPECT_EQ(
        html("| knob | `value` |\n|---|---|\n| a | ![](p.png) |\n| b |  |\n"),
        "<table class=\"text-table\">\n<thead><tr><th>knob</th><th><code>value</code></th></tr></thead>\n"
        "<tbody>\n<tr><td>a</td><td><img src=\"figures/p.png\" alt=\"\"></td></tr>\n"
        "<tr><td>b</td><td></td></tr>\n</tbody>\n</table>\n");
    // Two tables one after the other stay two tables.
    const std::string two = html("| a |\n|---|\n| 1 |\n\n| b |\n|---|\n| 2 |\n");
    EXPECT_EQ(two.find("<table", two.find("</table>")) != std::string::npos, true);
}

TEST(HandoutHtml, HeadingsTakeTheLevelThePageGivesThem) {
    EXPECT_EQ(markdownToHtml("### Exercise", {}, 4), "<h4>Exercise</h4>\n");
}

TEST(HandoutHtml, PicturesAndCodeNamesOfAText) {
    const std::string md =
        "![a](x.png) `bloom.down[0]` and `k`\n\n| ![](y.png) | `k` |\n\n```\n`not this`\n```\n![b](x.png)";
    EXPECT_EQ(pictureTargets(md), (std::vector<std::string>{"x.png", "y.png"}));
    EXPECT_EQ(codeSpans(md), (std::vector<std::string>{"bloom.down[0]", "k"}));
}

}  // namespace
