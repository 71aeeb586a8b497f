#include "app/facts_panel.hpp"

#include <imgui.h>

#include "base/log.hpp"
#include "base/words.hpp"

namespace fx {

void drawFacts(const Facts& facts, Size2D picture) {
    if (!facts.list().empty())
        ImGui::TextDisabled(
            "%s", say("facts.heading", {{"size", cat(picture.width, "x", picture.height)}}).c_str());
    for (const Fact& f : facts.list()) {
        if (!f.shown) continue;
        const std::string& label = f.shownLabel();
        if (f.done >= 0 && f.total > 0) {
            ImGui::TextWrapped("%s:", label.c_str());
            ImGui::ProgressBar(float(f.done) / float(f.total), ImVec2(-1.0f, 0.0f), f.value.c_str());
            continue;
        }
        ImGui::TextWrapped("%s: %s", label.c_str(), f.value.c_str());
    }
}

}  // namespace fx
