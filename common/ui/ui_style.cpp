#include "ui/ui_style.hpp"

#include <cstdio>

namespace fx::ui_style {

void continueRow(float width, float spacing) {
    ImGui::SameLine(0.0f, spacing);
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

const char* byteSizeText(unsigned long long bytes, char* buffer, int size) {
    if (bytes >= 1024ull * 1024ull) {
        std::snprintf(buffer, std::size_t(size), "%.2f MiB", double(bytes) / (1024.0 * 1024.0));
    } else if (bytes >= 1024ull) {
        std::snprintf(buffer, std::size_t(size), "%.1f KiB", double(bytes) / 1024.0);
    } else {
        std::snprintf(buffer, std::size_t(size), "%llu B", bytes);
    }
    return buffer;
}

}  // namespace fx::ui_style
