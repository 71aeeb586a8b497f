#pragma once
// What the runner hands the overlay every frame: the lesson's steps and parameters, the frame's
// graph and report, the camera's planes, and the actions only the runner can perform.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "base/lesson_text.hpp"
#include "base/params.hpp"
#include "bench/quality_sweep.hpp"
#include "render/frame_graph.hpp"
#include "render/frame_report.hpp"

namespace fx {

// One key of the window and what it does (from the runner's key table, app/window_input.cpp).
struct OverlayKey {
    std::string key, action;
};

struct OverlayModel {
    std::string title;
    // Every text of the run's words files (base/words.hpp): the font atlas loads their glyphs.
    std::vector<std::string_view> words;
    std::vector<LessonStep> steps;  // title and markdown text of each, from lesson.md (or its translation)
    // The lesson's own pages beside the steps (pitfalls, hard cases, the chapter's other exercises):
    // heading as title, markdown text, and a note where the language shown lacks the page.
    std::vector<LessonStep> pages;
    int* step = nullptr;          // 0-based, the overlay may change it
    std::string textError;        // what is wrong with lesson.md, shown until fixed
    int textRevision = 0;         // changes when the steps' text does (the overlay loads glyphs then)
    std::string language = "en";  // of the text shown; languages: those the lesson has a file for
    std::vector<std::string> languages;
    std::function<void(const std::string&)> setLanguage;
    ParamSet* params = nullptr;
    const FrameReport* frame = nullptr;
    // The frame's graph while its inspected textures are still held (the inspector reads them).
    const FrameGraph* graph = nullptr;
    std::string timing;  // method and why
    std::string renderer;
    double frameMs = 0;
    std::int64_t glErrors = 0;
    std::int64_t glExpectedErrors = 0;
    std::vector<std::string> shaderErrors;  // shown until fixed (the last good program keeps running)
    std::string status;                     // one line: "saved out/screenshot-3.png", "reloaded shaders"
    // The last thing the teacher did, confirmed at the top of the lesson window for a few seconds
    // (F12's file, "this is the last lesson", a shader reload and its errors); empty when none is new.
    std::string notice;
    // While the picture renders smaller than its place: how and why ("picture at 40% of 896x504 ...:
    // slow renderer"), at the top of the lesson window.
    std::string pictureScale;
    // While the lesson clock runs slower than the wall clock (a slow renderer): by how much, in the footer.
    std::string clockRate;
    std::function<void()> lessonPanel;
    std::function<void()> onSavePreset, onLoadPreset;
    // The camera's planes, for showing depth textures linearised.
    float cameraNear = 0.1f, cameraFar = 100.0f;
    // Starts the quality-knob sweep in the app (as ./fxlab bench does); the cost panel measures a
    // row of it before each frame. Its result has no points when the lesson has no knobs.
    std::function<std::unique_ptr<SweepRun>()> measureKnobs;
    // Every key of the window, for the Keys tab; empty headless. executable: for "--help".
    std::vector<OverlayKey> keys;
    std::string executable;
    // Shown at the top of the lesson window while they hold: "paused at 2.35 s (space resumes ...)",
    // "compare: split ...".
    std::string clock;
    std::string compare;
};

}  // namespace fx
