// Checks lesson 06's window test (run_bloom_window_test.sh): both runs were in a GLFW window with no
// GL error; with the inspector opened on bloom.down[0], every level of bloom.down[*] and bloom.up[*]
// was made (the inspector keeps the whole chain alive for its strip) and holds only finite values;
// and the screenshot shows the inspector's window where the run without the overlay shows the scene.
//   fx_bloom_inspector_check <run with overlay> <run without>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "image/png_file.hpp"

namespace {

nlohmann::json readReport(const std::string& dir) {
    std::ifstream in(dir + "/report.json");
    if (!in) return nlohmann::json();
    return nlohmann::json::parse(in, nullptr, false);
}

bool checkRun(const nlohmann::json& report, const char* what) {
    if (report.is_null() || report.is_discarded()) {
        std::cout << "FAIL: no readable report from the run " << what << " the overlay\n";
        return false;
    }
    bool ok = true;
    if (report.value("context", "").find("GLFW") == std::string::npos) {
        std::cout << "FAIL: the run " << what << " the overlay did not use a GLFW window\n";
        ok = false;
    }
    if (report.value("glErrors", -1LL) != 0) {
        std::cout << "FAIL: the run " << what << " the overlay reported GL errors\n";
        ok = false;
    }
    return ok;
}

bool finiteStats(const nlohmann::json& texture) {
    if (!texture.contains("stats")) return true;  // not captured: nothing to check
    for (auto& channel : texture["stats"]) {
        if (channel.value("nan", 0) > 0 || channel.value("inf", 0) > 0) return false;
    }
    return true;
}

// The share of pixels in columns [x0, x1) whose largest channel differs by more than 24 levels.
double differingShare(const fx::ByteImage& a, const fx::ByteImage& b, int x0, int x1) {
    long differing = 0, n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = x0; x < x1; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(a.texel(x, y, c)) - int(b.texel(x, y, c))));
            differing += d > 24;
            ++n;
        }
    return n ? double(differing) / double(n) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    // run_window_test.sh also passes a path for a difference image, which this check does not write.
    if (argc != 3 && argc != 4) {
        std::cerr << "usage: fx_bloom_inspector_check <run with overlay> <run without> [unused]\n";
        return 2;
    }
    nlohmann::json with = readReport(argv[1]), without = readReport(argv[2]);
    bool ok = checkRun(with, "with");
    ok = checkRun(without, "without") && ok;
    if (!ok) return 1;

    int down = 0, up = 0;
    for (auto& t : with["textures"]) {
        std::string name = t.value("name", "");
        bool isDown = name.rfind("bloom.down[", 0) == 0, isUp = name.rfind("bloom.up[", 0) == 0;
        if (!isDown && !isUp) continue;
        if (!t.value("allocated", false)) {
            std::cout << "FAIL: " << name << " was not made: " << t.value("reason", "") << "\n";
            ok = false;
        }
        if (!finiteStats(t)) {
            std::cout << "FAIL: " << name << " holds a NaN or an Inf\n";
            ok = false;
        }
        (isDown ? down : up)++;
    }
    std::printf("bloom.down[*]: %d levels, bloom.up[*]: %d levels\n", down, up);
    // 1200x800, the Bloom chapter's chain of 6 levels: 600x400 down to 18x12, and 5 accumulated levels.
    if (down != 6 || up != 5) {
        std::cout << "FAIL: expected 6 levels before accumulation and 5 after\n";
        ok = false;
    }

    auto a = fx::readPng(std::string(argv[1]) + "/final.png");
    auto b = fx::readPng(std::string(argv[2]) + "/final.png");
    if (!a || !b || a->width != b->width || a->height != b->height || a->width < 800) {
        std::cout << "FAIL: missing or mismatched screenshots\n";
        return 1;
    }
    // The inspector opens on the right half of the window (the lesson panel is on the left).
    double changed = differingShare(*a, *b, a->width / 2, a->width);
    std::printf("right half: %.0f%% of pixels differ with the inspector open\n", changed * 100.0);
    if (changed < 0.2) {
        std::cout << "FAIL: the inspector's window is not on the right half of the screenshot\n";
        ok = false;
    }
    return ok ? 0 : 1;
}
