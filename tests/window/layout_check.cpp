// Checks a window run in the presentation layout (run by classroom_test.sh): the run really was a GLFW
// window with no GL error, the report's layout puts every panel on the window, and the lesson's
// picture is uncovered: the window's screenshot (final.png, the back buffer after the overlay drew)
// holds, in the picture's place, exactly the pixels of the lesson's own picture (picture.png). Any
// panel drawn over any part of it would change those pixels.
//   fx_layout_check <run folder> [--window WxH] [--text-scale S] [--lesson NAME] [--split]
//                   [--picture-share F]
// --split: the compare view is on; the place shows a white line down its middle, this step's picture
// right of it and the previous step's left of it (which must differ from this step's somewhere).
// --difference: the compare view's difference: black where the steps agree, lit where they differ.
// --lit-below F: with --difference, the steps differ in under F of the place (and somewhere): both
// pictures of an animated lesson were taken at one moment, so only what the step changes is lit.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "base/file_io.hpp"
#include "image/png_file.hpp"

namespace {

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;  // from the top left
};

Rect rectFrom(const nlohmann::json& j) {
    return {j.at(0).get<int>(), j.at(1).get<int>(), j.at(2).get<int>(), j.at(3).get<int>()};
}

bool fail(const std::string& message) {
    std::cout << "FAIL: " << message << "\n";
    return false;
}

// Texel (x, y) from the top of an image stored bottom-up.
const std::uint8_t* at(const fx::ByteImage& image, int x, int y) {
    return &image.texel(x, image.height - 1 - y, 0);
}

