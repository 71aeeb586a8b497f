// Draws a bench run's plots again from its bench.json (after a change to the plots, without measuring
// again): fxlab-bench-replot out/bench/06-bloom/bench.json [OUT_DIR] [--cost traffic]
// (--cost traffic: the modelled memory traffic at 1920x1080 as the cost axis, as `--bench --cost traffic`)
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/bench.hpp"

int main(int argc, char** argv) {
    fx::BenchCost cost = fx::BenchCost::time;
    if (argc > 2 && std::string(argv[argc - 1]) == "traffic" && std::string(argv[argc - 2]) == "--cost") {
        cost = fx::BenchCost::traffic;
        argc -= 2;
    }
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: fxlab-bench-replot BENCH_JSON [OUT_DIR] [--cost traffic]\n");
        return 2;
    }
    std::ifstream in(argv[1]);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("points")) {
        std::fprintf(stderr, "%s: not a bench.json\n", argv[1]);
        return 1;
    }
    auto number = [](const nlohmann::json& v) { return v.is_number() ? v.get<double>() : 0.0; };
    fx::SweepResult r;
    r.lesson = j.value("lesson", "");
    r.width = j["size"][0];
    r.height = j["size"][1];
    r.timingMethod = j.value("timingMethod", "");
    r.copyMs = j.value("copyMs", 0.0);
    r.frames = j.value("frames", 0);
    for (const auto& p : j["points"]) {
        fx::SweepPoint s;
        s.knob = p["knob"];
        s.value = p["value"];
        s.reference = p["reference"];
        s.current = p["current"];
        s.medianMs = number(p["medianMs"]);
        s.copyMs = number(p.value("copyMs", nlohmann::json(0.0)));
        s.copyMultiple = number(p["copyMultiple"]);
        s.minMultiple = number(p.value("minMultiple", nlohmann::json(0.0)));
        s.maxMultiple = number(p.value("maxMultiple", nlohmann::json(0.0)));
        s.rmse = number(p["rmse"]);
        s.psnr = number(p["psnrDb"]);
        s.maxAbs = number(p["maxAbs"]);
        s.trafficBytes = static_cast<std::uint64_t>(number(p.value("trafficBytes1080p", nlohmann::json(0))));
        s.tapsPerPixel = number(p.value("tapsPerPixel", nlohmann::json(0.0)));
        r.points.push_back(s);
    }
    std::filesystem::path out =
        argc > 2 ? std::filesystem::path(argv[2]) : std::filesystem::path(argv[1]).parent_path();
    fx::Status s = fx::writeBenchOutputs(r, out, cost);
    if (!s) {
        std::fprintf(stderr, "%s\n", s.error().c_str());
        return 1;
    }
    return 0;
}
