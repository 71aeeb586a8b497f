#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/image_stats.hpp"
#include "image/plot.hpp"
#include "image/png_file.hpp"

namespace fx {
namespace {

// A bloom quality sweep as the benchmark would report it: time in ms, RMSE against the reference.
ScatterPlot bloomSweep() {
    ScatterPlot plot;
    plot.title = "bloom: error against time";
    plot.xLabel = "GPU time per frame (ms)";
    plot.yLabel = "RMSE against reference";
    plot.logY = true;
    plot.points = {
        {"3 levels", 0.42, 0.031},
        {"4 levels", 0.55, 0.012},
        {"5 levels", 0.61, 0.0046, false, true},
        {"5 levels, 13 tap", 0.83, 0.0052},
        {"6 levels", 0.74, 0.0021},
        {"6 levels, 13 tap", 1.10, 0.0024},
        {"8 levels, 25 tap", 1.62, 0.0, true},
    };
    return plot;
}

Rgba pixelAt(const ByteImage& image, double canvasX, double canvasY) {
    // Layout coordinates grow downwards; the image is stored bottom-up.
    const int x = static_cast<int>(std::floor(canvasX)),
              y = image.height - 1 - static_cast<int>(std::floor(canvasY));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return {};
    const std::uint8_t* t = &image.texel(x, y, 0);
    return {t[0], t[1], t[2], t[3]};
}

bool colourNear(const ByteImage& image, double x, double y, Rgba colour, int radius) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
            if (pixelAt(image, x + dx, y + dy) == colour) return true;
    return false;
}

int countColour(const ByteImage& image, Rgba colour) {
    int count = 0;
    for (std::size_t i = 0; i < image.texels.size(); i += 4)
        if (Rgba{image.texels[i], image.texels[i + 1], image.texels[i + 2], image.texels[i + 3]} == colour)
            ++count;
    return count;
}

TEST(Plot, ParetoFrontKeepsOnlyUndominatedPointsInXOrder) {
    const ScatterPlot plot = bloomSweep();
    const std::vector<std::size_t> front = paretoFront(plot.points);
    // 3 levels (fastest), 4 levels, 5 levels, 6 levels, reference (zero error). The 13- and 25-tap
    // variants below the reference are slower and worse than "6 levels".
    EXPECT_EQ(front, (std::vector<std::size_t>{0, 1, 2, 4, 6}));
}

TEST(Plot, ParetoFrontSkipsNanAndDuplicates) {
    std::vector<PlotPoint> points = {{"a", 1, 1}, {"b", 1, 1}, {"nan", std::nan(""), 0.0}, {"c", 2, 0.5}};
    EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{0, 3}));
    EXPECT_TRUE(paretoFront({}).empty());
}

// Times measured with a spread: a point that is cheaper only within the noise is no trade-off.
TEST(Plot, ParetoFrontJoinsOnlyPointsWhoseSpreadsDoNotOverlap) {
    PlotPoint a{"a", 10.0, 0.02}, b{"b", 10.5, 0.01}, c{"c", 30.0, 0.001};
    // Without spreads all three are a trade-off.
    EXPECT_EQ(paretoFront({a, b, c}), (std::vector<std::size_t>{0, 1, 2}));
    // a's time overlaps b's: b is as cheap as far as anyone can tell, and more accurate.
    a.xLow = 9.0, a.xHigh = 11.0;
    b.xLow = 9.5, b.xHigh = 11.5;
    c.xLow = 28.0, c.xHigh = 33.0;
    EXPECT_EQ(paretoFront({a, b, c}), (std::vector<std::size_t>{1, 2}));
    // Spreads that stay apart keep both.
    a.x = 9.2, a.xLow = 9.0, a.xHigh = 9.4;
    EXPECT_EQ(paretoFront({a, b, c}), (std::vector<std::size_t>{0, 1, 2}));
}

