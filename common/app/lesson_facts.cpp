#include "app/lesson_facts.hpp"

#include "base/log.hpp"

namespace fx {

namespace {
std::string labelOf(const std::string& name, const WordArgs& args) {
    return say("fact." + name, args);
}
}  // namespace

void Facts::add(std::string name, std::string value, const WordArgs& args) {
    std::string label = labelOf(name, args);
    facts_.push_back({std::move(name), std::move(value), std::move(label), true, -1, 0});
}

void Facts::addAs(std::string name, std::string_view key, std::string value, const WordArgs& args) {
    std::string label = say(cat("fact.", key), args);
    facts_.push_back({std::move(name), std::move(value), std::move(label), true, -1, 0});
}

void Facts::add(std::string name, bool value, const WordArgs& args) {
    add(std::move(name), std::string(value ? "true" : "false"), args);
}

void Facts::progress(std::string name, int done, int total, const WordArgs& args) {
    std::string label = labelOf(name, args);
    facts_.push_back({std::move(name), std::to_string(done) + " of " + std::to_string(total),
                      std::move(label), true, done, total});
}

void Facts::progressAs(std::string name, std::string_view key, int done, int total, const WordArgs& args) {
    std::string label = say(cat("fact.", key), args);
    facts_.push_back({std::move(name), std::to_string(done) + " of " + std::to_string(total),
                      std::move(label), true, done, total});
}

void Facts::check(std::string name, std::string value) {
    facts_.push_back({std::move(name), std::move(value), {}, false, -1, 0});
}

void Facts::check(std::string name, bool value) {
    check(std::move(name), std::string(value ? "true" : "false"));
}

const std::string* Facts::find(const std::string& name) const {
    for (const Fact& f : facts_) {
        if (f.name == name) return &f.value;
    }
    return nullptr;
}

}  // namespace fx
