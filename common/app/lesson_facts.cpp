#include "app/lesson_facts.hpp"

namespace fx {

void Facts::add(std::string name, std::string value, std::string label) {
    facts_.push_back({std::move(name), std::move(value), std::move(label), true, -1, 0});
}

void Facts::add(std::string name, bool value, std::string label) {
    add(std::move(name), std::string(value ? "true" : "false"), std::move(label));
}

void Facts::progress(std::string name, int done, int total, std::string label) {
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