// Lesson 01's mesh detail as measured: each cheaper setting's spread overlaps the next one's, so
// the front steps from the most accurate down only to settings clearly cheaper than the last.
TEST(Plot, ParetoFrontStepsOnlyToClearlyCheaperSettings) {
    std::vector<PlotPoint> p = {{"16", 1.51, 0.0196},
                                {"32", 1.94, 0.0098},
                                {"64", 2.4, 0.0046},
                                {"128", 5.11, 0.0020},
                                {"256", 17.3, 0.0, true}};
    const double spread[][2] = {{1.04, 1.7}, {1.12, 2.32}, {2.25, 4.59}, {3.33, 7.11}, {14.0, 21.5}};
    for (std::size_t i = 0; i < p.size(); ++i) p[i].xLow = spread[i][0], p[i].xHigh = spread[i][1];
    EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{1, 3, 4}));
}

// The bloom bench: settings near 10 copies and a reference near 550 on one axis.
TEST(Plot, WideXRangeGetsALogAxisAndSettingsStayApart) {
    EXPECT_TRUE(wantsLogAxis(10.0, 550.0));
    EXPECT_FALSE(wantsLogAxis(10.0, 150.0));
    EXPECT_FALSE(wantsLogAxis(0.0, 550.0));
    ScatterPlot plot;
    for (int i = 0; i < 6; ++i)
        plot.points.push_back({std::to_string(i + 2), 10.0 + i * 0.5, 0.01 * (6 - i)});
    plot.points.push_back({"Gaussian", 550.0, 0.0, true});
    PlotLayout layout = layoutScatterPlot(plot, 960, 600);
    EXPECT_TRUE(layout.xAxis.logarithmic);
    // On a linear axis 0.5 copies would be under 1 pixel apart; on the log axis they are several.
    EXPECT_GT(layout.pixelX(10.5) - layout.pixelX(10.0), 4.0);
    plot.logX = false;
    EXPECT_FALSE(layoutScatterPlot(plot, 960, 600).xAxis.logarithmic);
}

// Crowded points: every label drawn overlaps no other label and no marker.
TEST(Plot, LabelsNeverOverlap) {
    ScatterPlot plot;
    for (int i = 0; i < 14; ++i)
        plot.points.push_back({"setting " + std::to_string(i), 10.0 + i * 0.05, 0.02 + 0.0005 * (i % 3)});
    plot.points.push_back({"ref", 11.0, 0.0, true});
    std::vector<PlotBox> labels;
    renderScatterPlot(plot, 640, 400, &labels);
    ASSERT_FALSE(labels.empty());
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            EXPECT_EQ(labels[i].overlap(labels[j]), 0.0) << i << " and " << j;
    // Spread out, every point gets its label.
    ScatterPlot sparse;
    for (int i = 0; i < 5; ++i) sparse.points.push_back({"s" + std::to_string(i), 1.0 + i, 0.1 * (5 - i)});
    renderScatterPlot(sparse, 960, 600, &labels);
    EXPECT_EQ(labels.size(), 5u);
}

