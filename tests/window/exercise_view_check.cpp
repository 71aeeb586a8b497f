// Checks an exercise view in a window's screenshot (window.exercise-views): inside the rectangle where
// the lesson drew the view (its log line "exercise view N drawn at X,Y WxH"), either some pixel is
// magenta (a NaN or Inf the view marks) and some are not black, or every pixel is black (the difference
// of a solution that matches the reference).
//   fx_exercise_view_check SCREENSHOT.png X Y WIDTH HEIGHT nonfinite|black
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image/png_file.hpp"

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: %s SCREENSHOT.png X Y WIDTH HEIGHT nonfinite|black\n", argv[0]);
        return 2;
    }
    auto shot = fx::readPng(argv[1]);
    if (!shot) {
        std::fprintf(stderr, "%s\n", shot.error().c_str());
        return 1;
    }
    const int x0 = std::atoi(argv[2]), y0 = std::atoi(argv[3]), width = std::atoi(argv[4]),
              height = std::atoi(argv[5]);
    const std::string expect = argv[6];
    if (width < 1 || height < 1 || x0 < 0 || y0 < 0 || x0 + width > shot->width ||
        y0 + height > shot->height) {
        std::fprintf(stderr, "the view's place %d,%d %dx%d is not inside the %dx%d screenshot\n", x0, y0,
                     width, height, shot->width, shot->height);
        return 1;
    }
    long magenta = 0, notBlack = 0, brightest = 0;
    for (int y = y0; y < y0 + height; ++y) {
        const int row = shot->height - 1 - y;  // rows are bottom-up; the place counts from the top
        for (int x = x0; x < x0 + width; ++x) {
            const int r = shot->texel(x, row, 0), g = shot->texel(x, row, 1), b = shot->texel(x, row, 2);
            if (r == 255 && g == 0 && b == 255) ++magenta;
            const int most = std::max(r, std::max(g, b));
            if (most > 2) ++notBlack;
            brightest = std::max<long>(brightest, most);
        }
    }
    std::printf("%s: in %d,%d %dx%d: %ld magenta pixels, %ld not black, the brightest channel %ld\n", argv[1],
                x0, y0, width, height, magenta, notBlack, brightest);
    if (expect == "nonfinite") return magenta > 0 ? 0 : 1;
    if (expect == "black") return notBlack == 0 ? 0 : 1;
    std::fprintf(stderr, "expect nonfinite or black, not %s\n", expect.c_str());
    return 2;
}
