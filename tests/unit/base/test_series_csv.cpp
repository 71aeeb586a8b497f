#include <gtest/gtest.h>

#include "base/series_csv.hpp"

namespace fx {
namespace {

const SeriesColumns kSweep{"lights", "culling", {"lighting_ms", "culling_ms"}};

TEST(SeriesCsv, QuotedFieldsKeepCommasAndDoubledQuotes) {
    const std::vector<std::string> f = splitCsvLine(R"(a,"b, c","say ""hi""",)");
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(f[0], "a");
    EXPECT_EQ(f[1], "b, c");
    EXPECT_EQ(f[2], "say \"hi\"");
    EXPECT_EQ(f[3], "");
}

TEST(SeriesCsv, RepeatedRunsGiveTheirMedianAndSeriesKeepTheTablesOrder) {
    const char* table =
        "lights,culling,run,lighting_ms,culling_ms\r\n"
        "16,tiled,1,30,10\n"
        "16,tiled,2,900,0\n"  // one slow run must not move the curve
        "16,tiled,3,35,10\n"
        "4,tiled,1,20,5\n"
        "\n"
        "4,none,1,8,0\n"
        "4,none,2,12,0\n";
    const Result<std::vector<Series>> read = readSeriesCsv(table, kSweep, "sweep.csv");
    ASSERT_TRUE(read.ok()) << read.error();
    const std::vector<Series>& series = *read;
    ASSERT_EQ(series.size(), 2u);
    EXPECT_EQ(series[0].name, "tiled");
    EXPECT_EQ(series[1].name, "none");
    ASSERT_EQ(series[0].points.size(), 2u);
    EXPECT_DOUBLE_EQ(series[0].points[0].x, 4.0);  // sorted by x, not by row
    EXPECT_DOUBLE_EQ(series[0].points[0].y, 25.0);
    EXPECT_EQ(series[0].points[0].runs, 1);
    EXPECT_DOUBLE_EQ(series[0].points[1].x, 16.0);
    EXPECT_DOUBLE_EQ(series[0].points[1].y, 45.0);  // sums 40, 900, 45: the median
    EXPECT_EQ(series[0].points[1].runs, 3);
    ASSERT_EQ(series[1].points.size(), 1u);
    EXPECT_DOUBLE_EQ(series[1].points[0].y, 10.0);  // an even count: the mean of the middle two
}

void expectError(const char* table, const SeriesColumns& columns, const std::string& expected) {
    const Result<std::vector<Series>> read = readSeriesCsv(table, columns, "sweep.csv");
    ASSERT_FALSE(read.ok()) << "accepted: " << table;
    EXPECT_NE(read.error().find(expected), std::string::npos) << read.error();
}

TEST(SeriesCsv, BadTablesNameTheFileLineAndColumn) {
    expectError("", kSweep, "sweep.csv: no header line");
    expectError("lights,culling,lighting_ms\n1,none,3\n", kSweep,
                "sweep.csv: no column 'culling_ms' in the header (it has lights, culling, lighting_ms)");
    expectError("lights,culling,run,lighting_ms,culling_ms\n", kSweep, "sweep.csv: no rows below the header");
    expectError("lights,culling,run,lighting_ms,culling_ms\n1,none,1,3\n", kSweep,
                "sweep.csv line 2: 4 fields, the header has 5");
    expectError("lights,culling,run,lighting_ms,culling_ms\n1,none,1,3,0\n1,none,2,3ms,0\n", kSweep,
                "sweep.csv line 3, column lighting_ms: '3ms' is not a finite number");
    expectError("lights,culling,run,lighting_ms,culling_ms\nnan,none,1,3,0\n", kSweep,
                "column lights: 'nan' is not a finite number");
    expectError("lights,culling,run,lighting_ms,culling_ms\n1,none,1,,0\n", kSweep,
                "column lighting_ms: '' is not a finite number");
    expectError("a,b\n1,2\n", SeriesColumns{"a", "b", {}}, "no column named for y");
}

}  // namespace
}  // namespace fx
