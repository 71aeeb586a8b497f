// Checks the window test's two runs of a lesson (run_window_test.sh): both really ran in a GLFW
// window with no GL error, and the screenshot with the overlay shows the overlay's dark lesson
// window at the top left where the screenshot without it shows the scene. (That the panels never
// cover the picture is layout_check's job: with the overlay the picture has a place of its own.)
//   fx_window_check <run with overlay> <run without> <difference.png>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "image/image_compare.hpp"
#include "image/png_file.hpp"

namespace {

using fx::ByteImage;

struct Rect {
    int x0, y0, x1, y1;  // pixels, y from the top of the picture
};

double meanLuma(const ByteImage& image, Rect r) {
    double sum = 0.0;
    int n = 0;
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            int row = image.height - 1 - y;  // images are stored bottom-up
            sum += 0.2126 * image.texel(x, row, 0) + 0.7152 * image.texel(x, row, 1) +
                   0.0722 * image.texel(x, row, 2);
            ++n;
        }
    }
    return n ? sum / n : 0.0;
}

// The share of pixels whose largest channel difference is above 24 levels.
double differingShare(const ByteImage& a, const ByteImage& b, Rect r) {
    int differing = 0, n = 0;
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            int row = a.height - 1 - y;
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(a.texel(x, row, c)) - int(b.texel(x, row, c))));
            differing += d > 24 ? 1 : 0;
            ++n;
        }
    }
    return n ? double(differing) / n : 0.0;
}

bool checkReport(const std::string& dir, const char* what) {
    std::ifstream in(dir + "/report.json");
    if (!in) {
        std::cout << "FAIL: no report from the run " << what << " the overlay\n";
        return false;
    }
    nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    if (report.is_discarded()) {
        std::cout << "FAIL: the report of the run " << what << " the overlay is not JSON\n";
        return false;
    }
    bool ok = true;
    std::string context = report.value("context", "");
    if (context.find("GLFW") == std::string::npos) {
        std::cout << "FAIL: the run " << what << " the overlay used \"" << context
                  << "\", not a GLFW window\n";
        ok = false;
    }
    long long errors = report.value("glErrors", -1LL);
    if (errors != 0) {
        std::cout << "FAIL: the run " << what << " the overlay reported " << errors << " GL error(s)\n";
        ok = false;
    }
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: fx_window_check <run with overlay> <run without> <difference.png>\n";
        return 2;
    }
    const std::string withDir = argv[1], withoutDir = argv[2];
    bool ok = checkReport(withDir, "with");
    ok = checkReport(withoutDir, "without") && ok;

    auto with = fx::readPng(withDir + "/final.png");
    auto without = fx::readPng(withoutDir + "/final.png");
    if (!with || !without) {
        std::cout << "FAIL: missing screenshot: " << (with ? without.error() : with.error()) << "\n";
        return 1;
    }
    if (with->width != without->width || with->height != without->height || with->width < 400 ||
        with->height < 300) {
        std::cout << "FAIL: screenshots of " << with->width << "x" << with->height << " and "
                  << without->width << "x" << without->height
                  << "; expected two of the window's size (at least 400x300)\n";
        return 1;
    }
    if (auto diff = fx::differenceImage(*without, *with); diff) (void)fx::writePng(argv[3], *diff);

    // The lesson window starts at (8, 8) and is at least 360 pixels wide: its body is dark.
    const Rect overlay{14, 32, 340, 160};
    double changed = differingShare(*with, *without, overlay);
    double lumaWith = meanLuma(*with, overlay), lumaWithout = meanLuma(*without, overlay);
    std::printf("overlay region: %.0f%% of pixels differ, mean luma %.0f with the overlay, %.0f without\n",
                changed * 100.0, lumaWith, lumaWithout);
    if (changed < 0.5) {
        std::cout << "FAIL: the overlay's window is not in the screenshot (only " << changed * 100.0
                  << "% of its region differs from the run without it)\n";
        ok = false;
    }
    if (lumaWith > 90.0) {
        std::cout << "FAIL: the overlay's region is bright (mean luma " << lumaWith
                  << "): its dark window is missing\n";
        ok = false;
    }
    return ok ? 0 : 1;
}