TEST(Plot, SampleSweepDrawsFrontMarkersAndText) {
    const ScatterPlot plot = bloomSweep();
    const ByteImage image = renderScatterPlot(plot, 960, 600);
    ASSERT_EQ(image.width, 960);
    ASSERT_EQ(image.height, 600);
    ASSERT_EQ(image.channels, 4);
    EXPECT_FALSE(isFlat(image, 10));
    // Written for a person to look at; not needed by the test itself.
    EXPECT_TRUE(writePng("/tmp/fx_plot_sample.png", image).ok());

    const PlotLayout layout = layoutScatterPlot(plot, 960, 600);
    const std::vector<std::size_t> front = paretoFront(plot.points);
    for (std::size_t k = 0; k + 1 < front.size(); ++k) {
        const PlotPoint& a = plot.points[front[k]];
        const PlotPoint& b = plot.points[front[k + 1]];
        const double mx = (layout.pixelX(a.x) + layout.pixelX(b.x)) / 2.0;
        const double my = (layout.pixelY(a.y) + layout.pixelY(b.y)) / 2.0;
        EXPECT_TRUE(colourNear(image, mx, my, plot_colours::kParetoFront, 1)) << "segment " << k;
    }
    // Each ordinary point's centre is blue, the current one red.
    EXPECT_EQ(pixelAt(image, layout.pixelX(0.83), layout.pixelY(0.0052)), plot_colours::kPoint);
    EXPECT_EQ(pixelAt(image, layout.pixelX(0.61), layout.pixelY(0.0046)), plot_colours::kCurrent);
    // The reference (error 0) sits on the log floor, inside the frame, with the floor noted.
    const double referenceY = layout.pixelY(0.0);
    EXPECT_GT(referenceY, layout.top);
    EXPECT_LT(referenceY, layout.bottom);
    EXPECT_EQ(pixelAt(image, layout.pixelX(1.62), referenceY), plot_colours::kInk);  // the centre dot
    ASSERT_EQ(layout.notes.size(), 1u);
    EXPECT_NE(layout.notes[0].find("y <= 0"), std::string::npos);
    // There is a good deal of ink: text, ticks, the frame.
    EXPECT_GT(countColour(image, plot_colours::kInk), 3000);
}

TEST(Plot, LinearAxesPlaceValuesProportionally) {
    ScatterPlot plot;
    plot.points = {{"a", 0.0, 0.0}, {"b", 10.0, 5.0}};
    const PlotLayout layout = layoutScatterPlot(plot, 640, 480);
    EXPECT_LT(layout.pixelX(0.0), layout.pixelX(10.0));
    EXPECT_GT(layout.pixelY(0.0), layout.pixelY(5.0));  // y grows upwards on the page
    EXPECT_NEAR(layout.pixelX(5.0), (layout.pixelX(0.0) + layout.pixelX(10.0)) / 2.0, 1e-9);
    EXPECT_GT(layout.pixelX(0.0), layout.left);
    EXPECT_LT(layout.pixelX(10.0), layout.right);
}

TEST(Plot, DegenerateInputsStillGiveAPictureAndANote) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ScatterPlot empty;
    empty.title = "nothing yet";
    const ByteImage emptyImage = renderScatterPlot(empty);
    EXPECT_FALSE(isFlat(emptyImage, 0));
    EXPECT_FALSE(layoutScatterPlot(empty, 960, 600).notes.empty());

    ScatterPlot one;
    one.points = {{"only", 2.0, 0.5}};
    const PlotLayout oneLayout = layoutScatterPlot(one, 960, 600);
    EXPECT_GT(oneLayout.pixelX(2.0), oneLayout.left);
    EXPECT_LT(oneLayout.pixelX(2.0), oneLayout.right);
    EXPECT_FALSE(isFlat(renderScatterPlot(one), 0));

    ScatterPlot sameX;
    sameX.logY = true;
    sameX.points = {{"a", 1.0, 0.1}, {"b", 1.0, 0.01}, {"c", 1.0, 0.001}};
    EXPECT_FALSE(isFlat(renderScatterPlot(sameX), 0));

    ScatterPlot allZero;
    allZero.logY = true;
    allZero.points = {{"a", 1.0, 0.0}, {"b", 2.0, 0.0}};
    const PlotLayout zeroLayout = layoutScatterPlot(allZero, 960, 600);
    EXPECT_FALSE(zeroLayout.yAxis.logarithmic);
    EXPECT_FALSE(zeroLayout.notes.empty());

    ScatterPlot withNan;
    withNan.points = {
        {"good", 1.0, 1.0}, {"broken", nan, 1.0}, {"inf", 2.0, std::numeric_limits<double>::infinity()}};
    const PlotLayout nanLayout = layoutScatterPlot(withNan, 960, 600);
    ASSERT_EQ(nanLayout.notes.size(), 1u);
    EXPECT_NE(nanLayout.notes[0].find("broken"), std::string::npos);
    EXPECT_NE(nanLayout.notes[0].find("inf"), std::string::npos);
    EXPECT_FALSE(isFlat(renderScatterPlot(withNan), 0));
}

