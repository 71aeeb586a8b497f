#pragma once
// A bound on what a shader's macros expand to, checked before the driver's compiler sees the text: 23
// nested `#define Bn (Bn-1+Bn-1)` in 2 KB grow to 8 million tokens, and Mesa's compiler then takes
// gigabytes and dies (SIGSEGV) inside the lesson, in a window at every save. Each macro's expanded size
// is counted from the bodies (a macro naming another counts that one's size, however they are ordered;
// a macro naming itself counts 1, as the preprocessor leaves it unexpanded), and a shader whose macro
// grows past kMaxMacroTokens is refused naming the macro, its file and line, and the bound.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx::gl {

inline constexpr double kMaxMacroTokens = 1'000'000;

class MacroBudget {
public:
    // One line of a file, as the expander reads it (`where` is "file:line").
    void line(std::string_view text, std::string where);
    // The first macro past the bound, worded for the compile error, or nothing.
    std::optional<std::string> firstOverBudget() const;

private:
    struct Define {
        std::string name;
        std::vector<std::string> body;  // its identifiers (other tokens count 1 each)
        double others = 0;              // tokens that are not identifiers
        std::string where;
    };
    std::vector<Define> defines_;
};

}  // namespace fx::gl
