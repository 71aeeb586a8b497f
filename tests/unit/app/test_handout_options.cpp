// fxlab-handout's command line (app/handout_options.hpp): every error names the flag and the reason.
#include <gtest/gtest.h>

#include "app/handout_options.hpp"

namespace {

using fx::handout::parseCommandLine;
using Args = std::vector<std::string>;

std::string errorOf(const Args& args) {
    auto line = parseCommandLine(args);
    return line ? std::string() : line.error();
}

TEST(HandoutOptions, DefaultsAndEveryFlag) {
    auto plain = parseCommandLine({"build/lessons/fxlab-06-bloom"});
    ASSERT_TRUE(plain.ok()) << plain.error();
    EXPECT_EQ(plain->options.languages, Args{"en"});
    EXPECT_EQ(plain->options.size.width, 1280);
    EXPECT_EQ(plain->options.size.height, 720);
    EXPECT_EQ(plain->options.frames, 3);
    EXPECT_FALSE(plain->force);
    EXPECT_EQ(fx::handout::defaultOut(*plain), "out/handouts/06-bloom");

    auto all = parseCommandLine({"--lang", "en,ja", "--out", "h", "--force", "--with-bench", "--bench-dir",
                                 "b", "--size", "640x360", "--frames", "5", "fxlab-01-a", "fxlab-02-b"});
    ASSERT_TRUE(all.ok()) << all.error();
    EXPECT_EQ(all->options.languages, (Args{"en", "ja"}));
    EXPECT_EQ(all->out, "h");
    EXPECT_TRUE(all->force);
    EXPECT_TRUE(all->options.withBench);
    EXPECT_EQ(all->options.benchRoot, "b");
    EXPECT_EQ(all->options.size.width, 640);
    EXPECT_EQ(all->options.frames, 5);
    EXPECT_EQ(all->lessons.size(), 2u);
    EXPECT_EQ(fx::handout::defaultOut(*all), "out/handouts");
}

TEST(HandoutOptions, ErrorsNameTheFlagAndTheReason) {
    EXPECT_EQ(errorOf({}), "no lesson given (see --help)");
    EXPECT_EQ(errorOf({"--lang", "fr", "fxlab-06-bloom"}),
              "--lang: \"fr\" is not a language of the lessons' text (en, ja, or en,ja)");
    EXPECT_EQ(errorOf({"--lang", "ja,ja", "fxlab-06-bloom"}), "--lang: ja is given twice");
    EXPECT_EQ(errorOf({"--size", "12", "fxlab-06-bloom"}),
              "--size: expected WxH with sizes from 1 to 8192, got \"12\"");
    EXPECT_EQ(errorOf({"--frames", "0", "fxlab-06-bloom"}),
              "--frames: expected a whole number from 1 to 1000, got \"0\"");
    EXPECT_EQ(errorOf({"fxlab-06-bloom", "--out"}), "--out: needs a value");
    EXPECT_EQ(errorOf({"--force", "--force", "fxlab-06-bloom"}), "--force: given twice");
    EXPECT_EQ(errorOf({"--colour", "fxlab-06-bloom"}),
              "--colour: not an option of fxlab-handout (see --help)");
    EXPECT_EQ(errorOf({"bin/ls"}), "bin/ls: not a lesson executable (fxlab-NN-name)");
    EXPECT_TRUE(parseCommandLine({"--help"})->help);
}

}  // namespace
