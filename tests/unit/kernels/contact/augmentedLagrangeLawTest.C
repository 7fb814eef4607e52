// Unit tests of the augmented Lagrange law and its Uzawa update,
// src/kernels/contact/augmentedLagrangeLaw.
// References: Simo & Laursen (1992); Wriggers, Computational Contact
// Mechanics (2nd ed. 2006), ch. 6, chapter eq. 2.14-2.15. The Uzawa rate
// is derived below on a scalar model problem and asserted, not assumed.

#include "augmentedLagrangeLaw.H"

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

// Steel, K = 2mu + lambda, over a 1 mm cell: the contact stiffness K/h a
// face sees, and the initial interference of the model problem
const double Kc = 2.69e14;
const double g0 = -1e-5;


// Scalar model problem: a spring of stiffness Kc pressed by a prescribed
// displacement, so that the gap under a pressure p is g = g0 + p/Kc.
// The inner loop solves p = P(g0 + p/Kc; lambda) by Newton with the law's
// own slope (piecewise linear: one step inside a branch).
double innerSolve(const double lambda, const double eps)
{
    double p = lambda;
    for (int it = 0; it < 50; ++it)
    {
        const NormalLawValue v = augmentedLagrangePressure(g0 + p/Kc, lambda, eps);
        const double R = p - v.pressure;
        if (std::abs(R) <= 1e-15*std::abs(v.pressure))
        {
            break;
        }
        p -= R/(1 - v.dPressureDGap/Kc);
    }
    return p;
}

} // End anonymous namespace


TEST(augmentedLagrangeLaw, pressureIsPenaltyShiftedByMultiplier)
{
    const double lambda = 1e6, eps = 1e12;
    EXPECT_DOUBLE_EQ(augmentedLagrangePressure(-1e-6, lambda, eps).pressure, 2e6);
    EXPECT_DOUBLE_EQ(augmentedLagrangePressure(0.0, lambda, eps).pressure, lambda);
    // An open face keeps a pressure while eps g < lambda
    EXPECT_DOUBLE_EQ(augmentedLagrangePressure(1e-7, lambda, eps).pressure, 9e5);
    EXPECT_EQ(augmentedLagrangePressure(1e-7, lambda, eps).dPressureDGap, -eps);
    EXPECT_EQ(augmentedLagrangePressure(2e-6, lambda, eps).pressure, 0.0);
    EXPECT_EQ(augmentedLagrangePressure(2e-6, lambda, eps).dPressureDGap, 0.0);
}

TEST(augmentedLagrangeLaw, exactlyAtReleaseIsInactive)
{
    // 3 - 2*1.5 is exactly 0 in binary: the one-sided rule takes p = 0,
    // slope 0, as penaltyPressure does at g = 0
    const NormalLawValue v = augmentedLagrangePressure(1.5, 3.0, 2.0);
    EXPECT_EQ(v.pressure, 0.0);
    EXPECT_EQ(v.dPressureDGap, 0.0);
}

TEST(augmentedLagrangeLaw, zeroMultiplierIsPenaltyLaw)
{
    for (const double eps : {1e-3, 1.0, 3.7e9, 1e14})
    {
        for (const double g : {-1.0, -1e-6, -1e-300, -0.0, 0.0, 1e-300, 1e-6, 1.0})
        {
            const NormalLawValue a = augmentedLagrangePressure(g, 0.0, eps);
            const NormalLawValue b = penaltyPressure(g, eps);
            EXPECT_EQ(a.pressure, b.pressure) << "g = " << g;
            EXPECT_EQ(a.dPressureDGap, b.dPressureDGap) << "g = " << g;
        }
    }
}

