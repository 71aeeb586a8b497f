#include "app/facts_panel.hpp"

#include <imgui.h>

namespace fx {

void drawFacts(const Facts& facts) {
    for (const Fact& f : facts.list()) {
        if (!f.shown) continue;
        const std::string& label = f.label.empty() ? f.name : f.label;
        ImGui::TextWrapped("%s: %s", label.c_str(), f.value.c_str());
    }
}

}  // namespace fx
