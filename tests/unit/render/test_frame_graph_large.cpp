// A frame graph of a thousand passes compiles to what the plain definitions give: the duplicate-name
// errors are those a comparison of every pair finds, and the report lists the passes that run in
// execution order, then the others in derived order. compile() uses a set of names and a table of
// listed passes for these (linear in the frame's size); the tests check them against the pairwise
// scans they replaced.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

namespace fx {
namespace {

using Names = std::vector<std::string>;

const TextureDesc kHdr{TextureSize::output(), TextureFormat::RGBA16F};

// "two <what> are named '<name>'" for every name an earlier one already had, by comparing pairs.
Names pairwiseDuplicates(const Names& names, const std::string& what) {
    Names errors;
    for (std::size_t i = 0; i < names.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (names[i] == names[j]) {
                errors.push_back("two " + what + " are named '" + names[i] + "'");
                break;
            }
        }
    }
    return errors;
}

// The report's rows by the definition: execution order, then every other pass in derived order.
std::vector<std::uint32_t> expectedRows(const FrameGraph& graph) {
    std::vector<std::uint32_t> rows = graph.executionOrder();
    for (std::uint32_t p : graph.derivedOrder()) {
        if (std::find(rows.begin(), rows.end(), p) == rows.end()) rows.push_back(p);
    }
    return rows;
}

std::vector<std::uint32_t> reportRows(const FrameGraph& graph) {
    std::vector<std::uint32_t> rows;
    for (const PassRecord& p : graph.report().passes) rows.push_back(p.declaredIndex);
    return rows;
}

// A chain declared back to front (pass k reads what pass k+1 makes, so the derived order reverses
// the declared one), and beside it a second chain, also back to front, that reaches nothing: its
// passes are culled, disabled, or miss an input from a disabled one. The report's rows then mix
// passes that run with passes that do not, and the latter's derived order is not their declared one.
TEST(FrameGraphLarge, AThousandPassesReportTheirRowsInExecutionThenDerivedOrder) {
    constexpr int kChain = 1000;
    FrameGraph graph({.size = {64, 64}});
    std::vector<TextureHandle> chain, unused;
    for (int k = 0; k < kChain; ++k) {
        chain.push_back(graph.declareTexture("chain." + std::to_string(k), kHdr));
        unused.push_back(graph.declareTexture("unused." + std::to_string(k), kHdr));
    }
    for (int k = 0; k < kChain; ++k) {
        Pass& pass = graph.addPass("step " + std::to_string(k));
        pass.writeColor(chain[std::size_t(k)]);
        if (k + 1 < kChain) pass.read(chain[std::size_t(k + 1)]);
        if (k % 50 == 7) {
            Pass& side = graph.addPass("side " + std::to_string(k));
            side.read(chain[std::size_t(k)]).writeColor(unused[std::size_t(k)]);
            if (k + 50 < kChain) side.read(unused[std::size_t(k + 50)]);
            if (k % 100 == 7) side.disable("switched off by the test");
        }
    }
    graph.addPass("present").read(chain[0]).writeColor(graph.output());
    ASSERT_TRUE(graph.compile().ok()) << graph.compile().error();

    ASSERT_EQ(graph.derivedOrder().size(), graph.passCount());
    EXPECT_EQ(graph.executionOrder().size(), std::size_t(kChain) + 1) << "the chain and present run";
    EXPECT_EQ(graph.pass(graph.executionOrder().front()).name(), "step 999");
    EXPECT_EQ(graph.pass(graph.executionOrder().back()).name(), "present");
    EXPECT_EQ(reportRows(graph), expectedRows(graph));
    EXPECT_EQ(graph.report().passes.back().name, "side 7") << "the side chain in derived order: 957 first";
    // The rows' records belong to their passes, and those that do not run say why: side 957 makes
    // what only switched-off passes read, side 907, 807 ... 7 are disabled, and 857, 757 ... 57 miss
    // the input a disabled pass did not make.
    int unusedOutput = 0, disabled = 0, missingInput = 0;
    for (const PassRecord& record : graph.report().passes) {
        EXPECT_EQ(record.name, graph.pass(record.declaredIndex).name());
        unusedOutput += record.status == PassStatus::OutputUnused ? 1 : 0;
        disabled += record.status == PassStatus::Disabled ? 1 : 0;
        missingInput += record.status == PassStatus::MissingInput ? 1 : 0;
    }
    EXPECT_EQ(unusedOutput, 1);
    EXPECT_EQ(disabled, 10);
    EXPECT_EQ(missingInput, 9);
}

// Names that repeat (every one of 300 names comes back, some three or four times): one error per
// repeat, in declaration order, for passes and for textures, as the pairwise scan gives them. Rows
// still follow the derived order when the graph has errors.
TEST(FrameGraphLarge, RepeatedNamesGiveTheErrorsAPairwiseScanGives) {
    constexpr int kPasses = 1000;
    FrameGraph graph({.size = {64, 64}});
    Names passNames{}, textureNames{"output"};
    TextureHandle previous = graph.output();
    for (int i = 0; i < kPasses; ++i) {
        passNames.push_back("pass " + std::to_string((i * 7) % 300));
        textureNames.push_back("texture " + std::to_string((i * 11) % 450));
        Pass& pass = graph.addPass(passNames.back());
        TextureHandle made = pass.create(textureNames.back(), kHdr, TextureUsage::ColorAttachment);
        if (i > 0) pass.read(previous);
        previous = made;
    }
    graph.addPass("present").read(previous).writeColor(graph.output());
    passNames.push_back("present");
    ASSERT_FALSE(graph.compile().ok());

    Names expected = pairwiseDuplicates(textureNames, "textures");
    Names forPasses = pairwiseDuplicates(passNames, "passes");
    ASSERT_EQ(expected.size(), std::size_t(kPasses - 450)) << "the test's names repeat as meant";
    ASSERT_EQ(forPasses.size(), std::size_t(kPasses + 1 - 301));
    expected.insert(expected.end(), forPasses.begin(), forPasses.end());
    EXPECT_EQ(graph.errors(), expected);

    ASSERT_TRUE(graph.executionOrder().empty());
    EXPECT_EQ(reportRows(graph), expectedRows(graph));
    EXPECT_EQ(reportRows(graph).size(), graph.passCount());
}

}  // namespace
}  // namespace fx