TEST(augmentedLagrangeLaw, derivativeMatchesCentralDifferencesAwayFromRelease)
{
    // Both branches are linear, so the central difference has no
    // truncation error: what remains is rounding, an ulp of the pressure
    // and of g +- h (times eps) in each of the two values, over 2h
    for (const auto& [lambda, eps] :
        std::vector<std::pair<double, double>>{{0, 1e12}, {1e6, 1e12}, {5e8, 3e14}, {2.0, 0.5}})
    {
        // Length scale: the release gap lambda/eps (or 1 um for lambda = 0)
        const double L = lambda > 0 ? lambda/eps : 1e-6;
        const double h = 1e-4*L;
        for (const double s : {-30.0, -3.0, -1.0, -0.1, -1e-3, 1e-3, 0.1, 0.5, 0.99, 1.01, 2.0, 30.0})
        {
            const double g = s*L;
            const double pPlus = augmentedLagrangePressure(g + h, lambda, eps).pressure;
            const double pMinus = augmentedLagrangePressure(g - h, lambda, eps).pressure;
            const double fd = (pPlus - pMinus)/(2*h);
            const double tol =
                2*DBL_EPSILON*(std::max(pPlus, pMinus) + eps*(std::abs(g) + h))/(2*h);
            EXPECT_NEAR(augmentedLagrangePressure(g, lambda, eps).dPressureDGap, fd, tol)
                << "lambda = " << lambda << ", eps = " << eps << ", g = " << g;
        }
    }
}

TEST(augmentedLagrangeLaw, degenerateInputsStayFinite)
{
    std::vector<NormalLawValue> values;
    std::vector<double> epsUsed;
    std::feclearexcept(FE_ALL_EXCEPT);
    for (const double eps : {1e-200, 1.0, 1e12, 1e200})
    {
        for (const double lambda : {-1e6, -0.0, 0.0, 1e-300, 1.0, 1e6, 1e12})
        {
            for (const double g :
                {-1e3, -1.0, -1e-12, -1e-300, -0.0, 0.0, 1e-300, 1e-12, 1.0, 1e3})
            {
                values.push_back(augmentedLagrangePressure(g, lambda, eps));
                epsUsed.push_back(eps);
            }
        }
    }
    const int raised = std::fetestexcept(trapped);

    EXPECT_EQ(raised, 0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        const NormalLawValue& v = values[i];
        EXPECT_TRUE(std::isfinite(v.pressure) && std::isfinite(v.dPressureDGap)) << i;
        EXPECT_GE(v.pressure, 0.0) << i;
        // Active (slope -eps) exactly when there is a pressure
        if (v.pressure > 0)
        {
            EXPECT_EQ(v.dPressureDGap, -epsUsed[i]) << i;
        }
        else
        {
            EXPECT_EQ(v.dPressureDGap, 0.0) << i;
        }
    }
}

TEST(augmentedLagrangeLaw, negativeMultiplierOnlyReleasesEarlier)
{
    // A negative multiplier is not clamped by the law: <lambda - eps g>
    // with lambda < 0 needs more penetration before it presses
    const double eps = 1e12;
    EXPECT_EQ(augmentedLagrangePressure(-1e-7, -1e6, eps).pressure, 0.0);
    EXPECT_DOUBLE_EQ(augmentedLagrangePressure(-2e-6, -1e6, eps).pressure, 1e6);
}

TEST(uzawa, updateIsTheLawsPressure)
{
    for (const double lambda : {-1e6, 0.0, 1e6})
    {
        for (const double g : {-1e-6, 0.0, 5e-7, 1e-5})
        {
            EXPECT_EQ(uzawaUpdate(lambda, g, 1e12),
                      augmentedLagrangePressure(g, lambda, 1e12).pressure);
        }
    }
}

