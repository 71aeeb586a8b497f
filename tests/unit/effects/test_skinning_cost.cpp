// The skinning cost counts (Shader effects chapter, §2.2, its numeric vectors): T*(J*p) is 32 mul + 24
// add a vertex and (T*J)*p 80 mul + 60 add. Here they are counted, not quoted: a scalar that counts its
// own multiplies and adds goes through the two products in each order as GLSL evaluates them (each
// element of a product is a dot product), and the counts must be what operationCount, which lessons 01
// and 02 show, says. With plain floats the two orders give the same vertex: the count changes, not
// the result.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "effects/shadow/shadow_map.hpp"

namespace {

using namespace fx;

struct Tally {
    int mul = 0, add = 0;
};
Tally tally;

// A float that counts what is done to it.
struct Counted {
    float v = 0.0f;
};
Counted operator*(Counted a, Counted b) {
    ++tally.mul;
    return {a.v * b.v};
}
Counted operator+(Counted a, Counted b) {
    ++tally.add;
    return {a.v + b.v};
}

template <class T>
using Vec4 = std::array<T, 4>;
template <class T>
using Mat4 = std::array<Vec4<T>, 4>;  // columns, as GLSL and GLM store them

// Element r of m * v: row r of m dotted with v (4 multiplies, 3 adds).
template <class T>
T dot(const Mat4<T>& m, int r, const Vec4<T>& v) {
    T sum = m[0][std::size_t(r)] * v[0];
    for (std::size_t c = 1; c < 4; ++c) sum = sum + m[c][std::size_t(r)] * v[c];
    return sum;
}
template <class T>
Vec4<T> times(const Mat4<T>& m, const Vec4<T>& v) {
    return {dot(m, 0, v), dot(m, 1, v), dot(m, 2, v), dot(m, 3, v)};
}
template <class T>
Mat4<T> times(const Mat4<T>& a, const Mat4<T>& b) {
    return {times(a, b[0]), times(a, b[1]), times(a, b[2]), times(a, b[3])};
}

template <class T>
Mat4<T> matrix(float seed) {
    Mat4<T> m;
    for (std::size_t c = 0; c < 4; ++c)
        for (std::size_t r = 0; r < 4; ++r) m[c][r] = T{std::sin(seed + float(4 * c + r))};
    return m;
}

TEST(SkinningCost, EachOrderCostsWhatItsProductsCountAndGivesTheSameVertex) {
    const Mat4<Counted> t = matrix<Counted>(1.0f), j = matrix<Counted>(2.0f);
    const Vec4<Counted> p = {Counted{0.5f}, Counted{-1.0f}, Counted{2.0f}, Counted{1.0f}};

    tally = {};
    Vec4<Counted> parenthesised = times(t, times(j, p));  // T*(J*p)
    const Tally perVertex = tally;
    tally = {};
    Vec4<Counted> grouped = times(times(t, j), p);  // (T*J)*p
    const Tally groupedPerVertex = tally;

    EXPECT_EQ(perVertex.mul, operationCount(SkinningProduct::parenthesised).mul);
    EXPECT_EQ(perVertex.add, operationCount(SkinningProduct::parenthesised).add);
    EXPECT_EQ(groupedPerVertex.mul, operationCount(SkinningProduct::grouped).mul);
    EXPECT_EQ(groupedPerVertex.add, operationCount(SkinningProduct::grouped).add);
    // The chapter's numbers.
    EXPECT_EQ(perVertex.mul + perVertex.add, 32 + 24);
    EXPECT_EQ(groupedPerVertex.mul + groupedPerVertex.add, 80 + 60);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(parenthesised[i].v, grouped[i].v, 1e-5f) << i;
}

}  // namespace
