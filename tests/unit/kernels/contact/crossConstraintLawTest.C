// Unit tests of the cross-constraint normal law,
// src/kernels/contact/crossConstraintLaw (our formulation from Zavarise,
// Wriggers & Schrefler 1998, IJNME 42:473, and the CMISS implementation).
// The slope is checked against central differences with a tolerance
// built from the step (truncation h^2/6 max|p'''|, rounding an ulp of p
// over 2h); C1 continuity at g = 0 is checked from both sides; the
// degenerate sweep checks that no input raises a trapped floating-point
// exception, and the open side not even an underflow.

#include "crossConstraintLaw.H"

#include <gtest/gtest.h>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

using namespace c4f::contact;

namespace
{

// The floating-point exceptions that OpenFOAM traps (FOAM_SIGFPE)
const int trapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

// (lambda, eps) pairs from a soft to a stiff contact, including decay
// lengths lambda/eps from 1e-9 to 10
const std::vector<std::pair<double, double>> params
{
    {1e6, 1e12}, {1e8, 2.69e14}, {1e3, 1e12}, {1.0, 0.1}, {3e9, 1e15}
};

} // End anonymous namespace


TEST(crossConstraintLaw, valuesOnBothSides)
{
    const double lambda = 1e6, eps = 1e12, L = lambda/eps;

    const NormalLawValue pen = crossConstraintPressure(-1e-6, lambda, eps);
    EXPECT_DOUBLE_EQ(pen.pressure, 2e6);
    EXPECT_EQ(pen.dPressureDGap, -eps);

    // One decay length open: lambda/e and slope -eps/e
    const NormalLawValue open = crossConstraintPressure(L, lambda, eps);
    EXPECT_NEAR(open.pressure, lambda*std::exp(-1.0), 4*DBL_EPSILON*lambda);
    EXPECT_NEAR(open.dPressureDGap, -eps*std::exp(-1.0), 4*DBL_EPSILON*eps);
}

TEST(crossConstraintLaw, derivativeMatchesCentralDifferences)
{
    for (const auto& [lambda, eps] : params)
    {
        const double L = lambda/eps;   // open-side decay length
        const double h = 1e-5*L;
        for (const double s :
            {-30.0, -3.0, -1.0, -0.1, -1e-3, 1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0})
        {
            const double g = s*L;
            const double pPlus = crossConstraintPressure(g + h, lambda, eps).pressure;
            const double pMinus = crossConstraintPressure(g - h, lambda, eps).pressure;
            const double fd = (pPlus - pMinus)/(2*h);

            // Open side: |p'''| = (eps^3/lambda^2) exp(-g/L), largest at
            // g - h; the penetrated side is linear. Rounding: a few ulp
            // of each value (exp and the products), and of g +- h times
            // the slope, over 2h.
            const double p3 = g > 0 ? eps*eps*eps/(lambda*lambda)*std::exp(-(g - h)/L) : 0.0;
            const double tol =
                h*h/6*p3
              + 4*DBL_EPSILON*(std::max(pPlus, pMinus) + eps*(std::abs(g) + h))/(2*h);
            EXPECT_NEAR(crossConstraintPressure(g, lambda, eps).dPressureDGap, fd, tol)
                << "lambda = " << lambda << ", eps = " << eps << ", g = " << g;
        }
    }
}