// Rate on the model problem g = g0 + p/Kc. With the face active, the
// inner solve gives p_j = lambda_j - eps (g0 + p_j/Kc), i.e.
//     p_j (1 + eps/Kc) = lambda_j - eps g0,
// and the update takes lambda_{j+1} = p_j. The exact multiplier
// lambda* = -Kc g0 (zero gap) satisfies the same relation, so the error
// e_j = lambda_j - lambda* obeys
//     e_{j+1} = e_j/(1 + eps/Kc) = Kc/(Kc + eps) e_j
//             = (1/eps)/(1/eps + 1/Kc) e_j,
// and the gap of each solve is g_j = (p_j - lambda*)/Kc = e_{j+1}/Kc.
// (The rate is the penalty's share of the series compliance: large eps
// converges fast, eps -> 0 not at all.)
TEST(uzawa, convergesGeometricallyOnSpringModel)
{
    const double lambdaStar = -Kc*g0;
    for (const double scale : {0.1, 0.3, 1.0, 3.0})
    {
        const double eps = scale*Kc;
        const double rate = Kc/(Kc + eps);
        double lambda = 0;
        int checked = 0;
        for (int j = 0; j < 400 && std::abs(lambda - lambdaStar) > 1e-6*lambdaStar; ++j)
        {
            const double p = innerSolve(lambda, eps);
            const double g = g0 + p/Kc;
            const double next = uzawaUpdate(lambda, g, eps);

            // The update takes the converged pressure; the gap stays
            // penetrating and is the next error over Kc
            EXPECT_NEAR(next, p, 1e-14*lambdaStar);
            EXPECT_LT(g, 0.0);
            EXPECT_NEAR(g, (next - lambdaStar)/Kc, 1e-12*lambdaStar/Kc);

            EXPECT_NEAR((next - lambdaStar)/(lambda - lambdaStar), rate, 1e-6)
                << "eps/Kc = " << scale << ", update " << j;
            lambda = next;
            ++checked;
        }
        EXPECT_NEAR(lambda, lambdaStar, 1e-6*lambdaStar);
        // The number of updates is the one the rate predicts
        EXPECT_EQ(checked, static_cast<int>(std::ceil(std::log(1e-6)/std::log(rate))))
            << "eps/Kc = " << scale;
    }
}

TEST(uzawa, stopsWhenBothTestsHoldOnSpringModel)
{
    // Stopping at 1e-3 h penetration (h = 1 mm) and 1e-6 in the
    // multiplier: the multiplier test is the binding one here, and the
    // converged multiplier is within that tolerance of the exact one
    const double eps = 0.3*Kc, h = 1e-3, lambdaStar = -Kc*g0;
    double lambda = 0;
    bool converged = false;
    int updates = 0;
    while (!converged && updates < 400)
    {
        const double g = g0 + innerSolve(lambda, eps)/Kc;
        const double next = uzawaUpdate(lambda, g, eps);
        converged = uzawaConverged
        (
            std::max(0.0, -g), h, 1e-3,
            std::abs(next - lambda), std::abs(next), 1e-6
        );
        lambda = next;
        ++updates;
    }
    EXPECT_TRUE(converged);
    EXPECT_LT(updates, 100);
    // |d lambda| = |e_j|(1 - rate) <= 1e-6 lambda bounds the error by
    // 1e-6 lambda/(1 - rate) * rate
    const double rate = Kc/(Kc + eps);
    EXPECT_LE(std::abs(lambda - lambdaStar), 1.01e-6*lambdaStar*rate/(1 - rate));
}

TEST(uzawa, openModelProblemStaysAtZero)
{
    // A gap that never closes: no pressure, no multiplier, converged at
    // the first update
    const double gOpen = 1e-5, eps = Kc;
    const double next = uzawaUpdate(0.0, gOpen, eps);
    EXPECT_EQ(next, 0.0);
    EXPECT_TRUE(uzawaConverged(0.0, 1e-3, 1e-3, 0.0, 0.0, 1e-6));
}

TEST(uzawa, convergenceTest)
{
    const double h = 1e-3;
    EXPECT_TRUE(uzawaConverged(1e-7, h, 1e-3, 1.0, 1e7, 1e-6));
    EXPECT_TRUE(uzawaConverged(1e-6, h, 1e-3, 10.0, 1e7, 1e-6));   // both at the limit
    EXPECT_FALSE(uzawaConverged(2e-6, h, 1e-3, 1.0, 1e7, 1e-6));   // penetration
    EXPECT_FALSE(uzawaConverged(1e-7, h, 1e-3, 20.0, 1e7, 1e-6));  // multiplier
    EXPECT_TRUE(uzawaConverged(0.0, h, 1e-3, 0.0, 0.0, 1e-6));     // no contact
    EXPECT_FALSE(uzawaConverged(0.0, h, 1e-3, 1.0, 0.0, 1e-6));    // just released
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(uzawaConverged(nan, h, 1e-3, 0.0, 0.0, 1e-6));
    EXPECT_FALSE(uzawaConverged(0.0, h, 1e-3, nan, 1e7, 1e-6));
}
