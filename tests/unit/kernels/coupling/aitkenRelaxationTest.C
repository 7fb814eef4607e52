/*---------------------------------------------------------------------------*\
  contact4foam: unit tests of Aitken's dynamic relaxation
\*---------------------------------------------------------------------------*/

#include "aitkenRelaxation.H"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace c4f::coupling;

namespace
{

//- Run x <- x + omega (G(x) - x) with Aitken's factor on the linear map
//  G(x) = a + m x (component-wise); return the iterations to |r| < tol
int iterate
(
    const std::vector<double>& a,
    const std::vector<double>& m,
    double omega0,
    std::vector<double>& x,
    double tol = 1e-12
)
{
    std::vector<double> rPrev;
    double omega = omega0;
    for (int k = 0; k < 200; ++k)
    {
        std::vector<double> r(x.size());
        double norm = 0;
        for (size_t i = 0; i < x.size(); ++i)
        {
            r[i] = a[i] + m[i]*x[i] - x[i];
            norm += r[i]*r[i];
        }
        if (std::sqrt(norm) < tol)
        {
            return k;
        }
        if (!rPrev.empty())
        {
            AitkenSums s;
            for (size_t i = 0; i < x.size(); ++i)
            {
                accumulate(s, rPrev[i], r[i]);
            }
            omega = aitkenFactor(omega, s, 0.01, 1.0);
        }
        for (size_t i = 0; i < x.size(); ++i)
        {
            x[i] += omega*r[i];
        }
        rPrev = r;
    }
    return -1;
}

} // End anonymous namespace


// A scalar linear fixed point is solved exactly by the secant step: the
// second relaxed update lands on the solution
TEST(AitkenRelaxation, ScalarLinearMapConvergesInTwoSteps)
{
    // Dirichlet-Neumann with equal stiffness: G(x) = 1 - x, fixed point 0.5
    std::vector<double> x{0.0};
    const int k = iterate({1.0}, {-1.0}, 0.1, x);
    EXPECT_GE(k, 1);
    EXPECT_LE(k, 3);
    EXPECT_NEAR(x[0], 0.5, 1e-12);
}

// Plain iteration of G(x) = 1 - x never converges; Aitken does, for a
// spread of interface stiffness ratios
TEST(AitkenRelaxation, VectorMapWithSpreadOfRatios)
{
    const std::vector<double> m{-0.5, -1.0, -2.0, -0.9, -1.3};
    const std::vector<double> a{1.0, 2.0, -1.0, 0.3, 4.0};
    std::vector<double> x(m.size(), 0.0);
    const int k = iterate(a, m, 0.2, x);
    ASSERT_GT(k, 0);
    EXPECT_LT(k, 60);
    for (size_t i = 0; i < x.size(); ++i)
    {
        EXPECT_NEAR(x[i], a[i]/(1 - m[i]), 1e-10);
    }
}

TEST(AitkenRelaxation, FactorFromSums)
{
    // r_{k-1} = 1, r_k = -1 (factor -1 map with omega 1): omega = 0.5
    AitkenSums s;
    accumulate(s, 1.0, -1.0);
    EXPECT_DOUBLE_EQ(s.rPrevDotDiff, -2.0);
    EXPECT_DOUBLE_EQ(s.diffSqr, 4.0);
    EXPECT_DOUBLE_EQ(aitkenFactor(1.0, s, 0.01, 1.0), 0.5);
}

TEST(AitkenRelaxation, ClippedAndDegenerate)
{
    AitkenSums none;
    EXPECT_DOUBLE_EQ(aitkenFactor(0.3, none, 0.01, 1.0), 0.3);
    EXPECT_DOUBLE_EQ(aitkenFactor(5.0, none, 0.01, 1.0), 1.0);

    // Residual grew in the same direction: raw factor negative -> min
    AitkenSums grow;
    accumulate(grow, 1.0, 2.0);
    EXPECT_DOUBLE_EQ(aitkenFactor(0.5, grow, 0.01, 1.0), 0.01);

    // Residual barely shrank: raw factor huge -> max
    AitkenSums slow;
    accumulate(slow, 1.0, 0.999);
    EXPECT_DOUBLE_EQ(aitkenFactor(0.5, slow, 0.01, 1.0), 1.0);
}
