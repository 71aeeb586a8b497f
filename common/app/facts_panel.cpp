#include "app/facts_panel.hpp"

#include <imgui.h>

namespace fx {

void drawFacts(const Facts& facts) {
    for (const Fact& f : facts.list()) {
        if (!f.shown) continue;
        ImGui::TextWrapped("%s: %s", f.shownLabel().c_str(), f.value.c_str());
    }
}

}  // namespace fx
