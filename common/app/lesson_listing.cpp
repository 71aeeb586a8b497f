#include "app/lesson_listing.hpp"

#include <cstdio>
#include <iostream>

#include "base/log.hpp"

namespace fx {

std::string lessonFolderName(const LessonInfo& info) {
    char number[8];
    std::snprintf(number, sizeof number, "%02d", info.number);
    return cat(number, "-", info.slug);
}

std::string executableName(const LessonInfo& info) { return "fxlab-" + lessonFolderName(info); }

void printSteps(const std::vector<LessonStep>& steps) {
    for (std::size_t i = 0; i < steps.size(); ++i) {
        std::cout << i + 1 << ". " << steps[i].title << "\n   " << steps[i].text << "\n";
    }
}

void printParams(const ParamSet& params) {
    if (params.all().empty()) std::cout << "(this lesson has no parameters)\n";
    for (const Param& p : params.all()) {
        std::cout << p.name << " = " << p.text() << "  [" << toString(p.source()) << "]  (" << p.rangeText() << ")";
        if (p.knob) std::cout << "  quality knob, reference " << p.valueText(p.knob->reference);
        if (!p.sceneSetting.empty()) std::cout << "\n    starts from the scene's " << p.sceneSetting;
        std::cout << "\n    " << p.description << "\n";
    }
}

}  // namespace fx
