#include "app/lesson_listing.hpp"

#include <cstdio>
#include <iostream>

#include "base/log.hpp"
#include "base/paths.hpp"

namespace fx {

std::string lessonFolderName(const LessonInfo& info) {
    char number[8];
    std::snprintf(number, sizeof number, "%02d", info.number);
    return cat(number, "-", info.slug);
}

std::string executableName(const LessonInfo& info) {
    return "fxlab-" + lessonFolderName(info);
}

std::filesystem::path lessonSourceFolder(const LessonInfo& info) {
    std::string folder = lessonFolderName(info);
    for (char& c : folder) {
        if (c == '-') c = '_';
    }
    return projectRoot() / "lessons" / folder;
}

bool printSteps(const LessonTextFiles& text) {
    const std::vector<LessonStep>& steps = text.steps();
    for (std::size_t i = 0; i < steps.size(); ++i) {
        std::cout << i + 1 << ". " << steps[i].title << "\n";
        if (!steps[i].note.empty()) std::cout << "   (" << steps[i].note << ")\n";
        std::size_t start = 0;
        while (start < steps[i].text.size()) {
            std::size_t end = steps[i].text.find('\n', start);
            if (end == std::string::npos) end = steps[i].text.size();
            std::cout << "   " << std::string_view(steps[i].text).substr(start, end - start) << "\n";
            start = end + 1;
        }
    }
    return text.error().empty();  // the error was logged when the files were read
}

void printParams(const ParamSet& params) {
    if (params.all().empty()) std::cout << "(this lesson has no parameters)\n";
    for (const Param& p : params.all()) {
        const std::string label = p.label();
        std::cout << p.name << (label == p.name ? "" : cat(" (", label, ")")) << " = " << p.text() << "  ["
                  << toString(p.source()) << "]  (" << p.rangeText() << ")";
        if (p.knob) std::cout << "  quality knob, reference " << p.valueText(p.knob->reference);
        if (!p.sceneSetting.empty()) std::cout << "\n    starts from the scene's " << p.sceneSetting;
        if (!p.steps.empty()) {
            std::cout << "\n    acts in step" << (p.steps.size() > 1 ? "s" : "");
            for (std::size_t i = 0; i < p.steps.size(); ++i) std::cout << (i ? ", " : " ") << p.steps[i] + 1;
        }
        std::cout << "\n    " << p.help() << "\n";
    }
}

}  // namespace fx
