#include "ui/overlay_fonts.hpp"

#include <algorithm>
#include <system_error>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "base/log.hpp"
#include "base/markdown_text.hpp"
#include "gl/object.hpp"
#include "ui/gl_state_scope.hpp"

namespace fx {

namespace {
// The merged glyphs are drawn a pixel larger than the 13-pixel built-in font: kanji at 13 pixels lose
// strokes. One pixel down keeps them on the built-in font's baseline.
constexpr float kMergedPixels = 14.0f;
}  // namespace

std::vector<char32_t> codePointsBeyondLatin1(const std::vector<std::string_view>& texts) {
    std::vector<char32_t> points;
    for (std::string_view text : texts) {
        for (std::size_t i = 0; i < text.size();) {
            std::size_t length = 1;
            char32_t c = markdown::decodeUtf8(text, i, length);
            i += length;
            if (c > 0xFF) points.push_back(c);
        }
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

Status OverlayFonts::prepare(const std::vector<std::string_view>& texts, float scale) {
    std::vector<char32_t> wanted = codePointsBeyondLatin1(texts);
    // ImWchar is 16 bits in Debian's build: characters beyond the BMP cannot be loaded.
    wanted.erase(std::remove_if(wanted.begin(), wanted.end(), [](char32_t c) { return c > 0xFFFF; }),
                 wanted.end());
    if (wanted == merged_ && scale == scale_) return Status::success();
    const std::filesystem::path file = japaneseFontFile();
    std::error_code ec;
    if (!wanted.empty() && !std::filesystem::is_regular_file(file, ec)) {
        return Error{cat("overlay: the font ", file.string(),
                         " is missing (Debian package fonts-ipafont-gothic), so ", wanted.size(),
                         " characters of the lesson text cannot be shown")};
    }

    ImGuiIO& io = ImGui::GetIO();
    const bool textureMade = io.Fonts->TexID != ImTextureID{};
    io.Fonts->Clear();
    ImFontConfig base;
    base.SizePixels = 13.0f * scale;  // the built-in font's own size, scaled
    io.Fonts->AddFontDefault(&base);
    ranges_.clear();
    if (!wanted.empty()) {
        ImFontGlyphRangesBuilder builder;
        for (char32_t c : wanted) builder.AddChar(ImWchar(c));
        ImVector<ImWchar> ranges;
        builder.BuildRanges(&ranges);
        ranges_.assign(ranges.begin(), ranges.end());
        ImFontConfig config;
        config.MergeMode = true;
        config.PixelSnapH = true;
        config.GlyphOffset.y = 1.0f;
        config.OversampleH = 1;  // the atlas is sampled at whole pixels; no sub-pixel positions
        // ImGui takes the name in UTF-8 (and opens it with the wide functions on Windows).
        const std::string name = file.string();
        if (!io.Fonts->AddFontFromFileTTF(name.c_str(), kMergedPixels * scale, &config, ranges_.data())) {
            io.Fonts->Clear();
            io.Fonts->AddFontDefault(&base);
            ranges_.clear();
            wanted.clear();
            log::error("overlay: Dear ImGui could not read the font ", file.string());
        }
    }
    io.Fonts->Build();
    if (textureMade) {
        // Otherwise the backend makes it at its first NewFrame, from the atlas built here.
        GlStateScope keep;
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
        gl::labelObject(GL_TEXTURE, GLuint(reinterpret_cast<std::uintptr_t>(io.Fonts->TexID)),
                        "ui.font_atlas");
    }
    loaded_ = missing_ = 0;
    const ImFont* font = io.Fonts->Fonts.empty() ? nullptr : io.Fonts->Fonts[0];
    for (char32_t c : wanted) (font && font->FindGlyphNoFallback(ImWchar(c)) ? loaded_ : missing_)++;
    merged_ = std::move(wanted);
    scale_ = scale;
    if (!merged_.empty()) {
        log::info("overlay font: ", loaded_, " glyphs of the lesson text merged from ", file.string(), " (",
                  missing_, " not in the font), atlas ", io.Fonts->TexWidth, "x", io.Fonts->TexHeight);
    }
    return Status::success();
}

}  // namespace fx
