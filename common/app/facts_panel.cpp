#include "app/facts_panel.hpp"

#include <imgui.h>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/word_wrap.hpp"

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
        // Wrapped by Unicode's rules, so a number is never split across lines ("b + 0." / "0000").
        drawWrappedText(cat(label, ": ", f.value));
    }
}

}  // namespace fx