TEST(Plot, TinyAndZeroSizesDoNotCrash) {
    const ScatterPlot plot = bloomSweep();
    for (auto [w, h] : {std::pair{0, 0}, {1, 1}, {40, 30}, {200, 120}}) {
        const ByteImage image = renderScatterPlot(plot, w, h);
        EXPECT_EQ(image.width, w);
        EXPECT_EQ(image.height, h);
        EXPECT_EQ(image.texels.size(), static_cast<std::size_t>(w) * h * 4);
    }
}

// Lesson 09's max_coc: 16, 32 and 64 px give the same picture at the same cost; 8 clamps the blur.
// The taps: 16 and 22 cost the same within their spreads, 43 and 71 clearly more.
TEST(Plot, SettingsThatCostTheSameShowAsSuchInTheOrderOfTheirValues) {
    ScatterPlot maxCoc;
    maxCoc.points = {{"8", 36.2, 0.020, false, false, 35.0, 37.5},
                     {"16", 35.9, 0.015, false, true, 34.9, 37.0},
                     {"32", 36.4, 0.015, false, false, 35.2, 37.9},
                     {"64", 35.5, 0.015, true, false, 34.6, 36.8}};
    ScatterPlot g = groupEqualCosts(maxCoc);
    ASSERT_EQ(g.points.size(), 2u);
    EXPECT_EQ(g.points[0].label, "8");
    EXPECT_EQ(g.points[1].label, "16 = 32 = 64") << "one marker, the values in their order";
    EXPECT_TRUE(g.points[1].isReference);
    EXPECT_TRUE(g.points[1].isCurrent);
    EXPECT_DOUBLE_EQ(g.points[0].x, g.points[1].x) << "one cost for the group: the median";
    EXPECT_DOUBLE_EQ(g.points[0].x, 0.5 * (35.9 + 36.2));
    EXPECT_DOUBLE_EQ(g.points[1].xLow, 34.6);
    EXPECT_DOUBLE_EQ(g.points[1].xHigh, 37.9);
    ASSERT_EQ(g.notes.size(), 1u);
    EXPECT_EQ(g.notes[0], "same cost within the spread, drawn at one: 8, 16, 32, 64");

    ScatterPlot taps;
    taps.points = {{"16", 32.0, 0.0166, false, false, 30.5, 34.0},
                   {"22", 31.5, 0.0167, false, true, 30.0, 36.8},
                   {"43", 45.9, 0.0166, false, false, 44.0, 47.0},
                   {"71", 62.3, 0.0153, false, false, 57.5, 64.0},
                   {"accumulation", 560.0, 0.0, true, false, 540.0, 590.0}};
    g = groupEqualCosts(taps);
    ASSERT_EQ(g.points.size(), 5u);
    EXPECT_EQ(g.points[0].label, "16");
    EXPECT_EQ(g.points[1].label, "22");
    EXPECT_EQ(g.points[0].x, g.points[1].x) << "16 and 22: no order of cost to show";
    EXPECT_DOUBLE_EQ(g.points[2].x, 45.9) << "43 stands apart";
    EXPECT_EQ(g.notes, (std::vector<std::string>{"same cost within the spread, drawn at one: 16, 22"}));
    // Without spreads only equal costs group; NaN stays for the layout to name.
    ScatterPlot plain;
    plain.points = {{"a", 1.0, 0.5}, {"b", 1.0, 0.5}, {"c", 2.0, 0.1}, {"d", std::nan(""), 0.2}};
    g = groupEqualCosts(plain);
    ASSERT_EQ(g.points.size(), 3u);
    EXPECT_EQ(g.points[0].label, "a = b");
    EXPECT_EQ(g.points[1].label, "c");
    EXPECT_EQ(g.points[2].label, "d");
    // The picture draws the grouped plot: its labels hold the merged one.
    EXPECT_FALSE(isFlat(renderScatterPlot(maxCoc), 0));
}

}  // namespace
}  // namespace fx
