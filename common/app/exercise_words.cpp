#include "app/exercise_words.hpp"

#include <cstdlib>

#include "base/log.hpp"
#include "base/words.hpp"

namespace fx {

Status localiseExercise(Exercise& exercise, const std::string& language) {
    if (language == "en") return Status::success();
    const auto file = exercise.folder / ("words." + language);
    auto words = readWords(file);
    if (!words) return Error{words.error()};
    auto take = [&](const std::string& key, std::string& into) -> Status {
        auto it = words->entries.find(key);
        if (it == words->entries.end()) return Error{cat(file.string(), ": no '", key, "'")};
        into = it->second;
        return Status::success();
    };
    if (Status s = take("title", exercise.title); !s) return s;
    if (Status s = take("measures", exercise.measures); !s) return s;
    for (std::size_t i = 0; i < exercise.hints.size(); ++i) {
        if (Status s = take(cat("hint.", i + 1), exercise.hints[i].text); !s) return s;
    }
    return Status::success();
}

Status localiseExercises(std::vector<Exercise>& exercises, const std::string& language) {
    for (Exercise& e : exercises) {
        if (Status s = localiseExercise(e, language); !s) return s;
    }
    return Status::success();
}

std::string languageFromLocale() {
    for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
        const char* value = std::getenv(name);
        if (!value || !*value) continue;
        return std::string(value).rfind("ja", 0) == 0 ? "ja" : "en";
    }
    return "en";
}

}  // namespace fx
