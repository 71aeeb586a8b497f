#include "app/lesson_text_files.hpp"

#include <algorithm>
#include <system_error>

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {
namespace {

namespace fs = std::filesystem;

fs::file_time_type stampOf(const fs::path& path) {
    std::error_code ec;
    auto stamp = fs::last_write_time(path, ec);
    return ec ? fs::file_time_type::min() : stamp;
}

}  // namespace

const std::vector<std::string>& lessonTextLanguages() {
    static const std::vector<std::string> languages{"en", "ja"};
    return languages;
}

LessonTextFiles::LessonTextFiles(fs::path folder, std::vector<std::string> titles, std::string language)
    : folder_(std::move(folder)), titles_(std::move(titles)), language_(std::move(language)) {
    compose();  // titles only until the first read
}

fs::path LessonTextFiles::file(const std::string& language) const {
    return folder_ / (language == "en" ? std::string("lesson.md") : "lesson." + language + ".md");
}

std::vector<std::string> LessonTextFiles::available() const {
    std::vector<std::string> found;
    for (const std::string& language : lessonTextLanguages()) {
        std::error_code ec;
        if (language == "en" || fs::exists(file(language), ec)) found.push_back(language);
    }
    return found;
}

Status LessonTextFiles::setLanguage(const std::string& language) {
    bool known = false;
    for (const std::string& l : lessonTextLanguages()) known = known || l == language;
    if (!known) return Error{cat("lesson text: no language \"", language, "\" (there are en and ja)")};
    if (language != language_) {
        language_ = language;
        readOnce_ = false;
        (void)reloadIfChanged();
    }
    return Status::success();
}

bool LessonTextFiles::reloadIfChanged() {
    std::vector<fs::file_time_type> stamps{stampOf(file("en"))};
    if (language_ != "en") stamps.push_back(stampOf(file(language_)));
    if (readOnce_ && stamps == stamps_) return false;
    stamps_ = std::move(stamps);
    readOnce_ = true;
    read();
    compose();
    return true;
}

void LessonTextFiles::read() {
    const std::string previousError = error_;
    const fs::path english = file("en");
    if (auto text = readTextFile(english); !text) {
        englishError_ = cat(text.error(), "; the steps show their titles only");
    } else if (auto sections = parseStepSections(*text, english.string()); !sections) {
        englishError_ = sections.error();
    } else if (auto texts = matchLessonText(*sections, titles_, english.string()); !texts) {
        englishError_ = texts.error();
    } else {
        english_ = std::move(*texts);
        englishPages_ = lessonPages(*text);
        englishError_.clear();
    }

    translationError_.clear();
    if (language_ == "en") {
        translation_.clear();
        hasTranslation_.clear();
        translationPages_.clear();
    } else {
        const fs::path translated = file(language_);
        std::error_code ec;
        if (!fs::exists(translated, ec)) {
            translation_.clear();
            hasTranslation_.clear();
            translationPages_.clear();
            log::info("lesson text: there is no ", translated.string(),
                      "; every step shows its English text");
        } else if (auto text = readTextFile(translated); !text) {
            translationError_ = text.error();
        } else if (auto sections = parseStepSections(*text, translated.string()); !sections) {
            translationError_ = sections.error();
        } else if (auto byStep = matchTranslation(*sections, titles_.size(), translated.string()); !byStep) {
            translationError_ = byStep.error();
        } else {
            translationPages_ = lessonPages(*text);
            translation_.assign(titles_.size(), StepSection{});
            hasTranslation_.assign(titles_.size(), false);
            for (std::size_t i = 0; i < titles_.size(); ++i) {
                if (!(*byStep)[i]) continue;
                translation_[i] = *(*byStep)[i];
                hasTranslation_[i] = true;
            }
            log::info("lesson text: ", translated.string(), " translates ", sections->size(), " of ",
                      titles_.size(), " steps; the others show lesson.md's English");
        }
    }

    error_ = englishError_;
    if (!translationError_.empty()) error_ += (error_.empty() ? "" : "\n") + translationError_;
    if (!error_.empty() && error_ != previousError) log::error(error_);
    if (error_.empty() && !previousError.empty())
        log::info("lesson text: fixed, ", english.string(), " read again");
}

void LessonTextFiles::compose() {
    shown_.clear();
    translated_ = 0;
    for (std::size_t i = 0; i < titles_.size(); ++i) {
        if (i < hasTranslation_.size() && hasTranslation_[i]) {
            shown_.push_back({translation_[i].title, translation_[i].text, {}});
            ++translated_;
            continue;
        }
        LessonStep step{titles_[i], i < english_.size() ? english_[i] : std::string(), {}};
        if (language_ != "en") step.note = cat("not in lesson.", language_, ".md yet: the English text");
        shown_.push_back(std::move(step));
    }
    shownPages_.clear();
    for (std::size_t i = 0; i < std::max(englishPages_.size(), translationPages_.size()); ++i) {
        if (i < translationPages_.size()) {
            shownPages_.push_back({translationPages_[i].heading, translationPages_[i].text, {}});
            continue;
        }
        LessonStep page{englishPages_[i].heading, englishPages_[i].text, {}};
        if (language_ != "en") page.note = cat("not in lesson.", language_, ".md yet: the English text");
        shownPages_.push_back(std::move(page));
    }
    ++revision_;
}

}  // namespace fx
