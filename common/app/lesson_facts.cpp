#include "app/lesson_facts.hpp"

namespace fx {

void Facts::add(std::string name, std::string value, std::string label) {
    facts_.push_back({std::move(name), std::move(value), std::move(label), true});
}

void Facts::add(std::string name, bool value, std::string label) {
    add(std::move(name), std::string(value ? "true" : "false"), std::move(label));
}

void Facts::check(std::string name, std::string value) {
    facts_.push_back({std::move(name), std::move(value), {}, false});
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
