// Numbers in a lesson's text written as references to the facts they quote.
#include <gtest/gtest.h>

#include <map>

#include "base/fact_references.hpp"

namespace fx {
namespace {

const std::map<std::string, std::string> kFacts = {
    {"brightestEmitters", "firefly 900, sun 300, orange sphere 8"},
    {"levels", "6"},
    {"focusReadAs", "18.21 m"},
    {"drift", "unsung 3, sung -0.25e"},
};

std::optional<std::string> lookup(const std::string& name) {
    auto it = kFacts.find(name);
    return it == kFacts.end() ? std::nullopt : std::optional(it->second);
}

TEST(FactReferences, AReferenceReadsAsItsFactsValue) {
    EXPECT_EQ(
        resolveFactReferences("The firefly (about {fact:brightestEmitters firefly}) and the sun "
                              "({fact:brightestEmitters sun}); {fact:levels} levels, {fact:focusReadAs}.",
                              lookup),
        "The firefly (about 900) and the sun (300); 6 levels, 18.21 m.");
    EXPECT_EQ(resolveFactReferences("ホタル（約 {fact:brightestEmitters firefly}）", lookup),
              "ホタル（約 900）");
    // The word stands alone: "sung" is not inside "unsung"; a number's trailing marks are left out.
    EXPECT_EQ(resolveFactReferences("{fact:drift sung}", lookup), "-0.25");
}

TEST(FactReferences, AMissingFactShowsRatherThanAWrongNumber) {
    EXPECT_EQ(resolveFactReferences("{fact:nothing} and {fact:brightestEmitters moon}", lookup),
              "[nothing?] and [brightestEmitters moon?]");
    // Not references: left as written.
    EXPECT_EQ(resolveFactReferences("{fact:} {fact:levels {fact:x", lookup), "{fact:} {fact:levels {fact:x");
    EXPECT_EQ(resolveFactReferences("", lookup), "");
}

TEST(FactReferences, ListsEveryReference) {
    const auto refs = factReferences("a {fact:levels} b {fact:brightestEmitters sun} {fact:}");
    ASSERT_EQ(refs.size(), 2u);
    EXPECT_EQ(refs[0].name, "levels");
    EXPECT_EQ(refs[0].word, "");
    EXPECT_EQ(refs[1].name, "brightestEmitters");
    EXPECT_EQ(refs[1].word, "sun");
}

}  // namespace
}  // namespace fx