TEST(crossConstraintLaw, valueAndSlopeContinuousAtZeroGap)
{
    for (const auto& [lambda, eps] : params)
    {
        const double L = lambda/eps;
        const NormalLawValue v0 = crossConstraintPressure(0.0, lambda, eps);
        EXPECT_EQ(v0.pressure, lambda);
        EXPECT_EQ(v0.dPressureDGap, -eps);
        EXPECT_EQ(crossConstraintPressure(-0.0, lambda, eps).pressure, lambda);

        for (int k = 3; k <= 12; ++k)
        {
            const double d = std::pow(10.0, -k)*L;
            const NormalLawValue vOpen = crossConstraintPressure(d, lambda, eps);
            const NormalLawValue vPen = crossConstraintPressure(-d, lambda, eps);

            // One-sided limits of the value: |p(+-d) - lambda| <= eps d
            // (1 - exp(-x) <= x on the open side), plus an ulp of lambda
            const double ulp = 2*DBL_EPSILON*lambda;
            EXPECT_NEAR(vOpen.pressure, lambda, eps*d + ulp);
            EXPECT_NEAR(vPen.pressure, lambda, eps*d + ulp);

            // One-sided limits of the slope: the penetrated side is -eps
            // exactly, the open side within eps d/L of it
            EXPECT_EQ(vPen.dPressureDGap, -eps);
            EXPECT_NEAR(vOpen.dPressureDGap, -eps, eps*d/L + 2*DBL_EPSILON*eps);

            // One-sided difference quotients at 0 from each side: the
            // open one is off by the curvature, eps d/(2L), both by the
            // rounding of p over d
            const double qOpen = (vOpen.pressure - v0.pressure)/d;
            const double qPen = (v0.pressure - vPen.pressure)/d;
            EXPECT_NEAR(qOpen, -eps, eps*d/(2*L) + 2*ulp/d);
            EXPECT_NEAR(qPen, -eps, 2*ulp/d);
        }
    }
}

TEST(crossConstraintLaw, multiplierAtOrBelowZeroIsPenaltyLaw)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double lambda : {0.0, -0.0, -1.0, -1e6, -1e300, nan})
    {
        for (const double g : {-1.0, -1e-6, -1e-300, -0.0, 0.0, 1e-300, 1e-6, 1.0})
        {
            const NormalLawValue a = crossConstraintPressure(g, lambda, 1e12);
            const NormalLawValue b = penaltyPressure(g, 1e12);
            EXPECT_EQ(a.pressure, b.pressure) << "lambda = " << lambda << ", g = " << g;
            EXPECT_EQ(a.dPressureDGap, b.dPressureDGap) << "lambda = " << lambda << ", g = " << g;
        }
    }
}

TEST(crossConstraintLaw, tinyMultiplierTendsToPenaltyWithoutUnderflow)
{
    // lambda = 1e-300 and a subnormal one: the decay length is far below
    // any gap, so the open side has no pressure and no slope, reached
    // without forming an underflowing exp or product
    const double eps = 1e12;
    std::vector<NormalLawValue> open;
    std::feclearexcept(FE_ALL_EXCEPT);
    for (const double lambda : {1e-300, 1e-310, std::numeric_limits<double>::denorm_min()})
    {
        for (const double g : {1e-300, 1e-12, 1.0})
        {
            open.push_back(crossConstraintPressure(g, lambda, eps));
        }
    }
    const int raised = std::fetestexcept(FE_ALL_EXCEPT & ~FE_INEXACT);
    EXPECT_EQ(raised, 0);
    // Even the closest case (lambda = g = 1e-300: x = eps g/lambda = 1e12)
    // is far beyond where exp(-x) is representable
    for (const NormalLawValue& v : open)
    {
        EXPECT_EQ(v.pressure, 0.0);
        EXPECT_EQ(v.dPressureDGap, 0.0);
    }

    // The penetrated side keeps the multiplier plus the penalty
    const NormalLawValue pen = crossConstraintPressure(-1e-6, 1e-300, eps);
    EXPECT_DOUBLE_EQ(pen.pressure, 1e6);
    EXPECT_EQ(pen.dPressureDGap, -eps);
}

TEST(crossConstraintLaw, hugeOpenGapUnderflowsToZeroWithoutFlag)
{
    // x = eps g/lambda from 1e3 (where exp(-x) would underflow) to 1e306
    const double lambda = 1e6, eps = 1e12;
    std::vector<NormalLawValue> open;
    std::feclearexcept(FE_ALL_EXCEPT);
    for (const double g : {1e-3, 1.0, 1e3, 1e300, std::numeric_limits<double>::max()})
    {
        open.push_back(crossConstraintPressure(g, lambda, eps));
    }
    const int raised = std::fetestexcept(FE_ALL_EXCEPT & ~FE_INEXACT);
    EXPECT_EQ(raised, 0);
    for (const NormalLawValue& v : open)
    {
        EXPECT_EQ(v.pressure, 0.0);
        EXPECT_EQ(v.dPressureDGap, 0.0);
    }
}

