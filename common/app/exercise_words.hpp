#pragma once
// An exercise's words in a language other than English: exercises/LL-N/words.<language> (the format
// of base/words.hpp) gives its `title`, `measures` and each hint's text as `hint.N` (N: the hint's
// place in exercise.json, from 1). English is exercise.json's own. Every exercise has a words.ja,
// with every key (the unit test Words.EveryExerciseHasItsJapanese finds one missing).
#include <string>
#include <vector>

#include "app/exercise_catalog.hpp"
#include "base/result.hpp"

namespace fx {

// The exercise with its words in `language`; English leaves it as it is. A missing file or key is an
// error naming the file and the key.
Status localiseExercise(Exercise& exercise, const std::string& language);
Status localiseExercises(std::vector<Exercise>& exercises, const std::string& language);

// The language a command-line tool speaks when --lang does not say: "ja" when the locale
// (LC_ALL, LC_MESSAGES, LANG, in that order) is Japanese ("ja_JP.UTF-8"), else "en".
std::string languageFromLocale();

}  // namespace fx