bool samePixel(const std::uint8_t* a, const std::uint8_t* b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: fx_layout_check <run folder> [--window WxH] [--text-scale S] [--lesson NAME] "
                     "[--split]\n";
        return 2;
    }
    const std::string dir = argv[1];
    std::string expectWindow, expectLesson;
    double expectScale = -1, minShare = 0.45, litBelow = -1;
    bool split = false, difference = false;
    std::string nanLog;
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--window" && i + 1 < argc)
            expectWindow = argv[++i];
        else if (a == "--text-scale" && i + 1 < argc)
            expectScale = std::atof(argv[++i]);
        else if (a == "--lesson" && i + 1 < argc)
            expectLesson = argv[++i];
        else if (a == "--picture-share" && i + 1 < argc)
            minShare = std::atof(argv[++i]);
        else if (a == "--split")
            split = true;
        else if (a == "--difference")
            difference = true;
        else if (a == "--lit-below" && i + 1 < argc)
            litBelow = std::atof(argv[++i]);
        else if (a == "--nan-log" && i + 1 < argc)
            nanLog = argv[++i];
        else {
            std::cerr << "unknown argument " << a << "\n";
            return 2;
        }
    }
    auto reportText = fx::readTextFile(dir + "/report.json");
    nlohmann::json report = nlohmann::json::parse(reportText ? *reportText : std::string(), nullptr, false);
    if (report.is_discarded()) {
        fail("no report.json in " + dir);
        return 1;
    }
    bool ok = true;
    if (report.value("context", "").find("GLFW") == std::string::npos)
        ok = fail("the run was not in a GLFW window: " + report.value("context", std::string("?")));
    if (report.value("glErrors", -1LL) != 0) ok = fail("GL errors: " + report["glErrors"].dump());
    if (!expectLesson.empty() && report.value("lesson", "") != expectLesson)
        ok = fail("the run was " + report.value("lesson", std::string("?")) + ", not " + expectLesson);
    if (!report.contains("layout")) {
        fail("the report has no layout (was the overlay drawn?)");
        return 1;
    }
    const nlohmann::json& layout = report["layout"];
    const int ww = layout["window"][0], wh = layout["window"][1];
    std::printf("window %dx%d, text scale %.2f\n", ww, wh, layout.value("textScale", 0.0));
    if (!expectWindow.empty() && expectWindow != std::to_string(ww) + "x" + std::to_string(wh))
        ok = fail("the window is " + std::to_string(ww) + "x" + std::to_string(wh) + ", expected " +
                  expectWindow);
    if (expectScale > 0 && std::abs(layout.value("textScale", 0.0) - expectScale) > 1e-6)
        ok = fail("text scale " + layout["textScale"].dump() + ", expected " + std::to_string(expectScale));
    for (const char* name : {"picture", "lesson", "frame", "inspector"}) {
        Rect r = rectFrom(layout[name]);
        std::printf("  %-9s at %4d,%4d size %4dx%4d\n", name, r.x, r.y, r.w, r.h);
        if (r.x < 0 || r.y < 0 || r.x + r.w > ww || r.y + r.h > wh)
            ok = fail(std::string(name) + " is partly off the window");
    }
    const Rect picture = rectFrom(layout["picture"]);
    const double share = double(picture.w) * picture.h / (double(ww) * wh);
    std::printf("the picture has %.0f%% of the window\n", share * 100.0);
    if (share < minShare)
        ok = fail("the picture has only " + std::to_string(share * 100.0) + "% of the window");

    auto shot = fx::readPng(dir + "/final.png");
    auto alone = fx::readPng(dir + "/picture.png");
    if (!shot || !alone) {
        fail("missing final.png or picture.png in " + dir);
        return 1;
    }
    if (shot->width != ww || shot->height != wh) ok = fail("final.png is not the window's size");
    // The difference view is checked on the window alone (its pictures may render at a share of the
    // place: window.classroom.compare-scale); the others against the lesson's own picture.
    if (!difference && (alone->width != picture.w || alone->height != picture.h)) {
        fail("picture.png is not the picture's size");
        return 1;
    }
    const int middle = picture.w / 2;
    long covered = 0, leftDiffers = 0, lineWhite = 0;
    for (int y = 0; y < picture.h; ++y) {
        for (int x = 0; x < picture.w; ++x) {
            const std::uint8_t* s = at(*shot, picture.x + x, picture.y + y);
            const std::uint8_t* p = difference ? s : at(*alone, x, y);
            if (difference) {
                // The difference view: black where the steps agree, the change x8 where they do not.
                const bool black = s[0] == 0 && s[1] == 0 && s[2] == 0;
                covered += black ? 1 : 0;  // counted as "black" below
                leftDiffers += black ? 0 : 1;
            } else if (!split) {
                covered += samePixel(s, p) ? 0 : 1;
            } else if (x == middle) {
                lineWhite += s[0] == 255 && s[1] == 255 && s[2] == 255 ? 1 : 0;
            } else if (x > middle + 1) {
                covered += samePixel(s, p) ? 0 : 1;
            } else if (x < middle - 1) {
                leftDiffers += samePixel(s, p) ? 0 : 1;
            }
        }
    }
    if (difference) {
        const double area = double(picture.w) * picture.h, black = double(covered) / area;
        std::printf("difference: %.0f%% of the place black (the steps agree), %.0f%% lit\n", black * 100.0,
                    100.0 - black * 100.0);
        if (litBelow >= 0) {
            if (1.0 - black >= litBelow || black >= 1.0)
                ok = fail("the difference view should be lit in under " + std::to_string(litBelow * 100.0) +
                          "% of the place, and somewhere");
        } else if (black < 0.2 || black > 0.95) {
            ok = fail("the difference view is not black where the steps agree");
        }
        covered = 0;
    }
    std::printf("pixels of the picture's place that are not the lesson's picture: %ld\n", covered);
    if (covered > 0) ok = fail(std::to_string(covered) + " pixels of the picture are covered or changed");
    if (split) {
        std::printf("split: %ld white pixels on the line, %ld pixels left of it differ from this step\n",
                    lineWhite, leftDiffers);
        if (lineWhite != picture.h) ok = fail("the split's line is not a white column down the middle");
        if (leftDiffers == 0) ok = fail("left of the line is this step's picture, not the previous step's");
    }
    if (!nanLog.empty()) {
        // find-NaN (F4) logged where it pinned the probe; the lesson's facts say where the blur
        // centre is in pixels ("(448.5, 151.5)"): the texel under it holds the step's NaN.
        auto log = fx::readTextFile(nanLog);
        const std::string text = log ? *log : std::string();
        int fx = -1, fy = -1;
        const auto found = text.find("NaN/Inf at texel (");
        if (found != std::string::npos)
            std::sscanf(text.c_str() + found, "NaN/Inf at texel (%d, %d)", &fx, &fy);
        double cx = -1, cy = -1;
        const std::string centre = report["facts"].value("centrePixels", std::string());
        std::sscanf(centre.c_str(), "(%lf, %lf)", &cx, &cy);
        std::printf("find-NaN pinned texel (%d, %d); the blur centre is at %s pixels\n", fx, fy,
                    centre.c_str());
        if (fx != int(std::floor(cx)) || fy != int(std::floor(cy)) || fx < 0)
            ok = fail("find-NaN did not land on the centre texel");
    }
    // The panels are there: the column is the overlay's dark windows, not the picture.
    const Rect lesson = rectFrom(layout["lesson"]);
    double luma = 0;
    long n = 0;
    for (int y = lesson.y + 30; y < lesson.y + lesson.h - 4; y += 3) {
        for (int x = lesson.x + 4; x < lesson.x + lesson.w - 4; x += 3) {
            const std::uint8_t* s = at(*shot, x, y);
            luma += 0.2126 * s[0] + 0.7152 * s[1] + 0.0722 * s[2];
            ++n;
        }
    }
    if (n > 0) luma /= double(n);
    std::printf("the lesson window's mean luma %.0f\n", luma);
    if (n == 0 || luma > 100.0) ok = fail("the lesson window is missing from the column");
    return ok ? 0 : 1;
}