TEST(crossConstraintLaw, largeExponentWithHugeMultiplierKeepsItsValue)
{
    // x = 720 > 700, where exp(-x) alone is subnormal but lambda exp(-x)
    // with lambda = 1e300 is a normal 2e-13: evaluated as
    // exp(log lambda - x), accurate to |log lambda - x| ulp
    const double lambda = 1e300, eps = 1e12, g = 720*lambda/eps;
    const NormalLawValue v = crossConstraintPressure(g, lambda, eps);
    const long double expected =
        static_cast<long double>(lambda)*std::exp(-720.0L);
    EXPECT_NEAR(v.pressure, static_cast<double>(expected), 1e-13*static_cast<double>(expected));
    // eps exp(-720) = 2e-301 is still normal and takes the same path
    const long double expectedSlope =
        -static_cast<long double>(eps)*std::exp(-720.0L);
    EXPECT_NEAR(v.dPressureDGap, static_cast<double>(expectedSlope),
                -1e-13*static_cast<double>(expectedSlope));
}

TEST(crossConstraintLaw, degenerateInputsStayFinite)
{
    std::vector<NormalLawValue> values;
    std::vector<double> gaps;
    std::vector<double> lambdas;
    int raisedOpen = 0;
    std::feclearexcept(FE_ALL_EXCEPT);
    for (const double eps : {1e-200, 1.0, 1e12, 1e200})
    {
        for (const double lambda : {-1e6, 0.0, 1e-300, 1.0, 1e6, 1e12, 1e200})
        {
            for (const double g :
                {-1e3, -1.0, -1e-12, -1e-300, -0.0, 0.0, 1e-300, 1e-12, 1.0, 1e3})
            {
                // Underflow is checked on the open side only: there the
                // law is built not to form one, while on the penetrated
                // side eps g is an ordinary product (as in penaltyPressure)
                if (g > 0)
                {
                    std::feclearexcept(FE_UNDERFLOW);
                }
                values.push_back(crossConstraintPressure(g, lambda, eps));
                if (g > 0)
                {
                    raisedOpen |= std::fetestexcept(FE_UNDERFLOW);
                }
                gaps.push_back(g);
                lambdas.push_back(lambda);
            }
        }
    }
    const int raised = std::fetestexcept(trapped);

    EXPECT_EQ(raised, 0);
    EXPECT_EQ(raisedOpen, 0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const NormalLawValue& v = values[i];
        EXPECT_TRUE(std::isfinite(v.pressure) && std::isfinite(v.dPressureDGap)) << i;
        EXPECT_GE(v.pressure, 0.0) << i;
        EXPECT_LE(v.dPressureDGap, 0.0) << i;
        // The open side never presses harder than the multiplier
        if (gaps[i] > 0)
        {
            EXPECT_LE(v.pressure, std::max(0.0, lambdas[i])) << i;
        }
    }
}

TEST(crossConstraintLaw, updateOnSpringModelReachesZeroGap)
{
    // The multiplier update lambda <- p(g) after each converged inner
    // solve, on the spring g = g0 + p/Kc: penetrated throughout, it is
    // the Uzawa iteration and tends to the exact multiplier -Kc g0
    const double Kc = 2.69e14, g0 = -1e-5, eps = 0.5*Kc, lambdaStar = -Kc*g0;
    double lambda = 0;
    for (int j = 0; j < 200; ++j)
    {
        double p = lambda;
        for (int it = 0; it < 50; ++it)
        {
            const NormalLawValue v = crossConstraintPressure(g0 + p/Kc, lambda, eps);
            p -= (p - v.pressure)/(1 - v.dPressureDGap/Kc);
        }
        lambda = crossConstraintPressure(g0 + p/Kc, lambda, eps).pressure;
    }
    EXPECT_NEAR(lambda, lambdaStar, 1e-10*lambdaStar);
}
