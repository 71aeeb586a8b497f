// A lesson text's pictures copied into a handout (app/handout_sources.hpp) stay in the lesson's folder
// or docs/ (issue 40, defect 5: `![x](../../../../etc/passwd)` copied /etc/passwd into the figures).
#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

#include "app/handout_sources.hpp"
#include "base/file_io.hpp"

namespace fs = std::filesystem;

TEST(HandoutPictures, APictureOutsideTheLessonAndDocsIsRefusedAndNotCopied) {
    const fs::path root = fs::temp_directory_path() / ("fx_handout_pictures_" + std::to_string(::getpid()));
    fs::remove_all(root);
    const fs::path lesson = root / "lessons" / "01_x";
    const fs::path handout = root / "handout";
    ASSERT_TRUE(fx::writeFileAtomically(lesson / "figure.png", std::string_view("png")));
    ASSERT_TRUE(fx::writeFileAtomically(root / "secret.png", std::string_view("secret")));
    fs::create_symlink(root / "secret.png", lesson / "linked.png");
    ASSERT_EQ(::mkfifo((lesson / "pipe.png").c_str(), 0600), 0);
    fs::create_directories(handout);

    fx::handout::TextPictures pictures(lesson, handout);
    const fs::path md = lesson / "lesson.md";
    for (const char* target :
         {"../../../../../../../../../../etc/passwd", "/etc/passwd", "linked.png", "../../secret.png"}) {
        auto refused = pictures.add(std::string("![x](") + target + ")", md);
        ASSERT_FALSE(refused.ok()) << target;
        EXPECT_NE(refused.error().find(md.string() + ": the picture \""), std::string::npos)
            << refused.error();
        EXPECT_NE(refused.error().find("which is outside the lesson's folder"), std::string::npos)
            << refused.error();
        EXPECT_NE(refused.error().find("a lesson's text shows only pictures of the lesson or of docs/"),
                  std::string::npos)
            << refused.error();
    }
    auto fifo = pictures.add("![x](pipe.png)", md);  // refused by the read, unread, with the true reason
    ASSERT_FALSE(fifo.ok());
    EXPECT_NE(fifo.error().find("is a FIFO (named pipe)"), std::string::npos) << fifo.error();
    EXPECT_FALSE(fs::exists(handout / "figures"));  // nothing copied
    EXPECT_TRUE(pictures.add("![x](figure.png)", md).ok());
    EXPECT_EQ(*fx::readTextFile(handout / "figures" / "figure.png"), "png");
    fs::remove_all(root);
}
